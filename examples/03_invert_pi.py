"""Example 03: compensate hysteresis with the inverse of a fitted Prandtl-Ishlinskii model.

A PI model is fitted to the measured piezo loop (or, without the shared data, built by hand).
The desired displacement is a decaying oscillation: each reversal lies inside the previous one,
so the compensated input has to reproduce nested internal loops. The inverse must start from
the state consistent with the model's (state_consistent_with); the actuator's admissible input
range is passed as limits, and targets it cannot reach are reported, not raised.

Run: PYTHONPATH=build/python python3 examples/03_invert_pi.py
"""

import copy
import os
import sys
from pathlib import Path

import numpy as np

import hyst
from hyst import signals

data_dir = Path(os.environ.get("HYST_SHARED_DATA_DIR")
                or Path(__file__).resolve().parents[2] / "shared" / "data")
path = data_dir / "piezo_pzt_aixacct_butterfly" / "MeasurementData.mat"
if path.exists():
    voltage = hyst.io.read_mat_vector(path, "Vplus_15kv")
    displacement = hyst.io.read_mat_vector(path, "Displacement_15kv")
    model, state, report = hyst.fit_prandtl_ishlinskii(voltage, displacement, operators=12,
                                                       initial_state="periodic")
    print(report.brief())
else:
    print(f"no data at {path}: using a hand-made model")
    model = hyst.PrandtlIshlinskii(hyst.uniform_thresholds(8, 100.0), np.linspace(0.5, 0.05, 8))
    voltage = signals.generate(signals.TimeGrid(400, 1e-3), signals.Sine(amplitude=1900.0))
    state = model.initial_state()
v_min, v_max = voltage.min(), voltage.max()

# Desired output: nested loops around the middle of the model's major loop, inside it.
major_loop = model.simulate(voltage, copy.copy(state))  # simulate() advances the state it gets
grid = signals.TimeGrid(4000, 1e-3)
desired = signals.generate(grid, signals.DecayingSine(
    amplitude=0.35 * np.ptp(major_loop), frequency=3.0, time_constant=0.6,
    offset=0.5 * (major_loop.max() + major_loop.min())))

# The inverse, limited to the admissible voltage, started consistently with the model's state.
inverse = hyst.InversePrandtlIshlinskii(model, input_min=v_min, input_max=v_max)
inputs, inverse_report = inverse.invert(desired, inverse.state_consistent_with(state))
compensated = model.simulate(inputs, state)

error = np.abs(compensated - desired).max()
print(f"inverse: {inverse_report}, input range [{inputs.min():.1f}, {inputs.max():.1f}] V")
print(f"max |y - y_desired| = {error:.3g} (desired range {np.ptp(desired):.4g})")

# An unreachable target is answered with the limit and a status.
_, status = inverse.solve(inverse.initial_state(), 10 * major_loop.max())
print(f"target 10 x y_max: {status}")
sys.exit(0 if inverse_report.ok and error < 1e-9 * np.ptp(desired) else 1)
