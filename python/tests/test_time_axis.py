"""A record's time axis from Python: models with time in them re-discretised at the record's
step (Model.simulate(sample_time=/time=), hyst.evaluate, hyst.fit(time=)), rate-independent
models unchanged, a NARX held to its own sample time."""

import numpy as np
import pytest

import hyst

CREEP = {"thresholds": [0.0, 0.5], "weights": [1.0, 0.5], "time_constants": [0.05, 0.3],
         "creep_weights": [0.2, 0.1, 0.1, 0.05], "sample_time": 0.01}


def staircase(samples_per_level: int, levels: int = 12) -> np.ndarray:
    return np.repeat(np.array([(k % 4) - 1.5 for k in range(levels)]), samples_per_level)


def test_time_dependence_and_sample_time_of_models():
    creep = hyst.Model("pi_creep", CREEP)
    assert creep.time_dependence == "continuous" and creep.sample_time == 0.01
    pi = hyst.Model("pi", {"thresholds": [0.0, 0.5], "weights": [1.0, 0.5]})
    assert pi.time_dependence == "none" and pi.sample_time is None
    slower = creep.at_sample_time(0.1)
    assert slower.sample_time == 0.1 and slower.params["time_constants"] == [0.05, 0.3]
    assert creep.sample_time == 0.01  # unchanged


def test_the_same_physical_prediction_at_a_ten_times_coarser_step():
    creep = hyst.Model("pi_creep", CREEP)
    fine = creep.simulate(staircase(50))                       # 10 ms, the model's own
    coarse = creep.simulate(staircase(5), sample_time=0.1)     # 100 ms
    np.testing.assert_allclose(coarse, fine[9::10], rtol=0, atol=1e-12)
    times = 0.1 * np.arange(60)
    np.testing.assert_array_equal(creep.simulate(staircase(5), time=times), coarse)
    # Without a time axis the coarse samples are taken as 10 ms apart: another output.
    assert np.max(np.abs(creep.simulate(staircase(5)) - fine[9::10])) > 1e-2


def test_a_non_uniform_time_axis_is_stepped_run_by_run():
    creep = hyst.Model("pi_creep", CREEP)
    v = staircase(5, 4)
    times = np.concatenate([0.01 * np.arange(10), 0.09 + 0.1 * np.arange(1, 11)])
    stepped = creep.simulate(v, time=times)
    first, state = creep.simulate(v[:10], sample_time=0.01, return_state=True)
    second = creep.at_sample_time(0.1).simulate(v[10:], state=state)
    np.testing.assert_array_equal(stepped, np.concatenate([first, second]))
    with pytest.raises(hyst.Error, match="not uniform"):
        hyst.evaluate(creep, v, stepped, time=times)


def test_a_rate_independent_model_ignores_time():
    pi = hyst.Model("pi", {"thresholds": [0.0, 0.5], "weights": [1.0, 0.5]})
    v = staircase(3)
    np.testing.assert_array_equal(pi.simulate(v, sample_time=7.0), pi.simulate(v))


def test_evaluate_runs_at_the_records_step_and_says_so():
    creep = hyst.Model("pi_creep", CREEP)
    v = staircase(5)
    y = creep.simulate(v, sample_time=0.1)
    result = hyst.evaluate(creep, v, y, sample_time=0.1)
    assert result["rmse"] < 1e-12
    assert result["sample_time"] == 0.1 and result["time_dependence"] == "continuous"
    assert hyst.evaluate(creep, v, y)["rmse"] > 1e-3


def test_fit_takes_the_sample_time_from_a_time_column():
    creep = hyst.Model("pi_creep", CREEP)
    v = staircase(50)
    times = 0.01 * np.arange(v.size)
    y = creep.simulate(v)
    fitted = hyst.fit("pi_creep", v, y, time=times, time_constants=[0.05, 0.3])
    assert fitted.model.sample_time == pytest.approx(0.01)
    assert fitted.report.domain.sample_time == pytest.approx(0.01)
    with pytest.raises(hyst.Error, match="both give the sample time"):
        hyst.fit("pi_creep", v, y, time=times, sample_time=0.01)
    with pytest.raises(hyst.Error, match="has no sample time"):
        hyst.fit("pi", v, y, time=times)
    with pytest.raises(hyst.Error, match="not uniform"):
        hyst.fit("pi_creep", v, y, time=times ** 2)


def test_data_sample_time_of_a_time_column():
    assert hyst.data.sample_time([0.0, 0.25, 0.5, 0.75]) == pytest.approx(0.25)
    with pytest.raises(hyst.Error, match="not uniform"):
        hyst.data.sample_time([0.0, 0.1, 0.3])


