"""The one state rule of the Python API: models and inverses never change when they run; a run
starts from a state passed in or from the object's start state; what advances is a separate
running object (a typed model's State, a ModelRunner, an InverseRunner)."""

import numpy as np
import pytest

import hyst

PI_PARAMS = {"thresholds": [0.0, 0.3, 0.6], "weights": [1.0, 0.5, 0.25], "offset": 0.1}


def loops() -> np.ndarray:
    t = np.linspace(0.0, 1.0, 400)
    return 0.9 * np.sin(2 * np.pi * 3 * t) * np.exp(-t)


@pytest.mark.parametrize("name", ["pi", "bouc_wen", "jiles_atherton", "preisach"])
def test_model_simulate_never_changes_the_model(name):
    entry = hyst.model_entry(name)
    model = hyst.Model(name, entry.example_params)
    lo, hi = -1.0, 1.0
    v = lo + (hi - lo) * (0.5 + 0.5 * loops() / 0.9)
    start = model.state
    first = model.simulate(v)
    assert model.state == start
    np.testing.assert_array_equal(model.simulate(v), first)


def test_return_state_continues_a_run_and_leaves_the_dict_alone():
    model = hyst.Model("pi", PI_PARAMS)
    v = loops()
    whole = model.simulate(v)
    head, state = model.simulate(v[:150], return_state=True)
    passed = {"play": list(state["play"])}
    tail = model.simulate(v[150:], state=passed)
    np.testing.assert_array_equal(np.concatenate([head, tail]), whole)
    assert passed == state  # a state passed in is read, never written


def test_runner_advances_and_resets():
    model = hyst.Model("pi", PI_PARAMS)
    v = loops()
    whole = model.simulate(v)
    runner = model.runner()
    stepped = [runner.step(x) for x in v[:100]]
    rest = runner.simulate(v[100:])
    np.testing.assert_array_equal(np.concatenate([stepped, rest]), whole)
    _, final = model.simulate(v, return_state=True)
    assert runner.state == final
    assert runner.to_model().state == final
    assert model.state == {"play": [0.0, 0.0, 0.0]}
    runner.reset()
    assert runner.state == model.state
    np.testing.assert_array_equal(runner.simulate(v), whole)


def test_inverse_starts_from_the_models_start_state_however_the_model_ran():
    model = hyst.Model("pi", PI_PARAMS)
    v = loops()
    targets = model.simulate(v)
    fresh_inputs, _ = hyst.Model("pi", PI_PARAMS).inverse().invert(targets)
    model.simulate(v[:77])  # a validation run before the feedforward
    inverse = model.inverse()
    start = inverse.state
    inputs, report = inverse.invert(targets)
    assert report.ok
    np.testing.assert_array_equal(inputs, fresh_inputs)
    np.testing.assert_array_equal(inverse.invert(targets)[0], inputs)  # unchanged by invert
    assert inverse.state == start
    np.testing.assert_allclose(model.simulate(inputs), targets, rtol=0, atol=1e-12)


def test_inverse_runner_continues():
    model = hyst.Model("pi", PI_PARAMS)
    targets = model.simulate(loops())
    whole, _ = model.inverse().invert(targets)
    runner = model.inverse().runner()
    head, _ = runner.invert(targets[:200])
    stepped = [runner.step(y) for y in targets[200:]]
    np.testing.assert_allclose(np.concatenate([head, stepped]), whole, rtol=0, atol=1e-12)
    runner.reset()
    np.testing.assert_allclose(runner.invert(targets)[0], whole, rtol=0, atol=1e-12)


def test_runner_inverse_starts_from_the_running_state():
    model = hyst.Model("pi", PI_PARAMS)
    v = loops()
    runner = model.runner()
    runner.simulate(v[:120])
    targets = runner.to_model().simulate(v[120:])
    inputs, report = runner.inverse().invert(targets)
    assert report.ok
    np.testing.assert_allclose(inputs, v[120:], rtol=0, atol=1e-12)


def test_save_model_after_a_run_writes_the_start_state(tmp_path):
    model = hyst.Model("pi", PI_PARAMS)
    model.simulate(loops())
    path = tmp_path / "pi.json"
    hyst.save_model(path, model)
    assert hyst.load_model(path).state == {"play": [0.0, 0.0, 0.0]}


def test_typed_classes_follow_the_same_rule():
    pi = hyst.PrandtlIshlinskii(PI_PARAMS["thresholds"], PI_PARAMS["weights"],
                                PI_PARAMS["offset"])
    v = loops()
    whole = pi.simulate(v)
    np.testing.assert_array_equal(pi.simulate(v), whole)  # from initial_state() every time
    state = pi.initial_state()  # the running object: advanced by simulate and step
    head = pi.simulate(v[:150], state)
    tail = [pi.step(state, x) for x in v[150:]]
    np.testing.assert_array_equal(np.concatenate([head, tail]), whole)
    inverse = hyst.InversePrandtlIshlinskii(pi)
    inputs, _ = inverse.invert(whole)  # from initial_state() every time
    np.testing.assert_array_equal(inverse.invert(whole)[0], inputs)
    np.testing.assert_allclose(inputs, v, rtol=0, atol=1e-12)
    inverse_state = inverse.initial_state()
    head, _ = inverse.invert(whole[:150], inverse_state)
    tail, _ = inverse.invert(whole[150:], inverse_state)
    np.testing.assert_array_equal(np.concatenate([head, tail]), inputs)
