#!/usr/bin/env python3
"""The capture benchmark's two halves around `kestrel sweep --cases`.

  capture_benchmark.py scenarios N SEED0 FILE [--bands LO:HI,...] [--families F,...] [--flights DIR]
                                                draws N random engagements per speed band (seeds
                                                SEED0.. for the first band, SEED0 + 100000.. for
                                                the second, ...) as a cases file: one row per run,
                                                a column per --set; the agile family's flights are
                                                written to DIR
  capture_benchmark.py summarise OUTDIR LABEL SWEEPDIR...
                                                reads the runs' reports and writes OUTDIR/capture.json
  capture_benchmark.py curve FILE.csv LAW=SUMMARY...
                                                the capture rate per speed band and law, with its
                                                Wilson 95 % bounds, as a CSV for `kestrel plot`
  capture_benchmark.py family-curve FILE.csv SUMMARY
                                                the same per speed band and behaviour family
  capture_benchmark.py combine FILE MAIN [RENDERED]
                                                the main summary, with the rendered subset's under
                                                "rendered", as FILE
  capture_benchmark.py markdown CASES SUMMARY...
                                                the Markdown table of the summaries

Each scenario is drawn from its own seed, so scenario k is the same whatever N is, and the same
for the detection-level and the rendered camera. The ranges are those of docs/control.md
("The capture benchmark"): the intruder flies a figure-8, a line back and forth or random
manoeuvres, 4 to 9 m ahead of the hunter's start, at up to 3 m/s, in a wind of up to 3 m/s.

Behaviour families. The tuning families are the intruder node's own shapes (figure8, line, random,
jink, evade): the aim's values are chosen on them. The held-out families are never tuned on:
  agile     the second generator's flights (scripts/agile_flight.py, frozen before any tuning): a
            point mass that switches every 0.6-2.5 s between turns, dashes to a full stop,
            zigzags, climbing spirals and hovers, 4-16 m ahead, top speed in the band, 4-10 m/s^2
  recorded  flights recorded from real vehicles or a real autopilot stack (bench/flights/, their
            sources in its README), turned to a random heading, placed ahead of the hunter and
            played at the pace that puts their top speed in the band (0.5 to 2 times as fast)

A speed band LO:HI draws the intruder's top speed in [max(LO, 0.5), HI] m/s; the default band,
0:3, is the benchmark above, seed for seed. Above 3 m/s an intruder also flies as a multirotor
can: it turns and brakes at 4 to 8 m/s^2 at most, so its figure-8, its line and its random box
grow with its speed (a line long enough to reach its top speed, a figure-8 wide enough for its
turns, a box as wide as its turns), never lower than the default band's.
"""
import csv
import json
import math
import os
import random
import statistics
import sys

import capture_report
import held_out_families
from capture_report import band_label

SHAPES = ["figure8", "line", "random"]  # the default
ALL_SHAPES = SHAPES + ["jink", "evade"]
TUNING_FAMILIES = ALL_SHAPES  # the intruder node's shapes: the aim is tuned on these
HELD_OUT_FAMILIES = ["agile", "recorded"]  # never tuned on
FAMILIES = TUNING_FAMILIES + HELD_OUT_FAMILIES
MAX_INTRUDER_SPEED = 3.0  # m/s: the default band's top, and where the agile scaling starts
MAX_WIND = 3.0  # m/s
DISTANCE = (4.0, 9.0)  # m: the intruder's path from the hunter's start (--distance)
BAND_SEED_STRIDE = 100000  # band b's seeds start at SEED0 + b * BAND_SEED_STRIDE


def parse_bands(text):
    """'0:3,3:6' -> [(0.0, 3.0), (3.0, 6.0)]"""
    bands = []
    for item in text.split(","):
        lo, sep, hi = item.partition(":")
        if not sep:
            raise SystemExit(f"bad band '{item}': expected LO:HI in m/s")
        lo, hi = float(lo), float(hi)
        if not 0.0 <= lo < hi:
            raise SystemExit(f"bad band '{item}': expected 0 <= LO < HI")
        bands.append((lo, hi))
    return bands


