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
# The shots' error model, fitted to these runs' shots, with its reliability table.
shot_model = json.load(open(os.path.join(out, "shots", "shot_model.json")))
assert shot_model["shots"] == sum(1 for s in doc["per_run"] for x in s["shots"] if x.get("closest_m") is not None)
assert "## Shot error model" in md and "| predicted probability |" in md, md
assert "rendered" not in doc
PY

# By speed band and guidance law: the same engagements for each law, every band's figures
# recounted from the runs, the Wilson interval around the rate, and the curve drawn.
bands=$out/bands
scripts/capture-benchmark "$bands" --seeds 2 --rendered 0 --duration 8 --bands 0:3,6:10 \
  --guidance hold_aim,pn > /dev/null
python3 - "$bands" <<'PY'
import csv, json, os, sys
out = sys.argv[1]
cases = list(csv.DictReader(open(os.path.join(out, "cases.csv"))))
assert [c["seed"] for c in cases] == ["1", "2", "100001", "100002"], [c["seed"] for c in cases]
# The fast band's intruders fly faster than 6 m/s, the default band's no faster than 3.
for c in cases:
    speed = float(c["intruder.speed_m_s"] or c["intruder.max_speed_m_s"] or 0.0) or None
    if speed is not None:
        assert (speed >= 6.0) == (int(c["seed"]) > 100000), c
doc = json.load(open(os.path.join(out, "capture.json")))
assert set(doc["by_guidance"]) == {"hold_aim", "pn"}, doc.keys()
# The top-level list holds every law's bands, each entry with its bounds and law.
assert [(b["guidance"], b["lo_m_s"], b["hi_m_s"]) for b in doc["by_band"]] == \
    [("hold_aim", 0, 3), ("hold_aim", 6, 10), ("pn", 0, 3), ("pn", 6, 10)], doc["by_band"]
for b in doc["by_band"]:
    assert {"runs", "captured", "rate", "wilson_low", "first_shot_rate", "median_time_to_capture_s"} <= b.keys(), b
for law, summary in doc["by_guidance"].items():
    assert summary["runs"] == 4
    assert [(b["lo_m_s"], b["hi_m_s"]) for b in summary["by_band"]] == [(0, 3), (6, 10)], summary["by_band"]
    for b in summary["by_band"]:
        assert b["guidance"] == law, b
        runs = [r for r in summary["per_run"] if r["band"] == b["band"]]
        assert b["runs"] == len(runs) == 2
        assert b["captured"] == sum(r["captured"] for r in runs)
        assert b["wilson_low"] <= b["rate"] <= b["wilson_high"], b
        assert 0.0 <= b["wilson_low"] and b["wilson_high"] <= 1.0
    # Each law flew the same engagements: the same seeds with the same intruder.
    assert [r["seed"] for r in summary["per_run"]] == [1, 2, 100001, 100002]
    # The missed shots are sorted by cause and recounted from the shots: a miss is a shot whose
    # net came no nearer than its radius; by the manoeuvre when flying straight it was caught.
    shots = [(s, r["net_radius_m"]) for r in summary["per_run"] for s in r["shots"]]
    missed = [(s, radius) for s, radius in shots if s["closest_m"] is not None and s["closest_m"] > radius]
    assert summary["shots"] == len(shots) and summary["missed_shots"] == len(missed), summary
    assert summary["missed_by_manoeuvre"] + summary["missed_by_aim"] == len(missed)
    assert summary["missed_by_manoeuvre"] == sum(s["closest_straight_m"] <= radius for s, radius in missed)
    # The aim's prediction is paired with each launched shot; the launcher carried 2 nets.
    for s, _ in shots:
        assert "predicted_miss_m" in s and "spread_m" in s and "closest_straight_m" in s, s
    assert all(r["fire_count"] is None or len(r["shots"]) <= 2 for r in summary["per_run"])
assert os.path.getsize(os.path.join(out, "capture_curve.png")) > 1000
rows = list(csv.DictReader(open(os.path.join(out, "capture_curve.csv"))))
assert [r["band"] for r in rows] == ["0:3", "6:10"] and "pn_low" in rows[0], rows
PY

# Evading intruders and the net budget: --shapes evade draws them, --nets 1 gives one net a run.
evade=$out/evade
scripts/capture-benchmark "$evade" --seeds 2 --rendered 0 --duration 8 --shapes evade --nets 1 > /dev/null
python3 - "$evade" <<'PY'
import csv, json, os, sys
out = sys.argv[1]
cases = list(csv.DictReader(open(os.path.join(out, "cases.csv"))))
assert {c["intruder.shape"] for c in cases} == {"evade"} and all(c["intruder.evade_speed_m_s"] for c in cases), cases
doc = json.load(open(os.path.join(out, "capture.json")))
assert doc["by_shape"] == {"evade": {"runs": 2, "captured": doc["runs"] - len(doc["failures"])}}, doc["by_shape"]
for r in doc["per_run"]:
    assert len(r["shots"]) <= 1, r
