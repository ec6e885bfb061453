#!/usr/bin/env bash
# Runs scripts/capture-benchmark on a few short engagements with the detection-level camera and
# checks what it writes: the scenarios (one per seed, every shape), capture.json with the keys
# the issue names and figures that follow from the runs' own reports, and the Markdown table.
set -euo pipefail
out=$1
rm -rf "$out"
scripts/capture-benchmark "$out" --seeds 6 --rendered 0 --duration 12 > /dev/null
python3 - "$out" <<'PY'
import csv, json, os, statistics, sys
out = sys.argv[1]
cases = list(csv.DictReader(open(os.path.join(out, "cases.csv"))))
assert [c["seed"] for c in cases] == [str(s) for s in range(1, 7)], cases
assert {c["intruder.shape"] for c in cases} == {"figure8", "line", "random"}, cases
doc = json.load(open(os.path.join(out, "capture.json")))
for key in ("runs", "success_rate", "median_time_to_capture_s", "aim_rmse_m", "failures"):
    assert key in doc, f"capture.json lacks {key}"
assert doc["runs"] == 6, doc["runs"]
# The summary is the runs' reports, recounted here from each report.json.
caught, times = 0, []
for name in sorted(os.listdir(os.path.join(out, "fast", "runs"))):
    control = json.load(open(os.path.join(out, "fast", "runs", name, "report.json")))["control"]
    if control["captured"]:
        caught += 1
        times.append(control["time_to_capture_s"])
assert abs(doc["success_rate"] - caught / 6) < 1e-12, (doc["success_rate"], caught)
assert len(doc["failures"]) == 6 - caught
assert all(f["cause"] for f in doc["failures"])
if times:
    assert abs(doc["median_time_to_capture_s"] - statistics.median(times)) < 1e-9
# The loop catches most of these engagements even in 12 s.
assert caught >= 4, f"only {caught} of 6 caught"
md = open(os.path.join(out, "capture.md")).read()
assert "| detection-level camera | 6 |" in md, md
assert "rendered" not in doc
PY