def vec(v):
    return "[" + ", ".join(f"{x:.3f}" for x in v) + "]"


def parse_distance(text):
    """'4:9' -> (4.0, 9.0), the range of the intruder's path from the hunter's start, m"""
    lo, sep, hi = text.partition(":")
    if not sep:
        raise SystemExit(f"bad distance '{text}': expected LO:HI in m")
    lo, hi = float(lo), float(hi)
    if not 1.0 <= lo <= hi:
        raise SystemExit(f"bad distance '{text}': expected 1 <= LO <= HI")
    return lo, hi


def scenario(seed, band=(0.0, MAX_INTRUDER_SPEED), shapes=SHAPES, distance_range=DISTANCE, flights_dir="flights"):
    rng = random.Random(seed * 7919 + 17)
    shape = shapes[(seed - 1) % len(shapes)]  # each shape (family) as often as the others
    speed_lo, speed_hi = max(band[0], 0.5), band[1]
    distance = rng.uniform(*distance_range)  # from the hunter's start to the intruder's path
    lateral = rng.uniform(-1.5, 1.5)
    height = rng.uniform(2.0, 3.0)  # centre of the path; it stays above the height gate
    wind_speed, wind_dir = rng.uniform(0.0, MAX_WIND), rng.uniform(-math.pi, math.pi)
    s = {"seed": seed, "intruder.shape": shape,
         "hunter.wind_m_s": vec([wind_speed * math.cos(wind_dir), wind_speed * math.sin(wind_dir), 0.0]),
         "hunter.gust_std_m_s": f"{0.2 * wind_speed:.3f}"}
    if shape in HELD_OUT_FAMILIES:
        return held_out_families.scenario(s, shape, seed, rng, band, flights_dir, vec)
    if shape == "figure8":
        half_width, half_height = rng.uniform(0.5, 2.0), rng.uniform(0.25, 0.8)
        top_speed = rng.uniform(speed_lo, speed_hi)
        if top_speed > MAX_INTRUDER_SPEED:
            # Its acceleration, at most w^2 max(hw, 4 hh) with w = v / sqrt(hw^2 + 4 hh^2), within
            # what it can fly: the figure widens (never deepens: it stays above the height gate).
            accel = rng.uniform(4.0, 8.0)
            half_height = min(half_height, top_speed**2 / (4.0 * accel))
            while top_speed**2 * max(half_width, 4.0 * half_height) > accel * (half_width**2 + 4.0 * half_height**2):
                half_width *= 1.05
        # The Lissajous curve is fastest at its centre, where |v| = w sqrt(hw^2 + 4 hh^2).
        period = 2.0 * math.pi * math.hypot(half_width, 2.0 * half_height) / top_speed
        s.update({"intruder.distance_m": f"{distance:.3f}", "intruder.camera_position_m": vec([0.0, lateral, height]),
                  "intruder.half_width_m": f"{half_width:.3f}", "intruder.half_height_m": f"{half_height:.3f}",
                  "intruder.period_s": f"{period:.3f}", "intruder.start_s": f"{rng.uniform(0.0, period):.3f}"})
    elif shape == "line":
        length, climb = rng.uniform(3.0, 6.0), rng.uniform(-0.5, 0.5)
        heading = rng.uniform(-0.5, 0.5)  # rad off a pure crossing
        speed, line_accel = rng.uniform(speed_lo, speed_hi), rng.uniform(2.0, 6.0)
        if speed > MAX_INTRUDER_SPEED:
            line_accel = rng.uniform(4.0, 8.0)
            length = max(length, 1.5 * speed**2 / line_accel)  # it reaches its top speed
        dx, dy = math.sin(heading) * length / 2.0, math.cos(heading) * length / 2.0
        s.update({"intruder.line_start_m": vec([distance - dx, lateral - dy, height - climb / 2.0]),
                  "intruder.line_end_m": vec([distance + dx, lateral + dy, height + climb / 2.0]),
                  "intruder.speed_m_s": f"{speed:.3f}", "intruder.at_end": "repeat",
                  # It brakes and turns as a multirotor can: 2 to 6 m/s^2 (a small quadrotor's
                  # few m/s^2 up to a sporty one's).
                  "intruder.line_acceleration_m_s2": f"{line_accel:.3f}"})
    elif shape == "jink":
        # Bang-bang jinks at the limit, held 0.5-2 s, in a box as wide as two of its turns.
        speed, accel = rng.uniform(speed_lo, speed_hi), rng.uniform(2.0, 6.0) if speed_hi <= MAX_INTRUDER_SPEED \
            else rng.uniform(4.0, 8.0)
        turn = speed**2 / accel
        # It overshoots its box's height by up to (v/2)^2 / 2a: the centre is high enough that it
        # stays above the height gate and 1 m above the ground.
        centre_height = max(height, 1.5 + speed**2 / (8.0 * accel))
        s.update({"intruder.random_centre_m": vec([distance, lateral, centre_height]),
                  "intruder.random_half_extent_m": vec([max(1.0, 0.5 * turn), max(2.0, turn), 0.5]),
                  "intruder.jink_speed_m_s": f"{speed:.3f}", "intruder.jink_acceleration_m_s2": f"{accel:.3f}"})
    elif shape == "evade":
        # It sees the hunter: cruises in its box, flees at its top speed within 6 m, weaving, and
        # breaks across the hunter's line of sight within 2.5 m; its box is two of its turns wide,
        # high enough that a dive stays above the height gate.
        speed, accel = rng.uniform(speed_lo, speed_hi), rng.uniform(2.0, 6.0) if speed_hi <= MAX_INTRUDER_SPEED \
            else rng.uniform(4.0, 8.0)
        turn = speed**2 / accel
        s.update({"intruder.random_centre_m": vec([distance, lateral, max(height, 2.0 + speed**2 / (8.0 * accel))]),
                  "intruder.random_half_extent_m": vec([max(1.5, turn), max(2.0, 2.0 * turn), 0.5]),
                  "intruder.evade_speed_m_s": f"{speed:.3f}", "intruder.evade_acceleration_m_s2": f"{accel:.3f}",
                  "intruder.evade_cruise_speed_m_s": f"{min(2.0, 0.5 * speed):.3f}",
                  "intruder.evade_min_height_m": "1.5"})
    else:
        extent = [rng.uniform(0.3, 1.0), rng.uniform(0.5, 2.0), rng.uniform(0.2, 0.6)]
        speed = rng.uniform(speed_lo, speed_hi)
        if speed > MAX_INTRUDER_SPEED:
            accel = rng.uniform(4.0, 8.0)
            turn = speed**2 / accel  # the radius of its tightest turn
            extent = [max(extent[0], 0.5 * turn), max(extent[1], turn), extent[2]]  # never deeper
            s["intruder.max_acceleration_m_s2"] = f"{accel:.3f}"
        s.update({"intruder.random_centre_m": vec([distance, lateral, height]),
                  "intruder.random_half_extent_m": vec(extent),
                  "intruder.max_speed_m_s": f"{speed:.3f}"})
    return s


