#!/usr/bin/env bash
# Runs scripts/range-table on one range with very short runs, from the hovering hunter in both
# modes, and checks what it writes and what the 1280x960 mode must see: the intruder 15 m away in
# nearly every frame, placed within the range work's depth bar (0.5 m RMS at 15 m).
set -euo pipefail
out=$1
rm -rf "$out"
scripts/range-table "$out" --duration 1 --ranges 15 --modes "640 1280" --cameras hold --scenes open > /dev/null
python3 - "$out" <<'PY'
import json, os, sys
out = sys.argv[1]
doc = json.load(open(os.path.join(out, "range.json")))
rows = {r["mode"]: r for r in doc["rows"]}
assert sorted(rows) == ["1280", "640"] and all(r["camera"] == "hold" and r["range_m"] == 15.0 for r in rows.values())
for mode, r in rows.items():
    assert r["frames"] == 30, r
    # A quarter pixel of disparity at 15 m: fx = 304 px at 640 and 608 px at 1280, b = 0.12 m.
    assert abs(r["depth_bound_m"] - 225 * 0.25 / ((304.0 if mode == "640" else 608.0) * 0.12)) < 1e-9, r
    assert r["gate_dropped"] == 0, r  # no piece of the ground reaches the height gate
    assert r["ms_per_frame"] > 0, r
hi = rows["1280"]
assert hi["recall"] >= 0.9 and hi["precision"] >= 0.9, hi
assert 0 < hi["rmse_body_m"]["x"] <= 0.5, hi
md = open(os.path.join(out, "range.md")).read()
assert md.count("| hold | open | 15 |") == 2, md
assert os.path.getsize(os.path.join(out, "range.png")) > 1000
header = open(os.path.join(out, "range.csv")).readline().strip().split(",")
assert header[0] == "range_m" and "hold_open_1280" in header and "bound_640" in header, header
PY
