"""Every public name of the module (functions, classes, their methods and attributes) is used
somewhere in these tests: a binding added without a test fails here."""

import inspect
import re
from pathlib import Path

import hyst

# Attributes every Python exception or enum has, not bindings of hyst.
INHERITED = set(dir(Exception)) | {"name", "value"}


def public_names():
    for module in (hyst, hyst.signals, hyst.io, hyst.data):
        for name in dir(module):
            obj = getattr(module, name)
            if name.startswith("_") or inspect.ismodule(obj):
                continue
            yield f"{module.__name__}.{name}", name
            if inspect.isclass(obj):
                for attribute in dir(obj):
                    if not attribute.startswith("_") and attribute not in INHERITED:
                        yield f"{module.__name__}.{name}.{attribute}", attribute


def test_every_binding_is_used_in_a_test():
    here = Path(__file__).resolve().parent
    text = "\n".join(path.read_text() for path in here.glob("test_*.py") if path.name != Path(
        __file__).name)
    unused = [full for full, name in public_names() if not re.search(rf"\b{name}\b", text)]
    assert unused == []