def write_scenarios(n, seed0, path, bands=((0.0, MAX_INTRUDER_SPEED),), shapes=SHAPES, distance_range=DISTANCE,
                    flights_dir=None):
    flights_dir = flights_dir or os.path.join(os.path.dirname(os.path.abspath(path)), "flights")
    rows = [scenario(seed0 + b * BAND_SEED_STRIDE + k, band, shapes, distance_range, flights_dir)
            for b, band in enumerate(bands) for k in range(n)]
    keys = ["seed"] + sorted({k for r in rows for k in r if k != "seed"})
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys, restval="")
        w.writeheader()
        w.writerows(rows)


def failure_cause(r):
    """Why a run did not catch its intruder, from its report."""
    c, aim, hunter = r.get("control", {}), r.get("aim", {}), r.get("hunter", {})
    if r.get("outcome") != "completed":
        return "run failed: " + str(r.get("error", r.get("outcome")))
    if hunter.get("touchdowns", 0) > 0:
        return "the hunter touched the ground"
    if r.get("controller", {}).get("faults", 0) > 0:
        return "controller fault"
    if not aim.get("target_frames"):
        return "never saw the intruder"
    if c.get("fire_count", 0) > 0:
        closest = [s["closest_m"] for s in c.get("shots", []) if s.get("closest_m") is not None]
        best = f", the nearest by {min(closest):.2f} m" if closest else ""
        return f"fired {c['fire_count']} time(s) and missed{best}"
    if c.get("time_to_align_s") is None:
        return "never brought the intruder within the net's radius of x_E^d"
    if aim.get("holds", 0) > 0 and aim.get("target_frames", 0) < 0.5 * aim.get("frames", 1):
        return "lost the intruder and held"
    return "aligned, but never held the aim long enough to fire"


