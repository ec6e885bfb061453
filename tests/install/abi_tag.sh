#!/usr/bin/env bash
# The ABI tag follows declarations, not comments. Copies an install, edits public headers in the
# copy, regenerates kestrel/version.hpp from the edited tree as kestrel's build does
# (cmake/KestrelAbi.cmake), builds examples/hello_plugin against the copy, and loads the plugin
# with the original installed kestrel:
#   comment  comments and whitespace added to kestrel/node.hpp and a message header: same tag,
#            the plugin loads;
#   layout   msg::Detection gains a field: another tag, the plugin is refused (exit 4) and the
#            message names both tags.
# Usage: abi_tag.sh BUILD_DIR SOURCE_DIR VERSION comment|layout
set -euo pipefail
build=$(cd "$1" && pwd) source=$2 version=$3 mode=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
unset LD_LIBRARY_PATH KESTREL_PLUGIN_PATH

cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
kestrel=$work/prefix/bin/kestrel
cp -a "$work/prefix" "$work/edited"
inc=$work/edited/include
regenerate() {
  cmake -DOUTPUT="$1" -DVERSION="$version" -DINCLUDE_DIRS="$inc" -P "$source/cmake/KestrelAbi.cmake" > /dev/null
}
api_hash() { sed -n 's/^#define KESTREL_API_HASH "\(.*\)"$/\1/p' "$1"; }

# The generation reproduces the installed header from the unedited tree, byte for byte.
regenerate "$work/regenerated.hpp"
cmp "$work/regenerated.hpp" "$work/prefix/include/kestrel/version.hpp" \
  || { echo "FAIL: regenerating version.hpp from the installed headers gives another file"; exit 1; }

node=$inc/kestrel/node.hpp
detections=$inc/kestrel/messages/detections.hpp
case "$mode" in
  comment)
    sed -i -e '1i // An added comment line, then an empty line.\n' \
           -e 's/^class Node {$/class   Node\n{  \/* a block comment *\//' \
           -e 's/^\(  [a-z].*;\)$/\1   \/\/ a trailing comment/' "$node"
    sed -i -e 's/^struct Detection {$/\/**\n * A documented Detection.\n *\/\nstruct Detection\n{/' \
           -e 's/^  int point_count = 0;$/  int    point_count  =  0 ;  \/\/ spaced out/' "$detections"
    ;;
  layout)
    sed -i 's/^  double confidence = 1.0;$/&\n  double extra = 0;/' "$detections"
    grep -q 'double extra = 0;' "$detections" || { echo "FAIL: could not add a field to msg::Detection"; exit 1; }
    ;;
  *) echo "unknown mode '$mode': comment or layout" >&2; exit 2 ;;
esac
for f in "$node" "$detections"; do
  if [ "$mode" = comment ] || [ "$f" = "$detections" ]; then
    if cmp -s "$f" "$work/prefix/include/${f#"$inc/"}"; then
      echo "FAIL: the edit left $f unchanged"
      exit 1
    fi
  fi
done
echo "edited headers:"
diff -ru "$work/prefix/include" "$inc" | grep "^[+-][^+-]" | head -n 12 || true

regenerate "$inc/kestrel/version.hpp"
installed=$(api_hash "$work/prefix/include/kestrel/version.hpp")
edited=$(api_hash "$inc/kestrel/version.hpp")
echo "API hash: installed $installed, edited tree $edited"

cmake -S "$source/examples/hello_plugin" -B "$work/plugin" -DCMAKE_PREFIX_PATH="$work/edited" \
  -DCMAKE_BUILD_TYPE=Release > "$work/configure.log" || { cat "$work/configure.log"; exit 1; }
grep -q "^kestrel_DIR:PATH=$work/edited/" "$work/plugin/CMakeCache.txt" || { echo "FAIL: not built against the copy"; exit 1; }
cmake --build "$work/plugin" -j 2 > "$work/build.log" || { cat "$work/build.log"; exit 1; }
plugin=$work/plugin/kestrel_hello.so

rc=0
out=$(KESTREL_PLUGIN_PATH=$plugin "$kestrel" plugins 2>&1) || rc=$?
case "$mode" in
  comment)
    [ "$installed" = "$edited" ] || { echo "FAIL: a comment edit moved the API hash"; exit 1; }
    if [ "$rc" -ne 0 ] || ! grep -q "^hello .*kestrel_hello\.so" <<<"$out"; then
      echo "$out"
      echo "FAIL: kestrel exited $rc and did not load the plugin built against the commented headers"
      exit 1
    fi
    KESTREL_PLUGIN_PATH=$plugin "$kestrel" run "$source/examples/hello_plugin/hello.yaml" --report "$work/report" \
      --no-progress > "$work/run.log" 2>&1 || { cat "$work/run.log"; exit 1; }
    grep -q '"detections_seen": 10' "$work/report/report.json" || { cat "$work/report/report.json"; exit 1; }
    echo "comment edit: same ABI tag, plugin loaded and run"
    ;;
  layout)
    [ "$installed" != "$edited" ] || { echo "FAIL: a new message field left the API hash at $installed"; exit 1; }
    echo "$out" | grep -i 'refus' || true
    if [ "$rc" -ne 4 ]; then
      echo "$out"
      echo "FAIL: kestrel exited $rc, not 4, for a plugin built against another message layout"
      exit 1
    fi
    if ! grep -q "refusing plugin .*kestrel_hello\.so.*api-$edited.*api-$installed" <<<"$out"; then
      echo "$out"
      echo "FAIL: the refusal does not name both ABI tags (plugin api-$edited, kestrel api-$installed)"
      exit 1
    fi
    echo "layout change: ABI tag moved, plugin refused with exit 4"
    ;;
esac
