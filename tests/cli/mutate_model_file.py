"""Bad variants of a valid model file, for the bad-input tests (tests/cli/bad_input_corpus.sh and
python/tests/test_bad_inputs.py).

    python3 mutate_model_file.py EXAMPLE.json OUT_FOLDER

EXAMPLE.json is a model's example file (`hyst models NAME --json`, member "example", or the file
itself). Writes OUT_FOLDER/<model>__<mutation>.json and prints one line per file:
"<file name>\t<text the error must contain>". Only mutations that are wrong for every model are
made (a wrong type, a non-finite number, an unknown field or value, a cut file), so that the list
stays valid for models added later.
"""

import json
import pathlib
import sys

INFINITE = "__INFINITE__"  # replaced by 1e400 in the text: JSON has no infinity literal
OVERFLOW = "number overflow parsing '1e400' at line 1"  # beyond double: rejected when parsing


def variants(document):
    params = document["params"]
    for field, value in params.items():
        where = f"params.{field}"
        if isinstance(value, bool):
            continue
        if isinstance(value, (int, float)):
            yield f"{field}_string", {**params, field: "text"}, where
            yield f"{field}_null", {**params, field: None}, where
            yield f"{field}_infinite", {**params, field: INFINITE}, OVERFLOW
            yield f"{field}_object", {**params, field: {"value": value}}, where
        elif isinstance(value, list) and value and all(isinstance(x, (int, float)) for x in value):
            yield f"{field}_element_string", {**params, field: ["text"] + value[1:]}, where
            yield f"{field}_element_infinite", {**params, field: [INFINITE] + value[1:]}, OVERFLOW
            yield f"{field}_element_null", {**params, field: [None] + value[1:]}, where
            yield f"{field}_nested", {**params, field: [value]}, where
        elif isinstance(value, str):
            yield f"{field}_unknown_value", {**params, field: "no_such_value"}, where
            yield f"{field}_number", {**params, field: 1}, where
    yield "unknown_field", {**params, "no_such_field": 1}, "params.no_such_field"


def main():
    example = json.loads(pathlib.Path(sys.argv[1]).read_text())
    document = example.get("example", example)
    out = pathlib.Path(sys.argv[2])
    out.mkdir(parents=True, exist_ok=True)
    model = document["model"]
    for mutation, params, where in variants(document):
        bad = {key: value for key, value in document.items() if key != "state"}
        bad["params"] = params
        text = json.dumps(bad).replace(f'"{INFINITE}"', "1e400")
        name = f"{model}__{mutation}.json"
        (out / name).write_text(text)
        print(f"{name}\t{where}")
    whole = json.dumps(document, indent=1)
    name = f"{model}__cut.json"
    (out / name).write_text(whole[: len(whole) // 2])
    print(f"{name}\tnot valid JSON")
    name = f"{model}__state_string.json"
    (out / name).write_text(json.dumps({**document, "state": "text"}))
    print(f"{name}\tstate")


if __name__ == "__main__":
    main()