def test_a_narx_runs_at_its_own_sample_time_only():
    params = dict(hyst.model_entry("narx").example_params, sample_time=0.01)
    narx = hyst.Model("narx", params)
    assert narx.time_dependence == "discrete" and narx.sample_time == 0.01
    v = staircase(5)
    narx.simulate(v, sample_time=0.01)
    with pytest.raises(hyst.Error, match=r"identified at the sample time 0.01 s .* 0.1 s"):
        narx.simulate(v, sample_time=0.1)
    with pytest.raises(hyst.Error, match="sample_time or time, not both"):
        narx.simulate(v, sample_time=0.01, time=0.01 * np.arange(v.size))


def test_the_fitted_domain_knows_rates_holds_and_the_slowest_lag(tmp_path):
    creep = hyst.Model("pi_creep", CREEP)
    v = staircase(50)
    times = 0.01 * np.arange(v.size)
    fitted = hyst.fit("pi_creep", v, creep.simulate(v), time=times, time_constants=[0.05, 0.3])
    domain = fitted.report.domain
    assert domain.largest_time_constant == pytest.approx(0.3)
    assert domain.duration == pytest.approx(6.0)
    assert domain.largest_input_rate == pytest.approx(300.0)   # 1.5 to -1.5 in 10 ms
    assert domain.longest_hold == pytest.approx(2.0)            # 3 steps up and a level: 2 s
    inside, message = domain.check_timing(v)
    assert inside and message == ""
    long_holds = staircase(400)                                  # levels of 4 s
    inside, message = domain.check_timing(long_holds, sample_time=0.01)
    assert not inside and "longer than the longest fitted one (2 s)" in message
    path = tmp_path / "creep.json"
    hyst.save_model(path, fitted.model)
    assert hyst.load_fitted_domain(path) is None   # no info.domain
    hyst.save_model(path, fitted.model, {"domain": {
        "input_min": -1.5, "input_max": 1.5, "output_min": -3.0, "output_max": 3.0,
        "samples": 600, "largest_input_step": 1.0, "longest_hold_samples": 200,
        "sample_time": 0.01, "largest_time_constant": 0.3}})
    read = hyst.load_fitted_domain(path)
    assert read.longest_hold == pytest.approx(2.0) and read.largest_time_constant == 0.3
    result = hyst.evaluate(fitted.model, long_holds, creep.simulate(long_holds), domain=domain)
    assert result["domain"]["inside"] is False and "holds" in result["domain"]["message"]
    assert hyst.evaluate(fitted.model, v, creep.simulate(v))["domain"] is None


def test_leakage_and_the_logarithmic_law_from_python():
    leaky = dict(CREEP, leakage_conductance=0.004, leakage_current=-0.002)
    model = hyst.Model("pi_creep", leaky)
    v = staircase(500)
    times = np.arange(v.size) * 0.01
    y = model.simulate(v)
    fitted = hyst.fit("pi_creep", v, y, time=times, thresholds=[0.0, 0.5],
                      time_constants=[0.05, 0.3], fit_leakage=True)
    assert fitted.model.params["leakage_conductance"] == pytest.approx(0.004, abs=1e-8)
    assert fitted.model.params["leakage_current"] == pytest.approx(-0.002, abs=1e-8)
    law = hyst.fit("pi_creep", v, y, time=times, creep_law="logarithmic")
    assert "logarithmic creep law" in law.report.method
    assert law.model.params["time_constants"][-1] == pytest.approx(1e5)
    with pytest.raises(hyst.Error, match="expected free or logarithmic"):
        hyst.fit("pi_creep", v, y, time=times, creep_law="log")


def test_butterfly_strain_with_creep_from_python():
    # The butterfly example's switching and map with one lag of 0.05 s on v: after a step to
    # positive saturation the polarisation grows by 0.2 (1 - exp(-t / 0.05)) (hand calculation).
    params = {"levels": 3, "lower": -1.0, "upper": 1.0,
              "weights": [0.1, 0.0, 0.1, 0.7, 0.0, 0.1], "field_coefficient": 0.0,
              "polarisation_coefficients": [1.0, 0.3], "creep_thresholds": [0.0],
              "time_constants": [0.05], "creep_weights": [0.2], "sample_time": 0.01}
    model = hyst.Model("butterfly_strain_creep", params)
    y = model.simulate(np.ones(20))
    P = 1.0 + 0.2 * (1.0 - np.exp(-np.arange(1, 21) * 0.01 / 0.05))
    np.testing.assert_allclose(y, P + 0.3 * P**2, rtol=0, atol=1e-13)
    v = staircase(300)
    times = np.arange(v.size) * 0.01
    fitted = hyst.fit("butterfly_strain_creep", v, model.simulate(v), time=times, levels=3, lower=-1.0, upper=1.0,
                      initial_state="negative_saturation", creep_thresholds=[0.0],
                      time_constants=[0.05])
    assert fitted.model.params["sample_time"] == pytest.approx(0.01)
    assert fitted.report.fit.nrmse_percent < 5.0
    with pytest.raises(hyst.Error, match="rounds = 0"):
        hyst.fit("butterfly_strain_creep", v, v, time=times, rounds=0)
