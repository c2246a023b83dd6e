"""Every public callable of the package has a signature that inspect.signature() reads, with a
typed return value, and the runtime signatures (pybind11's signature lines, the package's Python
wrappers) agree with the shipped stubs (hyst/*.pyi) parameter by parameter and in the return
type."""

import ast
import inspect
import re
import sys
from pathlib import Path

import pytest

import hyst
import hyst.batch
from hyst import _signatures

PACKAGE = Path(hyst.__file__).resolve().parent
STUBS = {"hyst": "__init__.pyi", "hyst.io": "io.pyi", "hyst.data": "data.pyi",
         "hyst.signals": "signals.pyi"}
BOUND = (hyst, hyst.io, hyst.data, hyst.signals)
# Return annotations that say nothing of what comes back (pybind11 writes them for py::dict,
# py::tuple, py::list, py::object), and C++ names pybind11 could not translate.
UNTYPED = re.compile(r"^(list|dict|tuple|object|handle|Any)$|::")
# The stub generator's translation of pybind11's type names (python/stubgen/make_stubs.py).
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "stubgen"))
import make_stubs  # noqa: E402

NAMES = make_stubs.Names(hyst)


def constructible(cls):
    """A class that Python code can call: a constructor of its own (not pybind11's 'No
    constructor defined') or a Python class."""
    if type(cls).__name__ != "pybind11_type":
        return True
    init = vars(cls).get("__init__")
    return init is not None and bool(_signatures.signature_lines(init.__doc__, "__init__"))


def classes(module):
    def walk(cls, qualified):
        yield qualified, cls
        for name, member in vars(cls).items():
            if inspect.isclass(member) and not name.startswith("_"):
                yield from walk(member, f"{qualified}.{name}")
    for name, obj in vars(module).items():
        if inspect.isclass(obj) and not name.startswith("_") and obj.__module__.startswith("hyst"):
            yield from walk(obj, name)


def methods(cls):
    for name, member in vars(cls).items():
        if name.startswith("_") or inspect.isclass(member) or isinstance(member, property):
            continue
        function = member.__func__ if isinstance(member, staticmethod) else member
        if callable(function):
            yield name, getattr(cls, name)


def functions(module):
    for name, obj in vars(module).items():
        if (not name.startswith("_") and callable(obj) and not inspect.isclass(obj)
                and getattr(obj, "__module__", "").startswith("hyst")):
            yield name, obj


def public_callables():
    """(qualified name, callable) of every public function, class and method."""
    for module in BOUND + (hyst.plot, hyst.batch):
        for name, obj in functions(module):
            yield f"{module.__name__}.{name}", obj
        for qualified, cls in classes(module):
            if constructible(cls):
                yield f"{module.__name__}.{qualified}", cls
            for name, method in methods(cls):
                if name not in _signatures._PER_SAMPLE:
                    yield f"{module.__name__}.{qualified}.{name}", method


def test_every_public_callable_has_a_signature():
    missing = []
    count = 0
    for qualified, obj in public_callables():
        count += 1
        try:
            inspect.signature(obj)
        except (ValueError, TypeError) as error:
            missing.append(f"{qualified}: {error}")
    assert missing == []
    assert count > 150  # the walk reaches the methods, not only the module's functions


def test_the_per_sample_methods_are_the_only_ones_left_builtin():
    """`step` keeps the builtin (a wrapper would cost time on every sample); its signature line
    is still in its docstring, and the stubs declare it."""
    left = set()
    for module in BOUND:
        for qualified, cls in classes(module):
            for name, member in vars(cls).items():
                if not name.startswith("_") and inspect.isbuiltin(getattr(cls, name, None)) or \
                        type(member).__name__ == "instancemethod" and not name.startswith("_"):
                    left.add(name)
    assert left == _signatures._PER_SAMPLE
    assert hyst.PrandtlIshlinskii.step.__doc__.startswith("step(self: hyst.PrandtlIshlinskii")


def test_overloads_merge_into_a_signature_every_overload_fits():
    evaluate = inspect.signature(hyst.evaluate)
    assert list(evaluate.parameters) == ["model", "input", "output", "args", "kwargs"]
    assert repr(evaluate.parameters["model"].annotation) == (
        "Union[hyst.Model, hyst.StateSpace, hyst.HystereticLfr]")
    assert repr(evaluate.return_annotation) == "Dict[str, Any]"
    # Each overload binds to the merged signature.
    evaluate.bind("model", "u", "y", "rest", "none")
    evaluate.bind("model", "u", "y", layout="N,channel", periodic=True)
    generate = inspect.signature(hyst.signals.generate)
    assert list(generate.parameters) == ["grid", "signal"]
    assert "hyst.signals.Chirp" in repr(generate.parameters["signal"].annotation)


def test_merge_stops_at_the_first_parameter_the_overloads_do_not_share():
    first = _signatures.parse_line("f(a: int, b: float = 1.0) -> int", "f")
    second = _signatures.parse_line("f(a: str, *, c: bool = False) -> str", "f")
    merged = _signatures.merge_signatures([first, second])
    assert str(merged) == "(a: Union[int, str], *args, **kwargs) -> Union[int, str]"
    # A parameter required in one overload and optional in the other is not shared.
    third = _signatures.parse_line("f(a: int, b: float) -> int", "f")
    assert list(_signatures.merge_signatures([first, third]).parameters) == ["a", "args",
                                                                             "kwargs"]


