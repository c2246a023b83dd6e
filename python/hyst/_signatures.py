"""Signatures of the bindings for inspect.signature() and help().

pybind11 writes each function's signature as the first line of its docstring, e.g.
"fit(name: str, input: numpy.ndarray[numpy.float64], *, detrend: bool = False) -> tuple", but
CPython's builtin functions cannot carry a __signature__. This module parses that line and puts
the signature on a thin Python wrapper of the function, so that keyword arguments and their
defaults are visible. An overloaded function (several signature lines) gets the signature every
overload fits: the parameters they share (same name, kind and default, at the same place; the
union of their types), then *args and **kwargs for the rest, and the union of their return types; help() and the type
stubs list each overload. Per-sample methods (`step`, where a wrapper would cost time on every
sample) keep the builtin.
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


def signature_lines(doc, name):
    """The signature lines of a docstring: its first line, or each of an overloaded function's."""
    if not doc:
        return []
    if "\nOverloaded function." in doc:
        return [line.split(". ", 1)[1] for line in doc.splitlines()
                if re.match(rf"\d+\. {re.escape(name)}\(", line)]
    first = doc.lstrip().split("\n", 1)[0]
    return [first] if first.startswith(f"{name}(") else []


def parse_signature(doc, name):
    """The inspect.Signature of the first docstring line "NAME(...) -> R", or None."""
    if not doc or "\nOverloaded function." in doc:
        return None
    line = doc.lstrip().split("\n", 1)[0]
    return parse_line(line, name)


def _union(annotations):
    """One annotation for several: the common one, or Union[...] of the distinct ones."""
    texts = []
    for annotation in annotations:
        if annotation is inspect.Parameter.empty:
            return annotation
        if repr(annotation) not in texts:
            texts.append(repr(annotation))
    return annotations[0] if len(texts) == 1 else _Text(f"Union[{', '.join(texts)}]")


def merge_signatures(signatures):
    """The signature that every one of `signatures` (the overloads of one function) fits."""
    if len(signatures) == 1:
        return signatures[0]
    kinds = inspect.Parameter
    lists = [list(s.parameters.values()) for s in signatures]
    shared = []
    for column in zip(*lists):
        first = column[0]
        if (any(p.name != first.name or p.kind != first.kind for p in column)
                or first.kind in (kinds.VAR_POSITIONAL, kinds.VAR_KEYWORD)):
            break
        if len({repr(p.default) for p in column}) != 1:  # required in one, or other defaults
            break
        shared.append(first.replace(annotation=_union([p.annotation for p in column])))
    rest = [p for parameters in lists for p in parameters[len(shared):]]
    positional = (kinds.POSITIONAL_ONLY, kinds.POSITIONAL_OR_KEYWORD, kinds.VAR_POSITIONAL)
    keyword = (kinds.POSITIONAL_OR_KEYWORD, kinds.KEYWORD_ONLY, kinds.VAR_KEYWORD)
    merged = list(shared)
    if any(p.kind in positional for p in rest):
        merged.append(kinds("args", kinds.VAR_POSITIONAL))
    if any(p.kind in keyword for p in rest):
        merged.append(kinds("kwargs", kinds.VAR_KEYWORD))
    return inspect.Signature(
        merged, return_annotation=_union([s.return_annotation for s in signatures]))


def function_signature(doc, name):
    """The signature of a binding from its docstring: its own, or its overloads' merged; None
    when the docstring has no signature line pybind11 wrote."""
    signatures = [parse_line(line, name) for line in signature_lines(doc, name)]
    if not signatures or None in signatures:
        return None
    return merge_signatures(signatures)


def parse_line(line, name):
    """The inspect.Signature of one signature line "NAME(...) -> R", or None."""
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
    signature = function_signature(getattr(init, "__doc__", None), "__init__")
    if signature is not None and "self" in signature.parameters:
        # inspect.signature(cls) reads the class's __signature__, without self.
        cls.__signature__ = signature.replace(parameters=list(signature.parameters.values())[1:],
                                              return_annotation=inspect.Signature.empty)
    for name, member in list(vars(cls).items()):
        if inspect.isclass(member) and type(member).__name__ == "pybind11_type":
            if not name.startswith("_"):
                _sign_class(member)  # nested classes: State, ...
            continue
        function = getattr(member, "__func__", member)  # a staticmethod's function
        if name.startswith("_") or name in _PER_SAMPLE or not _is_builtin(function):
            continue
        signature = function_signature(function.__doc__, name)
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
                signature = function_signature(target.__doc__, name)
                if signature is None:
                    continue
                if inspect.isbuiltin(obj):
                    space[name] = _with_signature(obj, signature)
                elif not hasattr(obj, "__signature__"):
                    obj.__signature__ = signature
