"""Example 04: the Preisach model of the seed paper - 231 unweighted relays on 21 input levels -
driven by a decaying oscillation, and its numerical inverse, through the model registry.

Every registered model is available by name (hyst.models()); its parameters and state are plain
dicts, the same as in model files. The fast Everett form costs the same per sample whatever the
number of relays.

Run: PYTHONPATH=build/python /usr/bin/python3 examples/04_preisach.py
"""

import sys

import numpy as np

import hyst
from hyst import signals

# mu = 1 for each of the N(N+1)/2 = 231 relays on [-1, 1], from negative saturation.
params = {"levels": 21, "lower": -1.0, "upper": 1.0, "weights": [1.0] * 231,
          "layout": "cell_centred", "offset": 0.0, "initial_state": "negative_saturation"}
model = hyst.Model("preisach", params)
print(model.describe())

# Each reversal lies inside the previous one: a staircase of internal loops.
grid = signals.TimeGrid(2000, 1e-3)
v = signals.generate(grid, signals.DecayingSine(amplitude=1.2, frequency=5.0, time_constant=0.6))
y, final_state = model.simulate(v, return_state=True)  # the model itself never changes
print(f"output range [{y.min():g}, {y.max():g}] (saturation at +-231)")
print(f"memory after the run: {final_state['memory'][:6]} ...")

# The numerical inverse, started from the virgin model's state, reproduces the outputs.
inverse = model.inverse(-1.0, 1.0)
v_back, report = inverse.invert(y)
y_again = model.simulate(v_back)
error = np.abs(y_again - y).max()
print(f"inverse: {report}; max |P[P^-1[y]] - y| = {error:.3g}")
sys.exit(0 if report.ok and error < 1e-9 else 1)
