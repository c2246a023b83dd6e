"""hyst.data and hyst.io.read_aixacct: measured records from the instrument file to the fit."""

import json
import math
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import hyst
from hyst import data, io


def triangle(peak, periods):
    """Starts at 0 rising, 4 * peak samples per period, ends at 0: exact integers."""
    phase = np.arange(4 * peak * periods + 1) % (4 * peak)
    return np.where(phase <= peak, phase, np.where(phase <= 3 * peak, 2 * peak - phase,
                                                   phase - 4 * peak)).astype(float)


def test_reversal_points_branches_and_cycles_of_a_triangle():
    v = triangle(10, 3)
    points = data.reversal_points(v, band=1.5)
    assert [p.index for p in points] == [10, 30, 50, 70, 90, 110]
    assert [p.value for p in points] == [10, -10] * 3
    assert points[0].kind == data.Extremum.maximum and points[1].kind == data.Extremum.minimum
    assert "maximum 10 at 10" in repr(points[0])
    found = data.branches(v, 1.5)
    assert all(isinstance(b, data.Branch) for b in found)
    assert [(b.first, b.last) for b in found][:2] == [(0, 10), (10, 30)]
    assert found[1].direction == data.Direction.descending and found[1].samples == 21
    found = data.cycles(v, 1.5)
    assert isinstance(found[0], data.Cycle)
    assert [(c.first, c.last) for c in found] == [(0, 40), (40, 80), (80, 120)]
    assert not found[0].ends_at_record_end and found[0].samples == 41
    assert data.default_band(v) == pytest.approx(0.4)
    assert data.default_band(v, fraction=0.1) == pytest.approx(2.0)


def test_noise_below_the_band_is_ignored():
    v = triangle(10, 2)
    # Unit steps with noise in [-0.9, 0.9]: a later sample is at most 1.8 - 1 = 0.8 below an
    # earlier one on a rising part, so band 1 sees the 4 true reversals; a tiny band sees wiggles.
    noisy = v + np.random.default_rng(7).uniform(-0.9, 0.9, v.size)
    assert len(data.reversal_points(noisy, 1.0)) == len(data.reversal_points(v, 1.0)) == 4
    assert len(data.reversal_points(noisy, 1e-6)) > 4
    with pytest.raises(hyst.Error, match="hysteresis band = 0"):
        data.reversal_points(v, 0.0)
    with pytest.raises(hyst.Error, match=r"input\[1\] = nan"):
        data.reversal_points([0.0, math.nan, 1.0], 0.1)


def test_preisach_memory_wipes_out():
    history = [data.ReversalPoint(k, value, kind) for k, (value, kind) in enumerate(
        [(0.6, data.Extremum.maximum), (-0.2, data.Extremum.minimum),
         (0.3, data.Extremum.maximum), (0.1, data.Extremum.minimum),
         (0.6, data.Extremum.maximum)])]
    memory = data.preisach_memory(history)
    assert [(p.index, p.value) for p in memory] == [(4, 0.6)]


def test_loop_figures_of_an_ellipse():
    a, b, phi, n = 2.0, 3.0, 0.7, 2000
    t = 2 * np.pi * (np.arange(2 * n) + 0.5) / n
    x, y = a * np.sin(t), b * np.sin(t - phi)
    exact = n / 2 * np.sin(2 * np.pi / n) * a * b * np.sin(phi)
    assert data.loop_area(x[:n], y[:n]) == pytest.approx(exact, rel=1e-12)
    coercive = data.coercive_inputs(x, y)
    assert isinstance(coercive[0], data.LevelCrossing)
    assert coercive[0].value == pytest.approx(a * np.sin(phi), abs=1e-5)
    assert coercive[0].direction == data.Direction.ascending
    assert "ascending" in repr(coercive[0])
    remanent = data.remanent_outputs(x, y, input_level=0.0)
    assert remanent[0].value == pytest.approx(b * np.sin(phi), abs=1e-5)
    assert remanent[0].index == n // 2 - 1
    m = data.loop_metrics(x, y, 0, n - 1)
    assert isinstance(m, data.LoopMetrics)
    assert (m.first, m.last) == (0, n - 1)
    assert m.area == pytest.approx(data.loop_area(x[:n], y[:n]))
    assert m.input_max == pytest.approx(a, abs=1e-5) and m.input_min == pytest.approx(-a, abs=1e-5)
    assert m.output_max == pytest.approx(b, abs=1e-5)
    assert m.output_min == pytest.approx(-b, abs=1e-5)
    assert abs(m.closure_error) < 1e-2 and abs(m.input_mismatch) < 1e-2
    assert len(m.coercive) == 2 and len(m.remanent) == 1


