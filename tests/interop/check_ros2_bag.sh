#!/usr/bin/env bash
# Interop (CTest label `interop`): `kestrel mcap cat` on a ROS 2-style bag (profile ros2, cdr
# messages with ros2msg schemas, zstd chunks) synthesized with @mcap/core,
# @foxglove/rosmsg2-serialization and @foxglove/wasm-zstd, must print every message as those
# reference implementations decode it, and `kestrel mcap info` must agree on the channels.
# Usage: check_ros2_bag.sh KESTREL WORKDIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
kestrel=$1
work=$2
"$here/npm-install" "$work/node"
cp "$here"/*.mjs "$work/node/"
out="$work/ros2_bag"
rm -rf "$out"
mkdir -p "$out"
node "$work/node/ros2_bag_write.mjs" "$out/bag.mcap" > "$out/expected.jsonl"
"$kestrel" mcap cat "$out/bag.mcap" > "$out/kestrel.jsonl"
"$kestrel" mcap info "$out/bag.mcap" --json --verify > "$out/info.json"
"$kestrel" mcap cat "$out/bag.mcap" --topic /tf --limit 2 > "$out/tf.jsonl"
python3 - "$out" <<'PY'
import json, os, sys
out = sys.argv[1]
def lines(name): return [json.loads(l) for l in open(os.path.join(out, name))]
expected, got = lines("expected.jsonl"), lines("kestrel.jsonl")
assert len(got) == len(expected) == 55, (len(got), len(expected))
for e, g in zip(expected, got):
    assert e == g, f"kestrel printed\n{json.dumps(g)[:400]}\nthe reference decodes\n{json.dumps(e)[:400]}"
tf = lines("tf.jsonl")
assert [l["topic"] for l in tf] == ["/tf", "/tf"] and tf == [e for e in expected if e["topic"] == "/tf"][:2]
info = json.load(open(os.path.join(out, "info.json")))
assert info["profile"] == "ros2" and info["messages"] == 55 and list(info["compression"]) == ["zstd"], info
types = {c["topic"]: c["schema_name"] for c in info["channels"]}
assert types["/odom"] == "nav_msgs/msg/Odometry" and types["/points"] == "sensor_msgs/msg/PointCloud2", types
assert all(c["message_encoding"] == "cdr" and c["schema_encoding"] == "ros2msg" for c in info["channels"])
assert info["verified"]["chunks_with_crc"] == info["chunks"] > 1
print(f"kestrel mcap cat decodes the {len(got)} messages of a ROS 2-style bag as @foxglove/rosmsg2-serialization does")
PY
