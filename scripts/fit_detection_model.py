#!/usr/bin/env python3
"""Fits the detection-level camera model (node type `detection_model`) to runs of the rendered
perception chain. Reads each report folder's detection.csv (matched detections and their errors),
detection_per_frame.csv (false alarms per frame) and tracking_trajectory.csv (truth, for the misses
by depth), and the camera's resolved parameters from report.json.

The errors are measured where the model draws them: image column and row of the centroid and its
disparity, d = fx * b / z. Writes OUTDIR/fit.json and OUTDIR/fit.md.

Usage: fit_detection_model.py OUTDIR REPORT_DIR...
"""
import csv
import json
import math
import os
import sys

DEPTH_BINS = [(0.5, 3.5), (3.5, 5.5), (5.5, 8.0)]  # near, middle, far: the recall table's points
ERROR_BIN_M = 1.0  # the errors' variance is fitted against depth over bins this wide


def camera_of(report):
    params = report["graph"]["resolved"]["nodes"]["camera"]["params"]
    width, height = params["width"], params["height"]
    fx = (width / 2.0) / math.tan(math.radians(params["hfov_deg"]) / 2.0)
    max_depth = report["graph"]["resolved"]["nodes"].get("voxels", {}).get("params", {}).get("max_depth_m", 8.0)
    return {"fx": fx, "cx": (width - 1) / 2.0, "cy": (height - 1) / 2.0, "width": width, "height": height,
            "baseline": params["baseline_m"], "max_depth": max_depth}


def in_view(cam, x, y, z):
    if not (0.5 <= z <= cam["max_depth"]):
        return False
    u, v = cam["fx"] * x / z + cam["cx"], cam["fx"] * y / z + cam["cy"]
    return 0 <= u < cam["width"] and 0 <= v < cam["height"]


