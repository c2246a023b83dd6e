"""The Python package around the bindings: signatures that inspect and help() read, named fit
results, and the package layout (hyst._core re-exported as hyst)."""

import inspect
import pydoc
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import hyst


def loop_record():
    v = np.sin(np.linspace(0.0, 4.0 * np.pi, 400))
    return v, v + 0.2 * np.sign(np.gradient(v))


def test_functions_show_their_keywords_and_defaults():
    signature = inspect.signature(hyst.fit)
    assert list(signature.parameters)[:3] == ["name", "input", "output"]
    assert signature.parameters["detrend"].default is False
    assert signature.parameters["detrend"].kind is inspect.Parameter.KEYWORD_ONLY
    assert signature.parameters["validation_start"].default == "rest"
    assert signature.parameters["kwargs"].kind is inspect.Parameter.VAR_KEYWORD
    assert inspect.signature(hyst.io.read_csv).parameters["comment"].default == "#"
    assert "detrend: bool = False" in pydoc.render_doc(hyst.fit)


def test_classes_and_methods_show_their_signatures():
    assert list(inspect.signature(hyst.PrandtlIshlinskii).parameters) == [
        "thresholds", "weights", "offset"]
    assert inspect.signature(hyst.PrandtlIshlinskii).parameters["offset"].default == 0.0
    simulate = inspect.signature(hyst.Model.simulate)
    assert list(simulate.parameters)[:2] == ["self", "input"]
    assert simulate.parameters["return_state"].default is False
    model = hyst.Model("pi", {"thresholds": [0.0, 0.5], "weights": [1.0, 0.5]})
    assert "self" not in inspect.signature(model.simulate).parameters  # bound
    # Wrapped methods still run the binding.
    np.testing.assert_allclose(model.simulate(np.array([0.0, 1.0]))[1], 1.0 + 0.5 * 0.5)


def test_without_numpy_the_import_says_to_install_it(tmp_path):
    """A Python without numpy (hidden here by an import hook) fails at `import hyst` with a
    message that names numpy and how to install it, not at the first array."""
    package = Path(hyst.__file__).resolve().parents[1]
    script = tmp_path / "no_numpy.py"
    script.write_text(f"""
import sys
class HideNumpy:
    def find_spec(self, name, path=None, target=None):
        if name == "numpy" or name.startswith("numpy."):
            raise ModuleNotFoundError(f"No module named {{name!r}}", name=name)
sys.meta_path.insert(0, HideNumpy())
sys.path.insert(0, {str(package)!r})
import hyst
""")
    result = subprocess.run([sys.executable, "-I", str(script)], capture_output=True, text=True,
                            check=False)
    assert result.returncode == 1
    last = result.stderr.strip().splitlines()[-1]
    assert last.startswith("ImportError: hyst needs numpy, which is not installed"), last
    assert "apt install python3-numpy" in last and "pip install numpy" in last
    # The same script with numpy visible imports hyst.
    script.write_text(f"import sys\nsys.path.insert(0, {str(package)!r})\nimport hyst\n")
    assert subprocess.run([sys.executable, "-I", str(script)], check=False).returncode == 0


def test_fit_results_have_named_fields_and_unpack_as_before():
    v, y = loop_record()
    result = hyst.fit("pi", v, y)
    assert isinstance(result, hyst.FitResult) and isinstance(result, tuple)
    model, report = result
    assert result.model is model and result.report is report
    assert result.state == model.state
    assert repr(result).startswith("FitResult(model=pi, ")
    assert f"fit NRMSE [%]={report.fit.nrmse_percent:.4g}" in repr(result)
    html = result._repr_html_()
    assert html.startswith("<table>") and "<pre>" in html and "nnls" in html

    typed = hyst.fit_prandtl_ishlinskii(v, y)
    pi, state, typed_report = typed
    assert typed.model is pi and typed.state is state and typed.report is typed_report
    assert isinstance(typed.state, hyst.PrandtlIshlinskii.State)


def test_the_package_re_exports_the_extension():
    import hyst.io as io_module  # noqa: F401  (a submodule of the package)
    assert io_module is hyst.io
    assert hyst.Model.__module__ == "hyst"
    assert hyst.__version__ == hyst._core.__version__
    assert "State follows one rule" not in hyst.__doc__ or "simulate()" in hyst.__doc__
    with pytest.raises(hyst.Error):
        hyst.fit("no_such_model", *loop_record())
