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
# A graph for a device the machine lacks is validated, and its run must fail cleanly, saying why.
needs=$(python3 "$here/outcomes.py" hardware "$name")
if [ -n "$needs" ]; then
  "$cli" validate "$graph"
  mkdir -p "$out"
  set +e
  "$cli" run "$graph" --duration "$duration" --report "$out" --no-progress > "$out/output.txt" 2>&1
  code=$?
  set -e
  cat "$out/output.txt" >&2
  [ "$code" -eq 1 ] || { echo "expected exit code 1 without the device, got $code" >&2; exit 1; }
  grep -q "$needs" "$out/output.txt" || { echo "the run did not say '$needs'" >&2; exit 1; }
  exit 0
fi
# A replay graph replays a recording of the shortened run of the graph it names, with the files
# that run wrote (outcomes.py recorded).
replay=() live=() live_sets=()
{ read -r recorded || true; mapfile -t sets; } < <(python3 "$here/outcomes.py" recorded "$name")
if [ -n "${recorded:-}" ]; then
  for line in "${sets[@]}"; do
    read -r which key file <<< "$line"
    if [ "$which" = live ]; then live_sets+=(--set "$key=$out/live/$file"); else replay+=(--set "$key=$out/live/$file"); fi
  done
  "$cli" run "$(dirname "$graph")/$recorded.yaml" --duration "$duration" --record "$out/live/run.mcap" \
    --report "$out/live" --no-progress "${live_sets[@]}"
  live=("$out/live/report.json")
fi
# A graph whose MAVLink link is signed gets a fresh key, as a user writes one before the first run.
signing=()
for node in $(python3 "$here/outcomes.py" signing "$name"); do
  [ -f "$out/signing.key" ] || { mkdir -p "$out"; "$cli" mavlink keygen "$out/signing.key"; }
  signing+=(--set "$node.signing_key_file=$out/signing.key")
done
"$cli" validate "$graph" "${replay[@]}" "${signing[@]}"
"$cli" run "$graph" --duration "$duration" --report "$out" --no-progress --stats "${replay[@]}" "${signing[@]}"
test -s "$out/report.md"
python3 "$here/outcomes.py" check "$name" "$out/report.json" "$duration" "${live[@]}"
