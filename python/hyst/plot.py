"""Plots of records, fits and comparisons with matplotlib (an optional dependency: Debian's
python3-matplotlib).

Every function draws into the matplotlib Axes `ax` (a new figure when None) and returns it, so
that figures can be composed and saved (`ax.figure.savefig("loop.png")`). Signals are numpy
arrays or columns of a data file that know their unit (hyst.io.AixacctColumn): their name and
unit label the axes; `x_unit`/`y_unit` give a unit for plain arrays.
"""

import numpy as np

_MISSING = ("hyst.plot needs matplotlib, which is not installed: on Debian, "
            "'apt-get install python3-matplotlib' (the module hyst works without it)")


def _pyplot():
    try:
        import matplotlib.pyplot as pyplot
    except ImportError as error:
        raise ImportError(_MISSING) from error
    return pyplot


def _axes(ax):
    return ax if ax is not None else _pyplot().subplots(figsize=(7.0, 4.5))[1]


def _signal(values, name, unit):
    """(array, name, unit) of a numpy array or a column with .values, .name and .unit."""
    if hasattr(values, "values") and hasattr(values, "unit"):
        return (np.asarray(values.values, dtype=float), name or values.name,
                unit if unit is not None else values.unit)
    return np.asarray(values, dtype=float), name, unit


def _label(name, unit):
    return f"{name} [{unit}]" if unit else name


def _legend(ax):
    # Outside the data: above the plot area, in one row.
    ax.legend(loc="lower left", bbox_to_anchor=(0.0, 1.01), ncol=4, frameon=False)


def loop(input, output, *, model=None, ax=None, x_label=None, y_label=None, x_unit=None,
         y_unit=None, label="measured", color=None):
    """The loop output(input); with `model` (a hyst.Model or a typed model) also its simulated
    loop, run from its start state over the same input. `color`: the measured line's colour
    (dark grey by default; e.g. "C1" to tell several loops on one Axes apart)."""
    ax = _axes(ax)
    x, x_name, x_unit = _signal(input, x_label, x_unit)
    y, y_name, y_unit = _signal(output, y_label, y_unit)
    if x.shape != y.shape:
        raise ValueError(f"hyst.plot.loop: input has {x.size} samples, output {y.size}")
    ax.plot(x, y, label=label, color="0.3" if color is None else color, linewidth=1.2)
    if model is not None:
        simulated = model.simulate(x)
        name = getattr(model, "name", type(model).__name__)
        ax.plot(x, np.asarray(simulated), label=f"{name} (simulated)", linewidth=1.2)
    ax.set_xlabel(_label(x_name or "input", x_unit))
    ax.set_ylabel(_label(y_name or "output", y_unit))
    ax.grid(True, alpha=0.3)
    _legend(ax)
    return ax


def time_series(series, *, time=None, ax=None, unit=None, time_unit="s", sample_time=None):
    """Signals over time: `series` is {name: values} (arrays or columns with units). The time
    axis is `time`, or the sample index times `sample_time`, or the sample index."""
    ax = _axes(ax)
    units = set()
    length = None
    for name, values in series.items():
        y, y_name, y_unit = _signal(values, name, unit)
        length = y.size
        units.add(y_unit)
        t = (np.asarray(time, dtype=float) if time is not None
             else np.arange(y.size) * sample_time if sample_time else np.arange(y.size))
        if t.shape != y.shape:
            raise ValueError(f"hyst.plot.time_series: '{y_name}' has {y.size} samples, the time "
                             f"axis {t.size}")
        ax.plot(t, y, label=y_name, linewidth=1.0)
    if length is None:
        raise ValueError("hyst.plot.time_series: no series given")
    ax.set_xlabel(_label("time", time_unit) if time is not None or sample_time else "sample")
    shared_unit = units.pop() if len(units) == 1 else None
    ax.set_ylabel(_label("value", shared_unit))
    ax.grid(True, alpha=0.3)
    _legend(ax)
    return ax


def residuals(measured, predicted, *, ax=None, unit=None, held_out_from=None):
    """The error predicted - measured per sample, with its RMSE in the legend; samples from
    `held_out_from` on (a validation part) are shaded."""
    ax = _axes(ax)
    y, _, y_unit = _signal(measured, "measured", unit)
    p = np.asarray(predicted, dtype=float)
    if p.shape != y.shape:
        raise ValueError(f"hyst.plot.residuals: measured has {y.size} samples, predicted "
                         f"{p.size}")
    error = p - y
    rmse = float(np.sqrt(np.mean(error ** 2))) if error.size else 0.0
    ax.plot(np.arange(error.size), error, linewidth=0.9, label=f"error (RMSE {rmse:.4g})")
    ax.axhline(0.0, color="0.5", linewidth=0.8)
    if held_out_from is not None:
        ax.axvspan(held_out_from, error.size - 1, color="0.85", label="held out", zorder=0)
    ax.set_xlabel("sample")
    ax.set_ylabel(_label("predicted - measured", y_unit))
    ax.grid(True, alpha=0.3)
    _legend(ax)
    return ax


def _score(row):
    """Held-out NRMSE [%] of a row of either comparison (one record, or across records)."""
    return row.validation.nrmse_percent if hasattr(row, "validation") else row.mean_nrmse_percent


def comparison(result, *, ax=None):
    """The held-out NRMSE [%] of each model of a hyst.compare() result (ModelComparison or
    CrossRecordComparison) as horizontal bars, best on top, with the yardstick as a line."""
    ax = _axes(ax)
    names, scores = [], []
    for row in result.ranking:
        if not row.ok:
            continue
        names.append(row.model)
        scores.append(_score(row))
    if not names:
        raise ValueError("hyst.plot.comparison: no model of the comparison was fitted")
    positions = np.arange(len(names))[::-1]
    ax.barh(positions, scores, color="tab:blue")
    ax.set_yticks(positions, names)
    references = [_score(reference) for reference in result.references if not reference.error]
    if references:
        ax.axvline(min(references), color="tab:red", linestyle="--",
                   label="yardstick (best reference predictor)")
    ax.set_xlabel("held-out NRMSE [%]")
    ax.grid(True, axis="x", alpha=0.3)
    _legend(ax)
    return ax
