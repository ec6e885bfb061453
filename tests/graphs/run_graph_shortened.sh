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
# Half of a graph split over DDS runs with its other half: both on loopback, in a domain of this
# test's own; the ground half starts first and ends when the vehicle half does.
read -r dds_node partner partner_node order < <(python3 "$here/outcomes.py" split "$name") || true
if [ -n "${dds_node:-}" ]; then
  export CYCLONEDDS_URI='<CycloneDDS><Domain id="any"><General><Interfaces><NetworkInterface name="lo"/></Interfaces><AllowMulticast>false</AllowMulticast></General><Discovery><ParticipantIndex>auto</ParticipantIndex><MaxAutoParticipantIndex>20</MaxAutoParticipantIndex><Peers><Peer address="127.0.0.1"/></Peers></Discovery></Domain></CycloneDDS>'
  domain=$(( $$ % 200 + 1 ))
  mkdir -p "$out/partner"
  partner_graph="$(dirname "$graph")/$partner.yaml"
  partner_duration=$(python3 "$here/outcomes.py" duration "$partner")
  partner_args=(run "$partner_graph" --duration "$partner_duration" --report "$out/partner" --no-progress
                --set "$partner_node.domain_id=$domain")
  own_args=(--set "$dds_node.domain_id=$domain")
  # The ground records where the test writes.
  [ "$partner" = split_ground ] && partner_args+=(--set "recorder.file=$out/partner/ground.mcap")
  [ "$name" = split_ground ] && own_args+=(--set "recorder.file=$out/ground.mcap")
  if [ "$order" = first ]; then
    "$cli" "${partner_args[@]}" > "$out/partner/output.txt" 2>&1 &
    partner_pid=$!
    sleep 1
    "$cli" run "$graph" --duration "$duration" --report "$out" --no-progress --stats "${own_args[@]}"
    wait "$partner_pid" || { cat "$out/partner/output.txt" >&2; exit 1; }
  else
    "$cli" run "$graph" --duration "$duration" --report "$out" --no-progress --stats "${own_args[@]}" &
    own_pid=$!
    sleep 1
    "$cli" "${partner_args[@]}" > "$out/partner/output.txt" 2>&1 || { cat "$out/partner/output.txt" >&2; exit 1; }
    wait "$own_pid"
  fi
  live=("$out/partner/report.json")
else
  "$cli" run "$graph" --duration "$duration" --report "$out" --no-progress --stats "${replay[@]}" "${signing[@]}"
fi
test -s "$out/report.md"
python3 "$here/outcomes.py" check "$name" "$out/report.json" "$duration" "${live[@]}"
