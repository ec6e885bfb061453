#!/usr/bin/env bash
# Builds the example plugin outside the kestrel tree exactly as an outside user would
# (find_package(kestrel VERSION) + kestrel_add_plugin), then loads and runs it:
#   install     against an install that was moved after installing (the package is relocatable),
#               run by the installed kestrel;
#   build-tree  against the build folder itself (its exported targets), run by the build's kestrel.
# Usage: build_and_run.sh BUILD_DIR EXAMPLE_DIR [install|build-tree]
set -euo pipefail
build=$(cd "$1" && pwd) example=$2 mode=${3:-install}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

case "$mode" in
  install)
    cmake --install "$build" --prefix "$work/installed" > "$work/install.log"
    mv "$work/installed" "$work/prefix"
    package=$work/prefix
    kestrel=$work/prefix/bin/kestrel
    ;;
  build-tree)
    package=$build
    kestrel=$build/bin/kestrel
    ;;
  *) echo "unknown mode '$mode': install or build-tree" >&2; exit 2 ;;
esac

cmake -S "$example" -B "$work/build" -DCMAKE_PREFIX_PATH="$package" -DCMAKE_BUILD_TYPE=Release > "$work/configure.log" \
  || { cat "$work/configure.log"; exit 1; }
grep -q "^kestrel_DIR:PATH=$package" "$work/build/CMakeCache.txt" \
  || { grep kestrel_DIR "$work/build/CMakeCache.txt"; echo "FAIL: the package was not found in $package"; exit 1; }
cmake --build "$work/build" -j 2 || exit 1

export KESTREL_PLUGIN_PATH="$work/build"
unset LD_LIBRARY_PATH
"$kestrel" inspect greeter | grep -q "Node type greeter"
"$kestrel" run "$example/hello.yaml" --report "$work/report" --no-progress
grep -q '"outcome": "completed"' "$work/report/report.json"
grep -q '"detections_seen": 10' "$work/report/report.json" || { cat "$work/report/report.json"; exit 1; }
grep -q '"hello.detections_seen"' "$work/report/report.json" || { echo "no metrics_meta entry"; exit 1; }
[ "$(wc -l < "$work/report/detections.csv")" -eq 11 ] || { echo "detections.csv is not header + 10 rows"; exit 1; }
# The example's rule, broken from the command line: refused as an invalid graph (exit 3).
set +e
"$kestrel" validate "$example/hello.yaml" --set greeter.end_m=-1 > "$work/validate.log" 2>&1
rc=$?
set -e
[ "$rc" -eq 3 ] && grep -q "break the rule 'start_m < end_m'" "$work/validate.log" \
  || { echo "validate exited $rc:"; cat "$work/validate.log"; exit 1; }
echo "out-of-tree plugin built against the $mode package, loaded and run"