def test_return_values_are_typed():
    untyped = []
    for qualified, obj in public_callables():
        if inspect.isclass(obj):
            continue
        module = qualified.split(".")[0]
        if qualified.startswith(("hyst.plot.", "hyst.batch.")):
            continue  # Python code: mypy checks its annotations (test_stubs.py)
        returns = inspect.signature(obj).return_annotation
        text = "" if returns is inspect.Signature.empty else repr(returns)
        if not text or UNTYPED.search(text):
            untyped.append(f"{qualified} -> {text or '(none)'} ({module})")
    assert untyped == []
    assert repr(inspect.signature(hyst.models).return_annotation) == "List[hyst.ModelEntry]"
    assert all(isinstance(entry, hyst.ModelEntry) for entry in hyst.models())
    for name in hyst._FITS:
        assert repr(inspect.signature(getattr(hyst, name)).return_annotation) == (
            "hyst.FitResult"), name
        assert getattr(hyst, name).__doc__.split("\n", 1)[0].endswith(") -> hyst.FitResult")


def stub_functions(module_name):
    """{qualified name: [ast.FunctionDef, ...]} of a stub (overloads in order)."""
    tree = ast.parse((PACKAGE / STUBS[module_name]).read_text())
    found = {}

    def visit(body, prefix):
        for node in body:
            if isinstance(node, ast.FunctionDef):
                decorators = {ast.unparse(d) for d in node.decorator_list}
                if not decorators & {"property"} and not any(d.endswith(".setter")
                                                             for d in decorators):
                    found.setdefault(f"{prefix}{node.name}", []).append(node)
            elif isinstance(node, ast.ClassDef):
                visit(node.body, f"{prefix}{node.name}.")
    visit(tree.body, "")
    return found


def stub_form(signature, module, drop_self):
    """A runtime signature as the stub writes it: (name, kind, has default, annotation) per
    parameter and the return annotation, pybind11's names translated."""
    parameters = []
    for parameter in signature.parameters.values():
        annotation = ("" if parameter.annotation is inspect.Parameter.empty
                      else NAMES.annotation(repr(parameter.annotation), module, True))
        parameters.append((parameter.name, parameter.kind.name,
                           parameter.default is not inspect.Parameter.empty, annotation))
    if drop_self and parameters and parameters[0][0] == "self":
        parameters[0] = ("self", parameters[0][1], False, "")
    returns = ("Any" if signature.return_annotation is inspect.Signature.empty
               else NAMES.annotation(repr(signature.return_annotation), module))
    return parameters, returns


def stub_node_form(node):
    arguments = node.args
    parameters = []
    positional = arguments.posonlyargs + arguments.args
    defaults = [None] * (len(positional) - len(arguments.defaults)) + arguments.defaults
    for argument, default in zip(positional, defaults):
        kind = ("POSITIONAL_ONLY" if argument in arguments.posonlyargs
                else "POSITIONAL_OR_KEYWORD")
        parameters.append((argument.arg, kind, default is not None,
                           ast.unparse(argument.annotation) if argument.annotation else ""))
    if arguments.vararg:
        parameters.append((arguments.vararg.arg, "VAR_POSITIONAL", False,
                           ast.unparse(arguments.vararg.annotation)
                           if arguments.vararg.annotation else ""))
    for argument, default in zip(arguments.kwonlyargs, arguments.kw_defaults):
        parameters.append((argument.arg, "KEYWORD_ONLY", default is not None,
                           ast.unparse(argument.annotation) if argument.annotation else ""))
    if arguments.kwarg:
        parameters.append((arguments.kwarg.arg, "VAR_KEYWORD", False,
                           ast.unparse(arguments.kwarg.annotation)
                           if arguments.kwarg.annotation else ""))
    return parameters, ast.unparse(node.returns)


@pytest.mark.parametrize("module", BOUND, ids=lambda m: m.__name__)
def test_runtime_signatures_agree_with_the_stubs(module):
    declared = stub_functions(module.__name__)
    runtime = {}
    for name, obj in functions(module):
        runtime[name] = (obj, name, False)
    for qualified, cls in classes(module):
        if constructible(cls) and type(cls).__name__ == "pybind11_type":
            runtime[f"{qualified}.__init__"] = (vars(cls)["__init__"], "__init__", True)
        for name, _ in methods(cls):
            runtime[f"{qualified}.{name}"] = (vars(cls)[name], name, True)
    differences = []
    compared = 0
    for qualified, (obj, name, method) in sorted(runtime.items()):
        function = obj.__func__ if isinstance(obj, staticmethod) else obj
        # The lines help() shows: pybind11's (each overload's), or a Python wrapper's own.
        doc = function.__doc__ if hasattr(function, "__signature__") and not hasattr(
            function, "__wrapped__") else inspect.unwrap(function).__doc__
        lines = _signatures.signature_lines(doc, name)
        expected = [stub_form(_signatures.parse_line(line, name), module.__name__, method)
                    for line in lines]
        stubbed = [stub_node_form(node) for node in declared.get(qualified, [])]
        compared += 1
        if not lines:
            differences.append(f"{qualified}: no signature line in its docstring")
        elif expected != stubbed:
            differences.append(f"{qualified}: runtime {expected} != stub {stubbed}")
        elif (len(lines) == 1 and not isinstance(obj, staticmethod) and name != "__init__"
              and name not in _signatures._PER_SAMPLE):
            # inspect.signature() says what the docstring and the stub say.
            signature = inspect.signature(obj)
            if stub_form(signature, module.__name__, method) != expected[0]:
                differences.append(f"{qualified}: inspect.signature {signature} differs")
    assert differences == []
    assert compared > 5
