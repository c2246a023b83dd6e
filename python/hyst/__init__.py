"""hyst: hysteresis models, their inverses, identification, actuators and control.

The bindings of the C++ library live in the extension hyst._core and are re-exported here; this
package adds what is Python's own: signatures that inspect.signature() and help() can read
(hyst._signatures) and named fit results (hyst.FitResult). The bindings' own description, with
the rules on state, arrays and errors, follows.
"""

try:
    import numpy as _numpy  # noqa: F401  (the extension converts every array through numpy)
except ImportError as _error:
    raise ImportError(
        "hyst needs numpy, which is not installed for this Python "
        f"({_error}): install it (Debian: apt install python3-numpy; pip: pip install numpy; "
        "a venv made with --system-site-packages sees Debian's)") from _error
import inspect as _inspect
import re as _re

from . import _core
from ._core import *  # noqa: F401,F403  (every binding, documented in _core)
from ._core import __version__, data, io, signals  # noqa: F401
from . import plot  # noqa: F401  (matplotlib is imported when a plot is drawn)
from ._progress import as_callback as _as_progress_callback
from ._results import FitResult
from ._signatures import add_signatures as _add_signatures

# The fits that return a model and its report answer with a FitResult (still a tuple).
_FITS = ("fit", "fit_records", "fit_prandtl_ishlinskii", "fit_preisach_forcs",
         "fit_butterfly_strain_records", "fit_butterfly_strain_with_polarisation",
         "fit_butterfly_strain_creep_with_polarisation",
         "fit_state_space", "fit_hysteretic_lfr", "fit_hammerstein")


def _returning_fit_result(function):
    def fit(*args, **kwargs):
        if "progress" in kwargs:
            kwargs["progress"] = _as_progress_callback(kwargs["progress"], function.__name__)
        return FitResult(function(*args, **kwargs))
    fit.__name__ = fit.__qualname__ = function.__name__
    # The binding's signature line with the type this wrapper returns (inspect.signature(), help()
    # and the stubs read it): "fit(name: str, ...) -> hyst.FitResult".
    line, _, rest = function.__doc__.partition("\n")
    fit.__doc__ = _re.sub(r"\) -> [^\n]*$", ") -> hyst.FitResult", line) + "\n" + rest
    fit.__module__ = __name__
    return fit


for _name in _FITS:
    globals()[_name] = _returning_fit_result(getattr(_core, _name))


def compare(*args, progress=None, **kwargs):
    return _core.compare(*args, progress=_as_progress_callback(progress, "compare"), **kwargs)


compare.__doc__ = _core.compare.__doc__

_add_signatures(globals(), (io, data, signals))
# hyst.Error is raised with its message (and .field set after): Exception's own constructor.
Error.__signature__ = _inspect.Signature(  # noqa: F405  (from _core)
    [_inspect.Parameter("message", _inspect.Parameter.POSITIONAL_ONLY, annotation=str)])
__doc__ = __doc__ + "\n" + (_core.__doc__ or "")
del _name, _inspect, _re
