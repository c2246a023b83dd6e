"""The model registry from Python: the registry walk, model files, dict forms and hyst.fit."""

import copy
import json

import numpy as np
import pytest

import hyst

PI_PARAMS = {"thresholds": [0.0, 0.3], "weights": [1.0, 0.5], "offset": 0.1}


def probe_input() -> np.ndarray:
    grid = hyst.signals.TimeGrid(600, 1e-3)
    return hyst.signals.generate(
        grid, hyst.signals.DecayingSine(amplitude=1.5, frequency=4.0, time_constant=0.3))


def test_models_lists_the_registry():
    entries = hyst.models()
    assert [e.name for e in entries][0] == "pi"
    for entry in entries:
        assert entry.name and entry.description
        assert isinstance(entry.can_fit, bool)
        assert all(p.name and p.type for p in entry.parameters)
        assert isinstance(entry.example_params, dict)
        assert repr(entry).startswith(f"ModelEntry(name='{entry.name}'")
    pi = hyst.model_entry("pi")
    assert pi.can_fit and {p.name for p in pi.parameters} == {"thresholds", "weights", "offset"}
    assert "operators" in {o.name for o in pi.fit_options}
    assert "ParameterInfo(name=" in repr(pi.parameters[0])
    assert all(p.unit is not None and p.description for p in pi.parameters)
    with pytest.raises(hyst.Error, match="unknown model 'nope' \\(known: pi"):
        hyst.model_entry("nope")


@pytest.mark.parametrize("entry", hyst.models(), ids=lambda e: e.name)
def test_registry_walk(entry, tmp_path):
    """Every registered model: built from its example, simulated, saved, loaded, same output."""
    model = hyst.Model(entry.name, entry.example_params)
    assert model.name == entry.name
    v = probe_input()
    first, mid_run = model.simulate(v[:300], return_state=True)
    assert first.shape == (300,) and np.all(np.isfinite(first))

    # Saved with a mid-run start state: the loaded model continues exactly where the run ended.
    model.state = mid_run
    path = tmp_path / f"{entry.name}.json"
    hyst.save_model(path, model, info={"test": "registry walk"})
    loaded = hyst.load_model(path)
    assert loaded.name == entry.name and loaded.params == model.params
    assert loaded.state == model.state
    np.testing.assert_array_equal(loaded.simulate(v[300:]), model.simulate(v[300:]))

    # From the start, through the dict form.
    model.reset()
    twin = hyst.model_from_dict(hyst.model_to_dict(model))
    np.testing.assert_array_equal(twin.simulate(v), model.simulate(v))
    assert json.loads(path.read_text())["info"] == {"test": "registry walk"}

    if model.has_inverse():
        inverse = model.inverse()
        targets = model.simulate(v)
        inputs, report = inverse.invert(targets)
        assert report.ok
        np.testing.assert_allclose(model.simulate(inputs), targets, rtol=0, atol=1e-12)
        assert isinstance(inverse, hyst.Inverse) and isinstance(inverse.state, dict)


def test_model_params_state_and_copies():
    model = hyst.Model("pi", PI_PARAMS)
    assert model.params == PI_PARAMS
    assert model.state == {"play": [0.0, 0.0]}
    output, state = model.simulate([0.5, 1.0], return_state=True)
    np.testing.assert_allclose(output, [0.7, 1.45], atol=1e-15)
    assert state == pytest.approx({"play": [1.0, 0.7]})
    assert model.state == {"play": [0.0, 0.0]}  # running never changes the model
    np.testing.assert_allclose(model.simulate([0.6, 0.2, -1.0], state=state),
                               [1.05, 0.55, -1.25], atol=1e-15)
    saved = copy.copy(model)
    model.state = state
    assert saved.state == {"play": [0.0, 0.0]}
    model.state = {"play": np.array([0.5, 0.3])}
    assert model.state == {"play": [0.5, 0.3]}
    model.reset()
    assert model.state == {"play": [0.0, 0.0]}
    assert copy.deepcopy(model).params == PI_PARAMS
    assert model.parameter_count() == 3  # two weights and the offset
    assert "Prandtl-Ishlinskii" in model.describe()
    assert repr(model).startswith("hyst.Model('pi', params={")
    started = hyst.Model("pi", PI_PARAMS, state={"play": [0.2, 0.2]})
    assert started.state == {"play": [0.2, 0.2]}
    document = model.to_dict(info={"note": "x"})
    assert document["model"] == "pi" and document["version"] == 1
    assert document["info"] == {"note": "x"}


