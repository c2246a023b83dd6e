"""Example 08: from a raw instrument export to a fitted model.

RMN_TRAP_SLOW.dat is the text export of an aixACCT ferroelectric analyser: a summary table and
ten measurement tables, each one period of a triangular voltage on a piezoceramic with the
polarisation P1 [uC/cm2] and displacement D1 [nm]. This example reads table 6 (1400 V, 1 Hz),
finds the reversal points and cycles of the voltage, computes the P(V) loop's figures and compares
them with the ones the instrument computed itself (in the table's metadata), then fits a
Prandtl-Ishlinskii model to the loop after removing the polarisation drift (the loop does not
close) and resampling each branch on a uniform voltage grid. The shared data are found next to the
repository (../shared/data) or in $HYST_SHARED_DATA_DIR.

Run: PYTHONPATH=build/python python3 examples/08_measured_data.py
"""

import os
import sys
from pathlib import Path

import hyst
from hyst import data

data_dir = Path(os.environ.get("HYST_SHARED_DATA_DIR")
                or Path(__file__).resolve().parents[2] / "shared" / "data")
path = data_dir / "piezo_pzt_aixacct_butterfly" / "RMN_TRAP_SLOW.dat"
if not path.exists():
    print(f"data not found: {path} (set HYST_SHARED_DATA_DIR)")
    sys.exit(1)

export = hyst.io.read_aixacct(path)
table = export.measurement(6)
voltage, polarisation = table.column("V+"), table.column("P1")
print(f"{export.kind}, table {table.number} ({table.metadata['SampleName']}): {table.rows} "
      f"samples, columns {', '.join(c.header for c in table.columns)}")

# Turning points of the voltage, ignoring wiggles below 2 % of its range.
band = data.default_band(voltage)
for point in data.reversal_points(voltage, band):
    print(f"reversal: {point.kind.name} {point.value:.1f} V at sample {point.index}")
cycles = data.cycles(voltage, band)
print(f"cycles: {len(cycles)}")

# The loop's figures, next to the instrument's own.
loop = data.loop_metrics(voltage, polarisation, 0, len(voltage) - 1)
wloss, vc_plus = table.metadata_number("Wloss [uJ/cm2]"), table.metadata_number("Vc+ [V]")
print(f"loop area {loop.area:.1f} uJ/cm2 (instrument Wloss {wloss:.1f})")
print(f"coercive voltages {loop.coercive[0].value:.2f} / {loop.coercive[-1].value:.2f} V "
      f"(instrument Vc+ {vc_plus:.2f}, Vc- {table.metadata_number('Vc- [V]'):.2f})")
print(f"remanent polarisation {loop.remanent[0].value:.4f} uC/cm2 "
      f"(instrument Pr+ {table.metadata_number('Pr+ [uC/cm2]'):.4f})")
print(f"loop closure error {loop.closure_error:.3f} uC/cm2 (drift over the period)")

# Fit with the preparation of the record listed in the report.
model, report = hyst.fit("pi", voltage, polarisation, detrend=True, resample="input-grid",
                         operators=12, initial_state="periodic")
print()
print(report.brief())

ok = (len(cycles) == 1 and abs(loop.area - wloss) < 1e-4 * loop.area
      and abs(loop.coercive[0].value - vc_plus) < 0.01
      and report.termination == hyst.Termination.converged
      and len(report.preprocessing) == 2 and report.fit.nrmse_percent < 5)
sys.exit(0 if ok else 1)
