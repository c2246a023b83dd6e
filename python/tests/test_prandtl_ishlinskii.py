"""The Prandtl-Ishlinskii model: the hand case, states, arrays and error messages."""

import copy

import numpy as np
import pytest

import hyst

HAND_INPUT = [0.5, 1.0, 0.6, 0.2, -1.0]
HAND_OUTPUT = [0.7, 1.45, 1.05, 0.55, -1.25]


def test_hand_case(hand_pi):
    np.testing.assert_allclose(hand_pi.simulate(HAND_INPUT), HAND_OUTPUT, rtol=0, atol=1e-15)


def test_step_by_step_equals_simulate_and_advances_the_state(hand_pi):
    state = hand_pi.initial_state()
    outputs = [hand_pi.step(state, v) for v in HAND_INPUT]
    np.testing.assert_allclose(outputs, HAND_OUTPUT, atol=1e-15)
    np.testing.assert_allclose(state.play, [-1.0, -0.7], atol=1e-15)
    assert hand_pi.output(state) == pytest.approx(-1.25)

    # simulate() advances a given state: two halves equal the whole.
    state = hand_pi.initial_state()
    first = hand_pi.simulate(HAND_INPUT[:2], state)
    second = hand_pi.simulate(HAND_INPUT[2:], state)
    np.testing.assert_allclose(np.concatenate([first, second]), HAND_OUTPUT, atol=1e-15)


def test_parameters_are_read_only_views(hand_pi):
    assert hand_pi.offset == 0.1
    assert hand_pi.size() == len(hand_pi) == 2
    for array, expected in ((hand_pi.thresholds, [0.0, 0.3]), (hand_pi.weights, [1.0, 0.5])):
        assert isinstance(array, np.ndarray) and array.dtype == np.float64
        np.testing.assert_array_equal(array, expected)
        assert not array.flags.writeable
        with pytest.raises(ValueError):
            array[0] = 7.0
    # A view of the model's own memory, which it keeps alive.
    assert np.shares_memory(hand_pi.weights, hand_pi.weights)
    weights = hyst.PrandtlIshlinskii([0.0, 1.0], [2.0, 3.0]).weights
    np.testing.assert_array_equal(weights, [2.0, 3.0])


def test_outputs_are_writeable_float64_arrays_that_own_their_memory(hand_pi):
    out = hand_pi.simulate(np.array(HAND_INPUT))
    assert isinstance(out, np.ndarray)
    assert out.dtype == np.float64 and out.shape == (5,) and out.flags.writeable
    assert out.flags.c_contiguous
    assert out.base is not None  # the moved C++ vector, owned through a capsule: no copy
    out[0] = 42.0
    assert out[0] == 42.0
    assert hand_pi.simulate([]).shape == (0,)


def test_inputs_of_any_numeric_kind(hand_pi):
    expected = hand_pi.simulate(HAND_INPUT)
    np.testing.assert_array_equal(hand_pi.simulate(np.array(HAND_INPUT, dtype=np.float32)),
                                  hand_pi.simulate(np.float32(HAND_INPUT).astype(np.float64)))
    strided = np.repeat(np.array(HAND_INPUT), 2)[::2]  # a non-contiguous view
    np.testing.assert_array_equal(hand_pi.simulate(strided), expected)
    np.testing.assert_array_equal(hand_pi.simulate(tuple(HAND_INPUT)), expected)
    with pytest.raises(hyst.Error, match="one-dimensional"):
        hand_pi.simulate(np.zeros((2, 3)))


def test_states(hand_pi):
    rest = hand_pi.state_at_rest(0.4)
    np.testing.assert_array_equal(rest.play, [0.4, 0.4])
    assert len(rest) == 2
    state = hand_pi.make_state([0.5, 0.3])
    assert state == hand_pi.make_state(np.array([0.5, 0.3]))
    assert not state.play.flags.writeable  # a snapshot; states change through step/simulate
    assert repr(state) == "PrandtlIshlinskii.State(play=[0.5, 0.3])"

    copied = copy.copy(state)
    hand_pi.step(state, 2.0)
    np.testing.assert_array_equal(copied.play, [0.5, 0.3])
    assert copy.deepcopy(state) == state and copied != state
    with pytest.raises(TypeError):
        hyst.PrandtlIshlinskii.State()  # states come from a model


