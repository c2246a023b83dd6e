"""Every file of the bad-input corpus (tests/data/bad/, listed in expected.tsv) and bad variants
of every registered model's example file raise hyst.Error through Python - never another
exception, a crash or a hang - with a message that names the file and the place."""

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import hyst

REPOSITORY = Path(__file__).resolve().parents[2]
BAD = REPOSITORY / "tests" / "data" / "bad"
MUTATE = REPOSITORY / "tests" / "cli" / "mutate_model_file.py"


def corpus():
    for line in (BAD / "expected.tsv").read_text().splitlines():
        if line and not line.startswith("#"):
            name, how, text = line.split("\t")
            yield pytest.param(name, how, text, id=name)


def example_model():
    entry = hyst.model_entry("pi")
    return hyst.Model("pi", entry.example_params)


def use_as_data(path: Path, out: Path):
    """What `hyst simulate` and `hyst fit` do with a data file: read the columns v and y, run a
    model over v and write the result."""
    if path.suffix == ".mat":
        names = hyst.io.list_mat_variables(path)
        columns = {name: hyst.io.read_mat_vector(path, name) for name in names}
    elif path.suffix == ".hys":
        columns = hyst.io.read_micromag_loop(path).to_dict()
    else:
        columns = hyst.io.read_csv(path)
    if "v" not in columns:
        raise hyst.Error(f"{path.name}: no column 'v'")
    v = columns["v"]
    if "y" in columns and len(columns["y"]) != len(v):
        raise hyst.Error(f"{path.name}: 'v' and 'y' differ in length")
    if len(v) == 0:
        raise hyst.Error(f"{path.name}: no samples")
    hyst.io.write_csv(out, {"v": v, "y": example_model().simulate(v)})


@pytest.mark.parametrize("name,how,text", corpus())
def test_corpus_file_raises_hyst_error(name, how, text, tmp_path):
    path = BAD / name
    with pytest.raises(hyst.Error) as error:
        if how == "model":
            hyst.load_model(path).simulate([0.0, 0.5, 1.0, 0.2])
        else:
            use_as_data(path, tmp_path / "out.csv")
            if how == "fit":  # data that reads, but cannot be fitted (constant, 2 samples)
                columns = hyst.io.read_csv(path)
                hyst.fit("pi", columns["v"], columns["y"])
    message = str(error.value)
    assert message and "\n" not in message.strip()


def test_every_registered_models_bad_variants_raise_hyst_error(tmp_path):
    tried = 0
    for entry in hyst.models():
        example = tmp_path / f"{entry.name}.json"
        document = hyst.model_to_dict(hyst.Model(entry.name, entry.example_params))
        example.write_text(json.dumps(document))
        listing = subprocess.run(
            [sys.executable, str(MUTATE), str(example), str(tmp_path / "mutated")],
            check=True, capture_output=True, text=True).stdout
        for line in listing.splitlines():
            name, text = line.split("\t")
            with pytest.raises(hyst.Error) as error:
                hyst.load_model(tmp_path / "mutated" / name)
            assert name in str(error.value) and text in str(error.value), str(error.value)
            tried += 1
    assert tried > 0


def test_binary_noise_raises_hyst_error(tmp_path):
    noise = bytes((k * 7919 + 13) % 256 for k in range(4096))
    for suffix, read in ((".csv", hyst.io.read_csv), (".json", hyst.load_model),
                         (".mat", hyst.io.list_mat_variables)):
        path = tmp_path / f"noise{suffix}"
        path.write_bytes(noise)
        with pytest.raises(hyst.Error):
            read(path)


# Limits (include/hyst/io/limits.hpp): JSON nesting, duplicate keys, input bytes, sample counts.

def nested_dict(depth):
    """{"a": {"a": ... 1}} built without recursion."""
    value = 1
    for _ in range(depth):
        value = {"a": value}
    return value


def test_deeply_nested_python_values_raise_hyst_error():
    # 30 000 levels used to end the interpreter (stack overflow in the dict -> JSON conversion).
    deep = nested_dict(30000)
    with pytest.raises(hyst.Error, match="nested deeper than 256 levels"):
        hyst.Model("pi", deep)
    with pytest.raises(hyst.Error, match=r"^info\.a\.a.*nested deeper than 256 levels"):
        hyst.model_to_dict(example_model(), info=deep)
    with pytest.raises(hyst.Error, match="nested deeper than 256 levels"):
        hyst.ActuatorConfig(deep)
    with pytest.raises(hyst.Error, match="nested deeper than 256 levels"):
        hyst.fit("pi", [0.0, 1.0, 0.0, 1.0], [0.0, 1.0, 0.5, 1.0], operators=deep)
    endless = []
    endless.append(endless)  # a list that contains itself
    with pytest.raises(hyst.Error, match=r"thresholds\[0\]\[0\].*nested deeper than 256"):
        hyst.Model("pi", {"thresholds": endless, "weights": [1.0]})
    # 255 levels below the params object are still fine to convert (and then rejected as params).
    with pytest.raises(hyst.Error, match="expected"):
        hyst.Model("pi", {"thresholds": nested_dict(254), "weights": [1.0]})


