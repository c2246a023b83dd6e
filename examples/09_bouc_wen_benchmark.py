"""Example 09: the Bouc-Wen identification benchmark from Python.

The published oscillator, driven by the official multisine test input interpolated band-limited
(numpy FFT, x10) and simulated in steady state, reproduces the official test output; the same
model driven at 750 Hz with the input held between samples does not. Then the oscillator is
fitted by name (hyst.fit) to a short simulated record with noise. The full benchmark
identification (Ceres on the oversampled estimation record) is example 09's C++ program with
--full; see docs/results.md.

Run: PYTHONPATH=build/python /usr/bin/python3 examples/09_bouc_wen_benchmark.py
"""

import os
import sys
from pathlib import Path

import numpy as np

import hyst

data = Path(os.environ.get("HYST_SHARED_DATA_DIR")
            or Path(__file__).resolve().parents[2] / "shared" / "data") / "boucwen_benchmark"
u = hyst.io.read_mat_vector(data / "uval_multisine.mat", "uval_multisine")
y = hyst.io.read_mat_vector(data / "yval_multisine.mat", "yval_multisine")

FACTOR = 10
spectrum = np.fft.rfft(u)
n = len(u)
padded = np.zeros(n * FACTOR // 2 + 1, dtype=complex)
padded[: n // 2 + 1] = spectrum
padded[n // 2] *= 0.5  # the Nyquist bin stands for a cosine: half on each side
fine = np.fft.irfft(padded, n * FACTOR) * FACTOR

params = hyst.model_entry("bouc_wen_oscillator").example_params  # the published set
params.update(sample_time=1 / 750 / FACTOR, substeps=1)
model = hyst.Model("bouc_wen_oscillator", params)
model.state = {"displacement": 0.0, "velocity": 0.0, "hysteretic_force": 0.0,
               "previous_input": fine[-1]}
simulated = model.simulate(np.tile(fine, 3))[::FACTOR][2 * n:]
steady = np.sqrt(np.mean((simulated - y) ** 2))

held = hyst.Model("bouc_wen_oscillator",
                  dict(hyst.model_entry("bouc_wen_oscillator").example_params,
                       input_between_samples="hold"))
held_error = np.sqrt(np.mean((held.simulate(u) - y) ** 2))
print(f"published parameters vs yval_multisine: {steady:.3g} m (band-limited input, steady "
      f"state), {held_error:.3g} m (held input at 750 Hz)")

t = np.arange(2000) / 750.0
force = 40 * np.sin(2 * np.pi * 12 * t) + 25 * np.sin(2 * np.pi * 31 * t + 1.0)
truth = hyst.Model("bouc_wen_oscillator", hyst.model_entry("bouc_wen_oscillator").example_params)
measured = truth.simulate(force) + np.random.default_rng(1).normal(0.0, 2e-6, force.size)
fitted, report = hyst.fit("bouc_wen_oscillator", force, measured, max_iterations=40)
print(report.brief())
print({key: round(value, 4) for key, value in fitted.params.items()
       if key in ("mass", "damping", "stiffness", "alpha")})
sys.exit(0 if steady < 3e-7 and held_error > 1e-4 and report.fit.nrmse_percent < 0.5 else 1)
