"""hyst.plot: loops, time series, residuals and comparisons drawn with matplotlib, labelled with
the units the data carry; a clear message when matplotlib is missing."""

import os
import sys
from pathlib import Path

import numpy as np
import pytest

import hyst

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")

AIXACCT = Path(os.environ.get("HYST_SHARED_DATA_DIR", "../shared/data")) / \
    "piezo_pzt_aixacct_butterfly" / "RMN_TRAP_SLOW.dat"


def loop_record():
    v = np.sin(np.linspace(0.0, 4.0 * np.pi, 400))
    return v, v + 0.2 * np.sign(np.gradient(v))


def test_loop_with_a_model_and_units(tmp_path):
    v, y = loop_record()
    model, _ = hyst.fit("pi", v, y)
    ax = hyst.plot.loop(v, y, model=model, x_label="voltage", x_unit="V", y_unit="um")
    assert ax.get_xlabel() == "voltage [V]" and ax.get_ylabel() == "output [um]"
    measured, simulated = ax.get_lines()
    np.testing.assert_array_equal(measured.get_xdata(), v)
    np.testing.assert_allclose(simulated.get_ydata(), model.simulate(v))
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["measured", "pi (simulated)"]
    ax.figure.savefig(tmp_path / "loop.png")
    assert (tmp_path / "loop.png").stat().st_size > 1000


def test_loops_on_one_axes_take_a_colour_each():
    v, y = loop_record()
    ax = hyst.plot.loop(v, y, label="first")
    ax = hyst.plot.loop(v, 2 * y, ax=ax, label="second", color="C1")
    first, second = ax.get_lines()
    assert first.get_color() == "0.3"  # the default: dark grey
    assert matplotlib.colors.same_color(second.get_color(), "C1")
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["first", "second"]


@pytest.mark.skipif(not AIXACCT.is_file(), reason="shared data not found")
def test_columns_of_a_data_file_label_the_axes_with_their_units():
    columns = {column.name: column for column in
               hyst.io.read_aixacct(AIXACCT).measurement(6).columns}
    ax = hyst.plot.loop(columns["V+"], columns["P1"])
    assert ax.get_xlabel() == "V+ [V]" and ax.get_ylabel() == "P1 [uC/cm2]"
    np.testing.assert_array_equal(ax.get_lines()[0].get_xdata(), columns["V+"].values)


def test_time_series_residuals_and_mismatched_lengths():
    v, y = loop_record()
    ax = hyst.plot.time_series({"input": v, "output": y}, sample_time=1e-3, unit="V")
    assert ax.get_xlabel() == "time [s]" and ax.get_ylabel() == "value [V]"
    np.testing.assert_allclose(ax.get_lines()[1].get_xdata()[-1], 399e-3)
    ax = hyst.plot.residuals(y, y + 0.5, held_out_from=300)
    assert ax.get_lines()[0].get_ydata() == pytest.approx(np.full(400, 0.5))
    assert "RMSE 0.5" in ax.get_legend().get_texts()[0].get_text()
    with pytest.raises(ValueError, match="input has 400 samples, output 3"):
        hyst.plot.loop(v, y[:3])
    with pytest.raises(ValueError, match="no series given"):
        hyst.plot.time_series({})


def test_comparison_bars_best_on_top():
    v, y = loop_record()
    result = hyst.compare(np.tile(v, 3), np.tile(y, 3), ["pi", "maxwell_slip"])
    ax = hyst.plot.comparison(result)
    ranked = [row.model for row in result.ranking if row.ok]
    labels = dict(zip(ax.get_yticks(), (label.get_text() for label in ax.get_yticklabels())))
    assert [labels[position] for position in sorted(labels, reverse=True)] == ranked
    assert ax.get_xlabel() == "held-out NRMSE [%]"


def test_without_matplotlib_the_message_says_how_to_install_it(monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib.pyplot", None)
    with pytest.raises(ImportError, match="apt-get install python3-matplotlib"):
        hyst.plot.loop(*loop_record())
