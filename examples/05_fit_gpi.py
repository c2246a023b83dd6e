"""Example 05: fit the generalized Prandtl-Ishlinskii model (tanh envelopes, exponential
density) to a measured piezo loop with Ceres, then cancel its hysteresis with its inverse (IGPI).

The fit is nonlinear (Levenberg-Marquardt, automatic derivatives, several starting points from
the data); the report says how it ended. The fitted model comes back in the state it assumed for
the record (its periodic steady state), and its inverse starts consistently with that state.

Run: PYTHONPATH=build/python /usr/bin/python3 examples/05_fit_gpi.py
"""

import os
import sys
from pathlib import Path

import numpy as np

import hyst
from hyst import signals

data_dir = Path(os.environ.get("HYST_SHARED_DATA_DIR")
                or Path(__file__).resolve().parents[2] / "shared" / "data")
path = data_dir / "piezo_pzt_aixacct_butterfly" / "MeasurementData.mat"
voltage = hyst.io.read_mat_vector(path, "Vplus_15kv")
displacement = hyst.io.read_mat_vector(path, "Displacement_15kv")

model, report = hyst.fit("gpi", voltage, displacement, initial_state="periodic")
print(report.brief())

# Desired displacement: nested loops well inside the fitted one.
centre, half = 0.5 * (displacement.max() + displacement.min()), 0.5 * np.ptp(displacement)
desired = signals.generate(signals.TimeGrid(3000, 1e-3), signals.DecayingSine(
    amplitude=0.6 * half, frequency=3.0, time_constant=1.0, offset=centre))

inverse = model.inverse(-1500.0, 1500.0)  # the voltage the actuator accepts
command, inverse_report = inverse.invert(desired)
achieved = model.simulate(command)
error = np.abs(achieved - desired).max()
print(f"IGPI feedforward: max |GPI[IGPI[x_d]] - x_d| = {error:.3g} nm, {inverse_report}")
sys.exit(0 if report.fit.nrmse_percent < 5 and inverse_report.ok and error < 1e-6 * half else 1)
