"""Identification: the PI fitter recovers known weights; reports, metrics and splits."""

import numpy as np
import pytest

import hyst

THRESHOLDS = [0.0, 0.2, 0.4, 0.6, 0.8]
WEIGHTS = [0.9, 0.4, 0.3, 0.2, 0.1]


@pytest.fixture
def record(nested_loops):
    model = hyst.PrandtlIshlinskii(THRESHOLDS, WEIGHTS, offset=0.3)
    return nested_loops, model.simulate(nested_loops)


def test_fit_recovers_known_weights(record):
    v, y = record
    model, state, report = hyst.fit_prandtl_ishlinskii(v, y, thresholds=THRESHOLDS)
    assert isinstance(model, hyst.PrandtlIshlinskii)
    np.testing.assert_allclose(model.weights, WEIGHTS, atol=1e-8)
    assert model.offset == pytest.approx(0.3, abs=1e-8)
    np.testing.assert_array_equal(state.play, np.zeros(5))  # virgin
    assert report.termination == hyst.Termination.converged
    assert report.termination.name == "converged"
    assert report.model == "pi" and report.fit.samples == len(v)
    assert report.fit.nrmse_percent < 1e-7 and report.validation is None
    assert report.final_cost < 1e-12 < report.initial_cost
    assert report.parameters >= 5 and report.iterations >= 1 and report.seconds >= 0


def test_fit_with_validation_record_and_periodic_state(record):
    v, y = record
    model, _, report = hyst.fit_prandtl_ishlinskii(v[:1200], y[:1200], v, y, operators=8)
    assert report.validation is not None and report.validation.samples == len(v)
    assert isinstance(report.validation, hyst.ErrorMetrics)
    # Periodic: one period of a steady-state sine; the state is the one reached after a period.
    grid = hyst.signals.TimeGrid(400, 1e-3)
    period = hyst.signals.generate(grid, hyst.signals.Sine(amplitude=1.0, frequency=2.5))
    truth = hyst.PrandtlIshlinskii(THRESHOLDS, WEIGHTS)
    steady = hyst.pi_periodic_state(truth, period)
    measured = truth.simulate(period, steady)
    fitted, state, report = hyst.fit_prandtl_ishlinskii(
        period, measured, thresholds=THRESHOLDS, initial_state="periodic", fit_offset=False)
    np.testing.assert_allclose(fitted.weights, WEIGHTS, atol=1e-6)
    np.testing.assert_allclose(state.play, steady.play, atol=1e-9)


def test_fit_with_a_held_out_fraction(record):
    v, y = record
    _, _, report = hyst.fit_prandtl_ishlinskii(v, y, operators=6, validate_fraction=0.25)
    assert report.fit.samples == 1500 and report.validation.samples == 500


def test_report_text_forms(record):
    v, y = record
    _, _, report = hyst.fit_prandtl_ishlinskii(v, y, v, y, thresholds=THRESHOLDS)
    assert report.brief().startswith("pi fitted by nnls")
    assert str(report) == report.brief()
    assert "Fit report" in report.full() and "validation" in report.full()
    text = repr(report)
    assert text.startswith("<FitReport pi by nnls") and "validation NRMSE" in text
    assert repr(report.fit).startswith("ErrorMetrics(samples=2000, rmse=")
    assert report.message and report.method


def test_fit_errors(record):
    v, y = record
    bad = y.copy()
    bad[17] = np.nan
    with pytest.raises(hyst.Error, match=r"\[17\] = nan is not finite"):
        hyst.fit_prandtl_ishlinskii(v, bad)
    with pytest.raises(hyst.Error, match="same length"):
        hyst.fit_prandtl_ishlinskii(v, y[:-1])
    with pytest.raises(hyst.Error, match="given together"):
        hyst.fit_prandtl_ishlinskii(v, y, validation_input=v)
    with pytest.raises(hyst.Error, match="periodic"):
        hyst.fit_prandtl_ishlinskii(v, y, initial_state="steady")
    with pytest.raises(hyst.Error):
        hyst.fit_prandtl_ishlinskii(v, y, thresholds=[0.1, 0.2])


def test_error_metrics_and_split():
    metrics = hyst.error_metrics([0.0, 1.0, 2.0, 3.0], [0.0, 1.0, 2.0, 5.0])
    assert metrics.samples == 4
    assert metrics.rmse == pytest.approx(1.0) and metrics.nrmse_percent == pytest.approx(100 / 3)
    assert metrics.max_error == pytest.approx(2.0)
    with pytest.raises(hyst.Error, match="constant"):
        hyst.error_metrics([1.0, 1.0], [1.0, 1.0])
    split = hyst.split_by_fraction(10, 0.3)
    assert (split.fit_begin, split.fit_end, split.validation_begin, split.validation_end) == (
        0, 7, 7, 10)
    assert split.fit_size() == 7 and split.validation_size() == 3 and split.has_validation()
    assert repr(split) == "DataSplit(fit=[0, 7), validation=[7, 10))"
    with pytest.raises(hyst.Error):
        hyst.split_by_fraction(10, 1.5)


def test_default_thresholds():
    np.testing.assert_allclose(hyst.pi_default_thresholds([-1.0, 1.0], 4), [0, 0.25, 0.5, 0.75])


def test_termination_names():
    assert [t.name for t in (hyst.Termination.converged, hyst.Termination.max_iterations,
                             hyst.Termination.no_progress, hyst.Termination.failed)] == [
        "converged", "max_iterations", "no_progress", "failed"]


def test_fit_progress_tells_every_start_of_a_multistart_fit():
    v = np.sin(np.linspace(0.0, 4.0 * np.pi, 300))
    y = v + 0.2 * np.cos(np.linspace(0.0, 4.0 * np.pi, 300))
    calls = []
    result = hyst.fit("gpi", v, y, max_iterations=50,
                      progress=lambda done, total, current: calls.append((done, total, current)))
    assert isinstance(result, hyst.FitResult)
    assert calls[0][0] == 0 and calls[-1] == (calls[0][1], calls[0][1], "")
    assert [done for done, _, _ in calls] == sorted(done for done, _, _ in calls)
    silent = []
    hyst.fit("pi", v, y, progress=lambda *told: silent.append(told))
    assert silent == []