PY
if scripts/capture-benchmark "$out/bad" --seeds 1 --rendered 0 --shapes evade,loop > /dev/null 2>&1; then
  echo "an unknown shape was accepted" >&2
  exit 1
fi

# Behaviour families: the held-out ones fly flight files (the second generator's, drawn per seed, and
# the recorded flights, placed ahead of the hunter); capture.json gives each family's figures by band,
# recounted here from the runs, and says which families are held out; the curve draws each family.
families=$out/families
scripts/capture-benchmark "$families" --seeds 2 --rendered 0 --duration 6 --bands 0:3,6:10 \
  --families random,agile,recorded > /dev/null
python3 - "$families" <<'PY'
import csv, json, os, sys
out = sys.argv[1]
cases = list(csv.DictReader(open(os.path.join(out, "cases.csv"))))
assert [c["seed"] for c in cases] == ["1", "2", "100001", "100002"], cases
# The families in turn, by seed.
families = ["random", "agile", "recorded"]
for c in cases:
    family = families[(int(c["seed"]) - 1) % 3]
    if family == "agile":
        assert c["intruder.shape"] == "file" and os.path.basename(c["intruder.file"]) == f"agile_{c['seed']}.csv", c
        assert os.path.exists(c["intruder.file"]), c
    elif family == "recorded":
        assert c["intruder.shape"] == "file" and "bench/flights/" in c["intruder.file"], c
        assert 0.5 <= float(c["intruder.file_time_scale"]) <= 2.0, c
    else:
        assert c["intruder.shape"] == "random", c
doc = json.load(open(os.path.join(out, "capture.json")))
assert doc["families"] == {"tuning": ["random"], "held_out": ["agile", "recorded"]}, doc["families"]
assert [r["family"] for r in doc["per_run"]] == [families[(r["seed"] - 1) % 3] for r in doc["per_run"]]
for family, by_band in doc["by_family"].items():
    for band, b in by_band.items():
        runs = [r for r in doc["per_run"] if r["family"] == family and r["band"] == band]
        assert b["runs"] == len(runs) >= 1 and b["captured"] == sum(r["captured"] for r in runs), (family, band, b)
        assert b["wilson_low"] <= b["rate"] <= b["wilson_high"], b
assert os.path.getsize(os.path.join(out, "capture_curve.png")) > 1000
rows = list(csv.DictReader(open(os.path.join(out, "capture_curve.csv"))))
assert [r["band"] for r in rows] == ["0:3", "6:10"] and "agile_low" in rows[0] and "recorded" in rows[0], rows
assert "| agile | held out |" in open(os.path.join(out, "capture.md")).read()
PY

# Another graph on the same engagements: a variant that includes the shipped graph and changes a
# parameter; every run's report names it.
variant=$out/variant
mkdir -p "$variant"
cat > "$variant/variant.yaml" <<YAML
kestrel: 1
name: sim_intercept_fast_variant
executor: {type: lockstep, default_policy: latest}
include:
  - {file: $PWD/graphs/sim_intercept_fast.yaml, set: {aim.cooldown_s: 2.5}}
YAML
scripts/capture-benchmark "$variant/out" --seeds 1 --rendered 0 --duration 4 --graph "$variant/variant.yaml" > /dev/null
python3 - "$variant/out" <<'PY'
import json, os, sys
runs = os.path.join(sys.argv[1], "fast", "runs")
names = [json.load(open(os.path.join(runs, n, "report.json")))["graph"]["name"] for n in sorted(os.listdir(runs))]
assert names == ["sim_intercept_fast_variant"], names
PY
# A graph that is not there ends the benchmark with the sweep's own words, not a traceback.
if scripts/capture-benchmark "$variant/missing" --seeds 1 --rendered 0 --graph "$variant/none.yaml" \
    > /dev/null 2> "$variant/missing.err"; then
  echo "a missing graph was flown" >&2
  exit 1
fi
grep -q "ran nothing" "$variant/missing.err" && grep -q "none.yaml" "$variant/missing.err" \
  && ! grep -q Traceback "$variant/missing.err" || { cat "$variant/missing.err" >&2; exit 1; }
scripts/capture-benchmark --help | grep -q -- "--graph FILE" || { echo "--help does not list --graph" >&2; exit 1; }
if scripts/capture-benchmark --seeds 3 > /dev/null 2>&1; then
  echo "an option was taken for the output directory" >&2
  exit 1
fi
