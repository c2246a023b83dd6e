"""The hysteretic actuator from Python: configurations, closed loop, comparison, PID."""

import json
import math
import shutil
from pathlib import Path

import numpy as np
import pytest

import hyst

CONFIG_DIR = Path(__file__).resolve().parents[2] / "examples" / "config"


@pytest.fixture
def msma() -> hyst.ActuatorConfig:
    return hyst.load_actuator_config(CONFIG_DIR / "msma_assumed.json")


def test_linearised_plant_matches_the_reference_check(msma):
    plant = msma.linearised_plant()
    assert plant.dc_gain == pytest.approx(6.25e-5, rel=1e-12)  # msma_plant_check.py
    # x[20], x[100] of msma_plant_check.py (1 V step, 1 ms delay, h = 0.1 ms)
    x = plant.step_response([20e-4, 100e-4])
    assert x[0] == pytest.approx(1.572397e-06, rel=1e-6)
    assert x[1] == pytest.approx(4.260536e-05, rel=1e-6)
    poles = plant.poles()
    assert poles[0] == pytest.approx(-2.0 / 0.015)
    assert abs(poles[1]) == pytest.approx(1232.8828, rel=1e-7)
    assert abs(plant.frequency_response(0.0)) == pytest.approx(6.25e-5)
    assert msma.sample_time == 1e-4


def test_linearised_plant_by_hand():
    # R = 1, L = 1, k_F = 1, m = 1, b = 0, k = 1, no delay: x(t) = 1 - e^{-t}/2 - (cos t + sin t)/2
    plant = hyst.LinearisedPlant(resistance=1, inductance=1, force_gain=1, mass=1, damping=0,
                                 stiffness=1)
    t = np.array([0.5, 1.0, 3.0])
    expected = 1 - np.exp(-t) / 2 - (np.cos(t) + np.sin(t)) / 2
    assert plant.step_response(t) == pytest.approx(expected, rel=1e-12)


def test_closed_loop_settles_and_open_loop_does_not(msma):
    reference = np.full(2000, 5e-4)
    closed = msma.simulate(reference, "pid+ff")
    open_loop = msma.simulate(reference, "open_loop")
    assert set(closed) == {"reference", "measured", "position", "current_reference", "current",
                           "force", "voltage"}
    assert abs(closed["measured"][-1] - 5e-4) < 1e-6
    # Without compensation the static current k r / k_F gives the hysteretic force, not k r.
    assert abs(open_loop["measured"][-1] - 5e-4) > 1e-5
    assert np.all(closed["current"] >= 0.0) and np.all(closed["current"] <= 8.0)


def test_comparison_ranks_compensation_above_open_loop(msma):
    rows, markdown = msma.compare()
    assert len(rows) == 24 and "| triangle | pid_feedforward |" in markdown
    by_key = {(row["reference"], row["strategy"]): row for row in rows}
    for reference in ("sine_2Hz_full", "sine_10Hz_full", "triangle"):
        open_loop = by_key[(reference, "open_loop")]["rms_error"]
        pid = by_key[(reference, "pid")]["rms_error"]
        combined = by_key[(reference, "pid_feedforward")]["rms_error"]
        assert combined < pid < open_loop, reference
    assert math.isnan(by_key[("triangle", "pid")]["settling_time"])
    assert not math.isnan(by_key[("step", "pid")]["settling_time"])


def test_comparison_plots(msma, tmp_path):
    if shutil.which("gnuplot") is None:
        pytest.skip("gnuplot not installed")
    msma.compare(plot_folder=tmp_path)
    for name in ("tracking_step.png", "error_triangle.png", "tracking_sine_10Hz_half.png"):
        assert (tmp_path / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_config_from_dict_and_errors():
    document = json.loads((CONFIG_DIR / "piezo_stack.json").read_text())
    config = hyst.ActuatorConfig(document)
    assert config.hysteresis_model == "pi"
    document["mechanics"]["stiffness"] = -1.0
    with pytest.raises(hyst.Error, match=r"mechanics\.stiffness"):
        hyst.ActuatorConfig(document)
    with pytest.raises(hyst.Error, match="unknown control strategy"):
        config.simulate([0.0, 1e-6], "fastest")
    with pytest.raises(hyst.Error, match="not finite"):
        config.simulate([0.0, float("nan")])


def test_force_model_chosen_by_name(msma):
    # An Ikuta SMA force (heating 3..7 A raises it to 76 N, cooling 4..1 A lowers it to 0): the
    # numerical inverse is the feedforward, and the closed loop settles as with the GPI.
    document = json.loads((CONFIG_DIR / "msma_assumed.json").read_text())
    document["hysteresis"] = {"model": "ikuta_sma", "params": {
        "martensite_finish": 1.0, "martensite_start": 4.0, "austenite_start": 3.0,
        "austenite_finish": 7.0, "output_austenite": 76.0, "output_martensite": 0.0}}
    config = hyst.ActuatorConfig(document)
    assert config.hysteresis_model == "ikuta_sma"
    closed = config.simulate(np.full(2000, 5e-4), "pid+ff")
    assert abs(closed["measured"][-1] - 5e-4) < 1e-6
    document["hysteresis"] = {"model": "maxwell_slip",
                              "params": {"stiffness": [2.0], "break_away": [2.0]}}
    with pytest.raises(hyst.Error, match=r"hysteresis\.params\.linear_stiffness: .*> 0"):
        hyst.ActuatorConfig(document)


def test_pid_terms_and_anti_windup():
    pid = hyst.Pid(kp=2.0, ki=50.0, period=1e-3)
    outputs = [pid.step(1.5, 1.0) for _ in range(10)]
    # u[n] = kp e + n ki h e with e = 0.5
    assert outputs == pytest.approx([1.0 + n * 0.025 for n in range(10)])
    held = hyst.Pid(ki=100.0, output_min=-1.0, output_max=1.0, anti_windup="clamping",
                    period=1e-3)
    free = hyst.Pid(ki=100.0, output_min=-1.0, output_max=1.0, anti_windup="none", period=1e-3)
    for _ in range(100):
        held.step(5.0, 0.0)
        free.step(5.0, 0.0)
    assert free.integral == pytest.approx(50.0)
    # Clamping adds ki h e = 0.5 per sample until the output exceeds the limit: 0.5, 1.0, 1.5.
    assert held.integral == pytest.approx(1.5)
    assert hyst.Pid(kp=2.0, ki=4.0, period=1e-3).tracking_time == pytest.approx(0.5)  # Ti
    pid.reset()
    assert pid.integral == 0.0
    with pytest.raises(hyst.Error, match="anti-windup"):
        hyst.Pid(anti_windup="sometimes", period=1e-3)


def test_tracking_metrics_of_a_hand_made_response():
    metrics = hyst.tracking_metrics([0, 1, 1, 1, 1, 1, 1, 1], [0, 0, 0.8, 1.2, 1.05, 1.01, 0.995, 1],
                                    [0, 2, 2, 2, 2, 2, 2, 2], 1.0, step=(1.0, 0.0, 1.0))
    assert metrics["overshoot"] == pytest.approx(20.0)
    assert metrics["settling_time"] == pytest.approx(4.0)
    assert metrics["max_error"] == pytest.approx(1.0)
