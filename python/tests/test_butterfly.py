"""Butterfly strain: the fits beyond hyst.fit (several records, measured polarisation) and the
inverse that says where it does not exist."""

import numpy as np
import pytest

import hyst


def _butterfly_model():
    """Three levels on [-1, 1], P switching at +-2/3, y = P^2: a butterfly."""
    return hyst.Model("butterfly_strain", {
        "levels": 3, "lower": -1.0, "upper": 1.0, "weights": [0.1, 0.0, 0.1, 0.7, 0.0, 0.1],
        "polarisation_coefficients": [0.0, 1.0]})


def test_model_draws_a_butterfly_by_hand():
    model = _butterfly_model()
    # From negative saturation: P = -0.6 at 0, +1 at 1, 0.8 back at 0, -1 at -1 (y = P^2).
    y = model.simulate(np.array([0.0, 1.0, 0.0, -1.0]))
    np.testing.assert_allclose(y, [0.36, 1.0, 0.64, 1.0], atol=1e-15)


def test_inverse_reports_samples_that_are_not_invertible():
    model = _butterfly_model()
    inverse = model.inverse(input_min=-1.0, input_max=1.0)
    inputs, report = inverse.invert(np.array([0.5, 0.5, 0.5]))
    # Over [-1, 1] P can cross the vertex P* = 0: no unique input, none invented.
    assert report.not_invertible_samples == 3
    assert report.first_not_invertible == 0
    assert not report.ok
    # The status each such sample carries, as the C++ inverse gives it.
    assert hyst.InverseStatus.not_invertible.name == "not_invertible"


def _equal_weight_grid(levels):
    """A relay grid on [-1, 1] with equal weights summing to 1 (model-file parameters)."""
    relays = levels * (levels + 1) // 2
    return {"levels": levels, "lower": -1.0, "upper": 1.0,
            "weights": list(np.full(relays, 1.0 / relays))}


def _two_stage_record(levels=8):
    grid = np.linspace(-1, 1, 200)
    v = np.concatenate([grid, grid[::-1]])
    truth = hyst.Model("butterfly_strain", {
        **_equal_weight_grid(levels),
        "field_coefficient": 0.5, "polarisation_coefficients": [0.3, 1.2], "offset": 2.0})
    y = truth.simulate(v)
    return v, y, truth


def test_two_stage_fit_recovers_a_generated_map():
    v, y, _ = _two_stage_record()
    # The polarisation of the generating relays, computed independently as a Preisach model.
    levels = 8
    preisach = hyst.Model("preisach", _equal_weight_grid(levels))
    P = preisach.simulate(v)
    np.testing.assert_allclose(y, 2.0 + 0.5 * v + 0.3 * P + 1.2 * P**2, atol=1e-12)
    model, report, p_report, map_report, g = hyst.fit_butterfly_strain_with_polarisation(
        v, P, y, levels=8, lower=-1.0, upper=1.0, initial_state="negative_saturation")
    assert g == 0.0
    assert p_report.fit.rmse < 1e-9
    assert map_report.fit.rmse < 1e-9
    assert report.fit.rmse < 1e-8
    assert model.params["polarisation_coefficients"] == pytest.approx([0.3, 1.2], abs=1e-8)


def test_two_stage_fit_separates_a_leakage_charge():
    v, y, _ = _two_stage_record()
    levels = 8
    preisach = hyst.Model("preisach", _equal_weight_grid(levels))
    ts, g = 0.01, 0.05
    charge = hyst.data.leakage_charge(v, ts)
    # The trapezoidal integral, by hand for the first samples of the ramp.
    assert charge[1] == pytest.approx(0.5 * ts * (v[0] + v[1]), abs=1e-15)
    measured = preisach.simulate(v) + g * charge
    np.testing.assert_allclose(hyst.data.remove_leakage_charge(v, measured, ts, g),
                               measured - g * charge, atol=1e-15)
    _, report, p_report, map_report, fitted_g = hyst.fit_butterfly_strain_with_polarisation(
        v, measured, y, levels=8, lower=-1.0, upper=1.0, initial_state="negative_saturation",
        fit_leakage=True, sample_time=ts)
    assert fitted_g == pytest.approx(g, rel=1e-8)
    assert map_report.fit.rmse < 1e-8
    assert report.fit.rmse < 1e-8
    # 1 V across 100 MOhm on 100 mm^2: 10 nA, 0.01 uC/cm^2 each second.
    assert hyst.data.leakage_conductance(1e8, 100.0) == pytest.approx(0.01, rel=1e-15)


def test_two_stage_fits_name_the_model_report():
    v, y, _ = _two_stage_record()
    P = hyst.Model("preisach", _equal_weight_grid(8)).simulate(v)
    fitted = hyst.fit_butterfly_strain_with_polarisation(
        v, P, y, levels=8, lower=-1.0, upper=1.0, initial_state="negative_saturation")
    assert fitted.report is fitted[1] and fitted.model.name == "butterfly_strain"
    # With creep: the polarisation is matched by relays and lags, the map by the relays alone.
    creep = hyst.fit_butterfly_strain_creep_with_polarisation(
        v, P, y, levels=8, lower=-1.0, upper=1.0, initial_state="negative_saturation",
        sample_time=0.01, creep_law="free", lags=2, validate_fraction=0.25)
    model, report, p_report = creep
    assert creep.report is report and model.name == "butterfly_strain_creep"
    assert p_report.fit.rmse < 1e-6 and report.fit.rmse < 1e-5
    assert report.validation is not None and report.validation.samples == len(v) // 4
    with pytest.raises(hyst.Error, match="needs the measured polarisation"):
        hyst.fit("butterfly_strain_creep", v, y, sample_time=0.01, fit_leakage=True)


def test_records_fit_shares_one_model_and_names_bad_records():
    v, y, _ = _two_stage_record()
    model, report = hyst.fit_butterfly_strain_records([(v, y), (0.8 * v, y)], levels=6)
    assert report.fit.samples == 2 * len(v)
    assert model.name == "butterfly_strain"
    with pytest.raises(hyst.Error, match=r"records\[1\]"):
        hyst.fit_butterfly_strain_records([(v, y), (v,)])