def wilson_bounds(successes, n, z=1.959964):
    """The Wilson score interval of a rate (95 % by default): honest at 0 %, 100 % and small n."""
    if n == 0:
        return None, None
    p = successes / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return max(0.0, centre - half), min(1.0, centre + half)


def group_figures(runs):
    """Capture figures of a group of runs (a band, a shape)."""
    caught = [x for x in runs if x["captured"]]
    low, high = wilson_bounds(len(caught), len(runs))
    times = [x["time_to_capture_s"] for x in caught]
    nets = [x["fire_count"] for x in runs if x.get("fire_count") is not None]
    seen = [x["first_seen_range_m"] for x in runs if x.get("first_seen_range_m") is not None]
    return {"runs": len(runs), "captured": len(caught),
            "rate": len(caught) / len(runs) if runs else None, "wilson_low": low, "wilson_high": high,
            "first_shot_rate": sum(bool(x.get("first_shot_captured")) for x in runs) / len(runs) if runs else None,
            "median_time_to_capture_s": statistics.median(times) if times else None,
            "median_nets_used": statistics.median(nets) if nets else None,
            **missed_shots(runs),
            "first_seen_closer_than_4m": sum(r < 4.0 for r in seen) / len(seen) if seen else None}


def band_figures(band, runs):
    """A speed band's entry of `by_band`: its bounds in m/s and the guidance law, then its figures."""
    laws = sorted({x["guidance"] for x in runs if x.get("guidance")})
    return {"lo_m_s": band[0], "hi_m_s": band[1], "guidance": ",".join(laws) if laws else None,
            "band": band_label(band), **group_figures(runs)}


def paired_shots(launched, ordered):
    """Each launched shot (the net's log) with the aim's prediction for it (its order's log), paired
    by time: the predicted miss, its spread and probability beside the closest approach."""
    shots = []
    for shot in launched:
        order = min(ordered, key=lambda o: abs(o["t_s"] - shot["t_s"]), default=None)
        if order is not None and abs(order["t_s"] - shot["t_s"]) < 0.1:
            shot = {**{k: v for k, v in order.items() if k != "t_s"}, **shot}
        shots.append(shot)
    return shots


def missed_shots(runs):
    """The shots that missed, by cause: lost to the intruder's manoeuvre while the net flew (it would
    have been caught flying straight on at its velocity at the shot), or to the aim (missed even so)."""
    missed = [s for x in runs for s in x.get("shots", []) if s.get("closest_m") is not None
              and s["closest_m"] > x["net_radius_m"]]
    by_manoeuvre = sum(s.get("closest_straight_m") is not None and s["closest_straight_m"] <= x["net_radius_m"]
                       for x in runs for s in x.get("shots", []) if s in missed)
    return {"shots": sum(len(x.get("shots", [])) for x in runs), "missed_shots": len(missed),
            "missed_by_manoeuvre": by_manoeuvre, "missed_by_aim": len(missed) - by_manoeuvre}


def family_order(family):
    return FAMILIES.index(family) if family in FAMILIES else len(FAMILIES)


def shape_order(shape):
    return ALL_SHAPES.index(shape) if shape in ALL_SHAPES else len(ALL_SHAPES)


