"""Linear dynamics from Python: the state-space model against closed forms, the BLA and the
state-space fit of a system simulated here with numpy, and the benchmark score against a numpy
computation of its definition on the Fine Steering Mirror data."""

import json
import math
import warnings
from pathlib import Path

import numpy as np
import pytest

import hyst

REPOSITORY = Path(__file__).resolve().parents[2]
FSM_MODEL = REPOSITORY / "examples" / "models" / "fsm_linear_state_space.json"


def first_order(a=0.8, b=0.5, c=2.0, d=0.1):
    return hyst.StateSpace([[a]], [[b]], [[c]], [[d]], sample_time=0.01)


def test_state_space_simulates_and_answers_in_closed_form():
    model = first_order()
    assert (model.order, model.inputs, model.outputs, model.sample_time) == (1, 1, 1, 0.01)
    assert "1 states" in repr(model)
    u = np.ones((5, 1))
    y = model.simulate(u)
    # y[k] = c x[k] + d, x[k] = b (1 - a^k) / (1 - a)
    expected = [2.0 * 0.5 * (1 - 0.8 ** k) / 0.2 + 0.1 for k in range(5)]
    np.testing.assert_allclose(y[:, 0], expected, rtol=1e-14)
    np.testing.assert_allclose(model.simulate(u, initial_state=np.array([1.0]))[0, 0], 2.1)
    f = np.array([1.0, 10.0])
    z = np.exp(2j * np.pi * f * 0.01)
    np.testing.assert_allclose(model.frequency_response(f)[:, 0, 0], 2.0 * 0.5 / (z - 0.8) + 0.1,
                               rtol=1e-12)
    np.testing.assert_allclose(model.poles(), [0.8])
    assert model.spectral_radius() == pytest.approx(0.8)
    assert model.is_stable()
    np.testing.assert_array_equal(model.a, [[0.8]])
    np.testing.assert_array_equal(model.b, [[0.5]])
    np.testing.assert_array_equal(model.c, [[2.0]])
    np.testing.assert_array_equal(model.d, [[0.1]])


def test_zero_order_hold_and_periodic_steady_state():
    # dx/dt = -2 x + u: A = exp(-2 Ts), B = (1 - exp(-2 Ts)) / 2
    model = hyst.StateSpace.from_continuous([[-2.0]], [[1.0]], [[1.0]], [[0.0]], sample_time=0.1)
    assert model.a[0, 0] == pytest.approx(math.exp(-0.2), rel=1e-14)
    assert model.b[0, 0] == pytest.approx((1 - math.exp(-0.2)) / 2, rel=1e-14)
    period = np.sin(2 * np.pi * np.arange(16) / 16)[:, None]
    x0 = model.periodic_state(period)
    # one period from x0 returns to x0: the last output and the next state agree
    y = model.simulate(np.vstack([period, period]), initial_state=x0)
    np.testing.assert_allclose(y[:16], y[16:], atol=1e-14)
    np.testing.assert_allclose(model.simulate_periodic(period), y[:16], atol=1e-14)


def two_lag_experiment(realisations=4, periods=2, samples=128, seed=1):
    """Inputs and outputs (N, channel, realisation, period) of two coupled lags, simulated with
    numpy in periodic steady state (10 periods to settle)."""
    rng = np.random.default_rng(seed)
    a = np.diag([0.9, -0.5])
    b = np.array([[1.0, 0.0], [1.0, 1.0]])
    c = np.eye(2)
    d = np.array([[0.0, 0.5], [0.0, 0.0]])
    n = np.arange(samples)
    u = np.zeros((samples, 2, realisations, periods))
    y = np.zeros_like(u)
    for r in range(realisations):
        phases = rng.uniform(0, 2 * np.pi, (2, 30))
        one = np.stack([np.cos(2 * np.pi * np.outer(n, np.arange(1, 31)) / samples + phases[ch])
                        .sum(axis=1) for ch in range(2)], axis=1)
        x = np.zeros(2)
        for p in range(10 + periods):
            for k in range(samples):
                out = c @ x + d @ one[k]
                x = a @ x + b @ one[k]
                if p >= 10:
                    u[k, :, r, p - 10] = one[k]
                    y[k, :, r, p - 10] = out
    return u, y, hyst.StateSpace(a, b, c, d)