def test_inverse_from_the_start_state_with_limits():
    model = hyst.Model("pi", PI_PARAMS)
    _, model.state = model.simulate([0.8, -0.2], return_state=True)
    inverse = model.inverse(input_min=-1.0, input_max=1.0)
    inputs, report = inverse.invert([0.5, 5.0])
    assert report.saturated_samples == 1 and report.first_saturated == 1
    assert inputs[1] == 1.0
    np.testing.assert_allclose(model.simulate(inputs[:1]), [0.5], atol=1e-12)
    with pytest.raises(hyst.Error):
        hyst.Model("pi", {"thresholds": [0, 1], "weights": [1, -2]}).inverse()


def test_bad_models_raise_hyst_error_naming_the_field(tmp_path):
    with pytest.raises(hyst.Error, match=r"params.thresholds\[1\]: PI threshold r\[1\] = -0.2"):
        hyst.Model("pi", {"thresholds": [0, -0.2], "weights": [1, 1]})
    with pytest.raises(hyst.Error, match="params"):
        hyst.Model("pi", {"thresholds": [0], "weights": [1], "colour": "red"})
    with pytest.raises(hyst.Error, match="unknown model"):
        hyst.Model("nope", {})
    with pytest.raises(hyst.Error, match="state"):
        hyst.Model("pi", PI_PARAMS).state = {"play": [0.0, 5.0]}
    with pytest.raises(hyst.Error, match="cannot be stored as JSON"):
        hyst.Model("pi", {"thresholds": [0], "weights": [object()]})
    with pytest.raises(hyst.Error, match=r"input\[1\] = nan is not finite"):
        hyst.Model("pi", PI_PARAMS).simulate([0.0, np.nan])

    path = tmp_path / "broken.json"
    path.write_text('{"model": "pi", "version": 1, "params": {"thresholds": [0, 0.3]')
    with pytest.raises(hyst.Error, match="broken.json: not valid JSON"):
        hyst.load_model(path)
    path.write_text(json.dumps({"model": "pi", "version": 2, "params": PI_PARAMS}))
    with pytest.raises(hyst.Error, match="broken.json: version: 2 is not supported"):
        hyst.load_model(path)
    path.write_text(json.dumps({"model": "pi", "version": 1,
                                "params": {"thresholds": [0, 0.3, 0.2], "weights": [1, 1, 1]}}))
    with pytest.raises(hyst.Error, match=r"broken.json: params.thresholds\[2\]"):
        hyst.load_model(path)
    with pytest.raises(hyst.Error, match="cannot open"):
        hyst.load_model(tmp_path / "missing.json")
    with pytest.raises(hyst.Error, match="<dict>: "):
        hyst.model_from_dict({"model": "pi", "params": PI_PARAMS})


def test_fit_through_the_registry(nested_loops):
    truth = hyst.PrandtlIshlinskii([0.0, 0.5, 1.0], [1.0, 0.5, 0.25], offset=-0.2)
    y = truth.simulate(nested_loops)
    model, report = hyst.fit("pi", nested_loops, y, thresholds=[0.0, 0.5, 1.0])
    assert isinstance(model, hyst.Model) and isinstance(report, hyst.FitReport)
    np.testing.assert_allclose(model.params["weights"], [1.0, 0.5, 0.25], atol=1e-8)
    np.testing.assert_allclose(model.simulate(nested_loops), y, atol=1e-8)
    _, report = hyst.fit("pi", nested_loops[:1500], y[:1500], nested_loops, y, operators=np.int64(6),
                         initial_state="virgin", fit_offset=True)
    assert report.validation is not None
    with pytest.raises(hyst.Error, match="colour"):
        hyst.fit("pi", nested_loops, y, colour="red")
    with pytest.raises(hyst.Error, match="given together"):
        hyst.fit("pi", nested_loops, y, validation_output=y)


