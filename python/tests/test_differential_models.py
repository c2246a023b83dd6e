"""The differential models by name: Bouc-Wen, the Bouc-Wen oscillator, Duhem, backlash-like and
Jiles-Atherton, simulated, inverted and fitted through hyst.Model / hyst.fit."""

import math

import numpy as np
import pytest
from conftest import shared_data_dir

import hyst

DATA = shared_data_dir()


def test_backlash_like_matches_reference_check():
    # duhem_bw_check.py: a=3, c=1.2, B1=0.4, v = 3 sin(2 pi k / 4000): w at sample 1000 = 3.333366.
    model = hyst.Model("backlash_like", {"a": 3.0, "c": 1.2, "b1": 0.4})
    v = 3.0 * np.sin(2 * np.pi * np.arange(1, 1001) / 4000.0)
    assert model.simulate(v)[-1] == pytest.approx(3.333366, abs=5e-7)


def test_bouc_wen_reference_values_and_inverse():
    model = hyst.Model("bouc_wen", {"a": 1.0, "beta": 0.6, "gamma": 0.2, "n": 1.5,
                                    "stiffness": 1.0, "alpha_k": 0.0})
    k = np.arange(3000)
    x = 2.5 * np.sin(2 * np.pi * k / 1000.0) * (1 - k / 4000.0)
    z = model.simulate(x)
    assert z[250] == pytest.approx(1.080417782, abs=1e-9)
    model = hyst.Model("bouc_wen", hyst.model_entry("bouc_wen").example_params)
    y = model.simulate(x[:500])
    model.reset()
    u, report = model.inverse(-10.0, 10.0).invert(y)
    assert report.ok
    assert np.abs(u - x[:500]).max() < 1e-6


def test_jiles_atherton_fit_recovers_simulated_loop():
    params = {"ms": 1.2e6, "a": 300.0, "k": 200.0, "c": 0.3, "alpha": 4e-4,
              "variant": "venkataraman"}
    model = hyst.Model("jiles_atherton", params)
    h = 3000.0 * np.sin(2 * np.pi * np.arange(400) / 200.0)
    b = model.simulate(h)
    fitted, report = hyst.fit("jiles_atherton", h, b, variant="venkataraman")
    assert report.fit.nrmse_percent < 0.1
    assert fitted.params["variant"] == "venkataraman"


def test_bouc_wen_oscillator_has_no_inverse_and_fits_by_name():
    entry = hyst.model_entry("bouc_wen_oscillator")
    model = hyst.Model("bouc_wen_oscillator", entry.example_params)
    assert not model.has_inverse()
    t = np.arange(1500) / 750.0
    u = 40 * np.sin(2 * np.pi * 12 * t) + 25 * np.sin(2 * np.pi * 31 * t + 1)
    y = model.simulate(u)
    fitted, report = hyst.fit("bouc_wen_oscillator", u, y, max_iterations=40)
    assert report.fit.nrmse_percent < 0.5
    assert fitted.params["mass"] == pytest.approx(2.0, rel=0.05)


@pytest.mark.skipif(not (DATA / "bh_loops_jamodel").exists(), reason="no shared data")
def test_read_mat_columns_gives_one_loop_per_column():
    columns = hyst.io.read_mat_columns(DATA / "bh_loops_jamodel" / "H_MnZn_ferrite.mat", "HmeasT")
    assert len(columns) == 4
    assert all(len(c) == 129 for c in columns)
    assert math.isclose(max(columns[3]), 79.85, abs_tol=0.01)
