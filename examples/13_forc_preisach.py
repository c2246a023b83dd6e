"""Example 13: from a raw FORC file to a fitted Preisach model and its FORC diagram.

conventional_example.forc is a MicroMag AGM export of 120 first-order reversal curves (PmagPy, see
its PROVENANCE.md). This example reads it, corrects the moment drift with the calibration point
measured before every curve, fits the Preisach model (a tabulated Everett function on 32 levels,
NNLS on its cell weights) to 3 of every 4 curves, predicts the 4th, saves the model file, and
writes the identified Preisach density as a FORC diagram over the coercive field
Hc = (alpha - beta)/2 and the interaction field Hu = (alpha + beta)/2 (CSV; PNG through gnuplot
when it is installed, as the Python package has no heat-map plot of its own), plus measured
against predicted moments of a few held-out curves.

Run: PYTHONPATH=build/python python3 examples/13_forc_preisach.py [FORC file] [output folder]
Defaults: the file in $HYST_SHARED_DATA_DIR or next to the repository (../shared/data), and the
folder forc_preisach (created if missing).
"""

import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

import hyst

# docs/results.md reports 0.047 % for fit and held-out curves with these settings and a noise of
# about 0.03 % of the range; 0.1 % leaves a margin and still fails if the fit or drift breaks.
MAX_NRMSE_PERCENT = 0.1

data_dir = Path(os.environ.get("HYST_SHARED_DATA_DIR")
                or Path(__file__).resolve().parents[2] / "shared" / "data")
path = Path(sys.argv[1]) if len(sys.argv) > 1 else (
    data_dir / "pmagpy_forc_micromag_agm" / "conventional_example.forc")
out = Path(sys.argv[2]) if len(sys.argv) > 2 else Path("forc_preisach")
if not path.exists():
    print(f"data not found: {path} (set HYST_SHARED_DATA_DIR or pass the file)")
    sys.exit(1)
out.mkdir(parents=True, exist_ok=True)

forc = hyst.io.read_micromag_forc(path)
print(f"{path.name}: {len(forc.curves)} curves, {forc.points} points, "
      f"{forc.calibration_points} calibration points, HCal {forc.header_number('HCal'):.4g} T")

# The calibration moment drifts during the run; a drifting sensitivity scales every moment.
start = time.perf_counter()
model, report = hyst.fit_preisach_forcs(forc, drift="multiplicative", hold_out_every=4,
                                        intervals=32)
seconds = time.perf_counter() - start
print(report.brief())
held_out = list(range(3, len(forc.curves), 4))
print(f"fit NRMSE {report.fit.nrmse_percent:.3f} % ({report.fit.samples} points), held-out NRMSE "
      f"{report.validation.nrmse_percent:.3f} % ({len(held_out)} curves, "
      f"{report.validation.samples} points), fit time {seconds:.2f} s")
hyst.save_model(out / "forc_preisach.json", model)

