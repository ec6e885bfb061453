#!/usr/bin/env bash
# Interop (CTest label `interop`): kestrel's MAVLink 2 signatures against node-mavlink's, an
# independent implementation, at the version pinned in tests/interop/package-lock.json.
# - node-mavlink signs five messages (HEARTBEAT, COMMAND_LONG, SET_POSITION_TARGET_LOCAL_NED,
#   ATTITUDE_QUATERNION with its extension, SETUP_SIGNING): kestrel finds every signature right
#   and, signing the decoded message again with the same ids, link id and timestamp, writes the
#   same bytes;
# - kestrel signs five messages of its own: node-mavlink finds every signature right and writes
#   the same bytes; a copy with one payload bit changed is refused by both.
# Usage: check_mavlink_signing.sh SIGNING_TOOL WORKDIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
tool=$1
work=$2
"$here/npm-install" "$work/node"
rm -rf "$work/mavlink"
mkdir -p "$work/mavlink"
cp "$here"/*.mjs "$work/node/"

node "$work/node/mavlink_signed_frames.mjs" write "$work/mavlink/node_frames.json"
"$tool" check "$work/mavlink/node_frames.json" > "$work/mavlink/kestrel_verdicts.json"
key=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['key'])" "$work/mavlink/node_frames.json")
"$tool" write "$work/mavlink/kestrel_frames.json" "$key"
node "$work/node/mavlink_signed_frames.mjs" check "$work/mavlink/kestrel_frames.json" > "$work/mavlink/node_verdicts.json"

# One payload bit flipped and the checksum made good again: only the signature can tell.
python3 - "$work/mavlink" <<'PY'
import json, os, sys
d = sys.argv[1]
CRC_EXTRA = {0: 50, 76: 152, 84: 143, 31: 246, 256: 71}  # common.xml's, for the five messages
def crc16(data, extra):
    crc = 0xFFFF
    for b in list(data) + [extra]:
        t = (b ^ crc) & 0xFF
        t = (t ^ (t << 4)) & 0xFF
        crc = ((crc >> 8) ^ (t << 8) ^ (t << 3) ^ (t >> 4)) & 0xFFFF
    return crc
for src, dst in [("node_frames.json", "node_tampered.json"), ("kestrel_frames.json", "kestrel_tampered.json")]:
    data = json.load(open(os.path.join(d, src)))
    for f in data["frames"]:
        b = bytearray.fromhex(f["hex"])
        length, msgid = b[1], b[7] | b[8] << 8 | b[9] << 16
        b[10] ^= 0x01  # the payload's first byte
        crc = crc16(b[1:10 + length], CRC_EXTRA[msgid])
        b[10 + length], b[11 + length] = crc & 0xFF, crc >> 8
        f["hex"] = b.hex()
    json.dump(data, open(os.path.join(d, dst), "w"))
PY
"$tool" check "$work/mavlink/node_tampered.json" > "$work/mavlink/kestrel_tampered_verdicts.json"
node "$work/node/mavlink_signed_frames.mjs" check "$work/mavlink/kestrel_tampered.json" > "$work/mavlink/node_tampered_verdicts.json"

python3 - "$work/mavlink" <<'PY'
import json, os, sys
d = sys.argv[1]
def load(name): return json.load(open(os.path.join(d, name)))
names = ["HEARTBEAT", "COMMAND_LONG", "SET_POSITION_TARGET_LOCAL_NED", "ATTITUDE_QUATERNION", "SETUP_SIGNING"]
node_frames = load("node_frames.json")["frames"]
for who, verdicts, frames in [("kestrel on node-mavlink's frames", load("kestrel_verdicts.json"), node_frames),
                              ("node-mavlink on kestrel's frames", load("node_verdicts.json"),
                               load("kestrel_frames.json")["frames"])]:
    assert [v["name"] for v in verdicts] == names, (who, [v["name"] for v in verdicts])
    for v, f in zip(verdicts, frames):
        assert v["signed"] and v["matches"], (who, v)
        assert v["same_bytes"], (who, v, f["hex"])
    print(f"{who}: {len(verdicts)} signatures match, byte for byte")
for v, f in zip(load("kestrel_verdicts.json"), node_frames):
    assert v["link_id"] == f["linkId"] and v["timestamp"] == f["timestamp"], (v, f)
for who, name in [("kestrel", "kestrel_tampered_verdicts.json"), ("node-mavlink", "node_tampered_verdicts.json")]:
    tampered = load(name)
    assert len(tampered) == 5 and all(v["signed"] and not v["matches"] for v in tampered), (who, tampered)
print("tampered frames (checksum made good): both refuse every signature")
PY
