#!/usr/bin/env python3
"""Summarises the runs of scripts/range-table into range.json, range.md and range.csv.

  range_table.py OUTDIR DURATION "RANGES" "MODES" "OVERRIDES"
  range_table.py --plot-columns "MODES"     the --y argument of `kestrel plot` for range.png

Each row is one run's report.json: the detection evaluator's precision, recall and body-frame
errors (the paper's Table 1 axes: X forward = depth, Y left, Z up), and the chain's time per
frame from `kestrel run --stats` (lockstep: each stage's time is its own).
"""
import csv
import json
import os
import sys

CAMERAS = ["still", "hold", "climb", "turn"]
SCENES = ["open", "trees"]
CHAIN = ["depth", "voxels", "ground", "clusters", "refine", "gate"]
# The rig: 0.12 m baseline, 92.8 degree field of view, so fx = 304 px at 640 and 608 px at 1280.
FOCAL_BASELINE = {"640": 304.0 * 0.12, "1280": 608.0 * 0.12}
# The stereo error bound drawn beside the measured depth RMSE: a quarter pixel of disparity,
# z^2 * 0.25 / (fx b), what the object-level refiner must hold over a whole object.
BOUND_PX = 0.25


def bound_m(mode, z):
    return z * z * BOUND_PX / FOCAL_BASELINE[mode]


def chain_ms(report, frames):
    nodes = {n["id"]: n for n in report.get("stats", {}).get("nodes", [])}
    total = 0.0
    for name in CHAIN:
        n = nodes.get(name)
        if n:  # a stage called more than once a frame (the refiner) counts all its calls
            total += n["processing_us"]["mean"] * n["calls"] / max(frames, 1) / 1000.0
    return total


def row(out, camera, scene, mode, d):
    name = f"{camera}_{scene}_{mode}_d{d}"
    path = os.path.join(out, name, "report.json")
    if not os.path.exists(path):
        return None
    report = json.load(open(path))
    det = report["detection"]
    return {"camera": camera, "scene": scene, "mode": mode, "range_m": float(d),
            "precision": det["precision"], "recall": det["recall"], "rmse_body_m": det["rmse_body_m"],
            "bias_body_m": det["bias_body_m"], "tp": det["tp"], "fp": det["fp"], "fn": det["fn"],
            "frames": det["frames"], "ms_per_frame": chain_ms(report, det["frames"]),
            "depth_bound_m": bound_m(mode, float(d)),
            "gate_dropped": report.get("gate", {}).get("dropped")}


def fmt(v, spec=".3f"):
    return "n/a" if v is None else format(v, spec)


def plot_columns(modes):
    panels = []
    for mode in modes.split():
        panels.append("+".join([f"{c}_open_{mode}" for c in CAMERAS] + [f"bound_{mode}"]))
    return ",".join(panels)


def main():
    if sys.argv[1] == "--plot-columns":
        print(plot_columns(sys.argv[2]))
        return
    out, duration, ranges, modes, overrides = sys.argv[1:6]
    rows = [r for mode in modes.split() for d in ranges.split() for camera in CAMERAS for scene in SCENES
            if (r := row(out, camera, scene, mode, d))]
    json.dump({"rows": rows, "duration_s": float(duration), "overrides": overrides,
               "depth_bound_px": BOUND_PX}, open(os.path.join(out, "range.json"), "w"), indent=2)

    lines = ["# Detection at range", "",
             "Figure-8 (1.0 x 0.5 m, 12 s) at 30 FPS; the flying hunter manoeuvres from 2 s on. Body frame: X "
             f"forward (depth), Y left, Z up. Bound: {BOUND_PX} px of disparity. ms: the chain (depth to gate) per "
             "frame.", "",
             "| mode | camera | scene | range m | frames | precision | recall | RMSE X (depth) | bound X | RMSE Y | "
             "RMSE Z | ms/frame |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        e = r["rmse_body_m"]
        lines.append(f"| {r['mode']} | {r['camera']} | {r['scene']} | {r['range_m']:g} | {r['frames']} | "
                     f"{fmt(r['precision'])} | "
                     f"{fmt(r['recall'])} | {fmt(e['x'])} | {r['depth_bound_m']:.3f} | {fmt(e['y'])} | "
                     f"{fmt(e['z'])} | {r['ms_per_frame']:.1f} |")
    if overrides:
        lines += ["", f"Overrides: `{overrides}`"]
    open(os.path.join(out, "range.md"), "w").write("\n".join(lines) + "\n")

    # One line per range: the depth RMSE of each open-ground camera and the bound, per mode.
    columns = ["range_m"] + [c for mode in modes.split()
                             for c in [f"{cam}_open_{mode}" for cam in CAMERAS] + [f"bound_{mode}"]]
    with open(os.path.join(out, "range.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(columns)
        for d in ranges.split():
            values = {"range_m": d}
            for r in rows:
                if r["range_m"] == float(d) and r["scene"] == "open" and r["rmse_body_m"]["x"] is not None:
                    values[f"{r['camera']}_open_{r['mode']}"] = f"{r['rmse_body_m']['x']:.4f}"
            for mode in modes.split():
                values[f"bound_{mode}"] = f"{bound_m(mode, float(d)):.4f}"
            w.writerow([values.get(c, "nan") for c in columns])


if __name__ == "__main__":
    main()
