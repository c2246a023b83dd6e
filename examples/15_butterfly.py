"""Example 15: butterfly strain loops through the polarisation, by name through the registry.

The measured 1.9 kV loop of a piezoceramic is fitted with the polarisation as a latent signal
(voltage and displacement only) and predicts the 1.5 kV loop; three loops of Serie1.mat predict
the fourth; where the polarisation is measured too (aixACCT export: V+, P1, D1) the two-stage fit
identifies P(v) and checks the strain-polarisation map on the measured P; the inverse compensates
a unipolar drive and says where the butterfly has no inverse. The shared data are found next to
the repository (../shared/data) or in $HYST_SHARED_DATA_DIR.

Run: PYTHONPATH=build/python /usr/bin/python3 examples/15_butterfly.py
"""

import copy
import os
import sys
from pathlib import Path

import numpy as np

import hyst

data_dir = Path(os.environ.get("HYST_SHARED_DATA_DIR")
                or Path(__file__).resolve().parents[2] / "shared" / "data")
folder = data_dir / "piezo_pzt_aixacct_butterfly"
if not folder.is_dir():
    print(f"data not found: {folder} (set HYST_SHARED_DATA_DIR)")
    sys.exit(1)


def mat(name, variable):
    return hyst.io.read_mat_vector(str(folder / name), variable)


# 1. The 1.9 kV loop fitted, the 1.5 kV loop predicted from its own periodic steady state and
#    zeroed at its first sample, as the measured displacement is.
v19, y19 = mat("MeasurementData.mat", "Vplus_19kv"), mat("MeasurementData.mat", "Displacement_19kv")
v15, y15 = mat("MeasurementData.mat", "Vplus_15kv"), mat("MeasurementData.mat", "Displacement_15kv")
model, report = hyst.fit("butterfly_strain", v19, y19, v15, y15, validation_start="periodic",
                         validation_align="first-sample")
print(model.describe())
print(f"1.9 kV fit: NRMSE {report.fit.nrmse_percent:.2f} %; "
      f"1.5 kV predicted: NRMSE {report.validation.nrmse_percent:.2f} %")

# 2. Serie1.mat: four butterfly loops (1300-1600 V); three fitted together predict the fourth.
loops = [(mat("Serie1.mat", f"V_S1_{a}V_05Hz"), mat("Serie1.mat", f"D1_S1_{a}V_05Hz"))
         for a in (1300, 1400, 1500, 1600)]
joint, joint_report = hyst.fit_butterfly_strain_records(loops[:3])
v, y = loops[3]
joint.simulate(v)  # one period: the periodic steady state of this drive
predicted = joint.simulate(v)
predicted += y[0] - predicted[0]
nrmse = 100 * np.sqrt(np.mean((predicted - y) ** 2)) / np.ptp(y)
print(f"Serie1: 1300-1500 V fitted together (NRMSE {joint_report.fit.nrmse_percent:.2f} %), "
      f"1600 V predicted: NRMSE {nrmse:.2f} %")

# 3. Measured polarisation: table 6 of the aixACCT export (1400 V, 1 Hz).
table = hyst.io.read_aixacct(folder / "RMN_TRAP_SLOW.dat").measurement(6)
chain, chain_report, p_report, map_report, _ = hyst.fit_butterfly_strain_with_polarisation(
    table.column("V+"), table.column("P1"), table.column("D1"))
print(f"aixACCT table 6: P(v) NRMSE {p_report.fit.nrmse_percent:.2f} %, D1 from the measured P1 "
      f"NRMSE {map_report.fit.nrmse_percent:.2f} %, D1 from v through the model's P NRMSE "
      f"{chain_report.fit.nrmse_percent:.2f} %")

# 4. The inverse: exact on a unipolar drive between 200 and 800 V, "not invertible" across the
#    butterfly's vertex.
fitted, _ = hyst.fit("butterfly_strain", v19, y19)
drive = 500 + 290 * np.sin(0.05 * np.arange(201))
targets = copy.copy(fitted).simulate(drive)
inputs, inverse_report = fitted.inverse(input_min=200, input_max=800).invert(targets)
reached = copy.copy(fitted).simulate(inputs)
print(f"inverse on [200, 800] V: {inverse_report}, max error {np.abs(reached - targets).max():.2e} nm")
_, bipolar = fitted.inverse(input_min=-1900, input_max=1900).invert(targets)
print(f"inverse on [-1900, 1900] V: {bipolar.not_invertible_samples} of {len(targets)} samples "
      "not invertible")

# 5. Leakage? The polarisation of a lossy ceramic carries a leakage charge g * integral(v dt).
#    At 1, 0.1 and 0.01 Hz: g fitted with P(v) (two stages) against g = 1 / (Rav A) from the
#    instrument's summary; and what removing it does to the strain's map on the measured P.
export = hyst.io.read_aixacct(folder / "RMN_TRAP_SLOW.dat")
numbers = list(export.summary.column("Table No"))
print("table  rate     g fitted   g(Rav)    P(v) NRMSE [%]   D1 from P1 NRMSE [%]")
print("                 [uC/cm2/(V s)]        plain  leakage   plain  leakage")
for number in (6, 1, 2):
    table = export.measurement(number)
    time = table.column("Time")
    sample_time = time[1] - time[0]
    rav = export.summary.column("Rav")[numbers.index(number)]
    g_rav = hyst.data.leakage_conductance(rav, table.metadata_number("Area [mm2]"))
    args = (table.column("V+"), table.column("P1"), table.column("D1"))
    _, _, p_plain, map_plain, _ = hyst.fit_butterfly_strain_with_polarisation(*args)
    _, _, p_leak, map_leak, g = hyst.fit_butterfly_strain_with_polarisation(
        *args, fit_leakage=True, sample_time=sample_time)
    rate = table.metadata_number("Hysteresis Frequency [Hz]")
    print(f"{number:5}  {rate:<5g} Hz  {g:.3g}  {g_rav:.3g}   {p_plain.fit.nrmse_percent:5.2f}  "
          f"{p_leak.fit.nrmse_percent:5.2f}     {map_plain.fit.nrmse_percent:5.2f}  "
          f"{map_leak.fit.nrmse_percent:5.2f}")

if not inverse_report.ok or bipolar.not_invertible_samples == 0 or report.fit.nrmse_percent > 5:
    sys.exit(1)