def test_model_file_nested_100000_levels_names_file_line_column(tmp_path):
    path = tmp_path / "deep.json"
    path.write_text('{"model": "pi", "version": 1, "params": {"thresholds": [0], '
                    '"weights": [1]},\n "info": ' + '{"a": ' * 100000 + "1" + "}" * 100000 + "}")
    with pytest.raises(hyst.Error,
                       match=r"deep\.json:2:1540: JSON nesting deeper than 256 levels"):
        hyst.load_model(path)


def test_duplicate_keys_name_key_and_both_places(tmp_path):
    path = tmp_path / "dup.json"
    path.write_text('{"model": "pi", "version": 1,\n "params": {"thresholds": [0, 0.5], '
                    '"weights": [1, 0.5],\n   "weights": [2, 1]}}')
    with pytest.raises(hyst.Error) as error:
        hyst.load_model(path)
    assert str(error.value).endswith(
        "dup.json:3:4: duplicate key 'weights' in 'params' (first at line 2, column 37)")


def test_endless_stream_stops_at_the_input_limit(tmp_path):
    fifo = tmp_path / "endless.csv"
    os.mkfifo(fifo)
    writer = subprocess.Popen(["sh", "-c", f"cat /dev/zero > '{fifo}'"],
                              stderr=subprocess.DEVNULL)
    try:
        with pytest.raises(hyst.Error) as error:
            hyst.io.read_csv(fifo)
        assert str(error.value) == (f"cannot read '{fifo}': it holds more than 268435456 bytes, "
                                    "the limit of one input (an endless stream?)")
    finally:
        writer.kill()
        writer.wait()


def test_resampling_step_beyond_the_sample_limit_raises_hyst_error():
    v = [0.0, 1.0, 0.0, 1.0, 0.0] * 4
    y = [0.0, 0.8, 0.1, 0.9, 0.0] * 4
    for step in (1e-6, 1e-17, 1e-300):
        with pytest.raises(hyst.Error, match="more than the limit of 10000000"):
            hyst.fit("pi", v, y, resample="input-grid", resample_step=step)


# Counts given to the dynamic models, bounded before they cost anything, and their messages.

def lag():
    return hyst.StateSpace([[0.5]], [[1.0]], [[1.0]], [[0.0]], sample_time=1.0)


def lag_experiment(realisations=1, periods=2, samples=16):
    """(N, channel, realisation, period) arrays of the lag above in periodic steady state."""
    period = np.sin(2 * np.pi * np.arange(samples) / samples)
    u = np.empty((samples, 1, realisations, periods))
    u[:] = period[:, None, None, None]
    y = np.empty_like(u)
    y[:] = lag().simulate_periodic(period[:, None])[:, :, None, None]
    return u, y


def test_evaluate_without_data_says_what_is_missing():
    u, y = lag_experiment()
    with pytest.raises(hyst.Error, match=r"^input is missing \(None\)"):
        hyst.evaluate(lag(), None, None)
    with pytest.raises(hyst.Error, match=r"^output is missing \(None\)"):
        hyst.evaluate(lag(), u, None)
    with pytest.raises(hyst.Error, match=r"^input is a single number"):
        hyst.evaluate(lag(), 1.0, y)


def test_a_non_finite_output_is_named_by_its_sample_not_called_constant():
    u, y = lag_experiment()
    y[3, 0, 0, 1] = np.inf
    with pytest.raises(hyst.Error) as error:
        hyst.evaluate(lag(), u, y, periodic=True)
    assert str(error.value) == ("score: output: the value at (N = 3, channel = 0, realisation = 0, "
                                "period = 1) is inf; every sample must be finite")


def test_arrays_beyond_the_limit_of_files_are_refused_before_they_are_copied():
    # 2^26 x 3 samples as a view of one value (no memory): once a bare MemoryError after copying.
    huge = np.broadcast_to(np.float32(1.0), (1 << 26, 1, 3, 1))
    with pytest.raises(hyst.Error, match=r"^input has 201326592 values, more than the limit of "
                                         r"33554432 values of one array"):
        hyst.evaluate(lag(), huge, huge)
    with pytest.raises(hyst.Error, match="more than the limit of 33554432 values"):
        example_model().simulate(np.empty((1 << 25) + 1))  # pages never touched
    with pytest.raises(hyst.Error, match="^input has 201326592 values, more than the limit"):
        lag().simulate(np.broadcast_to(1.0, (1 << 26, 3)))
    with pytest.raises(hyst.Error, match=r"^input is missing \(None\)"):
        lag().simulate(None)


