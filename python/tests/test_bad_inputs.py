"""Every file of the bad-input corpus (tests/data/bad/, listed in expected.tsv) and bad variants
of every registered model's example file raise hyst.Error through Python - never another
exception, a crash or a hang - with a message that names the file and the place."""

import json
import subprocess
import sys
from pathlib import Path

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
