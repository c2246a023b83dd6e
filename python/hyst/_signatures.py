"""Signatures of the bindings for inspect.signature() and help().

pybind11 writes each function's signature as the first line of its docstring, e.g.
"fit(name: str, input: numpy.ndarray[numpy.float64], *, detrend: bool = False) -> tuple", but
CPython's builtin functions cannot carry a __signature__. This module parses that line and puts
the signature on a thin Python wrapper of the function, so that keyword arguments and their
defaults are visible. Overloaded functions (several signatures) and per-sample methods (`step`,
where a wrapper would cost time) keep the builtin.
"""

import ast
import functools
import inspect
import re

# Methods called once per sample, left unwrapped.
_PER_SAMPLE = {"step"}


class _Text:
    """An annotation or default shown as the text pybind11 wrote."""

    def __init__(self, text):
        self.text = text

    def __repr__(self):
        return self.text


def _value(node):
    try:
        return ast.literal_eval(node)
    except (ValueError, SyntaxError, TypeError):
        return _Text(ast.unparse(node))


def _annotation(node):
    return inspect.Parameter.empty if node is None else _Text(ast.unparse(node))


def parse_signature(doc, name):
    """The inspect.Signature of the first docstring line "NAME(...) -> R", or None."""
    if not doc or "\nOverloaded function." in doc:
        return None
    line = doc.lstrip().split("\n", 1)[0]
    if not line.startswith(f"{name}("):
        return None
    # Defaults that pybind11 shows by their repr, e.g. <Kind.play: 0>, are not Python syntax.
    line = re.sub(r"= <([^<>]*)>", lambda m: f"= {m.group(0)[2:]!r}", line)
    try:
        tree = ast.parse(f"def {line}: pass")
    except SyntaxError:
        return None
    arguments = tree.body[0].args
    kinds = inspect.Parameter
    parameters = []
    positional = arguments.posonlyargs + arguments.args
    defaults = [None] * (len(positional) - len(arguments.defaults)) + arguments.defaults
    for argument, default in zip(positional, defaults):
        kind = (kinds.POSITIONAL_ONLY if argument in arguments.posonlyargs
                else kinds.POSITIONAL_OR_KEYWORD)
        parameters.append(kinds(argument.arg, kind, annotation=_annotation(argument.annotation),
                                default=kinds.empty if default is None else _value(default)))
    if arguments.vararg:
        parameters.append(kinds(arguments.vararg.arg, kinds.VAR_POSITIONAL,
                                annotation=_annotation(arguments.vararg.annotation)))
    for argument, default in zip(arguments.kwonlyargs, arguments.kw_defaults):
        parameters.append(kinds(argument.arg, kinds.KEYWORD_ONLY,
                                annotation=_annotation(argument.annotation),
                                default=kinds.empty if default is None else _value(default)))
    if arguments.kwarg:
        parameters.append(kinds(arguments.kwarg.arg, kinds.VAR_KEYWORD,
                                annotation=_annotation(arguments.kwarg.annotation)))
    try:
        return inspect.Signature(parameters,
                                 return_annotation=_annotation(tree.body[0].returns))
    except ValueError:  # e.g. a parameter without default after one with
        return None


# One wrapper per binding, so that an alias (hyst.read_csv and hyst.io.read_csv) stays one object.
_wrappers = {}


def _with_signature(function, signature):
    if id(function) in _wrappers:
        return _wrappers[id(function)][1]

    @functools.wraps(function)
    def wrapper(*args, **kwargs):
        return function(*args, **kwargs)
    wrapper.__signature__ = signature
    _wrappers[id(function)] = (function, wrapper)  # the function kept alive: its id stays unique
    return wrapper


def _is_builtin(obj):
    return inspect.isbuiltin(obj) or type(obj).__name__ == "instancemethod"


def _sign_class(cls):
    init = cls.__dict__.get("__init__")
    signature = parse_signature(getattr(init, "__doc__", None), "__init__")
    if signature is not None:
        # inspect.signature(cls) reads the class's __signature__, without self.
        cls.__signature__ = signature.replace(parameters=list(signature.parameters.values())[1:],
                                              return_annotation=inspect.Signature.empty)
    for name, member in list(vars(cls).items()):
        if name.startswith("_") or name in _PER_SAMPLE or not _is_builtin(member):
            continue
        function = getattr(member, "__func__", member)
        signature = parse_signature(function.__doc__, name)
        if signature is not None:
            wrapper = _with_signature(function, signature)
            if isinstance(member, staticmethod) or "self" not in signature.parameters:
                wrapper = staticmethod(wrapper)
            setattr(cls, name, wrapper)


def add_signatures(namespace, modules):
    """Wraps the functions of `namespace` (a module's globals) and of `modules`, and signs the
    classes' constructors and methods."""
    spaces = [namespace] + [vars(module) for module in modules]
    for space in spaces:
        for name, obj in list(space.items()):
            if name.startswith("_"):
                continue
            if inspect.isclass(obj) and type(obj).__name__ == "pybind11_type":
                _sign_class(obj)
            elif inspect.isbuiltin(obj) or callable(obj) and not inspect.isclass(obj):
                target = getattr(obj, "__wrapped__", obj)
                signature = parse_signature(target.__doc__, name)
                if signature is None:
                    continue
                if inspect.isbuiltin(obj):
                    space[name] = _with_signature(obj, signature)
                elif not hasattr(obj, "__signature__"):
                    obj.__signature__ = signature
