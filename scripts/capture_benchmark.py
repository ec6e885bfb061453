#!/usr/bin/env python3
"""The capture benchmark's two halves around `kestrel sweep --cases`.

  capture_benchmark.py scenarios N SEED0 FILE   draws N random engagements (seeds SEED0..) as a
                                                cases file: one row per run, a column per --set
  capture_benchmark.py summarise OUTDIR LABEL SWEEPDIR...
                                                reads the runs' reports and writes OUTDIR/capture.json
  capture_benchmark.py combine FILE MAIN [RENDERED]
                                                the main summary, with the rendered subset's under
                                                "rendered", as FILE
  capture_benchmark.py markdown CASES SUMMARY...
                                                the Markdown table of the summaries

Each scenario is drawn from its own seed, so scenario k is the same whatever N is, and the same
for the detection-level and the rendered camera. The ranges are those of docs/control.md
("The capture benchmark"): the intruder flies a figure-8, a line back and forth or random
manoeuvres, 4 to 9 m ahead of the hunter's start, at up to 3 m/s, in a wind of up to 3 m/s.
"""
import csv
import json
import math
import os
import random
import statistics
import sys

SHAPES = ["figure8", "line", "random"]
MAX_INTRUDER_SPEED = 3.0  # m/s
MAX_WIND = 3.0  # m/s


def vec(v):
    return "[" + ", ".join(f"{x:.3f}" for x in v) + "]"


def scenario(seed):
    rng = random.Random(seed * 7919 + 17)
    shape = SHAPES[(seed - 1) % len(SHAPES)]  # each shape as often as the others
    distance = rng.uniform(4.0, 9.0)  # from the hunter's start to the intruder's path
    lateral = rng.uniform(-1.5, 1.5)
    height = rng.uniform(2.0, 3.0)  # centre of the path; it stays above the height gate
    wind_speed, wind_dir = rng.uniform(0.0, MAX_WIND), rng.uniform(-math.pi, math.pi)
    s = {"seed": seed, "intruder.shape": shape,
         "hunter.wind_m_s": vec([wind_speed * math.cos(wind_dir), wind_speed * math.sin(wind_dir), 0.0]),
         "hunter.gust_std_m_s": f"{0.2 * wind_speed:.3f}"}
    if shape == "figure8":
        half_width, half_height = rng.uniform(0.5, 2.0), rng.uniform(0.25, 0.8)
        top_speed = rng.uniform(0.5, MAX_INTRUDER_SPEED)
        # The Lissajous curve is fastest at its centre, where |v| = w sqrt(hw^2 + 4 hh^2).
        period = 2.0 * math.pi * math.hypot(half_width, 2.0 * half_height) / top_speed
        s.update({"intruder.distance_m": f"{distance:.3f}", "intruder.camera_position_m": vec([0.0, lateral, height]),
                  "intruder.half_width_m": f"{half_width:.3f}", "intruder.half_height_m": f"{half_height:.3f}",
                  "intruder.period_s": f"{period:.3f}", "intruder.start_s": f"{rng.uniform(0.0, period):.3f}"})
    elif shape == "line":
        length, climb = rng.uniform(3.0, 6.0), rng.uniform(-0.5, 0.5)
        heading = rng.uniform(-0.5, 0.5)  # rad off a pure crossing
        dx, dy = math.sin(heading) * length / 2.0, math.cos(heading) * length / 2.0
        s.update({"intruder.line_start_m": vec([distance - dx, lateral - dy, height - climb / 2.0]),
                  "intruder.line_end_m": vec([distance + dx, lateral + dy, height + climb / 2.0]),
                  "intruder.speed_m_s": f"{rng.uniform(0.5, MAX_INTRUDER_SPEED):.3f}", "intruder.at_end": "repeat",
                  # It brakes and turns as a multirotor can: 2 to 6 m/s^2 (a small quadrotor's
                  # few m/s^2 up to a sporty one's).
                  "intruder.line_acceleration_m_s2": f"{rng.uniform(2.0, 6.0):.3f}"})
    else:
        s.update({"intruder.random_centre_m": vec([distance, lateral, height]),
                  "intruder.random_half_extent_m": vec([rng.uniform(0.3, 1.0), rng.uniform(0.5, 2.0),
                                                        rng.uniform(0.2, 0.6)]),
                  "intruder.max_speed_m_s": f"{rng.uniform(0.5, MAX_INTRUDER_SPEED):.3f}"})
    return s


