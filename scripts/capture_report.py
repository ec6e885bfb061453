"""The capture benchmark's report: the Markdown table of its summaries and the CSVs its curves are
drawn from (capture rate against the intruder's top speed, per guidance law or per behaviour
family, with Wilson 95 % bounds)."""
import csv


def band_label(band):
    return f"{band[0]:g}:{band[1]:g}"


def markdown(summaries, scenarios_file):
    f = lambda v, spec: "n/a" if v is None else format(v, spec)
    lines = ["# Capture benchmark", "",
             f"Random engagements drawn by scripts/capture-benchmark (cases: {scenarios_file}); a run is a capture "
             "when the net catches the intruder within the run.", "",
             "| camera | runs | captured | success rate | first shot | median time to capture [s] | median aim RMSE [m] |",
             "|---|---:|---:|---:|---:|---:|---:|"]
    for s in summaries:
        captured = s["runs"] - len(s["failures"])
        lines.append(f"| {s['camera']} | {s['runs']} | {captured} | {f(s['success_rate'], '.1%')} | "
                     f"{f(s.get('first_shot_rate'), '.1%')} | "
                     f"{f(s['median_time_to_capture_s'], '.1f')} | {f(s['aim_rmse_m'], '.2f')} |")
    if any("by_band" in s for s in summaries):
        lines += ["", "## By intruder top speed", "",
                  "Rates with their Wilson 95 % interval; first shot: the first net caught it; seen < 4 m: the target "
                  "was first seen closer than 4 m; missed shots: lost to the intruder's manoeuvre while the net flew "
                  "(flying straight on it would have been caught) + lost to the aim.", "",
                  "| camera | band [m/s] | runs | captured | rate | 95 % interval | first shot | median time [s] | "
                  "median nets | seen < 4 m | shots | missed: manoeuvre + aim |",
                  "|---|---|---:|---:|---:|---|---:|---:|---:|---:|---:|---|"]
        for s in summaries:
            for b in s.get("by_band", []):
                lines.append(f"| {s['camera']} | {b['band']} | {b['runs']} | {b['captured']} | {f(b['rate'], '.1%')} | "
                             f"{f(b['wilson_low'], '.1%')} to {f(b['wilson_high'], '.1%')} | "
                             f"{f(b['first_shot_rate'], '.1%')} | {f(b['median_time_to_capture_s'], '.1f')} | "
                             f"{f(b['median_nets_used'], 'g')} | {f(b['first_seen_closer_than_4m'], '.0%')} | "
                             f"{b['shots']} | {b['missed_by_manoeuvre']} + {b['missed_by_aim']} |")
    if any("by_family" in s for s in summaries):
        lines += ["", "## By behaviour family", "",
                  "Tuning families: the aim's values were chosen on them; held-out families: never tuned on. Rates "
                  "with their Wilson 95 % interval.", "",
                  "| camera | family | kind | band [m/s] | runs | captured | rate | 95 % interval | first shot | "
                  "median time [s] |", "|---|---|---|---|---:|---:|---:|---|---:|---:|"]
        for s in summaries:
            for family, by_band in s.get("by_family", {}).items():
                kind = "held out" if family in s.get("families", {}).get("held_out", []) else "tuning"
                for band, b in by_band.items():
                    lines.append(f"| {s['camera']} | {family} | {kind} | {band} | {b['runs']} | {b['captured']} | "
                                 f"{f(b['rate'], '.1%')} | {f(b['wilson_low'], '.1%')} to "
                                 f"{f(b['wilson_high'], '.1%')} | {f(b['first_shot_rate'], '.1%')} | "
                                 f"{f(b['median_time_to_capture_s'], '.1f')} |")
    if any("futures_calibration" in s for s in summaries):
        lines += ["", "## The target's futures against the sightings", "",
                  "Each sighting ranked among the paths the aim drew tau seconds before it: the share within their "
                  "central half and central 90 % is 50 % and 90 % when the predictor's manoeuvre noise is right "
                  "(fewer: too small; more: too large).", "",
                  "| camera | family | tau [s] | sightings | within the half | within 90 % |", "|---|---|---:|---:|---:|---:|"]
        for s in summaries:
            for family, by_tau in s.get("futures_calibration", {}).items():
                for tau, t in by_tau.items():
                    lines.append(f"| {s['camera']} | {family} | {tau} | {t['sightings']} | "
                                 f"{f(t['within_half'], '.1%')} | {f(t['within_90'], '.1%')} |")
    for s in summaries:
        lines += ["", f"## {s['camera']}: by shape", "", "| shape | runs | captured |", "|---|---:|---:|"]
        for shape, v in s["by_shape"].items():
            lines.append(f"| {shape} | {v['runs']} | {v['captured']} |")
        lines += ["", f"## {s['camera']}: failures", ""]
        lines += [f"- seed {x['seed']}: {x['cause']}" for x in s["failures"]] or ["None."]
    return "\n".join(lines) + "\n"


def write_curve(path, laws):
    """One row per band: its mid speed, and each law's rate with its Wilson bounds."""
    bands = [(b["lo_m_s"], b["hi_m_s"]) for b in next(iter(laws.values()))["by_band"]]
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["band", "speed_m_s"] + [f"{law}{suffix}" for law in laws for suffix in ("", "_low", "_high")])
        for lo, hi in bands:
            row = [band_label((lo, hi)), (max(lo, 0.5) + hi) / 2.0]
            for summary in laws.values():
                b = next(x for x in summary["by_band"] if (x["lo_m_s"], x["hi_m_s"]) == (lo, hi))
                row += [b["rate"], b["wilson_low"], b["wilson_high"]]
            w.writerow(row)


def write_family_curve(path, summary):
    """One row per band: its mid speed, and each family's rate with its Wilson bounds (blank where the
    family flew nothing in that band)."""
    bands = [(b["lo_m_s"], b["hi_m_s"]) for b in summary["by_band"]]
    families = list(summary["by_family"])
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["band", "speed_m_s"] + [f"{x}{suffix}" for x in families for suffix in ("", "_low", "_high")])
        for band in bands:
            row = [band_label(band), (max(band[0], 0.5) + band[1]) / 2.0]
            for family in families:
                b = summary["by_family"][family].get(band_label(band))
                row += [b["rate"], b["wilson_low"], b["wilson_high"]] if b else ["", "", ""]
            w.writerow(row)