def fit_two(points, weights):
    """Least squares of v = a + c * g over (g, v) points, with a, c >= 0."""
    sw = sum(weights)
    sg = sum(w * g for (g, _), w in zip(points, weights))
    sv = sum(w * v for (_, v), w in zip(points, weights))
    sgg = sum(w * g * g for (g, _), w in zip(points, weights))
    sgv = sum(w * g * v for (g, v), w in zip(points, weights))
    det = sw * sgg - sg * sg
    a, c = ((sgg * sv - sg * sgv) / det, (sw * sgv - sg * sv) / det) if det > 0 else (sv / sw, 0.0)
    if c < 0:
        a, c = sv / sw, 0.0
    if a < 0:
        a, c = 0.0, sgv / sgg
    return a, c


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    out, runs = argv[1], argv[2:]
    errors = []  # per matched detection: true depth, error x, y, z (m), disparity error (px)
    frames = false_alarms = 0
    seen = {b: [0, 0] for b in DEPTH_BINS}  # per depth bin: truths in view, detected
    cam = None
    for run in runs:
        report = json.load(open(os.path.join(run, "report.json")))
        cam = camera_of(report)
        fxb = cam["fx"] * cam["baseline"]
        detected_at = set()
        for row in csv.DictReader(open(os.path.join(run, "detection.csv"))):
            z = float(row["z"])
            ex, ey, ez = float(row["error_x"]), float(row["error_y"]), float(row["error_z"])
            errors.append((z - ez, ex, ey, ez, fxb / z - fxb / (z - ez)))
            detected_at.add(round(float(row["capture_s"]), 3))
        for row in csv.DictReader(open(os.path.join(run, "detection_per_frame.csv"))):
            frames += 1
            false_alarms += int(row["fp"])
        for row in csv.DictReader(open(os.path.join(run, "tracking_trajectory.csv"))):
            if not row["series"].startswith("truth"):
                continue
            x, y, z = float(row["x"]), float(row["y"]), float(row["z"])
            if not in_view(cam, x, y, z):
                continue
            for b in DEPTH_BINS:
                if b[0] <= z < b[1]:
                    seen[b][0] += 1
                    seen[b][1] += round(float(row["t"]), 3) in detected_at
    if not errors:
        sys.exit("no matched detections in " + " ".join(runs))
    fx, fxb = cam["fx"], cam["fx"] * cam["baseline"]
    # Per depth bin, the variance of each error; then variance = object part + pixel part, the
    # pixel part growing as (z / fx)^2 laterally and (z^2 / (fx b))^2 in depth.
    bins = {}
    for e in errors:
        bins.setdefault(int(e[0] // ERROR_BIN_M), []).append(e)
    table, fitted = [], {}
    for axis, gain in ((1, lambda z: (z / fx) ** 2), (2, lambda z: (z / fx) ** 2), (3, lambda z: (z * z / fxb) ** 2)):
        points, weights = [], []
        for k in sorted(bins):
            rows = bins[k]
            mean = sum(r[axis] for r in rows) / len(rows)
            var = sum((r[axis] - mean) ** 2 for r in rows) / len(rows)
            z = sum(r[0] for r in rows) / len(rows)
            points.append((gain(z), var))
            weights.append(len(rows))
        fitted[axis] = fit_two(points, weights)
    for k in sorted(bins):
        rows = bins[k]
        z = sum(r[0] for r in rows) / len(rows)
        means = [sum(r[a] for r in rows) / len(rows) for a in (1, 2, 3)]
        rms = [math.sqrt(sum((r[a] - means[a - 1]) ** 2 for r in rows) / len(rows)) for a in (1, 2, 3)]
        model = [math.sqrt(fitted[a][0] + fitted[a][1] * g) for a, g in
                 ((1, (z / fx) ** 2), (2, (z / fx) ** 2), (3, (z * z / fxb) ** 2))]
        table.append((k * ERROR_BIN_M, (k + 1) * ERROR_BIN_M, len(rows), rms, model))
    far = [e[4] for e in errors if e[0] >= 3.0] or [e[4] for e in errors]
    disparity_bias = sum(far) / len(far)
    depths = [round((b[0] + b[1]) / 2.0, 2) for b in DEPTH_BINS if seen[b][0] > 0]
    recall = [round(seen[b][1] / seen[b][0], 4) for b in DEPTH_BINS if seen[b][0] > 0]
    fit = {
        "runs": len(runs), "detections": len(errors), "frames": frames,
        "centroid_sigma_px": [round(math.sqrt(fitted[1][1]), 3), round(math.sqrt(fitted[2][1]), 3)],
        "disparity_sigma_px": round(math.sqrt(fitted[3][1]), 4), "disparity_bias_px": round(disparity_bias, 4),
        "object_sigma_m": [round(math.sqrt(fitted[a][0]), 4) for a in (1, 2, 3)],
        "recall_depth_m": depths, "recall": recall, "truths_in_view": [seen[b][0] for b in DEPTH_BINS],
        "false_alarms_per_frame": round(false_alarms / max(1, frames), 4),
        "camera": cam,
    }
    os.makedirs(out, exist_ok=True)
    json.dump(fit, open(os.path.join(out, "fit.json"), "w"), indent=2)
    v = lambda xs: "[" + ", ".join(str(x) for x in xs) + "]"
    sets = [f"camera.centroid_sigma_px={v(fit['centroid_sigma_px'])}",
            f"camera.disparity_sigma_px={fit['disparity_sigma_px']}",
            f"camera.disparity_bias_px={fit['disparity_bias_px']}",
            f"camera.object_sigma_m={v(fit['object_sigma_m'])}",
            f"camera.recall_depth_m={v(depths)}", f"camera.recall={v(recall)}",
            f"clutter.rate_per_frame={fit['false_alarms_per_frame']}"]
    md = ["# The detection-level camera model, fitted to the rendered chain", "",
          f"{len(runs)} rendered runs, {frames} frames, {len(errors)} matched detections "
          f"(fx = {fx:.1f} px, baseline {cam['baseline']} m).", "",
          "Errors of the matched detections (camera frame: x right, y down, z depth): standard deviation per "
          "depth bin, rendered chain against the fitted model. The rendered chain's biases, which change sign with "
          "depth and pose, are not modelled beyond the disparity bias.", "",
          "| depth [m] | detections | x rendered | x model | y rendered | y model | z rendered | z model |",
          "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for lo, hi, n, rms, model in table:
        md.append(f"| {lo:g}-{hi:g} | {n} | {rms[0]:.3f} | {model[0]:.3f} | {rms[1]:.3f} | {model[1]:.3f} | "
                  f"{rms[2]:.3f} | {model[2]:.3f} |")
    md += ["", "| depth [m] | truths in view | recall |", "|---|---:|---:|"]
    for b in DEPTH_BINS:
        n, k = seen[b]
        md.append(f"| {b[0]}-{b[1]} | {n} | {'n/a' if n == 0 else f'{k / n:.4f}'} |")
    md += ["", f"False alarms after the height gate: {fit['false_alarms_per_frame']} per frame.", "",
           "As overrides of graphs/sim_intercept_fast.yaml:", "", "    " + " \\\n    ".join(sets), ""]
    open(os.path.join(out, "fit.md"), "w").write("\n".join(md))
    print("\n".join(md))


if __name__ == "__main__":
    main(sys.argv)
