#!/usr/bin/env bash
# scripts/capture-compare on two made-up benchmark outputs whose paired counts are known: the
# counts by family and band, the exact McNemar p-value and the paired interval, and a clear error
# (exit 1) for outputs that flew different engagements or are no benchmark's.
set -euo pipefail
out=$1
rm -rf "$out"
mkdir -p "$out/a" "$out/b" "$out/c"
python3 - "$out" <<'PY'
import json, os, sys
out = sys.argv[1]
# 20 figure-8s at 0:3 m/s: 6 caught by both, 10 by B only, none by A only, 4 by neither;
# 10 lines at 3:6 m/s: 5 by both, 2 by A only, 2 by B only, 1 by neither.
a, b = [], []
def run(seed, family, band, caught):
    return {"seed": seed, "family": family, "band": band, "captured": caught}
pattern = [("figure8", "0:3", 1, 1)] * 6 + [("figure8", "0:3", 0, 1)] * 10 + [("figure8", "0:3", 0, 0)] * 4 + \
          [("line", "3:6", 1, 1)] * 5 + [("line", "3:6", 1, 0)] * 2 + [("line", "3:6", 0, 1)] * 2 + \
          [("line", "3:6", 0, 0)]
for seed, (family, band, in_a, in_b) in enumerate(pattern, start=1):
    a.append(run(seed, family, band, bool(in_a)))
    b.append(run(seed, family, band, bool(in_b)))
json.dump({"per_run": a}, open(os.path.join(out, "a", "capture.json"), "w"))
json.dump({"per_run": b}, open(os.path.join(out, "b", "capture.json"), "w"))
json.dump({"per_run": b[:-1]}, open(os.path.join(out, "c", "capture.json"), "w"))
PY
scripts/capture-compare "$out/a" "$out/b" --json "$out/compare.json" > "$out/compare.md"
python3 - "$out" <<'PY'
import json, math, os, sys
out = sys.argv[1]
doc = json.load(open(os.path.join(out, "compare.json")))
g = doc["groups"]
assert set(g) == {"all", "family figure8", "family line", "band 0:3", "band 3:6"}, set(g)
f8 = g["family figure8"]
assert (f8["runs"], f8["both"], f8["a_only"], f8["b_only"], f8["neither"]) == (20, 6, 0, 10, 4), f8
assert abs(f8["rate_a"] - 0.3) < 1e-12 and abs(f8["rate_b"] - 0.8) < 1e-12 and abs(f8["difference"] - 0.5) < 1e-12
# Ten discordant engagements, all one way: p = 2 / 2^10.
assert abs(f8["p_value"] - 2.0 / 1024.0) < 1e-12, f8["p_value"]
lo, hi = f8["interval"]
assert 0.0 < lo < 0.5 < hi <= 1.0, f8["interval"]
line = g["family line"]
assert (line["both"], line["a_only"], line["b_only"], line["neither"]) == (5, 2, 2, 1), line
assert line["p_value"] == 1.0 and line["difference"] == 0.0
assert line["interval"][0] < 0.0 < line["interval"][1]
assert g["band 3:6"] == line and g["band 0:3"] == f8
every = g["all"]
assert (every["runs"], every["a_only"], every["b_only"]) == (30, 2, 12), every
assert abs(every["p_value"] - 2.0 * sum(math.comb(14, i) for i in range(3)) / 2 ** 14) < 1e-12
md = open(os.path.join(out, "compare.md")).read()
assert "| family figure8 | 20 | 6 | 0 | 10 | 4 | 30.0% | 80.0% | +50.0% |" in md, md
PY
# Different engagements, or a folder that holds no benchmark: a clear error, no traceback.
for bad in "$out/c" "$out"; do
  if scripts/capture-compare "$out/a" "$bad" > "$out/bad.out" 2> "$out/bad.err"; then
    echo "capture-compare accepted $bad" >&2; exit 1
  fi
  grep -q "^capture-compare: " "$out/bad.err" || { cat "$out/bad.err" >&2; exit 1; }
  if grep -q Traceback "$out/bad.err"; then cat "$out/bad.err" >&2; exit 1; fi
done
echo "capture-compare: ok"