def test_bla_and_fit_recover_a_system_simulated_with_numpy():
    u, y, truth = two_lag_experiment()
    bla = hyst.estimate_bla([(u, y)], sample_time=1.0)
    assert bla.lines == list(range(1, 31))
    assert (bla.blocks, bla.periods, bla.samples, bla.sample_time) == (2, 2, 128, 1.0)
    np.testing.assert_allclose(bla.frequencies, np.arange(1, 31) / 128)
    assert bla.response.shape == (30, 2, 2)
    assert bla.noise_variance.shape == (30, 2, 2) and bla.total_variance.shape == (30, 2, 2)
    assert isinstance(bla, hyst.BestLinearApproximation) and "30 lines" in repr(bla)
    np.testing.assert_allclose(bla.response, truth.frequency_response(bla.frequencies),
                               atol=1e-10)
    seen = []
    result = hyst.fit_state_space(bla, order=2, weighting="none",
                                  progress=lambda done, total, step: seen.append(step))
    assert result.report.model == "state_space" and seen
    np.testing.assert_allclose(np.sort_complex(result.model.poles()), [-0.5, 0.9], atol=1e-8)
    score = hyst.evaluate(result.model, u, y, periodic=True)
    assert score["mean_relative_error"] < 1e-8
    assert score["rmse"].shape == (2,) and score["scored_samples"] == 4 * 2 * 128
    assert score["relative_error"].shape == score["output_std"].shape == (2,)
    assert score["mean_rmse"] < 1e-8
    from_rest = hyst.evaluate(result.model, u, y, transient=0)
    assert from_rest["mean_relative_error"] > 1e-4
    with pytest.raises(hyst.Error, match="weighting"):
        hyst.fit_state_space(bla, order=2, weighting="heavy")
    with pytest.raises(hyst.Error, match="not a whole number of blocks of 2"):
        hyst.estimate_bla([(u[:, :, :1], y[:, :, :1])], sample_time=1.0)


def test_evaluate_says_when_the_free_run_cannot_be_trusted():
    u, y, truth = two_lag_experiment()
    score = hyst.evaluate(truth, u, y, periodic=True, strict=True)
    assert score["warnings"] == [] and score["runaway_samples"] == 0
    # A pole at 1.05 from rest: 1.05^n leaves the measured range within the record.
    unstable = hyst.StateSpace([[1.05, 0.0], [0.0, 0.5]], truth.b, truth.c, truth.d,
                               sample_time=truth.sample_time)
    score = hyst.evaluate(unstable, u, y)
    assert len(score["warnings"]) == 2 and score["runaway_samples"] > 0
    assert "pole of magnitude 1.05, outside the unit circle" in score["warnings"][0]
    assert "simulated samples ran away" in score["warnings"][1]
    with pytest.raises(hyst.Error, match=r"pole of magnitude 1.05.*\(strict=True\)"):
        hyst.evaluate(unstable, u, y, strict=True)
    # Simulating it says so too, and simulates all the same; a stable model says nothing.
    record = u[:, :, 0, 0]
    with pytest.warns(RuntimeWarning, match="pole of magnitude 1.05, outside the unit circle"):
        grown = unstable.simulate(record)
    assert np.abs(grown[-1, 0]) > 10 * np.abs(y).max()  # 1.05^128 = 514
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        truth.simulate(record)
    lfr = hyst.HystereticLfr.hammerstein(unstable, [pi_feedback(1.0), pi_feedback(1.0)])
    with pytest.warns(RuntimeWarning, match="pole of magnitude 1.05"):
        lfr.simulate(record)


def test_model_files_round_trip(tmp_path):
    model = first_order()
    model.save(tmp_path / "m.json", info={"made by": "test"})
    again = hyst.load_state_space(tmp_path / "m.json")
    np.testing.assert_array_equal(again.a, model.a)
    assert json.loads((tmp_path / "m.json").read_text())["info"] == {"made by": "test"}


