"""hyst.io: CSV and MAT files, round trips and error messages."""

import numpy as np
import pytest

import hyst
from hyst import io


def test_csv_round_trip_is_exact(tmp_path):
    rng = np.random.default_rng(3)
    columns = {"t": np.arange(50) * 1e-3, "v": rng.standard_normal(50), "y": rng.random(50) / 3}
    path = tmp_path / "data.csv"
    io.write_csv(path, columns)
    table = io.read_csv(path)
    assert list(table) == ["t", "v", "y"]  # file order
    for name, values in columns.items():
        assert table[name].dtype == np.float64 and table[name].flags.writeable
        np.testing.assert_array_equal(table[name], values)
    io.write_csv(str(path), {"a": [1.0, 2.0]}, separator=";", significant_digits=3)
    assert path.read_text() == "a\n1\n2\n"


def test_csv_parse_and_format():
    text = "# comment\nv;y\n1;2\n3;4.5\n"
    table = io.parse_csv(text, "inline.csv")
    np.testing.assert_array_equal(table["y"], [2.0, 4.5])
    assert io.format_csv({"v": [1.0, 3.0]}) == "v\n1\n3\n"
    assert io.parse_csv("a b\n1 2\n", separator=" ")["b"][0] == 2.0


def test_csv_errors_name_file_line_and_column(tmp_path):
    with pytest.raises(hyst.Error, match=r"inline.csv:3: column 2 \('y'\): 'abc' is not a number"):
        io.parse_csv("v,y\n1,2\n3,abc\n", "inline.csv")
    with pytest.raises(hyst.Error, match="cannot open"):
        io.read_csv(tmp_path / "missing.csv")
    with pytest.raises(hyst.Error, match="single character"):
        io.read_csv(tmp_path / "x.csv", separator=";;")
    with pytest.raises(hyst.Error):
        io.write_csv(tmp_path / "bad.csv", {"v": [1.0, float("nan")]})
    with pytest.raises(hyst.Error):
        io.write_csv(tmp_path / "bad.csv", {"v": [1.0], "w": [1.0, 2.0]})


def test_mat_round_trip_is_exact(tmp_path):
    rng = np.random.default_rng(5)
    variables = {"voltage": rng.standard_normal(30), "displacement": rng.standard_normal(30)}
    for version in ("v5", "v7.3"):
        path = tmp_path / f"data_{version}.mat"
        io.write_mat_vectors(path, variables, version)
        names = io.list_mat_variables(path)
        if version == "v5":
            assert names == ["voltage", "displacement"]  # file order
        else:
            assert sorted(names) == ["displacement", "voltage"]  # HDF5 lists by name
        for name, values in variables.items():
            np.testing.assert_array_equal(io.read_mat_vector(path, name), values)
    # (name, values) pairs work as well.
    io.write_mat_vectors(tmp_path / "pairs.mat", [("x", [1.0, 2.0])])
    np.testing.assert_array_equal(io.read_mat_vector(tmp_path / "pairs.mat", "x"), [1.0, 2.0])


def test_mat_errors(tmp_path):
    path = tmp_path / "a.mat"
    io.write_mat_vectors(path, {"a": [1.0]})
    with pytest.raises(hyst.Error, match=r"no variable 'x' \(variables: a\)"):
        io.read_mat_vector(path, "x")
    with pytest.raises(hyst.Error):
        io.write_mat_vectors(tmp_path / "b.mat", {"1bad": [1.0]})
    with pytest.raises(hyst.Error):
        io.write_mat_vectors(tmp_path / "c.mat", {"a": [1.0]}, "v6")
    with pytest.raises(hyst.Error):
        io.list_mat_variables(tmp_path / "missing.mat")


def test_measured_piezo_data(data_dir):
    path = data_dir / "piezo_pzt_aixacct_butterfly" / "MeasurementData.mat"
    names = io.list_mat_variables(path)
    assert "Vplus_19kv" in names and "Displacement_19kv" in names
    voltage = io.read_mat_vector(path, "Vplus_19kv")
    assert voltage.shape == (401,) and 1800 < voltage.max() < 2000
