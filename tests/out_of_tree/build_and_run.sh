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
echo "out-of-tree plugin built, loaded and run"