def test_make_state_rejects_unreachable_states(hand_pi):
    with pytest.raises(hyst.Error, match="no input history reaches this state"):
        hand_pi.make_state([0.0, 1.0])
    with pytest.raises(hyst.Error, match="same length"):
        hand_pi.make_state([0.0, 0.1, 0.2])


def test_a_state_of_another_model_is_rejected(hand_pi):
    other = hyst.PrandtlIshlinskii([0.0, 0.1, 0.2], [1.0, 1.0, 1.0])
    with pytest.raises(hyst.Error, match="state has 3 play outputs but the model has 2"):
        hand_pi.simulate([1.0], other.initial_state())
    with pytest.raises(hyst.Error, match="state has 3 play outputs"):
        hand_pi.step(other.initial_state(), 1.0)


def test_invertibility():
    assert hyst.PrandtlIshlinskii([0.0, 0.3], [1.0, 0.5]).is_invertible()
    assert not hyst.PrandtlIshlinskii([0.0, 0.3], [1.0, -1.5]).is_invertible()
    assert not hyst.PrandtlIshlinskii([0.0, 0.3], [0.0, 1.0]).is_invertible()


@pytest.mark.parametrize(
    "thresholds, weights, offset, message, field",
    [
        ([0.0, 0.5, 0.2], [1, 1, 1], 0.0, r"PI threshold r\[2\] = 0.2 must be > r\[1\] = 0.5",
         "thresholds[2]"),
        ([0.1, 0.5], [1, 1], 0.0, r"PI threshold r\[0\] = 0.1 must be 0", "thresholds[0]"),
        ([0.0, 0.5], [1, float("nan")], 0.0, r"PI weight p\[1\] = nan is not finite",
         "weights[1]"),
        ([0.0, 0.5], [1.0], 0.0, "PI has 2 thresholds r but 1 weights p", "weights"),
        ([], [], 0.0, "PI thresholds r is empty", "thresholds"),
        ([0.0], [1.0], float("inf"), "PI offset = inf is not finite", "offset"),
    ],
)
def test_bad_parameters_raise_hyst_error_naming_them(thresholds, weights, offset, message, field):
    with pytest.raises(hyst.Error, match=message) as error:
        hyst.PrandtlIshlinskii(thresholds, weights, offset=offset)
    assert error.value.field == field
    assert isinstance(error.value, Exception)


def test_error_without_a_field_and_nan_input_index(hand_pi):
    with pytest.raises(hyst.Error, match=r"input\[3\] = nan is not finite") as error:
        hand_pi.simulate([0.0, 0.1, 0.2, np.nan, 0.4])
    assert error.value.field is None
    assert str(error.value) == "input[3] = nan is not finite"


def test_uniform_thresholds():
    np.testing.assert_allclose(hyst.uniform_thresholds(4, 0.25), [0, 0.25, 0.5, 0.75])
    with pytest.raises(hyst.Error, match="spacing = -1 must be > 0"):
        hyst.uniform_thresholds(3, -1.0)


def test_repr_and_copy(hand_pi):
    assert repr(hand_pi) == "PrandtlIshlinskii(thresholds=[0, 0.3], weights=[1, 0.5], offset=0.1)"
    big = hyst.PrandtlIshlinskii(hyst.uniform_thresholds(20, 0.5), np.ones(20))
    assert repr(big).startswith("PrandtlIshlinskii(thresholds=[0, 0.5, 1, 1.5, 2, 2.5, ..., 9.5], ")
    twin = copy.deepcopy(hand_pi)
    np.testing.assert_array_equal(twin.simulate(HAND_INPUT), hand_pi.simulate(HAND_INPUT))