def summarise(out, label, sweep_dirs, bands=None, seed0=1):
    runs = []
    for sweep in sweep_dirs:
        runs_dir = os.path.join(sweep, "runs")
        for name in sorted(os.listdir(runs_dir)):
            report_file = os.path.join(runs_dir, name, "report.json")
            seed = int(name.split("_seed")[1])
            if not os.path.exists(report_file):
                runs.append({"seed": seed, "captured": False, "cause": "run failed: no report", "shape": "?",
                             "family": "?"})
                continue
            r = json.load(open(report_file))
            c = r.get("control", {})
            nodes = r["graph"]["resolved"]["nodes"]
            shape = nodes["intruder"]["params"]["shape"]
            guidance = nodes.get("aim", {}).get("params", {}).get("guidance")
            runs.append({"seed": seed, "shape": shape, "family": held_out_families.family_of(nodes["intruder"]["params"]),
                         "captured": c.get("captured") is True,
                         "guidance": guidance.get("type") if isinstance(guidance, dict) else guidance,
                         "first_shot_captured": c.get("first_shot_captured") is True,
                         "time_to_capture_s": c.get("time_to_capture_s"), "aim_rmse_m": c.get("aim_rmse_m"),
                         "fire_count": c.get("fire_count"),
                         "first_seen_range_m": r.get("aim", {}).get("first_seen_range_m"),
                         # each shot's prediction stays in its report (scripts/fit-shot-model reads it there)
                         "shots": [{k: v for k, v in s.items() if k != "prediction"}
                                   for s in paired_shots(c.get("shots", []), r.get("aim", {}).get("shots", []))],
                         "net_radius_m": nodes.get("net", {}).get("params", {}).get("radius_m", 0.6),
                         "futures_calibration": r.get("aim", {}).get("futures_calibration") or {},
                         "cause": None if c.get("captured") else failure_cause(r)})
    runs.sort(key=lambda x: x["seed"])
    caught = [x for x in runs if x["captured"]]
    times = [x["time_to_capture_s"] for x in caught]
    rmses = [x["aim_rmse_m"] for x in runs if x.get("aim_rmse_m") is not None]
    summary = {
        "camera": label, "runs": len(runs),
        "success_rate": len(caught) / len(runs) if runs else None,
        "median_time_to_capture_s": statistics.median(times) if times else None,
        "aim_rmse_m": statistics.median(rmses) if rmses else None,
        "failures": [{"seed": x["seed"], "cause": x["cause"]} for x in runs if not x["captured"]],
        "first_shot_rate": group_figures(runs)["first_shot_rate"],
        "first_seen_closer_than_4m": group_figures(runs)["first_seen_closer_than_4m"],
        **missed_shots(runs),
        "by_shape": {s: {"runs": sum(x["shape"] == s for x in runs),
                         "captured": sum(x["shape"] == s and x["captured"] for x in runs)}
                     for s in sorted({x["shape"] for x in runs}, key=shape_order)},
        "per_run": runs,
    }
    if bands:
        for x in runs:
            x["band"] = band_label(bands[(x["seed"] - seed0) // BAND_SEED_STRIDE])
        summary["by_band"] = [band_figures(b, [x for x in runs if x["band"] == band_label(b)]) for b in bands]
    # By behaviour family and speed band (the default band when none was asked for).
    for x in runs:
        x.setdefault("band", band_label((0.0, MAX_INTRUDER_SPEED)))
    families = sorted({x["family"] for x in runs}, key=family_order)
    summary["families"] = {"tuning": [f for f in families if f in TUNING_FAMILIES],
                           "held_out": [f for f in families if f in HELD_OUT_FAMILIES]}
    band_order = [band_label(b) for b in bands] if bands else [band_label((0.0, MAX_INTRUDER_SPEED))]
    summary["by_family"] = {f: {b: group_figures(group) for b in band_order
                                if (group := [x for x in runs if x["family"] == f and x["band"] == b])}
                            for f in families}
    if any(sightings_ranked(x) for x in runs):
        summary["futures_calibration"] = {f: futures_calibration([x for x in runs if x["family"] == f])
                                          for f in families}
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "capture.json"), "w") as f:
        json.dump(summary, f, indent=2)
    return summary


def sightings_ranked(run):
    return sum(t.get("sightings", 0) for t in run.get("futures_calibration", {}).values())


