#!/usr/bin/env bash
# Interop (CTest label `interop`): a kestrel recording of the paper's detection graph, every
# output recorded, read by the reference implementations Foxglove uses (@mcap/core with every CRC
# checked, @foxglove/rosmsg and @foxglove/rosmsg2-serialization decoding each channel from its
# schema), gives exactly the messages `kestrel mcap cat` prints.
# Usage: check_ros2_recording.sh KESTREL GRAPHS_DIR WORKDIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
kestrel=$1 graphs=$2 work=$3
"$here/npm-install" "$work/node"
cp "$here"/*.mjs "$work/node/"
out="$work/ros2_recording"
rm -rf "$out"
mkdir -p "$out"
# A short run, small images: every kestrel message type the detection graph publishes, clouds too.
"$kestrel" run "$graphs/paper_detection.yaml" --duration 0.2 --no-progress --record "$out/run.mcap" --topics '*' \
  --set camera.width=160 --set camera.height=120 --set camera.supersample=1 --set depth.num_disparities=16
# And the closed loop at detection level: vehicle states with /tf, tracks, setpoints, commands.
"$kestrel" run "$graphs/sim_intercept_fast.yaml" --duration 1 --no-progress --record "$out/loop.mcap" --topics '*'
for run in run loop; do
  "$kestrel" mcap cat "$out/$run.mcap" > "$out/$run.kestrel.jsonl"
  node "$work/node/ros2_recording_read.mjs" "$out/$run.mcap" > "$out/$run.reference.jsonl"
done
python3 - "$out" <<'PY'
import json, os, sys
out = sys.argv[1]
def lines(name): return [json.loads(l) for l in open(os.path.join(out, name))]
expected = {
    "run": {"/camera/frame/left": "sensor_msgs/msg/Image", "/camera/frame/left/camera_info": "sensor_msgs/msg/CameraInfo",
            "/depth/cloud": "sensor_msgs/msg/PointCloud2", "/refine/detections": "kestrel_msgs/msg/Detections",
            "/refine/detections/markers": "visualization_msgs/msg/MarkerArray",
            "/camera/truth": "kestrel_msgs/msg/GroundTruth"},
    "loop": {"/tf": "tf2_msgs/msg/TFMessage", "/tracker/tracks": "kestrel_msgs/msg/Tracks",
             "/tracker/tracks/markers": "visualization_msgs/msg/MarkerArray"},
}
for run, topics in expected.items():
    reference, got = lines(run + ".reference.jsonl"), lines(run + ".kestrel.jsonl")
    summary = reference.pop()["summary"]
    assert summary["profile"] == "ros2", summary
    assert len(got) == len(reference) == summary["messages"] > 0, (len(got), len(reference), summary["messages"])
    for e, g in zip(reference, got):
        assert e == g, f"kestrel printed\n{json.dumps(g)[:400]}\nthe reference decodes\n{json.dumps(e)[:400]}"
    schemas = {c["topic"]: c["schema"] for c in summary["channels"]}
    for topic, schema in topics.items():
        assert schemas.get(topic) == schema, (run, topic, schemas.get(topic))
    assert "seed" in summary["metadata"]["kestrel"], summary["metadata"]
    kinds = sorted(set(schemas.values()))
    print(f"@mcap/core and @foxglove/rosmsg2-serialization read the {len(got)} messages of a kestrel recording ({run}) "
          f"on {len(schemas)} channels as kestrel mcap cat prints them: {', '.join(kinds)}")
PY
