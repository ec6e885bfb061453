#!/usr/bin/env bash
# Runs scripts/paper-rsweep with very short runs and checks what it writes: a row per r value
# with the metrics the issue names, the Markdown table beside the paper's figures, and the plot.
set -euo pipefail
out=$1
rm -rf "$out"
scripts/paper-rsweep "$out" --duration 0.3 > /dev/null
python3 - "$out" <<'PY'
import json, os, sys
out = sys.argv[1]
doc = json.load(open(os.path.join(out, "rsweep.json")))
rs = [row["r"] for row in doc["rows"]]
assert rs == [0.5 + 0.5 * k for k in range(10)], rs
for row in doc["rows"]:
    for key in ("mota", "rmse_m", "target_mota"):
        assert isinstance(row[key], float) and row[key] >= 0, (key, row)
md = open(os.path.join(out, "rsweep.md")).read()
assert "| 2.5 |" in md and "paper: 0.09 m at r = 1.0" in md, md
assert os.path.getsize(os.path.join(out, "rsweep.png")) > 1000
PY
