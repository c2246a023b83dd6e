"""Example 12: which model fits? Several models fitted to the same record and ranked on the same
held-out part (hyst.compare), then the NARX model fitted by name and simulated in free run.

A saturating hysteretic system (a Bouc-Wen model) is driven by a random walk; PI, Bouc-Wen and
NARX are fitted to the first 75 % of the record and ranked by the free-run NRMSE on the last
25 %. The NARX model on the Bouc-Wen identification benchmark is the C++ example 12 with --full
(see docs/results.md).

Run: PYTHONPATH=build/python /usr/bin/python3 examples/12_compare_models.py
"""

import sys

import hyst

grid = hyst.signals.TimeGrid(1600, 1.0)
v = hyst.signals.generate(grid, hyst.signals.RandomWalk(max_step=0.15, lower=-2.0, upper=2.0,
                                                         start=0.0, seed=12))
system = hyst.Model("bouc_wen", {"a": 1.0, "beta": 0.6, "gamma": 0.3, "n": 1.0,
                                 "stiffness": 2.0, "alpha_k": 0.3})
y = system.simulate(v)

comparison = hyst.compare(v, y, ["pi", "bouc_wen", "narx"],
                          options={"narx": {"hidden_sizes": [6], "max_iterations": 30}})
print(comparison.markdown())
best = comparison.ranking[0]
print(f"best: {best.model} (validation NRMSE {best.validation.nrmse_percent:.3g})")

# The NARX model alone: fitted by name, saved and simulated like every model.
narx, report = hyst.fit("narx", v[:1200], y[:1200], v[1200:], y[1200:], hidden_sizes=[6],
                        max_iterations=30)
print(report.brief())
sys.exit(0 if best.model == "bouc_wen" and best.ok else 1)
