#!/usr/bin/env bash
# Interop (CTest label `interop`): `kestrel run --live` watched by @foxglove/ws-protocol's client,
# as Foxglove watches it. The closed loop, rendered camera and all, runs in realtime; the client
# sees the `time` capability and Time frames, lists the channels, subscribes to the cloud, the
# markers and the hunter's odometry, and decodes each from its advertised ros2msg schema; /tf
# places both vehicles in the world and the camera on the hunter. Then the
# run is stopped with SIGINT and must end cleanly with the bridge's figures in its report.
# Every topic docs/foxglove-layout.json's 3D panel shows must come through too, and its image
# must be advertised, so that the layout stays true.
# Usage: check_live_view.sh KESTREL GRAPHS_DIR WORKDIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
kestrel=$1 graphs=$2 work=$3
"$here/npm-install" "$work/node"
cp "$here"/*.mjs "$work/node/"
out="$work/live_view"
rm -rf "$out"
mkdir -p "$out"
# A free port, found the way the kernel hands them out; the bridge listens on it before the run
# starts, and "[kestrel] running" on stderr says the run has started.
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
"$kestrel" run "$graphs/sim_intercept.yaml" --executor realtime --duration 120 --no-progress --live "$port" \
  --report "$out/report" > "$out/kestrel.out" 2> "$out/kestrel.log" &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
for _ in $(seq 1 1200); do
  grep -q '^\[kestrel\] running' "$out/kestrel.log" && break
  kill -0 $pid 2>/dev/null || { cat "$out/kestrel.log" >&2; echo "kestrel ended before running" >&2; exit 1; }
  sleep 0.1
done
grep -q '^\[kestrel\] running' "$out/kestrel.log" || { cat "$out/kestrel.log" >&2; echo "the run did not start" >&2; exit 1; }
layout="$graphs/../docs/foxglove-layout.json"
mapfile -t layout_topics < <(python3 - "$layout" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))["configById"]
topics = {t for panel in c.values() for t in panel.get("topics", {})}
for t in sorted(topics): print(f"^{t}$")
PY
)
node "$work/node/live_view_client.mjs" "ws://127.0.0.1:$port" '/cloud$|/filtered$' '/markers$' '^/hunter/odometry$' \
  'tf:world>hunter' 'tf:hunter>camera' \
  "${layout_topics[@]}" > "$out/client.json"
kill -INT $pid
wait $pid
trap - EXIT
python3 - "$out" "$layout" <<'PY'
import json, os, sys
out = sys.argv[1]
c = json.load(open(os.path.join(out, "client.json")))
r = json.load(open(os.path.join(out, "report", "report.json")))
def check(cond, what):
    if not cond:
        sys.exit(f"check_live_view: {what}\nclient: {json.dumps(c)[:4000]}")
check("time" in c["serverInfo"]["capabilities"], "serverInfo declares the time capability")
check(c["times"] >= 1 and int(c["lastTime"]) >= int(c["firstTime"]), "Time frames carry the graph's clock")
topics = {ch["topic"]: ch for ch in c["channels"]}
check(all(ch["encoding"] == "cdr" and ch["schemaEncoding"] == "ros2msg" for ch in c["channels"]), "cdr with ros2msg")
check(topics.get("/hunter/odometry", {}).get("schemaName") == "nav_msgs/msg/Odometry", "the hunter's odometry channel")
check(topics.get("/tf", {}).get("schemaName") == "tf2_msgs/msg/TFMessage", "a /tf channel")
# The layout's image is advertised; its bytes are decoded by interop.ros2_recording (a Node client
# subscribed to two 1 MB images at 30 Hz falls behind the rest).
layout = json.load(open(sys.argv[2]))
for panel in layout["configById"].values():
    if "imageMode" in panel:
        t = panel["imageMode"]["imageTopic"]
        check(topics.get(t, {}).get("schemaName") == "sensor_msgs/msg/Image", f"the layout's image {t} is advertised")
got = c["received"]
clouds = [t for t, e in got.items() if e["schemaName"] == "sensor_msgs/msg/PointCloud2"]
check(clouds and got[clouds[0]]["sample"]["point_step"] == 12, "a cloud decoded, 12 bytes a point")
markers = [t for t, e in got.items() if e["schemaName"] == "visualization_msgs/msg/MarkerArray"]
check(markers, "markers decoded")
odom = got.get("/hunter/odometry")
check(odom and odom["sample"]["child_frame_id"] == "hunter", "the hunter's odometry decoded, child frame hunter")
check({"world>hunter", "hunter>camera"} <= set(c["transforms"]), "/tf places the hunter and its camera")
live = r["live"]
check(live["clients"] >= 1 and live["messages_sent"] >= 3, "the report counts the client and what it was sent")
print(f"check_live_view: port {live['port']}, {len(c['channels'])} channels, received "
      + ", ".join(f"{t} x{e['count']}" for t, e in sorted(got.items())))
PY