def benchmark_score(model_file, u, y):
    """The FSM benchmark's relative error by its definition (PROVENANCE.md), with numpy: periodic
    steady state from the first period's input, free run over both periods."""
    params = json.loads(model_file.read_text())["params"]
    a, b, c, d = (np.array(params[k], dtype=float) for k in "abcd")
    samples, _, realisations, periods = u.shape
    rmse = np.zeros(y.shape[1])
    for r in range(realisations):
        record = np.concatenate([u[:, :, r, p] for p in range(periods)])
        # x0 = (I - A^N)^-1 sum_k A^(N-1-k) B u[k]
        forced = np.zeros(a.shape[0])
        for k in range(samples):
            forced = a @ forced + b @ record[k]
        x = np.linalg.solve(np.eye(a.shape[0]) - np.linalg.matrix_power(a, samples), forced)
        out = np.zeros((len(record), y.shape[1]))
        for k in range(len(record)):
            out[k] = c @ x + d @ record[k]
            x = a @ x + b @ record[k]
        for p in range(periods):
            e = y[:, :, r, p] - out[p * samples:(p + 1) * samples]
            rmse += np.sqrt((e ** 2).mean(axis=0)) / (realisations * periods)
    relative = rmse / y.std(axis=(0, 2, 3))
    return rmse, relative


def test_benchmark_score_on_the_fine_steering_mirror_matches_its_definition(data_dir):
    folder = data_dir / "fsm_piezo_mimo_multisine"
    u = np.load(folder / "u_200mV_test.npy")
    y = np.load(folder / "y_200mV_test.npy")
    model = hyst.load_state_space(FSM_MODEL)
    assert (model.order, model.inputs, model.outputs) == (28, 3, 3)
    score = hyst.evaluate(model, u, y, periodic=True)
    rmse, relative = benchmark_score(FSM_MODEL, u, y)
    np.testing.assert_allclose(score["rmse"], rmse, rtol=1e-9)
    np.testing.assert_allclose(score["relative_error"], relative, rtol=1e-9)
    assert score["mean_relative_error"] == pytest.approx(relative.mean(), rel=1e-9)
    # the published one-model-for-all-levels linear baseline scores 6.61 % here
    assert score["mean_relative_error"] < 0.0661


def pi_feedback(scale):
    return hyst.model_from_dict({"model": "pi", "version": 1, "params": {
        "thresholds": [0.0, 0.2 * scale], "weights": [0.5, 0.3]}})


def test_hysteretic_lfr_agrees_with_its_loop_written_in_numpy(tmp_path):
    # One state; inputs (u, w), outputs (y, z); w = PI[z].
    linear = hyst.StateSpace([[0.9]], [[0.5, -0.3]], [[1.2], [0.8]], [[0.1, 0.25], [0.4, 0.0]],
                             sample_time=0.01)
    model = hyst.HystereticLfr(linear, inputs=1, feedback=[pi_feedback(0.5)])
    assert (model.order, model.inputs, model.outputs, model.feedback_channels) == (1, 1, 1, 1)
    assert model.feedback_model == "pi"
    assert "'pi' feedback" in repr(model)
    k = np.arange(300)
    u = (np.sin(2 * np.pi * k / 50) + 0.4 * np.sin(2 * np.pi * 3 * k / 50))[:, None]
    x, play, expected = 0.0, 0.0, []
    for value in u[:, 0]:
        z = 0.8 * x + 0.4 * value
        play = max(z - 0.1, min(z + 0.1, play))
        w = 0.5 * z + 0.3 * play
        expected.append(1.2 * x + 0.1 * value + 0.25 * w)
        x = 0.9 * x + 0.5 * value - 0.3 * w
    np.testing.assert_allclose(model.simulate(u)[:, 0], expected, rtol=0, atol=1e-14)

    path = tmp_path / "lfr.json"
    model.save(path, info={"made_by": "test"})
    loaded = hyst.load_hysteretic_lfr(path)
    np.testing.assert_array_equal(loaded.simulate(u), model.simulate(u))
    assert json.loads(path.read_text())["info"] == {"made_by": "test"}
    # Periodic steady state: one more period from it changes nothing.
    period = u[:50]
    steady = model.simulate_periodic(period)
    np.testing.assert_allclose(model.simulate(np.tile(period, (60, 1)))[-50:], steady, atol=1e-9)


