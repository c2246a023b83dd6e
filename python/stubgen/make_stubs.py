"""Writes the type stubs of the package hyst from the built module (run by the build).

Usage: make_stubs.py BUILD_PYTHON_FOLDER

Imports hyst from BUILD_PYTHON_FOLDER and writes hyst/__init__.pyi, io.pyi, data.pyi, signals.pyi
and the PEP 561 marker py.typed beside it. Signatures come from pybind11's signature lines (the
parser of hyst._signatures; overloads as typing.overload), pybind11's type names become typing
ones (numpy.ndarray[numpy.float64] -> NDArray[numpy.float64], handle -> Any, ...), and a type the
bindings do not export (a C++ type pybind11 could only name) becomes Any.
"""

import ast
import inspect
import re
import sys
from pathlib import Path

HEADER = '''# Type stubs of hyst, generated from the built module by python/stubgen/make_stubs.py.
from typing import Any, ClassVar, Dict, Iterator, List, Optional, Sequence, Tuple, Union, overload
import os
import numpy
from numpy.typing import ArrayLike, NDArray
'''

TYPING = {"Any", "ArrayLike", "ClassVar", "Dict", "Iterator", "List", "Optional", "Sequence", "Tuple", "Union",
          "NDArray", "numpy", "os", "None", "bool", "int", "float", "complex", "str", "bytes",
          "dict", "list", "tuple", "object", "Callable"}
RENAMES = [(r"numpy\.ndarray\[numpy\.float64\]", "NDArray[numpy.float64]"),
           (r"\bhandle\b", "Any"), (r"\bobject\b", "Any"), (r"\bsequence\b", "Sequence[Any]"),
           (r"\bos\.PathLike\b", "Union[str, os.PathLike[str]]"), (r"\bcallable\b", "Any")]
# Dunder methods worth declaring (the others come from object).
DUNDERS = {"__len__", "__getitem__", "__iter__", "__contains__", "__call__", "__eq__", "__enter__",
           "__exit__"}


class Names:
    """The classes the bindings export, by qualified name (hyst.io.AixacctTable), and how a stub
    module refers to them."""

    def __init__(self, hyst):
        self.known = set()
        for module in (hyst, hyst.io, hyst.data, hyst.signals):
            for name, obj in vars(module).items():
                if inspect.isclass(obj) and not name.startswith("_"):
                    self._add(f"{module.__name__}.{name}", obj)

    def _add(self, qualified, cls):
        self.known.add(qualified)
        for name, obj in vars(cls).items():
            if inspect.isclass(obj) and not name.startswith("_"):
                self._add(f"{qualified}.{name}", obj)

    def annotation(self, text, module, parameter=False):
        """A valid annotation in stub `module` ("hyst" or "hyst.io") for pybind11's `text`. A
        parameter takes any array-like where pybind11 converts one (lists, other dtypes)."""
        for pattern, replacement in RENAMES:
            text = re.sub(pattern, replacement, text)
        if parameter:
            text = text.replace("NDArray[numpy.float64]", "ArrayLike")
        try:
            tree = ast.parse(text, mode="eval")
        except SyntaxError:
            return "Any"
        resolver = self

        class Resolve(ast.NodeTransformer):
            def _name(self, node):
                dotted = ast.unparse(node)
                if dotted.split(".")[0] in TYPING:
                    return node
                if dotted in resolver.known:
                    local = dotted
                    if module == "hyst" and dotted.startswith("hyst."):
                        local = dotted[len("hyst."):]
                    return ast.parse(local, mode="eval").body
                return ast.Name("Any")

            def visit_Name(self, node):
                return self._name(node)

            def visit_Attribute(self, node):
                return self._name(node)

        return ast.unparse(Resolve().visit(tree))


def signature_lines(doc, name):
    """The signature lines of a docstring (hyst._signatures', imported once main() has put the
    built package on the path)."""
    from hyst._signatures import signature_lines as lines
    return lines(doc, name)


def render_signature(parse, names, line, name, module, returns=None, drop_self=False):
    signature = parse(line, name)
    if signature is None:
        return f"def {name}(*args: Any, **kwargs: Any) -> Any: ..."
    parts = []
    star = False
    for parameter in signature.parameters.values():
        text = parameter.name
        if parameter.annotation is not inspect.Parameter.empty:
            text += f": {names.annotation(repr(parameter.annotation), module, True)}"
        if parameter.kind is inspect.Parameter.VAR_POSITIONAL:
            text, star = "*" + text, True
        elif parameter.kind is inspect.Parameter.VAR_KEYWORD:
            text = "**" + text
        elif parameter.kind is inspect.Parameter.KEYWORD_ONLY and not star:
            parts.append("*")
            star = True
        if parameter.default is not inspect.Parameter.empty:
            text += " = ..."
        parts.append(text)
    if drop_self and parts and parts[0].startswith("self"):
        parts[0] = "self"
    result = returns or (names.annotation(repr(signature.return_annotation), module)
                         if signature.return_annotation is not inspect.Signature.empty
                         else "Any")
    return f"def {name}({', '.join(parts)}) -> {result}: ..."