def test_one_validation_rule_on_the_piezo_amplitudes():
    """hyst.fit predicts a separate record by the stated rule; the README's piezo fit gives the
    8.44 % of docs/results.md (example 02, the library's own PI fitter) in one call."""
    from conftest import shared_data_dir

    path = shared_data_dir() / "piezo_pzt_aixacct_butterfly" / "MeasurementData.mat"
    if not path.exists():
        pytest.skip(f"{path} is missing")
    v15, y15, v1, y1 = (hyst.io.read_mat_vector(str(path), name) for name in
                        ("Vplus_15kv", "Displacement_15kv", "Vplus_1kv", "Displacement_1kv"))
    model, report = hyst.fit("pi", v15, y15, v1, y1, validation_start="periodic",
                             validation_align="first-sample", operators=10,
                             initial_state="periodic")
    assert "periodic steady state" in report.validation_rule
    assert "measured first sample" in report.validation_rule
    # The rule done by hand: one pass from rest for the periodic state, then the prediction,
    # shifted to the measured first sample.
    predictor = copy.copy(model)
    predictor.reset()
    _, periodic = predictor.simulate(v1, return_state=True)
    predicted = predictor.simulate(v1, state=periodic)
    predicted += y1[0] - predicted[0]
    nrmse_percent = 100 * np.sqrt(np.mean((y1 - predicted) ** 2)) / (y1.max() - y1.min())
    assert report.validation.nrmse_percent == pytest.approx(nrmse_percent, rel=1e-12)
    assert report.validation.nrmse_percent == pytest.approx(8.44, abs=0.005)
    # hyst.evaluate scores the saved model on the record by the same rule, to the last digit.
    score = hyst.evaluate(model, v1, y1, validation_start="periodic",
                          validation_align="first-sample")
    assert score["nrmse_range_percent"] == pytest.approx(report.validation.nrmse_percent,
                                                          rel=1e-12)
    np.testing.assert_allclose(score["predicted"], predicted, rtol=1e-12, atol=1e-9)
    std_percent = 100 * np.sqrt(np.mean((y1 - predicted) ** 2)) / np.std(y1)
    assert score["nrmse_std_percent"] == pytest.approx(std_percent, rel=1e-9)
    assert set(score["yardsticks_on_this_record"]) == {"mean", "cubic y(v)"}
    with pytest.raises(hyst.Error, match="'continue' needs the record the model was fitted to"):
        hyst.evaluate(model, v1, y1, validation_start="continue")
    # The domain of the fit part: the 15 kV record's ranges; the 1 kV input lies inside it, the
    # 15 kV input scaled by 2 does not.
    domain = report.domain
    assert isinstance(domain, hyst.FittedDomain) and domain.sample_time is None
    assert (domain.input_min, domain.input_max) == (v15.min(), v15.max())
    assert domain.largest_input_step == pytest.approx(np.abs(np.diff(v15)).max())
    assert 1 < domain.longest_hold_samples < len(v15)
    assert (domain.output_min, domain.output_max) == (y15.min(), y15.max())
    assert domain.samples == len(v15)
    assert domain.check_inputs(v1) == (True, "")
    inside, message = domain.check_inputs(2 * v15)
    assert not inside and "inputs above the fitted range" in message
    assert not domain.check_targets(3 * y15)[0]
    # The default is stated too: the model's initial state, the prediction as it is.
    _, default = hyst.fit("pi", v15, y15, v1, y1, operators=10, initial_state="periodic")
    assert "validation start 'rest'" in default.validation_rule
    assert "validation align 'none'" in default.validation_rule
    with pytest.raises(hyst.Error, match="validation start 'hot' is not known"):
        hyst.fit("pi", v15, y15, v1, y1, validation_start="hot")