def test_drift_offset_and_resampling():
    v = triangle(10, 3)
    loop = v + 4.0 * (np.diff(v, prepend=v[0]) < 0)
    measured = loop + 0.02 * np.arange(v.size) + 1.5
    metrics = data.cycle_metrics(v, measured, band=1.5)
    assert [m.closure_error for m in metrics] == pytest.approx([0.8] * 3)
    removal = data.remove_drift(v, measured, band=1.5)
    assert isinstance(removal, data.DriftRemoval)
    assert removal.cycles == 3 and removal.closure_error == pytest.approx(2.4)
    np.testing.assert_allclose(removal.output, loop + 1.5, atol=1e-12)
    np.testing.assert_allclose(removal.drift, 0.02 * np.arange(v.size), atol=1e-12)
    values, offset = data.remove_offset(removal.output, reference="first")
    assert offset == 1.5 and values[0] == 0.0
    with pytest.raises(hyst.Error, match="unknown offset reference"):
        data.remove_offset(values, reference="median")

    grid_v, grid_y = data.resample_on_input_grid(v, loop, band=1.5, input_step=5.0)
    assert grid_v[:3] == pytest.approx([0.0, 5.0, 10.0])
    arc_v, arc_y = data.resample_by_arc_length(v, loop, band=1.5, step=0.1)
    assert arc_v.size == arc_y.size and arc_v[0] == 0.0
    kept_v, kept_y, steps = data.preprocess(v, measured, band=1.5, detrend=True, cycles="2-3",
                                            resample="input-grid", resample_step=5.0)
    assert kept_v.size == 17 and len(steps) == 3
    assert steps[1] == "cycles 2-3 of 3 kept (samples 40..120)"


def test_read_aixacct(data_dir):
    export = io.read_aixacct(data_dir / "piezo_pzt_aixacct_butterfly" / "RMN_TRAP_SLOW.dat")
    assert isinstance(export, io.AixacctFile)
    assert export.kind == "PiezoResult" and export.titles == ["Piezo"]
    assert export.header["Program"].startswith("aixPlorer")
    assert export.source.endswith("RMN_TRAP_SLOW.dat")
    assert export.summary.rows == 10 and len(export.measurements) == 10
    table = export.measurement(6)
    assert table.number == 6 and table.first_line == 2325 and table.rows == 401
    assert table.metadata["SampleName"] == "TEST_1400V"
    assert table.metadata_number("Hysteresis Amplitude [V]") == 1400.0
    assert isinstance(table, io.AixacctTable)
    column = table.columns[1]
    assert isinstance(column, io.AixacctColumn)
    assert (column.name, column.unit, column.header) == ("V+", "V", "V+ [V]")
    assert "401 values" in repr(column) and "401 rows" in repr(table)
    np.testing.assert_array_equal(table.column("V+ [V]"), column.values)
    assert table.column("V+").max() == pytest.approx(table.metadata_number("Vmax+ [V]"), abs=0.01)
    columns = table.to_dict()
    assert list(columns)[:2] == ["Time [s]", "V+ [V]"]
    np.testing.assert_array_equal(columns["D1 [nm]"], table.column("D1"))
    with pytest.raises(hyst.Error, match="no measurement table 11"):
        export.measurement(11)
    with pytest.raises(hyst.Error, match=r"s.dat:1: not an aixACCT export"):
        io.parse_aixacct("hello\n", "s.dat")


def test_fit_with_preprocessing(data_dir):
    export = io.read_aixacct(data_dir / "piezo_pzt_aixacct_butterfly" / "RMN_TRAP_SLOW.dat")
    table = export.measurement(6)
    v, d = table.column("V+"), table.column("D1")
    model, report = hyst.fit("pi", v, d, detrend=True, cycles="1", resample="input-grid",
                             resample_step=20.0, band=0.0, operators=8)
    assert len(report.preprocessing) == 3
    assert report.preprocessing[0].startswith("linear drift removed")
    assert "Preprocessing:" in report.brief()
    _, plain = hyst.fit("pi", v, d, operators=8)
    assert plain.preprocessing == []
    with pytest.raises(hyst.Error, match="cycles 2 requested"):
        hyst.fit("pi", v, d, cycles="2")


