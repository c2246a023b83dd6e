"""Relay, play, backlash, stop and dead zone: hand cases, states and bad parameters."""

import copy

import numpy as np
import pytest

import hyst

INPUTS = [1.0, 0.8, 0.0, -1.0, 0.2]


def test_relay_switches_at_its_thresholds():
    relay = hyst.Relay(0.5, -0.5)
    assert (relay.alpha, relay.beta) == (0.5, -0.5)
    out = relay.simulate([0.0, 0.6, 0.0, -0.6, 0.5])
    np.testing.assert_array_equal(out, [-1, 1, 1, -1, 1])
    state = relay.make_state(1.0)
    assert relay.step(state, 0.0) == 1.0
    assert state.output == 1.0
    assert relay.initial_state().output == -1.0
    assert "Relay(alpha=0.5" in repr(relay) and "Relay.State" in repr(state)


def test_relay_rejects_alpha_below_beta():
    with pytest.raises(hyst.Error):
        hyst.Relay(-1.0, 1.0)
    with pytest.raises(hyst.Error):
        hyst.Relay(1.0, 0.0).make_state(0.5)


def test_play_hand_case_and_state_advance():
    play = hyst.Play(0.5)
    assert play.half_width == 0.5
    np.testing.assert_allclose(play.simulate(INPUTS), [0.5, 0.5, 0.5, -0.5, -0.3], atol=1e-15)
    state = play.make_state(0.25)
    play.simulate([0.0, 0.0], state)
    assert state.output == 0.25  # inside the dead band: unchanged
    assert play.step(state, 2.0) == 1.5
    assert play.initial_state().output == 0.0
    assert "Play(half_width=0.5)" == repr(play)


def test_play_rejects_negative_half_width():
    with pytest.raises(hyst.Error, match="-0.1"):
        hyst.Play(-0.1)


def test_backlash_is_a_scaled_play_with_saturation():
    backlash = hyst.Backlash(gain=2.0, half_width=0.5)
    np.testing.assert_allclose(backlash.simulate(INPUTS), [1, 1, 1, -1, -0.6], atol=1e-15)
    saturated = hyst.Backlash(gain=2.0, half_width=0.5, output_max=0.8)
    assert (saturated.gain, saturated.half_width, saturated.output_max) == (2.0, 0.5, 0.8)
    assert saturated.output_min == -np.inf
    np.testing.assert_allclose(saturated.simulate(INPUTS), [0.8, 0.8, 0.8, -1, -0.6], atol=1e-15)
    state = saturated.make_state(0.3)
    assert state.output == 0.3 and saturated.initial_state().output == 0.0
    assert "Backlash(gain=2" in repr(saturated)
    with pytest.raises(hyst.Error):
        hyst.Backlash(gain=0.0)


def test_stop_is_input_minus_play():
    stop, play = hyst.Stop(0.5), hyst.Play(0.5)
    assert stop.half_width == 0.5
    np.testing.assert_allclose(stop.simulate(INPUTS), np.array(INPUTS) - play.simulate(INPUTS),
                               atol=1e-15)
    state = stop.state_from_play(0.2, 0.5)
    assert (state.output, state.last_input) == pytest.approx((0.3, 0.5))
    assert stop.initial_state().last_input == 0.0
    assert "Stop.State" in repr(state) and repr(stop) == "Stop(half_width=0.5)"
    with pytest.raises(hyst.Error):
        stop.state_from_play(0.0, 1.0)  # |v - w| > r


def test_dead_zone_both_signs():
    np.testing.assert_allclose(hyst.DeadZone(0.5).apply([1.0, 0.2, -1.0]), [0.5, 0.0, 0.0])
    np.testing.assert_allclose(hyst.DeadZone(-0.5).apply([1.0, 0.2, -1.0]), [0.0, 0.0, -0.5])
    zone = hyst.DeadZone(0.0)
    assert zone(0.7) == 0.7 and zone.threshold == 0.0
    assert repr(zone) == "DeadZone(threshold=0)"
    with pytest.raises(hyst.Error):
        hyst.DeadZone(float("nan"))


def test_operator_states_are_values():
    play = hyst.Play(0.5)
    state = play.initial_state()
    saved = copy.copy(state)
    play.step(state, 3.0)
    assert state.output == 2.5 and saved.output == 0.0
    assert copy.deepcopy(state).output == 2.5


def test_step_and_simulate_reject_nan_input():
    play = hyst.Play(0.5)
    with pytest.raises(hyst.Error, match=r"input\[2\] = nan is not finite"):
        play.simulate([0.0, 1.0, float("nan")])
    with pytest.raises(hyst.Error, match="input = inf is not finite"):
        play.step(play.initial_state(), float("inf"))