def futures_calibration(runs):
    """The aim's futures against the sightings they foresaw, summed over runs: per look-ahead, the
    share of sightings within the paths' central half and central 90 % (0.5 and 0.9 when the
    predictor's manoeuvre noise is right; fewer: too small; more: too large)."""
    out = {}
    for x in runs:
        for tau, t in x.get("futures_calibration", {}).items():
            o = out.setdefault(tau, {"sightings": 0, "within_half": 0, "within_90": 0, "rank_sum": 0.0})
            o["sightings"] += t["sightings"]
            o["within_half"] += t["within_half"]
            o["within_90"] += t["within_90"]
            o["rank_sum"] += (t["mean_rank"] or 0.0) * t["sightings"]
    return {tau: {"sightings": o["sightings"],
                  "within_half": o["within_half"] / o["sightings"] if o["sightings"] else None,
                  "within_90": o["within_90"] / o["sightings"] if o["sightings"] else None,
                  "mean_rank": o["rank_sum"] / o["sightings"] if o["sightings"] else None}
            for tau, o in sorted(out.items(), key=lambda kv: float(kv[0]))}


def main(argv):
    import argparse
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("scenarios")
    p.add_argument("n", type=int)
    p.add_argument("seed0", type=int)
    p.add_argument("file")
    p.add_argument("--bands", default=None)
    p.add_argument("--shapes", "--families", dest="shapes", default=",".join(SHAPES))
    p.add_argument("--distance", default="4:9")
    p.add_argument("--flights", default=None, help="where the agile family's flights are written")
    p = sub.add_parser("summarise")
    p.add_argument("out")
    p.add_argument("label")
    p.add_argument("sweep_dirs", nargs="+")
    p.add_argument("--bands", default=None)
    p.add_argument("--seed0", type=int, default=1)
    p = sub.add_parser("combine")
    p.add_argument("file")
    p.add_argument("main")
    p.add_argument("rendered", nargs="?")
    p.add_argument("--law", action="append", default=[], help="LAW=SUMMARY: a guidance law's summary")
    p = sub.add_parser("markdown")
    p.add_argument("cases")
    p.add_argument("summaries", nargs="+")
    p = sub.add_parser("family-curve")
    p.add_argument("file")
    p.add_argument("summary")
    p = sub.add_parser("curve")
    p.add_argument("file")
    p.add_argument("laws", nargs="+", help="LAW=SUMMARY")
    a = parser.parse_args(argv[1:])
    if a.command == "scenarios":
        bands = parse_bands(a.bands) if a.bands else [(0.0, MAX_INTRUDER_SPEED)]
        shapes = a.shapes.split(",")
        if unknown := [x for x in shapes if x not in FAMILIES]:
            raise SystemExit(f"unknown family (shape) {', '.join(unknown)}: choose from {', '.join(FAMILIES)}")
        write_scenarios(a.n, a.seed0, a.file, bands, shapes, parse_distance(a.distance), a.flights)
    elif a.command == "summarise":
        summarise(a.out, a.label, a.sweep_dirs, parse_bands(a.bands) if a.bands else None, a.seed0)
    elif a.command == "combine":
        combined = json.load(open(a.main))
        if a.rendered:
            combined["rendered"] = json.load(open(a.rendered))
        if a.law:
            combined["by_guidance"] = {law: json.load(open(path))
                                       for law, _, path in (item.partition("=") for item in a.law)}
            # One list over every law's bands: the same engagements, told apart by `guidance`.
            if all("by_band" in s for s in combined["by_guidance"].values()):
                combined["by_band"] = [b for s in combined["by_guidance"].values() for b in s["by_band"]]
        with open(a.file, "w") as f:
            json.dump(combined, f, indent=2)
    elif a.command == "markdown":
        sys.stdout.write(capture_report.markdown([json.load(open(p)) for p in a.summaries], a.cases))
    elif a.command == "family-curve":
        capture_report.write_family_curve(a.file, json.load(open(a.summary)))
    elif a.command == "curve":
        capture_report.write_curve(a.file, {law: json.load(open(path)) for law, _, path in (item.partition("=") for item in a.laws)})


if __name__ == "__main__":
    main(sys.argv)
