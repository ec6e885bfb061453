#!/usr/bin/env bash
# Runs scripts/paper-table1 with very short runs and checks what it writes: a row per distance
# for each field of view (and with trees behind the intruder), each with the camera-frame and the body-frame figures, the body-frame
# RMSE being the camera-frame one on the paper's axes (X = depth = camera z, Y = camera x,
# Z = camera y), and the table that sets the paper's X/Y/Z beside ours.
set -euo pipefail
out=$1
rm -rf "$out"
scripts/paper-table1 "$out" --duration 0.5 > /dev/null
python3 - "$out" <<'PY'
import json, os, sys
out = sys.argv[1]
doc = json.load(open(os.path.join(out, "table1.json")))
for rows in (doc["rows"], doc["variants"]["ocams_fov_70.6"]):
    assert [r["distance_m"] for r in rows] == [2.5, 5.0, 7.5], rows
    for r in rows:
        c, b, m, bias = r["rmse_m"], r["rmse_body_m"], r["mean_error_m"], r["bias_body_m"]
        assert r["tp"] > 0, r
        for body, camera in (("x", "z"), ("y", "x"), ("z", "y")):
            assert abs(b[body] - c[camera]) < 1e-12, (body, b, c)
        assert abs(bias["x"] - m["z"]) < 1e-12 and abs(bias["y"] + m["x"]) < 1e-12 and abs(bias["z"] + m["y"]) < 1e-12
trees = doc["variants"]["trees_1_3m_behind"]
assert [r["distance_m"] for r in trees] == [2.5, 5.0, 7.5] and all(r["frames"] > 0 for r in trees), trees
assert [p["rmse_body_m"]["x"] for p in doc["paper"]] == [0.063, 0.073, 0.174], doc["paper"]
md = open(os.path.join(out, "table1.md")).read()
assert "| distance [m] | source | RMSE X, depth [m] | RMSE Y, left [m] | RMSE Z, up [m] |" in md, md
assert md.count("| paper |") == 3 and md.count("kestrel, FOV 92.8°") == 12, md
assert md.count("kestrel, FOV 92.8°, trees 1–3 m behind") == 6, md
PY