def render_function(parse, names, obj, name, module, indent="", returns=None, method=False):
    target = inspect.unwrap(obj)
    lines = signature_lines(target.__doc__, name)
    if not lines:
        return [f"{indent}def {name}(*args: Any, **kwargs: Any) -> Any: ..."]
    out = []
    for line in lines:
        if len(lines) > 1:
            out.append(f"{indent}@overload")
        out.append(indent + render_signature(parse, names, line, name, module, returns,
                                             drop_self=method))
    return out


def property_type(names, prop, module):
    doc = (prop.fget.__doc__ or "") if prop.fget else ""
    # "(self: hyst.X) -> float", or "(arg0: hyst.X) -> float" for a lambda's getter.
    match = re.match(r"\((?:self|arg0): [^)]*\) -> (.+)", doc.lstrip().split("\n", 1)[0])
    return names.annotation(match.group(1), module) if match else "Any"


def render_class(parse, names, cls, name, module, indent=""):
    out = [f"{indent}class {name}:"]
    body = indent + "    "
    members = vars(cls)
    if hasattr(cls, "__members__"):  # a pybind11 enum
        for member in cls.__members__:
            out.append(f"{body}{member}: ClassVar[{name}]")
        out.append(f"{body}def __init__(self, value: int) -> None: ...")
        out.append(f"{body}@property")
        out.append(f"{body}def name(self) -> str: ...")
        out.append(f"{body}@property")
        out.append(f"{body}def value(self) -> int: ...")
        out.append(f"{body}def __int__(self) -> int: ...")
        return out
    for member_name, member in members.items():
        if inspect.isclass(member) and not member_name.startswith("_"):
            out += render_class(parse, names, member, member_name, module, body)
    init = members.get("__init__")
    if init is not None and signature_lines(init.__doc__, "__init__"):
        out += render_function(parse, names, init, "__init__", module, body, "None", True)
    for member_name, member in members.items():
        if member_name.startswith("_") and member_name not in DUNDERS:
            continue
        if isinstance(member, property):
            out.append(f"{body}@property")
            out.append(f"{body}def {member_name}(self) -> "
                       f"{property_type(names, member, module)}: ...")
            if member.fset is not None:
                out.append(f"{body}@{member_name}.setter")
                out.append(f"{body}def {member_name}(self, value: Any) -> None: ...")
        elif isinstance(member, staticmethod):
            out += _static(render_function(parse, names, member.__func__, member_name, module,
                                           body), body)
        elif callable(member) and not inspect.isclass(member):
            out += render_function(parse, names, member, member_name, module, body, None, True)
    if len(out) == 1:
        out.append(f"{body}...")
    return out


def _static(lines, body):
    """Puts @staticmethod under each @overload (or above a single def)."""
    out = []
    for line in lines:
        if line.strip().startswith("def "):
            out.append(f"{body}@staticmethod")
        out.append(line)
    return out


def render_module(parse, names, module):
    out = [HEADER]
    name = module.__name__
    if name == "hyst":
        out.append("from . import data as data, io as io, plot as plot, signals as signals")
        out.append("from ._results import FitResult as FitResult")
        out.append("from . import _core as _core")
        out.append("__version__: str")
        out.append("class Error(Exception):")
        out.append("    field: Optional[str]")
    else:
        out.append("import hyst")
    for member_name, member in sorted(vars(module).items()):
        if member_name.startswith("_") or inspect.ismodule(member):
            continue
        if member_name in ("Error", "FitResult") and name == "hyst":
            continue
        if inspect.isclass(member):
            out += render_class(parse, names, member, member_name, name)
        elif callable(member):
            out += render_function(parse, names, member, member_name, name)
    return "\n".join(out) + "\n"


def main():
    folder = Path(sys.argv[1]).resolve()
    sys.path.insert(0, str(folder))
    import hyst
    from hyst._signatures import parse_signature
    names = Names(hyst)
    package = folder / "hyst"
    stubs = {"__init__.pyi": render_module(parse_signature, names, hyst)}
    for module in (hyst.io, hyst.data, hyst.signals):
        stubs[f"{module.__name__.split('.')[-1]}.pyi"] = render_module(
            parse_signature, names, module)
    for file_name, text in stubs.items():
        ast.parse(text, filename=file_name)  # a generator bug fails the build, not a user
        (package / file_name).write_text(text)
    (package / "py.typed").write_text("")


if __name__ == "__main__":
    main()
