"""The capture benchmark's held-out families: engagements no value of the aim was chosen on.

  agile     the second generator's flights (agile_flight.py, frozen before any tuning), one file
            per engagement, written to the benchmark's flights folder
  recorded  the recorded flights of bench/flights/ (their sources in its README), turned to a
            random heading, their near side 4-7 m ahead of the hunter, played 0.5 to 2 times as
            fast so that their top speed falls in the band

Both are played by the intruder's `shape: file`, held at their end.
"""
import csv
import functools
import math
import os

import agile_flight

RECORDED_FLIGHTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bench", "flights")
AGILE_DURATION_S = 60.0  # longer than any engagement the benchmark flies by default


@functools.cache  # read once per benchmark, not once per engagement
def recorded_flights(folder=RECORDED_FLIGHTS):
    """The recorded flights: each file's path, its top speed (m/s, over 0.5 s) and its extent."""
    flights = []
    for name in sorted(os.listdir(folder)):
        if not name.endswith(".csv"):
            continue
        path = os.path.abspath(os.path.join(folder, name))
        rows = [(float(r["t"]), float(r["x"]), float(r["y"]), float(r["z"])) for r in csv.DictReader(open(path))]
        top = 0.0
        j = 0
        for i, row in enumerate(rows):  # the speed over 0.5 s: a recording's noise is no speed
            while j < len(rows) and rows[j][0] < row[0] + 0.5:
                j += 1
            if j < len(rows):
                top = max(top, math.dist(row[1:], rows[j][1:]) / (rows[j][0] - row[0]))
        low = [min(r[k] for r in rows) for k in (1, 2, 3)]
        high = [max(r[k] for r in rows) for k in (1, 2, 3)]
        flights.append({"path": path, "top_speed": top, "low": low, "high": high})
    if not flights:
        raise SystemExit(f"no recorded flights (*.csv) in {folder}")
    return flights


def scenario(s, family, seed, rng, band, flights_dir, vec):
    """A held-out family's engagement: the scenario `s` (its seed and wind drawn) made to play a flight
    file (the intruder's shape file), drawn on with `rng`; `vec` writes a vector as a --set value."""
    speed_lo, speed_hi = max(band[0], 1.0), band[1]
    s["intruder.shape"] = "file"
    s["intruder.at_end"] = "hold"
    if family == "agile":
        top_speed, accel = rng.uniform(speed_lo, speed_hi), rng.uniform(4.0, 10.0)
        os.makedirs(flights_dir, exist_ok=True)
        path = os.path.abspath(os.path.join(flights_dir, f"agile_{seed}.csv"))
        agile_flight.write_csv(path, agile_flight.flight(seed, top_speed, accel, AGILE_DURATION_S))
        s["intruder.file"] = path
        return s
    # recorded: a flight that reaches the band's speed at 0.5-2 times its own pace
    flights = recorded_flights()
    top_speed = rng.uniform(speed_lo, speed_hi)
    fits = [f for f in flights if 0.5 * f["top_speed"] <= top_speed <= 2.0 * f["top_speed"]]
    flight = rng.choice(fits or [max(flights, key=lambda f: f["top_speed"])])
    scale = min(2.0, max(0.5, top_speed / flight["top_speed"]))
    yaw = rng.uniform(-math.pi, math.pi)
    # Turned about its own centre's vertical, the flight's near side lies 4-7 m ahead of the hunter.
    centre = [(lo + hi) / 2.0 for lo, hi in zip(flight["low"], flight["high"])]
    c, si = math.cos(yaw), math.sin(yaw)
    corners = [(x, y) for x in (flight["low"][0], flight["high"][0]) for y in (flight["low"][1], flight["high"][1])]
    turned = [(c * (x - centre[0]) - si * (y - centre[1]), si * (x - centre[0]) + c * (y - centre[1]))
              for x, y in corners]
    near = rng.uniform(4.0, 7.0)
    ahead = near - min(x for x, _ in turned)
    lateral = rng.uniform(-1.5, 1.5)
    height = rng.uniform(1.5, 2.5) - flight["low"][2]
    # world = R p + offset: the flight's centre, turned, lands at (ahead, lateral)
    offset = [ahead - (c * centre[0] - si * centre[1]), lateral - (si * centre[0] + c * centre[1]), height]
    s.update({"intruder.file": flight["path"], "intruder.file_offset_m": vec(offset),
              "intruder.file_yaw_deg": f"{math.degrees(yaw):.2f}", "intruder.file_time_scale": f"{scale:.4f}"})
    return s


def family_of(params):
    """A run's behaviour family, from its intruder's parameters: its shape, or for a flight file,
    agile (the files scenario() writes) or recorded."""
    if params.get("shape") != "file":
        return params.get("shape", "?")
    return "agile" if os.path.basename(str(params.get("file", ""))).startswith("agile_") else "recorded"
