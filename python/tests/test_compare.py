"""Model comparison and the NARX model from Python: hyst.compare ranks a PI record with PI first,
reports a failing fit per model, and hyst.fit("narx", ...) gives a model that simulates and
saves like every other."""

import shutil
import sys

import numpy as np
import pytest

import hyst

THRESHOLDS = [0.0, 0.3, 0.7, 1.1]


def random_walk(samples: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    v = np.cumsum(rng.uniform(-0.2, 0.2, samples))
    return np.clip(v, -2.0, 2.0)


def pi_record(samples: int, seed: int):
    v = random_walk(samples, seed)
    model = hyst.PrandtlIshlinskii(THRESHOLDS, [0.8, 0.5, 0.3, 0.2])
    return v, model.simulate(v)


def test_compare_ranks_the_generating_model_first(tmp_path):
    v, y = pi_record(1000, 1)
    comparison = hyst.compare(v, y, ["narx", "pi"], validate_fraction=0.3,
                              options={"pi": {"thresholds": THRESHOLDS},
                                       "narx": {"hidden_sizes": [3], "max_iterations": 10}},
                              timing_seconds=0.0)
    assert isinstance(comparison, hyst.ModelComparison)
    assert comparison.split.validation_begin == 700
    best = comparison.ranking[0]
    assert isinstance(best, hyst.ComparedModel)
    assert best.model == "pi" and best.ok and best.error == ""
    assert best.validation.nrmse_percent < 1e-7
    assert best.parameters == 5 and best.fit_seconds >= 0 and best.ns_per_sample > 0
    assert best.report.model == "pi"
    assert len(best.simulated) == len(v)
    assert repr(best).startswith("ComparedModel(model='pi'")
    # The held-out inputs against the fit part's range, widened by 5 % of its width.
    low, high = min(v[:700]), max(v[:700])
    margin = 0.05 * (high - low)
    outside = sum(1 for x in v[700:] if x < low - margin or x > high + margin)
    assert best.held_out_domain["inside"] == (outside == 0)
    assert (f"{outside} of 300 samples" in best.held_out_domain["message"]) == (outside > 0)
    assert "| 1 | pi |" in comparison.markdown()
    assert comparison.csv().startswith("rank,model,status,validation_nrmse_percent")
    # The yardstick: the exact PI beats every reference predictor; no no-fit verdict.
    names = [reference.name for reference in comparison.references]
    assert names == ["mean", "last value held", "polynomial y(v), degree 3", "ARX(2,2)"]
    assert isinstance(comparison.references[0], hyst.ReferenceScore)
    assert best.report.quality_note == ""
    assert best.beats_yardstick and best.report.status in ("converged", "iteration limit")
    assert comparison.yardstick.startswith("Yardstick (reference predictors")
    assert comparison.no_fit == "" and comparison.no_fit_percent == 20.0
    page = comparison.html(v, y, title="PI & NARX", input_label="v [V]", output_label="y [m]")
    assert "<h1>PI &amp; NARX</h1>" in page and page.count("<canvas>") == 3
    assert '"input_label":"v [V]"' in page and '"output_label":"y [m]"' in page
    if shutil.which("gnuplot"):
        comparison.write_plots(v, y, tmp_path / "loops.png", tmp_path / "errors.png")
        assert (tmp_path / "loops.png").stat().st_size > 0
        assert (tmp_path / "errors.png").stat().st_size > 0


def test_compare_reports_a_failing_fit_and_runs_the_others():
    v, y = pi_record(40, 2)
    comparison = hyst.compare(v, y, ["narx", "pi"], timing_seconds=0.0)
    pi, narx = comparison.ranking
    assert pi.ok and pi.model == "pi"
    assert not narx.ok and "too few for" in narx.error and narx.report is None
    assert len(narx.simulated) == 0
    assert "failed" in repr(narx)
    with pytest.raises(hyst.Error, match="listed twice"):
        hyst.compare(v, y, ["pi", "pi"])


def test_narx_fits_simulates_and_round_trips(tmp_path):
    v = random_walk(1500, 3)
    play = np.zeros_like(v)
    state = 0.0
    for k, x in enumerate(v):
        state = max(x - 0.4, min(x + 0.4, state))
        play[k] = state
    y = np.tanh(1.2 * play) + 0.1 * v
    model, report = hyst.fit("narx", v, y, play_thresholds=[0.4], hidden_sizes=[3],
                             input_lags=0, output_lags=0, max_iterations=40)
    assert report.model == "narx" and report.fit.nrmse_percent < 1
    path = tmp_path / "narx.json"
    hyst.save_model(path, model)
    loaded = hyst.load_model(path)
    np.testing.assert_array_equal(loaded.simulate(v), model.simulate(v))


def sine_record(amplitude: float, samples: int = 300):
    v = amplitude * np.sin(2 * np.pi * np.arange(samples) / 100)
    model = hyst.PrandtlIshlinskii(THRESHOLDS, [0.8, 0.5, 0.3, 0.2])
    return v, model.simulate(v)


def test_compare_on_separate_records():
    # PI records at two amplitudes, each simulated from rest: fitted with its thresholds on the
    # large one, PI predicts the small one from rest exactly.
    comparison = hyst.compare(models=["bouc_wen", "pi"], options={"pi": {"thresholds": THRESHOLDS}},
                              fit_records={"large": sine_record(2.0)},
                              validate_records={"small": sine_record(0.8)},
                              validation_start="rest", validation_align="none")
    assert isinstance(comparison, hyst.CrossRecordComparison)
    assert not comparison.leave_one_out
    assert comparison.fit_records == ["large"] and comparison.validate_records == ["small"]
    assert "validation start 'rest'" in comparison.rule
    best = comparison.ranking[0]
    assert isinstance(best, hyst.CrossRecordRow)
    assert best.model == "pi" and best.ok and best.error == "" and best.status == "converged"
    assert best.mean_nrmse_percent < 1e-6 and best.worst_record == "small"
    assert best.worst_nrmse_percent == best.mean_nrmse_percent
    assert best.parameters == 5 and best.fit_seconds >= 0
    score = best.scores[0]
    assert isinstance(score, hyst.HeldOutScore)
    assert score.record == "small" and score.fitted_on == ["large"]
    assert score.metrics.nrmse_percent == best.mean_nrmse_percent
    # The small record stays inside the large one's domain.
    assert score.domain == {"inside": True, "message": ""}
    assert comparison.ranking[1].mean_nrmse_percent > 0.1
    assert "| 1 | pi |" in comparison.markdown()
    assert comparison.csv().startswith("rank,model,status,mean_nrmse_percent")
    # The yardstick: mean, last value held and the cubic y(v) (no ARX: a separate record).
    assert [reference.name for reference in comparison.references][:2] == \
        ["mean", "last value held"]
    assert len(comparison.references) == 3 and all(r.ok for r in comparison.references)
    large_v, large_y = sine_record(2.0)
    small_v, small_y = sine_record(0.8)
    mean = comparison.references[0]
    assert isinstance(mean, hyst.CrossRecordReference)
    assert mean.scores[0].metrics.rmse == pytest.approx(
        np.sqrt(np.mean((np.asarray(small_y) - np.mean(large_y)) ** 2)), rel=1e-12)
    assert best.beats_yardstick
    assert comparison.no_fit == [] and comparison.no_fit_percent == 20.0


def test_compare_on_separate_records_no_fit_verdict():
    # A held-out butterfly (y = v^2) over twice the fitted range: no model describes it.
    v, _ = sine_record(2.0)
    comparison = hyst.compare(models=["pi"], fit_records={"plain": sine_record(1.0)},
                              validate_records={"butterfly": (v, np.asarray(v) ** 2)},
                              no_fit_percent=25.0)
    assert comparison.no_fit_percent == 25.0
    [verdict] = comparison.no_fit
    assert isinstance(verdict, hyst.NoFitVerdict)
    assert verdict.record == "butterfly" and verdict.best_model == "pi"
    assert verdict.best_nrmse_percent > 25.0
    assert any(finding.startswith("butterfly") for finding in verdict.findings)
    assert any(finding.startswith("extrapolation") for finding in verdict.findings)
    assert "No model describes the record butterfly" in comparison.markdown()


def test_compare_leave_one_out():
    # The small record never moves the play of threshold 1.1: held out, the large one is the worst.
    comparison = hyst.compare(models=["pi"], options={"pi": {"thresholds": THRESHOLDS}},
                              fit_records=[sine_record(2.0), sine_record(0.8)],
                              leave_one_out=True)
    assert comparison.leave_one_out and comparison.fit_records == []
    assert comparison.validate_records == ["record 1", "record 2"]
    row = comparison.ranking[0]
    assert [score.record for score in row.scores] == ["record 1", "record 2"]
    # Held out, the large record leaves the domain of the small one (amplitude 2 against 0.8).
    assert not row.scores[0].domain["inside"]
    assert "inputs above the fitted range" in row.scores[0].domain["message"]
    assert row.scores[1].domain["inside"]
    assert "Held-out record 'record 1' leaves the domain" in comparison.markdown()
    assert row.scores[1].metrics.nrmse_percent < 1e-6
    assert row.worst_record == "record 1" and row.worst_nrmse_percent > 1e-3
    assert row.mean_nrmse_percent == pytest.approx(
        (row.scores[0].metrics.nrmse_percent + row.scores[1].metrics.nrmse_percent) / 2)
    with pytest.raises(hyst.Error, match="fit_records needs either validate_records"):
        hyst.compare(fit_records=[sine_record(2.0)])
    with pytest.raises(hyst.Error, match="validation start 'later' is not known"):
        hyst.compare(fit_records=[sine_record(2.0)], validate_records=[sine_record(1.0)],
                     validation_start="later")


def progress_record():
    v = np.sin(np.linspace(0.0, 4.0 * np.pi, 400))
    return v, v + 0.2 * np.sign(np.gradient(v))


def test_progress_callback_is_called_before_each_model_and_at_the_end():
    calls = []
    hyst.compare(*progress_record(), ["pi", "maxwell_slip"],
                 progress=lambda done, total, current: calls.append((done, total, current)))
    assert calls == [(0, 2, "pi"), (1, 2, "maxwell_slip"), (2, 2, "")]
    with pytest.raises(TypeError, match="progress must be None, True or a callable"):
        hyst.compare(*progress_record(), ["pi"], progress="yes")


def test_progress_true_draws_lines_without_tqdm(monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "tqdm.auto", None)
    hyst.compare(*progress_record(), ["pi", "maxwell_slip"], progress=True)
    lines = capsys.readouterr().err.splitlines()
    assert lines[0].startswith("hyst.compare: 0/2, now pi; ")
    assert lines[-1].startswith("hyst.compare: 2/2; ")


def test_progress_true_draws_a_tqdm_bar_when_installed(capsys):
    pytest.importorskip("tqdm")
    hyst.compare(*progress_record(), ["pi", "maxwell_slip"], progress=True)
    err = capsys.readouterr().err
    assert "hyst.compare" in err and "2/2" in err