def test_schema_defaults_and_every_gpi_fit_option_from_python():
    """Defaults come from the options' table; bounds and starts are keyword arguments."""
    gpi = hyst.model_entry("gpi")
    options = {o.name: o for o in gpi.fit_options}
    assert {"starts", "lower", "upper", "screening_iterations", "function_tolerance"} <= set(options)
    assert options["screening_iterations"].default == "15"
    assert options["initial_state"].default == "rest"
    assert {p.name: p.default for p in hyst.model_entry("pi").parameters}["offset"] == "0"

    v = np.sin(np.linspace(0.0, 4.0 * np.pi, 400))
    y = np.tanh(2.0 * v)
    with pytest.raises(hyst.Error, match=r"fit options\.lower\.a9: unknown field"):
        hyst.fit("gpi", v, y, lower={"a9": 1.0})
    with pytest.raises(hyst.Error, match="GPI fit bounds of tau"):
        hyst.fit("gpi", v, y, lower={"tau": 2.0}, upper={"tau": 1.0})
    model, report = hyst.fit("gpi", v, y, m=4, screening_iterations=1, max_iterations=5,
                             function_tolerance=1e-6, upper={"tau": 0.5})
    # Default screening alone runs 15 iterations from each of the data-derived starts.
    assert model.name == "gpi" and report.iterations <= 20


def _triangle(frequency: float, sample_time: float) -> np.ndarray:
    """Two periods of a 0 -> 1 -> -1 -> 0 triangle."""
    t = np.arange(1, int(round(2 / (frequency * sample_time))) + 1) * sample_time
    return 2 / np.pi * np.arcsin(np.sin(2 * np.pi * frequency * t))


@pytest.mark.parametrize("name", ["pi_creep", "modified_pi_creep"])
def test_fit_records_at_their_own_sample_times(name):
    """One creep model from two rates, each record at its own sample time: the weights of the
    model that made them come back (the same structure given)."""
    params = {"thresholds": [0.0, 0.3], "weights": [1.0, 0.5], "time_constants": [0.1, 1.0],
              "creep_weights": [0.05, 0.02, 0.05, 0.03], "sample_time": 1e-3}
    if name == "modified_pi_creep":
        params.update(pi_offset=0.0, dead_zone_thresholds=[-0.8, 0.0, 0.8],
                      dead_zone_weights=[-0.4, 1.0, -0.4], offset=0.0)
    else:
        params["offset"] = 0.0
    records, times = [], [1e-3, 1e-2]
    for frequency, ts in zip([1.0, 0.1], times):
        moved = hyst.Model(name, dict(params, sample_time=ts))
        v = _triangle(frequency, ts)
        records.append((v, moved.simulate(v)))
    options = {"thresholds": [0.0, 0.3], "time_constants": [0.1, 1.0]}
    if name == "modified_pi_creep":
        # The inverse map's thresholds, S(d_i): the structure that reproduces the data exactly.
        options.update(dead_zone_thresholds=[-0.8, 0.0, 0.8], output_offset=0.0,
                       clamp_output=False)
    model, report = hyst.fit_records(name, records, sample_times=times, **options)
    assert report.model == name and report.fit.samples == sum(len(v) for v, _ in records)
    assert report.fit.nrmse_percent < 1e-4
    assert model.params["sample_time"] == pytest.approx(1e-3)
    np.testing.assert_allclose(model.params["creep_weights"], params["creep_weights"], atol=1e-6)
    np.testing.assert_allclose(model.params["weights"], params["weights"], atol=1e-6)


def test_fit_records_refuses_what_it_cannot_do():
    v = _triangle(1.0, 1e-2)
    with pytest.raises(hyst.Error, match="model 'pi' has no fit of several records "
                                         "\\(models with one: pi_creep, modified_pi_creep"):
        hyst.fit_records("pi", [(v, v)])
    with pytest.raises(hyst.Error, match="model 'butterfly_strain' has no sample time"):
        hyst.fit_records("butterfly_strain", [(v, v), (v, 2 * v)], sample_times=[1e-2, 1e-2])
    with pytest.raises(hyst.Error, match="2 sample times for 1 records"):
        hyst.fit_records("pi_creep", [(v, v)], sample_times=[1e-2, 1e-2])
    assert hyst.model_entry("pi_creep").can_fit_records
    assert not hyst.model_entry("pi").can_fit_records