def test_fit_counts_have_limits():
    experiment = lag_experiment()
    with pytest.raises(hyst.Error, match="100000 threshold_fractions are above the limit of 100"):
        hyst.fit_hysteretic_lfr(lag(), [experiment],
                                threshold_fractions=list(np.linspace(0, 1, 100000)))
    with pytest.raises(hyst.Error, match="1001 threshold_fractions are above the limit of 100"):
        hyst.fit_hammerstein(lag(), [experiment],
                             threshold_fractions=list(np.linspace(0, 1, 1001)))
    with pytest.raises(hyst.Error, match="1001 records, more than the limit of 1000"):
        hyst.fit_hysteretic_lfr(lag(), [experiment] * 1001)
    bla = hyst.estimate_bla([experiment], 1.0)
    with pytest.raises(hyst.Error, match=r"order 101 must be in 1\.\.100"):
        hyst.fit_state_space(bla, 101)
    v = np.sin(np.linspace(0, 20, 200))
    with pytest.raises(hyst.Error, match="^5000 records, more than the limit of 1000 records"):
        hyst.fit_records("modified_pi_creep", [(v, v)] * 5000)


def test_model_sizes_have_limits():
    n = 501
    with pytest.raises(hyst.Error, match="order n = 501 is above the limit of 500 states"):
        hyst.StateSpace(np.zeros((n, n)), np.zeros((n, 1)), np.zeros((1, n)), [[1.0]])
    with pytest.raises(hyst.Error, match="257 inputs are above the limit of 256"):
        hyst.StateSpace([[0.5]], np.zeros((1, 257)), [[1.0]], np.zeros((1, 257)))
    linear = hyst.StateSpace([[0.5]], [[1.0, 1.0]], [[1.0], [1.0]], np.zeros((2, 2)))
    plays = hyst.model_from_dict({"model": "pi", "version": 1, "params": {
        "thresholds": list(np.arange(1001) / 1001), "weights": [0.001] * 1001}})
    with pytest.raises(hyst.Error, match="1002 parameters, more than the limit of 1000"):
        hyst.HystereticLfr(linear, 1, [plays])
    n = 101
    block = hyst.StateSpace(np.zeros((n, n)), np.zeros((n, 2)), np.zeros((2, n)), np.zeros((2, 2)))
    one_play = hyst.model_from_dict({"model": "pi", "version": 1, "params": {
        "thresholds": [0.0], "weights": [1.0]}})
    with pytest.raises(hyst.Error, match="linear block has 101 states, more than the limit of 100"):
        hyst.HystereticLfr(block, 1, [one_play])
    # A fit from such a linear model is refused before it starts, not when its result is built.
    wide = hyst.StateSpace(np.zeros((n, n)), np.ones((n, 1)), np.ones((1, n)), [[0.0]])
    with pytest.raises(hyst.Error, match="the linear model has 101 states, more than the limit of "
                                         "100 of a hysteretic LFR's linear block"):
        hyst.fit_hysteretic_lfr(wide, [lag_experiment()])


def test_a_diverging_loop_says_so_instead_of_nan():
    # w = -50 z: the loop's pole at 0.5 - 50 is far outside the unit circle.
    linear = hyst.StateSpace([[0.5]], [[1.0, 1.0]], [[1.0], [1.0]], np.zeros((2, 2)))
    negative = hyst.model_from_dict({"model": "pi", "version": 1, "params": {
        "thresholds": [0.0, 0.5], "weights": [-50.0, 0.1]}})
    lfr = hyst.HystereticLfr(linear, 1, [negative])
    period = np.sin(2 * np.pi * np.arange(64) / 64)[:, None]
    with pytest.raises(hyst.Error) as error:
        lfr.simulate_periodic(period)
    message = str(error.value)
    assert message.startswith("hysteretic LFR: the loop diverges: in period 1 ")
    assert "nan" not in message


@pytest.mark.parametrize("fit", [hyst.fit_hysteretic_lfr, hyst.fit_hammerstein])
@pytest.mark.parametrize("which,value", [("input", np.nan), ("output", np.inf)])
def test_simulation_error_fits_refuse_non_finite_samples_in_the_warm_up_period(fit, which, value):
    u, y = lag_experiment()
    (u if which == "input" else y)[5, 0, 0, 0] = value  # period 0: driven, not scored
    with pytest.raises(hyst.Error) as error:
        fit(lag(), [(u, y)], max_iterations=1)
    assert str(error.value).endswith(
        f"experiment 0 {which}: the value at (N = 5, channel = 0, realisation = 0, period = 0) "
        f"is {value}; every sample must be finite")


def test_a_failed_allocation_is_a_memory_error_naming_what_was_built():
    # In a child process whose address space ends 300 MB after the 256 MiB array is made: the
    # copies of it that arranging the periodic signals makes cannot both fit.
    script = """
import resource, numpy as np, hyst
u = np.ones((1 << 25, 1))
size = int(open("/proc/self/status").read().split("VmSize:")[1].split()[0]) * 1024
resource.setrlimit(resource.RLIMIT_AS, (size + 300_000_000, resource.RLIM_INFINITY))
try:
    hyst.evaluate(hyst.StateSpace([[0.5]], [[1.0]], [[1.0]], [[0.0]]), u, u)
except MemoryError as error:
    print(error)
"""
    child = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                           timeout=60, env=os.environ)
    assert child.stdout.strip() == ("out of memory while arranging input (33554432 values) as "
                                    "periodic signals"), child.stderr
