"""Example 07: the modified Prandtl-Ishlinskii model (Kuhnen) - a PI model followed by a dead-zone
superposition, which makes the loops asymmetric - with its analytic inverse as a feedforward
compensator, and the fit of such a model by constrained least squares, all by name through the
model registry.

Run: PYTHONPATH=build/python /usr/bin/python3 examples/07_modified_pi.py
"""

import sys

import numpy as np

import hyst
from hyst import signals

params = {"thresholds": [0.0, 0.3, 0.7, 1.0], "weights": [0.8, 0.5, 0.3, 0.2],
          "dead_zone_thresholds": [-1.5, -0.8, -0.3, 0.0, 0.4, 0.9, 1.6],
          "dead_zone_weights": [0.05, 0.1, 0.2, 1.0, -0.15, -0.2, -0.1], "offset": 0.0}
model = hyst.Model("modified_pi", params)
print(model.describe())

# Feedforward: inputs for a desired output with internal loops, then the model driven by them.
desired = signals.generate(signals.TimeGrid(3000, 1e-3),
                           signals.DecayingSine(amplitude=2.0, frequency=4.0, time_constant=1.0))
inputs, report = model.inverse().invert(desired)
reached = model.simulate(inputs)
error = np.abs(reached - desired).max()
print(f"inverse: {report}; max |P[P^-1[y_d]] - y_d| = {error:.3g}")

# Identification with default grids, validated on the same record.
fitted, fit_report = hyst.fit("modified_pi", inputs, reached, inputs, reached, operators=10)
print(fit_report.brief())
sys.exit(0 if error < 1e-12 and fitted.has_inverse() and fit_report.fit.nrmse_percent < 2 else 1)
