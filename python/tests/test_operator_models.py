"""Ikuta's SMA model, Krasnosel'skii-Pokrovskii, Maxwell-slip, modified PI and rate-dependent PI
through the registry: hyst.Model and hyst.fit by name."""

import numpy as np
import pytest

import hyst

IKUTA = {"martensite_finish": 0.0, "martensite_start": 1.0, "austenite_start": 2.0,
         "austenite_finish": 3.0, "output_austenite": 0.0, "output_martensite": 1.0}
MODIFIED_PI = {"thresholds": [0.0, 0.3, 0.7, 1.0], "weights": [0.8, 0.5, 0.3, 0.2],
               "dead_zone_thresholds": [-1.5, -0.8, -0.3, 0.0, 0.4, 0.9, 1.6],
               "dead_zone_weights": [0.05, 0.1, 0.2, 1.0, -0.15, -0.2, -0.1], "offset": 0.2}


def decaying(amplitude=1.2, samples=2000):
    grid = hyst.signals.TimeGrid(samples, 1e-3)
    return hyst.signals.generate(
        grid, hyst.signals.DecayingSine(amplitude=amplitude, frequency=8.0, time_constant=0.7))


def test_ikuta_has_no_return_point_memory():
    model = hyst.Model("ikuta_sma", IKUTA)
    # Heat to 2.5 (fraction 0.5), cool to 0.5 (0.75), heat to 2.5 again: 0.375, not 0.5.
    y, state = model.simulate([1.0, 2.5, 1.5, 0.5, 1.5, 2.5], return_state=True)
    np.testing.assert_allclose(y[[1, 3, 5]], [0.5, 0.75, 0.375], atol=1e-15)
    assert state["branch"] == "heating"
    assert not model.has_inverse()
    with pytest.raises(hyst.Error, match="not invertible"):
        model.inverse()
    with pytest.raises(hyst.Error, match="austenite_finish A_f = 2 must be > austenite_start"):
        hyst.Model("ikuta_sma", dict(IKUTA, austenite_finish=2.0))


def test_kp_fit_recovers_its_own_output():
    levels = 5
    weights = [0.05 + 0.01 * (r % 4) for r in range(levels * (levels + 1) // 2)]
    truth = hyst.Model("kp", {"levels": levels, "lower": -1.0, "upper": 1.0, "weights": weights})
    v = decaying()
    y = truth.simulate(v)
    fitted, report = hyst.fit("kp", v, y, levels=levels, lower=-1.0, upper=1.0)
    assert fitted.name == "kp" and report.fit.rmse < 1e-9
    np.testing.assert_allclose(fitted.simulate(v), y, atol=1e-9)


def test_maxwell_slip_inverse_and_fit():
    params = {"stiffness": [3.0, 2.0, 1.0], "break_away": [0.3, 0.4, 0.5],
              "linear_stiffness": 0.5}
    model = hyst.Model("maxwell_slip", params)
    x = decaying()
    force = model.simulate(x)
    model.reset()
    x_back, report = model.inverse().invert(force)
    assert report.ok
    np.testing.assert_allclose(x_back, x, atol=1e-12)
    fitted, fit_report = hyst.fit("maxwell_slip", x, force, x, force, elements=12)
    assert fit_report.validation.nrmse_percent < 2
    assert fitted.params["linear_stiffness"] > 0
    saturating = hyst.Model("maxwell_slip", dict(params, linear_stiffness=0.0))
    assert not saturating.has_inverse()


def test_modified_pi_inverse_round_trip_and_fit():
    model = hyst.Model("modified_pi", MODIFIED_PI)
    v = decaying(amplitude=2.0)
    y = model.simulate(v)
    model.reset()
    v_back, report = model.inverse().invert(y)
    assert report.ok
    np.testing.assert_allclose(v_back, v, atol=1e-12)
    fitted, fit_report = hyst.fit("modified_pi", v, y, operators=8, dead_zones=3)
    assert fitted.has_inverse() and fit_report.fit.nrmse_percent < 2
    # One period of a periodic excitation: the fitted model starts in the periodic state.
    period = np.sin(2 * np.pi * np.arange(500) / 500) * 1.5
    model.reset()
    _, after_one_period = model.simulate(period, return_state=True)
    steady = model.simulate(period, state=after_one_period)
    periodic, periodic_report = hyst.fit("modified_pi", period, steady, operators=8,
                                         initial_state="periodic")
    assert periodic_report.fit.nrmse_percent < 2
    assert periodic.state["play"] != [0.0] * 8
    with pytest.raises(hyst.Error, match=r"params.dead_zone_thresholds"):
        hyst.Model("modified_pi", dict(MODIFIED_PI, dead_zone_thresholds=[-1, 0.5, 0, 1, 2, 3, 4]))


def test_rate_dependent_pi_loops_widen_with_frequency():
    params = {"thresholds": [0.0, 0.2, 0.4, 0.6], "weights": [1.0, 0.6, 0.4, 0.2],
              "rate_gain": 0.01, "sample_time": 1e-4}
    areas = []
    for frequency in (0.5, 5.0, 20.0):
        samples = int(round(3 / (frequency * 1e-4)))
        v = np.sin(2 * np.pi * frequency * 1e-4 * np.arange(samples + 1))
        y = hyst.Model("rate_dependent_pi", params).simulate(v)
        period = int(round(1 / (frequency * 1e-4)))
        vl, yl = v[-period - 1:], y[-period - 1:]
        areas.append(abs(np.sum(vl[:-1] * yl[1:] - vl[1:] * yl[:-1])) / 2)
    assert areas[0] < areas[1] < areas[2]
    # Weights by NNLS for the known rate gain, from the highest-frequency record.
    fitted, report = hyst.fit("rate_dependent_pi", v, y, thresholds=params["thresholds"],
                              rate_gain=0.01, sample_time=1e-4)
    assert report.fit.rmse < 1e-9
    np.testing.assert_allclose(fitted.params["weights"], params["weights"], atol=1e-7)
    classical = hyst.Model("pi", {"thresholds": params["thresholds"], "weights": params["weights"]})
    v = decaying()
    np.testing.assert_allclose(
        hyst.Model("rate_dependent_pi", dict(params, rate_gain=0.0)).simulate(v),
        classical.simulate(v), atol=1e-12)
