#!/usr/bin/env bash
# scripts/fit-shot-model on shots whose answer is known: 600 shots drawn from a known error model
# (an unforeseen acceleration of 3 m/s^2 per axis whatever the speed, half the estimated
# acceleration going on, the estimate's covariance as it is), written as run reports. The fit must find that model, its probabilities must be calibrated, and a wrong
# model must score worse. Then on real runs of the closed loop: the script recomputes the
# probability the aim planner logged for each shot, from the shot's own prediction.
set -euo pipefail
out=$1
rm -rf "$out"
mkdir -p "$out"
/usr/bin/python3 - "$out/synthetic" <<'PY'
import json, os, sys
import numpy as np
out = sys.argv[1]
rng = np.random.default_rng(7)
manoeuvre, radius = 3.0, 0.6
tau = np.linspace(0.4, 0.7, 31)
for run in range(30):
    aim, control = [], []
    for k in range(20):
        # The net's path relative to the target: a miss across it and a closing speed along it.
        miss0 = np.array([0.0, rng.uniform(0.0, 0.5), rng.uniform(-0.2, 0.2)])
        along = np.array([rng.uniform(-8.0, 8.0), 0.0, 0.0])
        crossing_at = rng.uniform(0.3, 0.8)
        path = miss0[None, :] + along[None, :] * (tau - crossing_at)[:, None]
        covariance = np.diag([0.01, 0.01, 0.01, 0.09, 0.09, 0.09])
        lead = 0.05
        velocity = rng.uniform(-5.0, 5.0, 3)
        estimated_acceleration = rng.uniform(-4.0, 4.0, 3)
        s = lead + tau
        truth = rng.multivariate_normal(np.zeros(6), covariance)
        acceleration = 0.5 * estimated_acceleration + manoeuvre * rng.standard_normal(3)
        off = path + truth[:3] + truth[3:] * s[:, None] + 0.5 * (s * s)[:, None] * acceleration
        t = 10.0 * k
        aim.append({"t_s": t, "probability": None, "prediction": {
            "lead_s": lead, "miss_path_m": [[float(a), *map(float, m)] for a, m in zip(tau, path)],
            "position_velocity_covariance": covariance.tolist(),
            "estimate": [0.0, 0.0, 0.0, *velocity.tolist(), *estimated_acceleration.tolist()]}})
        control.append({"t_s": t, "closest_m": float(np.linalg.norm(off, axis=1).min())})
    folder = os.path.join(out, "runs", f"{run:03d}_seed{run + 1}")
    os.makedirs(folder)
    json.dump({"graph": {"resolved": {"nodes": {"net": {"params": {"radius_m": radius}}}}},
               "aim": {"shots": aim}, "control": {"shots": control}}, open(os.path.join(folder, "report.json"), "w"))
PY
scripts/fit-shot-model "$out/fit" "$out/synthetic" > /dev/null
scripts/fit-shot-model "$out/wrong" "$out/synthetic" --model 0,0,0,1 > /dev/null
/usr/bin/python3 - "$out" <<'PY'
import json, os, sys
out = sys.argv[1]
fit = json.load(open(os.path.join(out, "fit", "shot_model.json")))
assert fit["shots"] == 600, fit["shots"]
found = {k: fit[k] for k in ("shot_manoeuvre_m_s2", "shot_turn_rate_rad_s", "shot_acceleration_share",
                             "shot_covariance_scale")}
assert found["shot_manoeuvre_m_s2"] in (2.0, 3.0, 4.0), found
assert found["shot_turn_rate_rad_s"] in (0.0, 0.25), found
assert found["shot_acceleration_share"] in (0.25, 0.5, 0.75), found
assert found["shot_covariance_scale"] in (0.5, 1.0, 2.0), found
# Calibrated: every well-filled bin catches about as often as it predicts, and the model beats the
# base rate alone.
for row in fit["reliability"]:
    if row["shots"] >= 50:
        assert abs(row["caught"] - row["predicted"]) < 0.12, row
assert fit["log_likelihood"] > fit["base_rate"]["log_likelihood"] + 0.05, fit
wrong = json.load(open(os.path.join(out, "wrong", "shot_model.json")))
assert not wrong["fitted"] and wrong["shot_manoeuvre_m_s2"] == 0.0
assert wrong["log_likelihood"] < fit["log_likelihood"] - 0.05, (wrong["log_likelihood"], fit["log_likelihood"])
PY
# Bad input: a clear error, no traceback.
if scripts/fit-shot-model "$out/none" "$out/missing" > "$out/none.log" 2>&1; then exit 1; fi
grep -q "no shot with a prediction" "$out/none.log"
if scripts/fit-shot-model "$out/none" "$out/synthetic" --model 3 > "$out/bad.log" 2>&1; then exit 1; fi
grep -q "M,W,A,K" "$out/bad.log"
if grep -q Traceback "$out/none.log" "$out/bad.log"; then exit 1; fi

# Real shots: the closed loop's own log, recomputed from each shot's prediction with the model
# the aim planner flew with (its defaults, from each report's resolved parameters).
scripts/capture-benchmark "$out/loop" --seeds 4 --rendered 0 --duration 12 --bands 3:6 \
  --set aim.max_speed_m_s=12 --set aim.max_acceleration_m_s2=8 > /dev/null
/usr/bin/python3 - "$out" <<'PY'
import os, sys
sys.path.insert(0, "scripts")
import importlib.machinery, importlib.util
loader = importlib.machinery.SourceFileLoader("fit_shot_model", "scripts/fit-shot-model")
spec = importlib.util.spec_from_loader("fit_shot_model", loader)
fit_shot_model = importlib.util.module_from_spec(spec)
loader.exec_module(fit_shot_model)
out = sys.argv[1]
shots = fit_shot_model.load_shots([os.path.join(out, "loop", "fast")])
assert shots, "the loop fired no shot with an outcome"
import numpy as np
draws = np.random.default_rng(11).standard_normal((4096, 9))
for shot in shots:
    again = fit_shot_model.probability(shot, shot["flown"], draws)
    # Two Monte Carlo estimates of one probability (2048 and 4096 draws: 0.014 apart at most, one
    # standard deviation).
    assert abs(again - shot["logged"]) < 0.06, (again, shot["logged"])
PY
