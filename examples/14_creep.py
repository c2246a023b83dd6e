"""Example 14: hysteresis with creep, by name through the model registry. A PI model with Kuhnen's
creep operator drifts after a voltage step; its inverse cancels the drift of a held position;
the model is identified from a triangle record with its sample time. The modified PI with creep
adds dead zones after it for a saturating actuator.

Run: PYTHONPATH=build/python /usr/bin/python3 examples/14_creep.py
"""

import sys

import numpy as np

import hyst

# Two plays, creep lags of 0.1 s and 1 s on each, sampled at 1 ms.
params = {"thresholds": [0.0, 0.3], "weights": [1.0, 0.5],
          "time_constants": [0.1, 1.0], "creep_weights": [0.05, 0.02, 0.05, 0.03],
          "sample_time": 1e-3, "offset": 0.0}
model = hyst.Model("pi_creep", params)
print(model.describe())

# A step to 1 V: the instantaneous response, then the creep towards the static gain.
step = model.simulate(np.ones(5000))
model.reset()
print(f"step: y(1 ms) = {step[0]:.4f}, y(5 s) = {step[-1]:.4f} "
      f"(settles at 1 + 0.05 + 0.05 + (0.5 + 0.02 + 0.03) * 0.7 = {1.1 + 0.55 * 0.7:.4f})")

# Hold 0.8: the inverse with creep keeps it exactly.
desired = np.full(5000, 0.8)
inputs, report = model.inverse().invert(desired)
held = model.simulate(inputs)
model.reset()
hold_error = np.abs(held - desired).max()
print(f"inverse: {report}; max |y - 0.8| while holding = {hold_error:.2e}")

# Identification: a 0.5 Hz triangle, the same sample time, the model's time constants.
t = np.arange(1, 8001) * 1e-3
v = 2 / np.pi * np.arcsin(np.sin(2 * np.pi * 0.5 * t))
y = model.simulate(v)
fitted, fit_report = hyst.fit("pi_creep", v, y, thresholds=[0.0, 0.3],
                              time_constants=[0.1, 1.0], sample_time=1e-3)
print(fit_report.brief())
recovered = np.array(fitted.params["creep_weights"])
print("creep weights:", np.round(recovered, 6))

# The modified PI with creep: the same plays and lags, then dead zones that halve the slope
# beyond +-1 (saturation). Its inverse holds a position inside the saturation.
modified_params = dict(params, pi_offset=0.0, dead_zone_thresholds=[-1.0, 0.0, 1.0],
                       dead_zone_weights=[-0.5, 1.0, -0.5])
del modified_params["offset"]
saturating = hyst.Model("modified_pi_creep", modified_params)
response = saturating.simulate(np.ones(5000))
saturating.reset()
print(f"modified: step to 1 V, y(5 s) = {response[-1]:.4f} "
      f"(1 + 0.5 * ({step[-1]:.4f} - 1) = {1 + 0.5 * (step[-1] - 1):.4f})")
targets = np.full(5000, 1.2)
saturating_inputs, saturating_report = saturating.inverse().invert(targets)
saturating_hold = np.abs(saturating.simulate(saturating_inputs) - targets).max()
saturating.reset()
print(f"modified inverse: {saturating_report}; max |y - 1.2| = {saturating_hold:.2e}")
# Identified from its triangle response (default dead zones, output-error stage).
y_saturating = saturating.simulate(v)
saturating.reset()
refit, refit_report = hyst.fit("modified_pi_creep", v, y_saturating, thresholds=[0.0, 0.3],
                               time_constants=[0.1, 1.0], sample_time=1e-3)
print(refit_report.brief())

ok = (abs(step[-1] - (1.1 + 0.55 * 0.7)) < 1e-3 and hold_error < 1e-10
      and np.allclose(recovered, params["creep_weights"], atol=1e-6)
      and abs(response[-1] - (1 + 0.5 * (step[-1] - 1))) < 1e-12 and saturating_hold < 1e-10
      and refit_report.fit.nrmse_percent < 1.0)
sys.exit(0 if ok else 1)
