#!/usr/bin/env bash
# kestrel on DDS against a DDS application that is not ours: a C subscriber and publisher made of
# Cyclone's C API and the types idlc compiled from ROS 2's message definitions (dds/*.idl).
#  1. kestrel publishes known messages (dds_bridge's publication); the C subscriber reads each
#     topic with its own generated types, and every field must equal what kestrel sent.
#  2. The C publisher sends known messages; kestrel's subscription must rebuild them exactly.
# Usage: check_dds_idl.sh PEER_TOOL IDL_SUBSCRIBER IDL_PUBLISHER WORK_DIR
set -euo pipefail
peer=$1 subscriber=$2 publisher=$3 work=$4
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work"
source "$here/dds/loopback.sh"
pids=()
trap 'for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done' EXIT

"$peer" publish "$DDS_DOMAIN" 30 interop "$work/sent.jsonl" &
pids+=($!)
"$subscriber" "$DDS_DOMAIN" 20 /interop > "$work/received.jsonl"
python3 - "$work/sent.jsonl" "$work/received.jsonl" <<'PY'
import json, sys
sent = {}
for line in open(sys.argv[1]):
    m = json.loads(line)
    sent[m["topic"]] = m["message"]
received = [json.loads(line) for line in open(sys.argv[2])]
def diff(a, b, path):
    if isinstance(a, dict) and isinstance(b, dict):
        if list(a) != list(b):
            return [f"{path}: fields {list(a)} != {list(b)}"]
        return [d for k in a for d in diff(a[k], b[k], f"{path}.{k}")]
    if isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            return [f"{path}: {len(a)} items != {len(b)}"]
        return [d for i, (x, y) in enumerate(zip(a, b)) for d in diff(x, y, f"{path}[{i}]")]
    return [] if a == b else [f"{path}: {a!r} != {b!r}"]
problems = []
for r in received:
    if r["topic"] not in sent:
        problems.append(f"{r['topic']}: kestrel sent nothing there")
        continue
    problems += diff(sent[r["topic"]], r["message"], r["topic"])
if len(received) != 6:
    problems.append(f"{len(received)} topics read, not 6")
for p in problems:
    print("MISMATCH", p)
print(f"{len(received)} topics read by the idlc-generated subscriber, {len(problems)} mismatches")
sys.exit(1 if problems else 0)
PY

"$publisher" "$DDS_DOMAIN" 30 /ros &
pids+=($!)
"$peer" expect "$DDS_DOMAIN" 20 ros
echo "kestrel rebuilt every message the idlc-generated publisher sent"
