#!/usr/bin/env bash
# Runs scripts/paper-rsweep with very short runs and checks what it writes: one row per r value,
# each with the outcome the paper reports for every r (MOTA above 0.999, one identity) and a
# selected-track RMSE that is a real error below the goal's bound and depends on r; the Markdown
# table beside the paper's figures, and the plot.
set -euo pipefail
out=$1
rm -rf "$out"
scripts/paper-rsweep "$out" --duration 0.3 > /dev/null
python3 - "$out" <<'PY'
import json, math, os, sys
out = sys.argv[1]
doc = json.load(open(os.path.join(out, "rsweep.json")))
rows = doc["rows"]
rs = [row["r"] for row in rows]
assert rs == [0.5 + 0.5 * k for k in range(10)], f"one row per r from 0.5 to 5.0 expected, got {rs}"
# The detections' error bound at 5 m (tests/graphs/outcomes.py): the paper's X and Y errors at
# 5 m and half a pixel of disparity in Z; a tracker fed them must do no worse.
bound = math.sqrt(0.073**2 + 0.108**2 + (0.5 * 5.0**2 / (304.0 * 0.12))**2)
failures = []
for row in rows:
    r = row["r"]
    if row["runs"] != doc["seeds"]:
        failures.append(f"r = {r}: {row['runs']} successful run(s) of {doc['seeds']}")
    for key in ("mota", "target_mota"):
        if not (isinstance(row[key], (int, float)) and row[key] >= 0.999):
            failures.append(f"r = {r}: {key} = {row[key]}, the paper has MOTA above 0.999 at every r")
    if row["idsw"] != 0:
        failures.append(f"r = {r}: {row['idsw']} identity switch(es)")
    rmse = row["rmse_m"]
    if not (isinstance(rmse, (int, float)) and math.isfinite(rmse) and 0 < rmse <= bound):
        failures.append(f"r = {r}: RMSE {rmse} is not a finite error in (0, {bound:.3f}] m")
# r is the filter's measurement noise: it shapes the gain, so the error cannot be the same at
# every r (a tracker that ignored r, or its detections, would give one value throughout).
if len({round(row["rmse_m"], 9) for row in rows if isinstance(row["rmse_m"], float)}) < 2:
    failures.append("the RMSE is the same at every r: r has no effect")
assert not failures, "\n".join(failures)
md = open(os.path.join(out, "rsweep.md")).read()
assert md.count("\n| ") == 1 + 10, "a header and one table row per r expected:\n" + md
assert "| 2.5 |" in md and "paper: 0.09 m at r = 1.0" in md, md
assert os.path.getsize(os.path.join(out, "rsweep.png")) > 1000
PY