def test_initial_state_from_the_first_outputs():
    # The numpy loop above with the state x0 = 2: the first 40 outputs give it back, and the
    # run from it continues the record.
    linear = hyst.StateSpace([[0.9]], [[0.5, -0.3]], [[1.2], [0.8]], [[0.1, 0.25], [0.4, 0.0]],
                             sample_time=0.01)
    model = hyst.HystereticLfr(linear, inputs=1, feedback=[pi_feedback(0.5)])
    k = np.arange(200)
    u = np.sin(2 * np.pi * k / 50)[:, None]
    y = model.simulate_from_state(u, np.array([2.0]))
    state, rms, iterations = model.estimate_initial_state(u, y, 40)
    assert state == pytest.approx([2.0], abs=1e-6) and rms < 1e-8 and iterations >= 1
    np.testing.assert_allclose(model.simulate_from_state(u, state), y, atol=1e-6)
    with pytest.raises(hyst.Error, match="state: 2 values for a linear block of 1 states"):
        model.simulate_from_state(u, np.zeros(2))
    # A linear model: least squares, exact without noise.
    plant = hyst.StateSpace([[0.8, 0.1], [0.0, -0.5]], [[1.0], [0.3]], [[1.0, 0.5]], [[0.0]])
    measured = plant.simulate(u, initial_state=np.array([1.5, -3.0]))
    x0, residual = plant.estimate_initial_state(u, measured, 10)
    np.testing.assert_allclose(x0, [1.5, -3.0], atol=1e-9)
    assert residual < 1e-10


def test_hammerstein_is_its_blocks_then_the_linear_block():
    linear = hyst.StateSpace([[0.5, 0.1], [0.0, 0.7]], [[1.0, 0.0], [0.3, 1.0]],
                             [[1.0, 0.0], [0.5, 1.0]], [[0.0, 0.2], [0.1, 0.0]])
    blocks = [pi_feedback(1.0), pi_feedback(2.0)]
    system = hyst.HystereticLfr.hammerstein(linear, blocks)
    rng = np.random.default_rng(5)
    u = np.cumsum(rng.normal(size=(200, 2)), axis=0) * 0.1
    w = np.column_stack([blocks[i].simulate(u[:, i]) for i in range(2)])
    np.testing.assert_allclose(system.simulate(u), linear.simulate(w), rtol=1e-12, atol=1e-13)
    with pytest.raises(hyst.Error, match="3 blocks for a linear block with 2 inputs"):
        hyst.HystereticLfr.hammerstein(linear, blocks + [pi_feedback(1.0)])
    with pytest.raises(hyst.Error, match="algebraic loop"):
        hyst.HystereticLfr(hyst.StateSpace([[0.5]], [[1.0, 1.0]], [[1.0], [1.0]],
                                           [[0.0, 0.0], [0.0, 1.0]]), 1, [pi_feedback(1.0)])


def test_hysteretic_lfr_with_the_feedback_cut_scores_as_the_linear_model():
    linear = hyst.load_state_space(FSM_MODEL)
    a, b, c, d = linear.a, linear.b, linear.c, linear.d
    n = a.shape[0]
    cut = hyst.StateSpace(a, np.hstack([b, np.zeros((n, 1))]), np.vstack([c, c[:1]]),
                          np.vstack([np.hstack([d, np.zeros((3, 1))]), np.zeros((1, 4))]),
                          sample_time=linear.sample_time)
    model = hyst.HystereticLfr(cut, 3, [pi_feedback(1e-6)])
    data = REPOSITORY.parent / "shared" / "data" / "fsm_piezo_mimo_multisine"
    if not data.is_dir():
        pytest.skip("shared data not present")
    u = np.load(data / "u_200mV_test.npy")[:, :, :1]
    y = np.load(data / "y_200mV_test.npy")[:, :, :1]
    expected = hyst.evaluate(linear, u, y, periodic=True)
    score = hyst.evaluate(model, u, y, periodic=True)
    assert score["mean_relative_error"] == pytest.approx(expected["mean_relative_error"], rel=1e-10)


