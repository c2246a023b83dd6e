"""Example 11: from measured data to a compensator in plain C for a real-time controller.

Fits a Prandtl-Ishlinskii model to the P(V) loop of a piezoceramic (aixACCT export, table 6 of
RMN_TRAP_SLOW.dat, as in example 08), exports the model and its inverse as C99 code
(hyst.export_c, the same as `hyst export --lang c`), compiles a tiny C program with gcc that
compensates a desired polarisation trajectory sample by sample (inverse step -> voltage -> model
step), and compares the C results with the library's inverse and model. The shared data are found
next to the repository (../shared/data) or in $HYST_SHARED_DATA_DIR; gcc must be on the PATH.

Run: PYTHONPATH=build/python python3 examples/11_export_c.py
"""

import os
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

import hyst

PROGRAM = r"""#include <stdio.h>
#include "piezo.h"
int main(void) {
  double desired;
  piezo_state model;
  piezo_inverse_state inverse;
  piezo_init(&model);
  piezo_inverse_init(&inverse);
  while (scanf("%lf", &desired) == 1) {
    const double voltage = piezo_inverse_step(&piezo_INVERSE_PARAMS, &inverse, desired);
    const double response = piezo_step(&piezo_PARAMS, &model, voltage);
    printf("%.17g %.17g\n", voltage, response);
  }
  return 0;
}
"""

data_dir = Path(os.environ.get("HYST_SHARED_DATA_DIR")
                or Path(__file__).resolve().parents[2] / "shared" / "data")
path = data_dir / "piezo_pzt_aixacct_butterfly" / "RMN_TRAP_SLOW.dat"
if not path.exists():
    print(f"data not found: {path} (set HYST_SHARED_DATA_DIR)")
    sys.exit(1)

# 1. Fit (as example 08).
table = hyst.io.read_aixacct(path).measurement(6)
voltage, polarisation = table.column("V+"), table.column("P1")
# A lower bound on p_0 keeps the inverse well conditioned (its first weight is 1 / p_0).
model, report = hyst.fit("pi", voltage, polarisation, detrend=True, resample="input-grid",
                         operators=12, initial_state="periodic", min_linear_weight=1e-3)
print(report.brief())

with tempfile.TemporaryDirectory() as folder:
    # 2. Export.
    files = hyst.export_c(model, folder, prefix="piezo", source="RMN_TRAP_SLOW.dat table 6 (fitted)")
    print(f"exported {files['header']} and {files['source']}")

    # 3. A desired trajectory: two decaying sine periods inside 80 % of the measured range.
    low, high = float(np.min(polarisation)), float(np.max(polarisation))
    phase = 2 * np.pi * np.arange(2000) / 1000.0
    desired = 0.5 * (low + high) + 0.4 * (high - low) * np.exp(-0.3 * phase / np.pi) * np.sin(phase)
    text = "".join(f"{y!r}\n" for y in desired)  # repr: the exact double

    # 4. Compile and run the controller.
    Path(folder, "main.c").write_text(PROGRAM)
    subprocess.run(["gcc", "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O2", "-o",
                    "controller", "main.c", "piezo.c", "-lm"], cwd=folder, check=True)
    run = subprocess.run(["./controller"], cwd=folder, input=text, capture_output=True, text=True,
                         check=True)
    result = np.array([[float(x) for x in line.split()] for line in run.stdout.splitlines()])
    c_voltage, c_response = result[:, 0], result[:, 1]

# 5. The library on the same trajectory.
library_voltage, _ = model.inverse().invert(desired)
library_response = model.simulate(library_voltage)
voltage_difference = np.max(np.abs(c_voltage - library_voltage))
response_difference = np.max(np.abs(c_response - library_response))
tracking_error = np.max(np.abs(c_response - desired))
print(f"C vs library: max |voltage difference| {voltage_difference:.3g} V, "
      f"max |response difference| {response_difference:.3g} uC/cm2")
print(f"C controller: max |model response - desired| {tracking_error:.3g} uC/cm2 over "
      f"{len(desired)} samples (range {high - low:.3g} uC/cm2)")
# Rounding only: the sums run in another order in the library (vectorised) than in the C code.
voltage_span = float(np.max(voltage) - np.min(voltage))
ok = (voltage_difference <= 1e-11 * voltage_span and response_difference <= 1e-11 * (high - low)
      and tracking_error <= 1e-11 * (high - low))
sys.exit(0 if ok else 1)
