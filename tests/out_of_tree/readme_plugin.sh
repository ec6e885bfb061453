#!/usr/bin/env bash
# The README's plugin, exactly as printed: the first C++ block and the CMake block of "A plugin in
# five minutes" are copied into a fresh folder, built against the build tree with find_package,
# then the plugin is loaded and run. The README cannot drift from what compiles and works.
# Usage: readme_plugin.sh BUILD_DIR README
set -euo pipefail
build=$(cd "$1" && pwd) readme=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The n-th fenced block of a language inside the README's plugin section.
block() {
  awk -v lang="$1" -v want="$2" '
    /^## / { in_section = ($0 == "## A plugin in five minutes") }
    in_section && $0 == "```" lang { n++; if (n == want) { copying = 1; next } }
    copying && $0 == "```" { exit }
    copying { print }
  ' "$readme"
}
mkdir -p "$work/src"
block cpp 1 > "$work/src/hello.cpp"
block cmake 1 > "$work/src/CMakeLists.txt"
grep -q "KESTREL_REGISTER_NODE" "$work/src/hello.cpp" || { echo "FAIL: no plugin source found in $readme"; exit 1; }
grep -q "kestrel_add_plugin" "$work/src/CMakeLists.txt" || { echo "FAIL: no CMakeLists.txt found in $readme"; exit 1; }

cmake -S "$work/src" -B "$work/build" -DCMAKE_PREFIX_PATH="$build" -DCMAKE_BUILD_TYPE=Release > "$work/configure.log" \
  || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/build" -j 2 || { echo "FAIL: the README's plugin does not build"; exit 1; }

export KESTREL_PLUGIN_PATH="$work/build"
"$build/bin/kestrel" inspect greeter | grep -q "start_m < end_m" || { echo "FAIL: greeter not loaded"; exit 1; }
cat > "$work/graph.yaml" <<'YAML'
nodes:
  - {id: greeter, type: greeter, params: {rate_hz: 10}}
  - {id: plot, type: trajectory_plot}
connections:
  - {from: greeter.detections, to: plot.detections}
duration: 1.0
YAML
"$build/bin/kestrel" run "$work/graph.yaml" --report "$work/report" --no-progress
grep -q '"outcome": "completed"' "$work/report/report.json"
grep -Eq '"samples": (10|11)\b' "$work/report/report.json" || { cat "$work/report/report.json"; exit 1; }
echo "the README's plugin builds, loads and runs"
