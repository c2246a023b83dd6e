"""The type stubs shipped beside the module (hyst/*.pyi, py.typed): they parse, declare every
binding, and a type checker (mypy, Debian's python3-mypy) reads them: right calls pass, wrong
ones are named."""

import ast
import inspect
import os
import subprocess
import sys
from pathlib import Path

import pytest

import hyst

PACKAGE = Path(hyst.__file__).resolve().parent
MODULES = {"__init__.pyi": hyst, "io.pyi": hyst.io, "data.pyi": hyst.data,
           "signals.pyi": hyst.signals}


def declared(tree):
    """Top-level names of a stub, and the member names of each class (nested classes too)."""
    names, members = set(), {}

    def visit_class(node, prefix):
        qualified = f"{prefix}{node.name}"
        names.add(qualified)
        members[qualified] = set()
        for item in node.body:
            if isinstance(item, (ast.FunctionDef, ast.ClassDef)):
                members[qualified].add(item.name)
            elif isinstance(item, ast.AnnAssign):
                members[qualified].add(item.target.id)
            if isinstance(item, ast.ClassDef):
                visit_class(item, f"{qualified}.")

    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            visit_class(node, "")
        elif isinstance(node, ast.FunctionDef):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            names.add(node.target.id)
        elif isinstance(node, ast.ImportFrom):
            names.update(alias.asname or alias.name for alias in node.names)
    return names, members


def test_the_marker_and_every_stub_are_beside_the_module():
    assert (PACKAGE / "py.typed").is_file()
    for name in MODULES:
        ast.parse((PACKAGE / name).read_text(), filename=name)


@pytest.mark.parametrize("stub", sorted(MODULES))
def test_every_binding_is_declared(stub):
    names, members = declared(ast.parse((PACKAGE / stub).read_text()))
    module = MODULES[stub]
    missing = []
    for name in dir(module):
        obj = getattr(module, name)
        if name.startswith("_") or inspect.ismodule(obj):
            continue
        if name not in names:
            missing.append(name)
        elif inspect.isclass(obj) and name in members and name != "Error":
            for attribute in vars(obj):
                if not attribute.startswith("_") and attribute not in members[name]:
                    missing.append(f"{name}.{attribute}")
    assert missing == []


def mypy(tmp_path, source):
    script = tmp_path / "use_hyst.py"
    script.write_text(source)
    environment = dict(os.environ, PYTHONPATH=str(PACKAGE.parent))
    return subprocess.run([sys.executable, "-m", "mypy", "--cache-dir", str(tmp_path / "cache"),
                           "--no-error-summary", str(script)], capture_output=True, text=True,
                          env=environment, check=False)


def test_a_type_checker_reads_the_stubs(tmp_path):
    pytest.importorskip("mypy")
    right = mypy(tmp_path, """
import numpy as np
import hyst
from hyst import io

v = np.sin(np.linspace(0.0, 12.0, 200))
result = hyst.fit("pi", v, v, detrend=False)
model, report = result
nrmse: float = report.fit.nrmse_percent
pi = hyst.PrandtlIshlinskii([0.0, 0.5], [1.0, 0.5])
y = pi.simulate(v, pi.initial_state())
grid = hyst.signals.TimeGrid(100, 1e-3)
table = io.read_csv("x.csv")
import hyst.batch
rows = hyst.batch.fit("d/*.csv", "pi", input="v", output="y", out="fits", workers=0,
                      options={"operators": 12})
seconds: float = rows[0].seconds
""")
    assert right.returncode == 0, right.stdout + right.stderr
    wrong = mypy(tmp_path, """
import hyst
hyst.fit(1, [0.0], [0.0])
hyst.signals.TimeGrid(0.5)
text: str = hyst.PrandtlIshlinskii([0.0], [1.0]).initial_state()
import hyst.batch
hyst.batch.fit("d/*.csv", "pi", input=1, output="y", out="fits")
""")
    assert wrong.returncode == 1
    assert 'Argument 1 to "fit" has incompatible type "int"; expected "str"' in wrong.stdout
    assert 'Argument 1 to "TimeGrid" has incompatible type "float"; expected "int"' in wrong.stdout
    assert 'has type "State"' in wrong.stdout, wrong.stdout
    assert 'Argument "input" to "fit" has incompatible type "int"; expected "str"' in wrong.stdout


def test_the_batch_module_is_typed(tmp_path):
    """hyst.batch is plain Python: its own annotations are what mypy reads, so they must hold."""
    pytest.importorskip("mypy")
    environment = dict(os.environ, PYTHONPATH=str(PACKAGE.parent))
    result = subprocess.run([sys.executable, "-m", "mypy", "--cache-dir", str(tmp_path / "cache"),
                             "--disallow-untyped-defs", "-m", "hyst.batch"],
                            capture_output=True, text=True, env=environment, check=False)
    assert result.returncode == 0, result.stdout + result.stderr
