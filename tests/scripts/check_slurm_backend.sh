#!/usr/bin/env bash
# Label `slurm`: kestrel's Slurm backend against a real Slurm 22.05 cluster of one node that the
# test starts on 127.0.0.1 (slurm_cluster.sh).
# - a 10-case sweep (graphs/hover_step.yaml) run here and as a Slurm job array gives the same
#   sweep.csv, number for number, and the same report from every run (wall time aside);
# - a run that fails and a task cancelled before it ran are reported with what Slurm says of them
#   and counted as failed, and `kestrel collect` says so again when run twice (idempotent);
# - a 10-engagement capture benchmark through Slurm gives the local run's capture.json.
# Usage: check_slurm_backend.sh WORKDIR   (KESTREL: the kestrel binary; run from the source tree)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
kestrel=${KESTREL:?set KESTREL to the kestrel binary}
work=$1
rm -rf "$work"
mkdir -p "$work"
source "$here/slurm_cluster.sh"
start_slurm_cluster "$work/cluster"
graph=$PWD/graphs/hover_step.yaml  # absolute, as a Slurm batch makes it: the reports name it alike

python3 - "$work/cases.csv" <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write("setpoint.step_yaw_deg,seed\n")
    for i in range(10):
        f.write(f"{10 * i},{i + 1}\n")
PY
"$kestrel" sweep "$graph" --cases "$work/cases.csv" --duration 8 --report "$work/local" > /dev/null
"$kestrel" sweep "$graph" --cases "$work/cases.csv" --duration 8 --report "$work/slurm" \
  --backend slurm --wait > "$work/slurm.out"
test -s "$work/slurm/batch/collected"

# Same numbers and reports; only the wall-clock readings may differ.
python3 - "$work" <<'PY'
import csv, json, os, sys
work = sys.argv[1]
def timing(key): return "wall_time" in key or key.startswith("stats")
def rows(name):
    with open(os.path.join(work, name, "sweep.csv")) as f:
        return [{k: v for k, v in r.items() if not timing(k)} for r in csv.DictReader(f)]
local, slurm = rows("local"), rows("slurm")
assert len(local) == len(slurm) == 10, (len(local), len(slurm))
assert local == slurm, next((a, b) for a, b in zip(local, slurm) if a != b)
assert all(r["exit_code"] == "0" for r in slurm)
def report(name, run):
    r = json.load(open(os.path.join(work, name, "runs", run, "report.json")))
    return {k: v for k, v in r.items() if not timing(k)}
runs = sorted(os.listdir(os.path.join(work, "local", "runs")))
assert runs == sorted(os.listdir(os.path.join(work, "slurm", "runs"))) and len(runs) == 10
for run in runs:
    assert report("local", run) == report("slurm", run), run
print("sweep: 10 runs through Slurm, the same numbers as here")
PY

# A run that fails (case 2: its intruder's file is missing) is reported with what Slurm says of
# the task, and a task cancelled before it ran (case 3) with what can be known of it; both count as
# failed, in the collector's summary and again in a second `kestrel collect`.
printf 'intruder.shape,intruder.file,seed\n,,1\n,,2\nfile,/nonexistent/flight.csv,3\n,,4\n,,5\n' > "$work/failing.csv"
"$kestrel" sweep "$PWD/graphs/sim_intercept_fast.yaml" --cases "$work/failing.csv" --duration 2 \
  --report "$work/failing" --backend slurm --array-limit 1 2> "$work/failing.err" > /dev/null
ids=$(python3 -c "import json,sys; j=json.load(open(sys.argv[1])); print(j['array_job'], j['collect_job'])" \
  "$work/failing/batch/slurm.json")
read -r array collector <<< "$ids"
scancel "${array}_3"
for _ in $(seq 600); do
  [ -z "$(squeue -h -j "$array,$collector" 2> /dev/null)" ] && break
  sleep 0.5
done
test -s "$work/failing/batch/collected" || { cat "$work/failing/batch/collect.out" >&2; exit 1; }
[ "$(cat "$work/failing/batch/collected")" = 1 ] || { echo "the collector did not count the failures" >&2; exit 1; }
for expected in "Slurm task ${array}_2: FAILED, the run exited 1" "Slurm task ${array}_3: never ran" "runs/002_"; do
  grep -qF "$expected" "$work/failing/sweep.md" || { echo "sweep.md lacks '$expected'" >&2; cat "$work/failing/sweep.md" >&2; exit 1; }
done
grep -q "cannot open trajectory file /nonexistent/flight.csv" "$work/failing/runs/"*002*/run.log
python3 - "$work/failing/sweep.csv" <<'PY'
import csv, sys
codes = [r["exit_code"] for r in csv.DictReader(open(sys.argv[1]))]
assert codes == ["0", "0", "1", "1", "0"], codes
PY
set +e
"$kestrel" collect "$work/failing" > "$work/collect-again.out" 2>&1
code=$?
set -e
[ "$code" -eq 1 ] || { echo "kestrel collect gave $code, not 1, for a batch with failures" >&2; exit 1; }
grep -qF "Slurm task ${array}_2: FAILED" "$work/collect-again.out"
echo "a failed run and a cancelled task: reported with Slurm's word and counted, again on a second collect"

# The capture benchmark through Slurm: the same capture.json as here.
KESTREL=$kestrel scripts/capture-benchmark "$work/capture-local" --seeds 10 --rendered 0 --duration 12 > /dev/null
KESTREL=$kestrel scripts/capture-benchmark "$work/capture-slurm" --seeds 10 --rendered 0 --duration 12 \
  --backend slurm > /dev/null
python3 - "$work" <<'PY'
import json, os, sys
work = sys.argv[1]
def load(name):
    c = json.load(open(os.path.join(work, name, "capture.json")))
    c.pop("wall_time_s", None)
    return json.dumps(c, sort_keys=True)
assert load("capture-local") == load("capture-slurm")
print("capture benchmark: 10 engagements through Slurm, the same capture.json as here")
PY
