"""Example 02: fit a Prandtl-Ishlinskii model to a measured piezo loop and validate it on a
loop of another amplitude.

The record (MeasurementData.mat, voltage [V] -> displacement [nm]) holds one period of a
periodic excitation in steady state, so the fit starts from the periodic state, not from the
virgin one. The model is fitted at 1.5 kV, the largest loop with monotone branches (at 1.9 kV the
ceramic starts to switch polarisation, a "butterfly" that no PI model follows), and validated at
1 kV: the smaller loop lies inside the fitted one and tests the model's internal loops. Each
record was zeroed at its first sample, so the prediction is zeroed the same way. The shared data
are found next to the repository (../shared/data) or in $HYST_SHARED_DATA_DIR.

Run: PYTHONPATH=build/python python3 examples/02_fit_pi.py
"""

import os
import sys
from pathlib import Path

import hyst

data_dir = Path(os.environ.get("HYST_SHARED_DATA_DIR")
                or Path(__file__).resolve().parents[2] / "shared" / "data")
path = data_dir / "piezo_pzt_aixacct_butterfly" / "MeasurementData.mat"
if not path.exists():
    print(f"data not found: {path} (set HYST_SHARED_DATA_DIR)")
    sys.exit(1)

voltage = hyst.io.read_mat_vector(path, "Vplus_15kv")
displacement = hyst.io.read_mat_vector(path, "Displacement_15kv")
validation_voltage = hyst.io.read_mat_vector(path, "Vplus_1kv")
validation_displacement = hyst.io.read_mat_vector(path, "Displacement_1kv")

model, initial_state, report = hyst.fit_prandtl_ishlinskii(
    voltage, displacement, operators=10, initial_state="periodic")

print(report.brief())
print(f"model: {model}")
print(f"invertible: {model.is_invertible()}")

# The fitted model from the state it assumed reproduces the fit error of the report.
predicted = model.simulate(voltage, initial_state)
metrics = hyst.error_metrics(displacement, predicted)
print(f"re-simulated fit NRMSE: {metrics.nrmse_percent:.3g} %")

# Validation: the 1 kV loop from its own periodic state, zeroed at its first sample.
predicted = model.simulate(validation_voltage, hyst.pi_periodic_state(model, validation_voltage))
validation = hyst.error_metrics(validation_displacement, predicted - predicted[0])
print(f"validation at 1 kV: NRMSE {validation.nrmse_percent:.3g} % (docs/results.md: 8.44 %)")

ok = (report.termination == hyst.Termination.converged and model.is_invertible()
      and abs(metrics.rmse - report.fit.rmse) <= 1e-9 * report.fit.rmse
      and report.fit.nrmse_percent < 5 and validation.nrmse_percent < 10)
sys.exit(0 if ok else 1)