def test_detrend_reaches_the_validation_record(data_dir):
    export = io.read_aixacct(data_dir / "piezo_pzt_aixacct_butterfly" / "RMN_TRAP_SLOW.dat")
    v, p = export.measurement(6).column("V+"), export.measurement(6).column("P1")
    v5, p5 = export.measurement(5).column("V+"), export.measurement(5).column("P1")
    _, report = hyst.fit("pi", v, p, v5, p5, detrend=True, resample="input-grid", operators=8)
    assert report.validation.samples == 401  # resampling is for the fit record only
    assert report.preprocessing[0].startswith("fit record: linear drift removed")
    assert report.preprocessing[1].startswith("fit record: resampled per branch")
    assert report.preprocessing[2].startswith("validation record: linear drift removed between 2")
    # The same as removing the drift by hand with each record's default band.
    fit_p = data.remove_drift(v, p, data.default_band(v)).output
    fit_v, fit_p, _ = data.preprocess(v, fit_p, resample="input-grid")
    by_hand = data.remove_drift(v5, p5, data.default_band(v5)).output
    _, manual = hyst.fit("pi", fit_v, fit_p, v5, by_hand, operators=8)
    assert manual.preprocessing == []
    assert report.validation.nrmse_percent == pytest.approx(manual.validation.nrmse_percent, rel=1e-12)
    assert report.fit.nrmse_percent == pytest.approx(manual.fit.nrmse_percent, rel=1e-12)
    _, raw = hyst.fit("pi", fit_v, fit_p, v5, p5, operators=8)
    assert raw.validation.nrmse_percent != pytest.approx(manual.validation.nrmse_percent, rel=1e-3)


def test_backbone_of_an_ellipse():
    a, b, phi, n = 2.0, 3.0, 0.7, 4000
    t = 2 * np.pi * np.arange(n + 1) / n
    x, y = a * np.sin(t), b * np.sin(t - phi)
    bone = data.backbone(x, y, band=0.1, first=0, last=n, points=21)
    assert isinstance(bone, data.Backbone) and bone.input.size == 21
    inner = np.abs(bone.input) < 0.95 * a
    np.testing.assert_allclose(bone.centre[inner], b / a * np.cos(phi) * bone.input[inner],
                               atol=1e-5)
    np.testing.assert_allclose(
        bone.half_width[inner], b * np.sin(phi) * np.sqrt(1 - bone.input[inner] ** 2 / a**2),
        atol=1e-5)
    np.testing.assert_allclose(bone.descending - bone.ascending, 2 * bone.half_width, atol=1e-12)


def cli_output(*args):
    """stdout of the hyst command line program ($HYST_CLI, else build/apps/hyst next to the
    module); the test is skipped without it."""
    program = Path(os.environ.get("HYST_CLI", Path(hyst.__file__).parents[1] / "apps" / "hyst"))
    if not program.is_file():
        pytest.skip(f"hyst command line program not found at {program}")
    return subprocess.run([str(program), *map(str, args)], check=True, capture_output=True,
                          text=True).stdout


def test_info_is_the_cli_json(data_dir):
    path = data_dir / "piezo_pzt_aixacct_butterfly" / "RMN_TRAP_SLOW.dat"
    assert hyst.read_aixacct is io.read_aixacct
    everything = data.info(path)
    assert everything == json.loads(cli_output("data", "info", path, "--json"))
    assert [t["table"] for t in everything["tables"]] == ["summary"] + [
        f"table {n}" for n in range(1, 11)]
    assert everything["format"] == ("aixACCT export (PiezoResult), a summary table and 10 "
                                    "measurement tables")
    one = data.info(path, table=6, band_fraction=0.05, loop=("V+", "P1 [uC/cm2]"))
    assert one == json.loads(cli_output("data", "info", path, "--table", 6, "--band-fraction",
                                        0.05, "--loop", "V+,P1 [uC/cm2]", "--json"))
    # Known values: the file's own metadata (Vmax+, Vmax-, Wloss, Vc+, Vc-) and one triangle
    # period of the voltage (a maximum and a minimum, one cycle).
    table = io.read_aixacct(path).measurement(6)
    (entry,) = one["tables"]
    assert entry["table"] == "table 6" and entry["metadata"]["SampleName"] == "TEST_1400V"
    voltage = next(c for c in entry["columns"] if c["name"] == "V+")
    assert (voltage["unit"], voltage["samples"], voltage["reversals"], voltage["cycles"]) == (
        "V", 401, 2, 1)
    # The metadata holds 6 significant digits.
    assert voltage["max"] == pytest.approx(table.metadata_number("Vmax+ [V]"), abs=0.005)
    assert voltage["min"] == pytest.approx(table.metadata_number("Vmax- [V]"), abs=0.005)
    (loop,) = entry["loops"]
    assert loop["area"] == pytest.approx(table.metadata_number("Wloss [uJ/cm2]"), abs=0.05)
    up, down = loop["coercive_inputs"]
    assert up["direction"] == "ascending" and down["direction"] == "descending"
    assert up["value"] == pytest.approx(table.metadata_number("Vc+ [V]"), abs=0.005)
    assert down["value"] == pytest.approx(table.metadata_number("Vc- [V]"), abs=0.005)
    constant = next(c for c in entry["columns"] if c["name"] == "V-")
    assert constant["reversals"] is None and constant["cycles"] is None


