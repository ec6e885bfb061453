#!/usr/bin/env bash
# Installs kestrel into a scratch prefix, builds the example plugin against the installed
# package exactly as an outside user would (find_package + kestrel_add_plugin), then loads it.
# Usage: build_and_run.sh BUILD_DIR EXAMPLE_DIR
set -euo pipefail
build=$1 example=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
cmake -S "$example" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release > "$work/configure.log" \
  || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/build" -j 2 || exit 1

export KESTREL_PLUGIN_PATH="$work/build"
kestrel="$work/prefix/bin/kestrel"
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
echo "out-of-tree plugin built, loaded and run"