def test_fit_hysteretic_lfr_learns_a_feedback_the_linear_model_lacks():
    # The true system: a lightly damped mode with a PI model of its output fed back to its input.
    a = 0.97 * np.array([[math.cos(0.3), math.sin(0.3)], [-math.sin(0.3), math.cos(0.3)]])
    linear = hyst.StateSpace(a, [[0.0], [1.0]], [[0.2, 0.1]], [[0.0]], sample_time=1e-3)
    truth = hyst.HystereticLfr(
        hyst.StateSpace(a, [[0.0, 0.0], [1.0, -0.5]], [[0.2, 0.1], [0.2, 0.1]],
                        [[0.0, 0.0], [0.0, 0.0]], sample_time=1e-3),
        1, [hyst.model_from_dict({"model": "pi", "version": 1, "params": {
            "thresholds": [0.0, 0.3, 0.8], "weights": [0.2, 0.4, 0.3]}})])
    rng = np.random.default_rng(3)
    n = np.arange(256)
    experiments = []
    for rms in (0.5, 3.0):
        u = np.empty((256, 1, 3, 2))
        y = np.empty_like(u)
        for r in range(3):
            period = sum(np.cos(2 * np.pi * k * n / 256 + rng.uniform(0, 2 * np.pi))
                         for k in range(1, 41))
            period *= rms / np.sqrt(np.mean(period ** 2))
            steady = truth.simulate_periodic(period[:, None])
            u[:, 0, r, :] = period[:, None]
            y[:, 0, r, :] = steady
        experiments.append((u, y))
    result = hyst.fit_hysteretic_lfr(linear, experiments, threshold_fractions=[0, 0.1, 0.25, 0.5])
    # Then every matrix free: 3 weights, a pole pair, B 2 x 2, C 2 x 2, D 2 x 2 but Dzw.
    assert result.report.parameters == 16
    alone = hyst.fit_hysteretic_lfr(linear, experiments, threshold_fractions=[0, 0.1, 0.25, 0.5],
                                    general_iterations=0)
    assert alone.report.parameters == 12  # Theta, T, 3 weights, a pole pair, B (2), C (2), D
    two = hyst.fit_hysteretic_lfr(linear, experiments, threshold_fractions=[0, 0.1, 0.25, 0.5],
                                  general_iterations=0, feedback_channels=2)
    assert two.report.parameters == 17  # Theta (1 x 2), T (2 x 1), 2 x 3 weights, 2, 2, 2, 1
    for u, y in experiments:
        before = hyst.evaluate(linear, u, y, periodic=True)["mean_relative_error"]
        after = hyst.evaluate(result.model, u, y, periodic=True)["mean_relative_error"]
        assert before > 0.1
        assert after < 0.1 * before


def test_fit_hammerstein_finds_an_input_hysteresis():
    # The true system: a PI model ahead of a lightly damped mode, its thresholds at 10 and 30 % of
    # the largest input, on the fit's grid of fractions.
    a = 0.97 * np.array([[math.cos(0.3), math.sin(0.3)], [-math.sin(0.3), math.cos(0.3)]])
    linear = hyst.StateSpace(a, [[0.0], [1.0]], [[0.2, 0.1]], [[0.0]], sample_time=1e-3)
    rng = np.random.default_rng(5)
    n = np.arange(256)
    periods = {}
    for rms in (0.3, 1.5):
        periods[rms] = []
        for _ in range(3):
            period = sum(np.cos(2 * np.pi * k * n / 256 + rng.uniform(0, 2 * np.pi))
                         for k in range(1, 41))
            periods[rms].append(period * rms / np.sqrt(np.mean(period ** 2)))
    largest = max(np.max(np.abs(p)) for level in periods.values() for p in level)
    pi = hyst.model_from_dict({"model": "pi", "version": 1, "params": {
        "thresholds": [0.0, 0.1 * largest, 0.3 * largest], "weights": [1.0, -0.3, -0.2]}})
    # As an LFR: z = u, w = PI[z] drives the linear block, y = C x.
    truth = hyst.HystereticLfr(
        hyst.StateSpace(a, [[0.0, 0.0], [0.0, 1.0]], [[0.2, 0.1], [0.0, 0.0]],
                        [[0.0, 0.0], [1.0, 0.0]], sample_time=1e-3), 1, [pi])
    experiments = []
    for level in periods.values():
        u = np.empty((256, 1, 3, 2))
        y = np.empty_like(u)
        for r, period in enumerate(level):
            u[:, 0, r, :] = period[:, None]
            y[:, 0, r, :] = truth.simulate_periodic(period[:, None])
        experiments.append((u, y))
    result = hyst.fit_hammerstein(linear, experiments, threshold_fractions=[0, 0.1, 0.2, 0.3, 0.5])
    assert result.report.parameters == 4 + 2 + 2 + 2 + 1  # weights, a pole pair, B, C, D
    for u, y in experiments:
        before = hyst.evaluate(linear, u, y, periodic=True)["mean_relative_error"]
        after = hyst.evaluate(result.model, u, y, periodic=True)["mean_relative_error"]
        assert before > 0.02
        assert after < 1e-4
    with pytest.raises(hyst.Error, match="Hammerstein fit: threshold_fractions must start at 0"):
        hyst.fit_hammerstein(linear, experiments, threshold_fractions=[0.1, 0.2])
