# Checks shared by the install and package tests. Source it; each check exits on failure.
# shellcheck shell=bash

# check_relative_rpaths PREFIX: every installed ELF file finds its libraries relative to itself.
check_relative_rpaths() {
  local prefix=$1 f entry
  while IFS= read -r f; do
    head -c 4 "$f" | grep -q 'ELF' || continue
    while IFS= read -r entry; do
      case "$entry" in
        '$ORIGIN' | '$ORIGIN/'*) ;;
        *) echo "FAIL: $f has a non-relative RPATH entry '$entry'" >&2; exit 1 ;;
      esac
    done < <(readelf -d "$f" | sed -n 's/.*R\(UN\)\{0,1\}PATH.*\[\(.*\)\]/\2/p' | tr ':' '\n')
  done < <(find "$prefix" -type f \( -path '*/bin/*' -o -name '*.so*' \))
}

# check_plugins KESTREL BUILD_DIR: `kestrel plugins` exits 0, refuses nothing and lists every
# plugin the build made, each loaded from beside the installed runtime.
check_plugins() {
  local kestrel=$1 build=$2 out rc=0 so name count=0
  out=$(env -u LD_LIBRARY_PATH -u KESTREL_PLUGIN_PATH "$kestrel" plugins 2>&1) || rc=$?
  if [ "$rc" -ne 0 ] || grep -qi 'refus' <<<"$out"; then
    echo "$out" >&2
    echo "FAIL: kestrel plugins exited $rc" >&2
    exit 1
  fi
  for so in "$build"/lib/kestrel/plugins/kestrel_*.so; do
    name=$(basename "$so" .so)
    name=${name#kestrel_}
    if ! grep -Eq "^$name [0-9.]+ +\(.*/kestrel/plugins/kestrel_$name\.so\)" <<<"$out"; then
      echo "$out" >&2
      echo "FAIL: plugin $name is not listed" >&2
      exit 1
    fi
    count=$((count + 1))
  done
  [ "$count" -gt 0 ] || { echo "FAIL: no plugin in $build/lib/kestrel/plugins" >&2; exit 1; }
  echo "kestrel plugins: all $count in-tree plugins loaded"
}

# check_graph KESTREL GRAPH WORKDIR: a one-second run of GRAPH from WORKDIR completes.
check_graph() {
  local kestrel=$1 graph=$2 dir=$3
  mkdir -p "$dir"
  (cd "$dir" && env -u LD_LIBRARY_PATH -u KESTREL_PLUGIN_PATH "$kestrel" run "$graph" --duration 1 --report report \
    --no-progress > run.log 2>&1) || { cat "$dir/run.log" >&2; echo "FAIL: kestrel run $graph" >&2; exit 1; }
  grep -q '"outcome": "completed"' "$dir/report/report.json" || { cat "$dir/report/report.json" >&2; exit 1; }
  echo "kestrel run $graph: completed from $dir"
}
