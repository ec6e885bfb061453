#!/usr/bin/env bash
# The capture benchmark's second generator (scripts/agile_flight.py) is frozen: its held-out family
# is only held out while nothing tuned on it changes what it draws. These digests are its flights as
# written when it was frozen; a change to any of them fails here. A flight also stays in its fence
# and within its speed limit, and bad arguments are refused.
set -euo pipefail
out=$1
rm -rf "$out" && mkdir -p "$out"
check() {  # check SEED TOP_SPEED MAX_ACCELERATION DIGEST
  python3 scripts/agile_flight.py "$1" "$2" "$3" "$out/flight_$1.csv"
  local got
  got=$(sha256sum "$out/flight_$1.csv" | cut -d' ' -f1)
  [ "$got" = "$4" ] || { echo "agile flight $1 ($2 m/s, $3 m/s^2) changed: $got" >&2; exit 1; }
}
check 1 2 4 766bba264235c87ae591ff26bd83cf1dcd2ca38fbfc3af4b4e14666d7dbfd152
check 2 6 8 6368f4da2fbe43627a35761a0ae61d0e611207dd6cf47a671642fc736afcd17d
check 3 10 10 6ac59b7d97af67b5410c7a9ea1b0f9d2699a43fd2a1d561831e88f38b02942ac
python3 - "$out" <<'PY'
import csv, math, os, sys
for name, top in (("flight_1.csv", 2.0), ("flight_2.csv", 6.0), ("flight_3.csv", 10.0)):
    rows = [tuple(map(float, (r["t"], r["x"], r["y"], r["z"]))) for r in csv.DictReader(open(os.path.join(sys.argv[1], name)))]
    assert rows[0][0] == 0.0 and abs(rows[-1][0] - 40.0) < 1e-9, (name, rows[0], rows[-1])
    # In its fence (4-16 m ahead, 5 m either side, 1.5-5 m up), give or take the stop it overshoots by.
    for t, x, y, z in rows:
        assert 3.0 <= x <= 17.0 and -6.0 <= y <= 6.0 and 1.0 <= z <= 5.5, (name, t, x, y, z)
    speeds = [math.dist(a[1:], b[1:]) / (b[0] - a[0]) for a, b in zip(rows, rows[1:])]
    assert max(speeds) <= top * 1.01 + 0.1, (name, max(speeds))  # 3 decimals of rounding
    assert max(speeds) >= 0.7 * top, (name, max(speeds))  # its dashes reach near the top speed
PY
if python3 scripts/agile_flight.py 1 0 4 "$out/bad.csv" 2> "$out/bad.err"; then
  echo "a flight with no speed was drawn" >&2
  exit 1
fi
grep -q "must be positive" "$out/bad.err"
