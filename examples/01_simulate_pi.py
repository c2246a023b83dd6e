"""Example 01: build a Prandtl-Ishlinskii model, drive it with a decaying sine (nested loops),
and cancel its hysteresis with the analytic inverse. The Python twin of 01_simulate_pi.cpp.

Run: PYTHONPATH=build/python python3 examples/01_simulate_pi.py
"""

import sys

import numpy as np

import hyst
from hyst import signals

# Parameters are validated once; a bad one raises hyst.Error naming it.
model = hyst.PrandtlIshlinskii(thresholds=[0.0, 0.3, 0.7, 1.0], weights=[0.8, 0.5, 0.3, 0.2])
inverse = hyst.InversePrandtlIshlinskii(model)

grid = signals.TimeGrid(2000, 1e-3)
desired = signals.generate(
    grid, signals.DecayingSine(amplitude=2.0, frequency=2.0, time_constant=0.8))

# The state lives apart from the model: start both at the virgin state (all plays at 0).
inverse_state = inverse.initial_state()
inputs, report = inverse.invert(desired, inverse_state)

model_state = model.initial_state()
output = model.simulate(inputs, model_state)

worst = np.abs(output - desired).max()
print(f"max |P[P^-1[y_d]] - y_d| = {worst:.3g} over {len(output)} samples")
sys.exit(0 if worst < 1e-12 and report.ok else 1)