def test_info_of_csv_and_errors(tmp_path):
    v = triangle(10, 2)
    io.write_csv(tmp_path / "t.csv", {"v": v, "y": 2 * v})
    info = data.info(tmp_path / "t.csv", band_fraction=0.1, loop=["v", "y"])
    assert info == json.loads(cli_output("data", "info", tmp_path / "t.csv", "--band-fraction",
                                         0.1, "--loop", "v,y", "--json"))
    assert info["format"] == "CSV, 2 columns"
    (table,) = info["tables"]
    assert [(c["name"], c["min"], c["max"], c["reversals"], c["cycles"]) for c in
            table["columns"]] == [("v", -10.0, 10.0, 4, 2), ("y", -20.0, 20.0, 4, 2)]
    # y = 2 v encloses no area; the loop passes (0, 0) twice per period.
    assert [(m["first"], m["last"], m["area"]) for m in table["loops"]] == [(0, 40, 0.0),
                                                                            (40, 80, 0.0)]
    with pytest.raises(hyst.Error, match="band fraction 1 must be > 0 and < 1"):
        data.info(tmp_path / "t.csv", band_fraction=1.0)
    with pytest.raises(hyst.Error, match=r"t.csv: --table \(Python: table=\) chooses a table"):
        data.info(tmp_path / "t.csv", table=2)


def test_info_with_a_time_column(tmp_path):
    # The triangle at 0.25 s per sample (steps of 1): rate 4 per s, the longest run between
    # reversals 20 samples = 5 s; the same as the command line's.
    v = triangle(10, 2)
    io.write_csv(tmp_path / "t.csv", {"t": 0.25 * np.arange(len(v)), "v": v})
    info = data.info(tmp_path / "t.csv", time="t")
    assert info == json.loads(cli_output("data", "info", tmp_path / "t.csv", "--time", "t",
                                         "--json"))
    (table,) = info["tables"]
    assert table["time"] == {"column": "t", "uniform": True, "sample_time": 0.25,
                             "min_step": 0.25, "max_step": 0.25, "duration": 20.0}
    v_info = table["columns"][1]
    assert v_info["largest_rate"] == pytest.approx(4.0)
    assert v_info["longest_run"] == pytest.approx(5.0)
    assert "time" not in data.info(tmp_path / "t.csv")["tables"][0]
    with pytest.raises(hyst.Error, match="no table has the time column 'x'"):
        data.info(tmp_path / "t.csv", time="x")


def test_extract_like_the_cli(data_dir, tmp_path):
    path = data_dir / "piezo_pzt_aixacct_butterfly" / "RMN_TRAP_SLOW.dat"
    columns = data.extract(path, ["V+", "P1 [uC/cm2]"], table=6, out=tmp_path / "py.csv")
    assert list(columns) == ["V+", "P1 [uC/cm2]"]
    table = io.read_aixacct(path).measurement(6)
    np.testing.assert_array_equal(columns["V+"], table.column("V+"))
    np.testing.assert_array_equal(columns["P1 [uC/cm2]"], table.column("P1"))
    cli_output("data", "extract", path, "--table", 6, "--columns", "V+,P1 [uC/cm2]", "--out",
               tmp_path / "cli.csv")
    assert (tmp_path / "py.csv").read_bytes() == (tmp_path / "cli.csv").read_bytes()
    written = io.read_csv(tmp_path / "py.csv")
    np.testing.assert_array_equal(written["V+"], columns["V+"])
    assert sorted(p.name for p in tmp_path.iterdir()) == ["cli.csv", "py.csv"]  # no temp files

    io.write_csv(tmp_path / "t.csv", {"a": [1.0, 2.0], "b": [3.0, 4.0]})
    both = data.extract(tmp_path / "t.csv")
    assert list(both) == ["a", "b"] and both["b"].tolist() == [3.0, 4.0]
    with pytest.raises(hyst.Error, match="10 measurement tables; choose one with --table N"):
        data.extract(path, ["V+"])
    with pytest.raises(hyst.Error, match="table 6: no column 'V9'"):
        data.extract(path, ["V9"], table=6)
