#!/usr/bin/env bash
# Runs one graph of graphs/ for a short time and checks that it ran to its end cleanly.
# Usage: run_graph_shortened.sh KESTREL_CLI GRAPH OUT_DIR
set -euo pipefail
cli=$1 graph=$2 out=$3
rm -rf "$out"
"$cli" validate "$graph"
"$cli" run "$graph" --duration "${KESTREL_SHORT_DURATION:-2}" --report "$out" --no-progress --stats
grep -q '"outcome": "completed"' "$out/report.json" || { echo "run did not complete"; cat "$out/report.json"; exit 1; }
test -s "$out/report.md"