def write_scenarios(n, seed0, path):
    rows = [scenario(seed0 + k) for k in range(n)]
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


def summarise(out, label, sweep_dirs):
    runs = []
    for sweep in sweep_dirs:
        runs_dir = os.path.join(sweep, "runs")
        for name in sorted(os.listdir(runs_dir)):
            report_file = os.path.join(runs_dir, name, "report.json")
            seed = int(name.split("_seed")[1])
            if not os.path.exists(report_file):
                runs.append({"seed": seed, "captured": False, "cause": "run failed: no report", "shape": "?"})
                continue
            r = json.load(open(report_file))
            c = r.get("control", {})
            shape = r["graph"]["resolved"]["nodes"]["intruder"]["params"]["shape"]
            runs.append({"seed": seed, "shape": shape, "captured": c.get("captured") is True,
                         "time_to_capture_s": c.get("time_to_capture_s"), "aim_rmse_m": c.get("aim_rmse_m"),
                         "fire_count": c.get("fire_count"), "cause": None if c.get("captured") else failure_cause(r)})
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
        "by_shape": {s: {"runs": sum(x["shape"] == s for x in runs),
                         "captured": sum(x["shape"] == s and x["captured"] for x in runs)} for s in SHAPES},
        "per_run": runs,
    }
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "capture.json"), "w") as f:
        json.dump(summary, f, indent=2)
    return summary


def markdown(summaries, scenarios_file):
    f = lambda v, spec: "n/a" if v is None else format(v, spec)
    lines = ["# Capture benchmark", "",
             f"Random engagements drawn by scripts/capture-benchmark (cases: {scenarios_file}); a run is a capture "
             "when the net catches the intruder within the run.", "",
             "| camera | runs | captured | success rate | median time to capture [s] | median aim RMSE [m] |",
             "|---|---:|---:|---:|---:|---:|"]
    for s in summaries:
        captured = s["runs"] - len(s["failures"])
        lines.append(f"| {s['camera']} | {s['runs']} | {captured} | {f(s['success_rate'], '.1%')} | "
                     f"{f(s['median_time_to_capture_s'], '.1f')} | {f(s['aim_rmse_m'], '.2f')} |")
    for s in summaries:
        lines += ["", f"## {s['camera']}: by shape", "", "| shape | runs | captured |", "|---|---:|---:|"]
        for shape, v in s["by_shape"].items():
            lines.append(f"| {shape} | {v['runs']} | {v['captured']} |")
        lines += ["", f"## {s['camera']}: failures", ""]
        lines += [f"- seed {x['seed']}: {x['cause']}" for x in s["failures"]] or ["None."]
    return "\n".join(lines) + "\n"


def main(argv):
    if len(argv) == 5 and argv[1] == "scenarios":
        write_scenarios(int(argv[2]), int(argv[3]), argv[4])
    elif len(argv) >= 4 and argv[1] == "markdown":
        summaries = [json.load(open(p)) for p in argv[3:]]
        sys.stdout.write(markdown(summaries, argv[2]))
    elif len(argv) in (4, 5) and argv[1] == "combine":
        combined = json.load(open(argv[3]))
        if len(argv) == 5:
            combined["rendered"] = json.load(open(argv[4]))
        with open(argv[2], "w") as f:
            json.dump(combined, f, indent=2)
    elif len(argv) >= 5 and argv[1] == "summarise":
        summarise(argv[2], argv[3], argv[4:])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv)
