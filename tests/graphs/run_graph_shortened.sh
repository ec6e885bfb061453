#!/usr/bin/env bash
# Runs one graph of graphs/ for a short time and checks its outcome in report.json against what
# the method must achieve in that time (tests/graphs/outcomes.py).
# Usage: run_graph_shortened.sh KESTREL_CLI GRAPH OUT_DIR
# KESTREL_SHORT_DURATION overrides the run length that outcomes.py gives the graph.
set -euo pipefail
cli=$1 graph=$2 out=$3
here=$(cd "$(dirname "$0")" && pwd)
name=$(basename "$graph" .yaml)
duration=${KESTREL_SHORT_DURATION:-$(python3 "$here/outcomes.py" duration "$name")}
rm -rf "$out"
# A replay graph replays a recording of the shortened run of the graph it names.
recorded=$(python3 "$here/outcomes.py" recorded "$name")
replay=() live=()
if [ -n "$recorded" ]; then
  "$cli" run "$(dirname "$graph")/$recorded.yaml" --duration "$duration" --record "$out/live/run.mcap" \
    --report "$out/live" --no-progress
  replay=(--set "replay.file=$out/live/run.mcap")
  live=("$out/live/report.json")
fi
"$cli" validate "$graph" "${replay[@]}"
"$cli" run "$graph" --duration "$duration" --report "$out" --no-progress --stats "${replay[@]}"
test -s "$out/report.md"
python3 "$here/outcomes.py" check "$name" "$out/report.json" "$duration" "${live[@]}"