# The Preisach density as a FORC diagram, as in the C++ example: cell weight / cell area, with
# mu_ij = E[i+1,j] - E[i,j] - E[i+1,j+1] + E[i,j+1] the weight of the relays with alpha in cell i
# and beta in cell j (the mixed second difference, constant in a cell of the bilinear table), in
# nA m^2 / mT^2. The diagonal cells (the reversible part, its weight on alpha = beta) are left out
# and their share printed.
levels = np.asarray(model.params["levels"])
values = np.asarray(model.params["values"])
k = len(levels) - 1
table = np.zeros((k + 1, k + 1))  # E[a, c], zero for c >= a
for a in range(1, k + 1):
    table[a, :a] = values[a * (a - 1) // 2:a * (a - 1) // 2 + a]
weight = table[1:, :-1] - table[:-1, :-1] - table[1:, 1:] + table[:-1, 1:]  # [i, j]
np.fill_diagonal(weight, np.diagonal(table[1:, :-1]))
lower_cells = np.tril(np.ones((k, k), dtype=bool))
total = table[k, 0]
min_weight = weight[lower_cells].min()
reversible_share = np.trace(weight) / total

lower, upper = levels[0] * 1e3, levels[-1] * 1e3
hc, hu = np.meshgrid(np.arange(0.5, 0.5 * (upper - lower), 1.0), np.arange(lower + 0.5, upper, 1.0))
alpha, beta = hu + hc, hu - hc
inside = (alpha <= upper) & (beta >= lower)
i = np.clip(np.searchsorted(levels, alpha * 1e-3, side="right") - 1, 0, k - 1)
j = np.clip(np.searchsorted(levels, beta * 1e-3, side="right") - 1, 0, k - 1)
inside &= i > j
width = np.diff(levels)
density = weight[i, j] * 1e9 / (width[i] * width[j] * 1e6)
print(f"Preisach density: {hc.shape[1]} x {hc.shape[0]} cells of 1 mT, smallest cell weight "
      f"{min_weight:.3g} A m^2, reversible share {100 * reversible_share:.1f} %")
hyst.io.write_csv(out / "forc_diagram.csv", {"hc_mT": hc[inside], "hu_mT": hu[inside],
                                              "density_nAm2_per_mT2": density[inside]})

# Measured (drift-corrected, as fitted) against predicted for four held-out curves; each
# prediction runs from the model's start state, positive saturation.
corrected = hyst.io.correct_drift(forc, "multiplicative")
shown = [held_out[n * (len(held_out) - 1) // 3] for n in range(4)]
columns = {}
for index in shown:
    curve = corrected.curves[index]
    columns[f"FORC {index + 1}"] = (curve.field * 1e3, curve.moment * 1e9,
                                   model.simulate(curve.field) * 1e9)

if shutil.which("gnuplot"):
    # One gnuplot script per image, rendered to a temporary file and renamed over the target,
    # so that a reader never sees half an image.
    def render(script, target):
        temporary = target.with_name(f".{target.name}.tmp.{os.getpid()}")
        header = ("set terminal pngcairo noenhanced size 900,700 font ',11'\n"
                  f"set output '{temporary}'\n")
        subprocess.run(["gnuplot"], input=header + script, text=True, check=True)
        os.replace(temporary, target)

    render("set datafile separator ','\n"
           "set title 'FORC diagram: Preisach density identified from the FORCs'\n"
           "set xlabel 'Hc = (alpha - beta)/2 [mT]'\nset ylabel 'Hu = (alpha + beta)/2 [mT]'\n"
           "set cblabel 'density [nA m^2 / mT^2]'\nset cbrange [0:*]\n"
           f"set xrange [0:{0.5 * (upper - lower)}]\nset yrange [{lower}:{upper}]\n"
           "set palette defined (0 '#ffffff', 0.1 '#c6dbef', 0.3 '#3182bd', 0.55 '#31a354', "
           "0.75 '#fec44f', 1 '#d7301f')\n"
           "set rmargin at screen 0.84\nset tics out\nset grid front\nunset key\n"
           "set style fill solid 1.0 noborder\n"
           f"plot '{out / 'forc_diagram.csv'}' skip 1 using 1:2:($1-0.5):($1+0.5):($2-0.5):"
           "($2+0.5):3 with boxxyerror fc palette\n",
           out / "forc_diagram.png")
    blocks, plots = "", []
    for n, (name, (field, measured, predicted)) in enumerate(columns.items()):
        blocks += f"$d{n} << EOD\n" + "".join(
            f"{f!r} {m!r} {p!r}\n" for f, m, p in zip(field, measured, predicted)) + "EOD\n"
        colour = ("#1b9e77", "#d95f02", "#7570b3", "#e7298a")[n]  # one per curve
        plots += [f"$d{n} using 1:2 with points pt 7 ps 0.6 lc rgb '{colour}' "
                  f"title '{name} measured'",
                  f"$d{n} using 1:3 with lines lw 1.5 lc rgb '{colour}' title 'predicted'"]
    render(blocks + "set title 'Held-out FORCs: measured and predicted'\n"
           "set xlabel 'mu0 H [mT]'\nset ylabel 'moment [nA m^2]'\nset grid\n"
           "set key top left box opaque\nplot " + ", ".join(plots) + "\n",
           out / "held_out_forcs.png")
    print(f"wrote {out}: forc_preisach.json, forc_diagram.csv/.png, held_out_forcs.png")
else:
    print(f"wrote {out}: forc_preisach.json, forc_diagram.csv (gnuplot not found: no plots)")

# Cell weights must be >= 0 up to rounding (the table's own slack); the model file reads back.
saved_ok = hyst.load_model(out / "forc_preisach.json").params == model.params
ok = (report.fit.nrmse_percent < MAX_NRMSE_PERCENT
      and report.validation.nrmse_percent < MAX_NRMSE_PERCENT
      and min_weight >= -1e-10 * total and saved_ok)
if not ok:
    print(f"FAILED: NRMSE must stay below {MAX_NRMSE_PERCENT} %, every cell weight >= 0, the "
          f"model file must read back (saved ok: {saved_ok})")
sys.exit(0 if ok else 1)
