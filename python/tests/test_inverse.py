"""The analytic inverse of the PI model: reference parameters, round trips, states, limits."""

import copy

import numpy as np
import pytest

import hyst

THRESHOLDS = [0.0, 0.3, 0.7, 1.0, 1.6, 2.2]
WEIGHTS = [0.8, 0.5, 0.3, 0.2, 0.1, 0.05]


@pytest.fixture
def model():
    return hyst.PrandtlIshlinskii(THRESHOLDS, WEIGHTS, offset=0.25)


def test_inverse_parameters_reference(model):
    inverse = hyst.InversePrandtlIshlinskii(model)
    operator = inverse.inverse_operator()
    assert isinstance(operator, hyst.PrandtlIshlinskii)
    np.testing.assert_allclose(operator.thresholds, [0, 0.24, 0.76, 1.24, 2.32, 3.46], atol=1e-12)
    sums = np.cumsum(WEIGHTS)
    expected = [1 / 0.8] + [-WEIGHTS[j] / (sums[j] * sums[j - 1]) for j in range(1, 6)]
    np.testing.assert_allclose(operator.weights, expected, rtol=1e-14)
    assert operator.offset == 0.0
    np.testing.assert_array_equal(inverse.forward().weights, WEIGHTS)


def test_model_of_inverse_is_identity(model, nested_loops):
    inverse = hyst.InversePrandtlIshlinskii(model)
    inputs, report = inverse.invert(nested_loops)
    assert report.ok and report.saturated_samples == 0
    assert repr(report) == "InverseReport(ok)"
    np.testing.assert_allclose(model.simulate(inputs), nested_loops, rtol=0, atol=1e-12)
    # ...and the other way round.
    targets = model.simulate(nested_loops)
    back, _ = inverse.invert(targets)
    np.testing.assert_allclose(back, nested_loops, rtol=0, atol=1e-12)


def test_consistent_states_round_trip_and_continue_a_run(model, nested_loops):
    inverse = hyst.InversePrandtlIshlinskii(model)
    state = model.initial_state()
    model.simulate(nested_loops[:700], state)  # somewhere inside the loops
    inverse_state = inverse.state_consistent_with(state)
    back = inverse.forward_state_consistent_with(inverse_state)
    np.testing.assert_allclose(back.play, state.play, rtol=0, atol=1e-12)

    targets = nested_loops[700:] * 0.5 + 0.25
    inputs, report = inverse.invert(targets, inverse_state)
    assert report.ok
    np.testing.assert_allclose(model.simulate(inputs, state), targets, rtol=0, atol=1e-12)
    assert isinstance(inverse_state, hyst.InversePrandtlIshlinskii.State)


def test_solve_and_step_one_sample(model):
    inverse = hyst.InversePrandtlIshlinskii(model)
    state = inverse.initial_state()
    saved = copy.copy(state)
    value, status = inverse.solve(state, 1.0)
    assert status == hyst.InverseStatus.ok
    assert inverse.step(saved, 1.0) == value
    assert model.simulate([value])[0] == pytest.approx(1.0, abs=1e-12)
    with pytest.raises(hyst.Error, match="target = nan is not finite"):
        inverse.solve(state, float("nan"))
    with pytest.raises(hyst.Error, match="state has 2 play outputs"):
        inverse.solve(hyst.PrandtlIshlinskii([0, 1], [1, 1]).initial_state(), 0.0)


def test_input_limits_saturate_with_a_status(model):
    inverse = hyst.InversePrandtlIshlinskii(model, input_min=-0.5, input_max=0.5)
    assert (inverse.input_min, inverse.input_max) == (-0.5, 0.5)
    state = inverse.initial_state()
    assert inverse.solve(state, 10.0) == (0.5, hyst.InverseStatus.above_range)
    assert inverse.solve(state, -10.0) == (-0.5, hyst.InverseStatus.below_range)
    inputs, report = inverse.invert([0.0, 0.3, 5.0, 6.0])
    assert not report.ok
    assert (report.saturated_samples, report.first_saturated) == (2, 2)
    assert "saturated_samples=2" in repr(report)
    assert inputs.max() == 0.5
    assert str(hyst.InverseStatus.below_range) == "InverseStatus.below_range"


def test_inverse_exists_only_for_positive_partial_sums():
    with pytest.raises(hyst.Error, match=r"PI weight p\[0\] = 0 must be > 0"):
        hyst.InversePrandtlIshlinskii(hyst.PrandtlIshlinskii([0, 1], [0.0, 1.0]))
    with pytest.raises(hyst.Error, match=r"partial sum S\[1\] = p\[0\] \+ ... \+ p\[1\] = -0.5"):
        hyst.InversePrandtlIshlinskii(hyst.PrandtlIshlinskii([0, 1], [1.0, -1.5]))
    with pytest.raises(hyst.Error, match="v_min <= v_max"):
        hyst.InversePrandtlIshlinskii(hyst.PrandtlIshlinskii([0], [1.0]), input_min=1, input_max=0)


def test_repr_and_copy(model):
    inverse = hyst.InversePrandtlIshlinskii(model, input_max=3.0)
    assert repr(inverse).startswith("InversePrandtlIshlinskii(model=PrandtlIshlinskii(")
    assert "input_max=3)" in repr(inverse)
    twin = copy.deepcopy(inverse)
    np.testing.assert_array_equal(twin.invert([0.1, 0.2])[0], inverse.invert([0.1, 0.2])[0])


def test_unreachable_bouc_wen_targets_are_reported_not_searched_forever():
    # Without linear spring (alpha_k = 0) the force stays below k z0 = 2 (z0 = 1): 1e6, 1e300 and
    # -1e300 are out of reach; the inverse answers with the saturated input and counts them.
    params = {"a": 1.0, "beta": 0.6, "gamma": 0.4, "n": 1.5, "stiffness": 2.0, "alpha_k": 0.0}
    model = hyst.Model("bouc_wen", params)
    inputs, report = model.inverse().invert([0.5, 1e6, 1e300, -1e300])
    assert report.saturated_samples == 3 and report.first_saturated == 1
    assert not report.ok
    assert np.all(np.isfinite(inputs)) and np.all(np.abs(inputs) < 1e3)
    forces = hyst.Model("bouc_wen", params).simulate(inputs)
    np.testing.assert_allclose(forces, [0.5, 2.0, 2.0, -2.0], atol=1e-9)


def test_subnormal_weight_refused_by_the_inverse_as_written():
    model = hyst.PrandtlIshlinskii([0.0, 1.0], [1e-320, 1.0])
    with pytest.raises(hyst.Error, match=r"PI weight p\[0\] = 1e-320 is too small") as caught:
        hyst.InversePrandtlIshlinskii(model)
    assert "inf" not in str(caught.value)


def test_report_names_the_first_limited_sample():
    """A target out of reach after one in reach: first_limited points at it."""
    model = hyst.Model("pi", {"thresholds": [0.0, 0.3], "weights": [1.0, 0.5], "offset": 0.0})
    inputs, report = model.inverse(input_min=-1.0, input_max=1.0).invert(
        np.array([0.2, 0.4, 5.0, 0.1]))
    assert report.saturated_samples == 1 and report.limited_samples == 1
    assert report.not_invertible_samples == 0
    assert report.first_limited == 2 and report.first_saturated == 2
    assert inputs[2] == 1.0
