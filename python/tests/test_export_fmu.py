"""hyst.export_fmu: the FMU, loaded with ctypes as a Python co-simulation host would, reproduces
the model and its inverse."""

import ctypes
import xml.etree.ElementTree as ElementTree
import zipfile

import numpy as np
import pytest

import hyst


class CallbackFunctions(ctypes.Structure):
    _fields_ = [("logger", ctypes.c_void_p), ("allocateMemory", ctypes.c_void_p),
                ("freeMemory", ctypes.c_void_p), ("stepFinished", ctypes.c_void_p),
                ("componentEnvironment", ctypes.c_void_p)]


LIBC = ctypes.CDLL(None)


def run_fmu(path, folder, inputs, step=1e-3):
    """Unpacks the FMU, instantiates it and returns its outputs for `inputs` (set, get, step)."""
    with zipfile.ZipFile(path) as archive:
        archive.extractall(folder)
    description = ElementTree.parse(folder / "modelDescription.xml").getroot()
    identifier = description.find("CoSimulation").get("modelIdentifier")
    fmu = ctypes.CDLL(str(folder / "binaries" / "linux64" / f"{identifier}.so"))
    fmu.fmi2Instantiate.restype = ctypes.c_void_p
    fmu.fmi2Instantiate.argtypes = [ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p,
                                    ctypes.c_char_p, ctypes.POINTER(CallbackFunctions),
                                    ctypes.c_int, ctypes.c_int]
    for name in ("fmi2SetupExperiment", "fmi2EnterInitializationMode",
                 "fmi2ExitInitializationMode", "fmi2SetReal", "fmi2GetReal", "fmi2DoStep",
                 "fmi2FreeInstance"):
        getattr(fmu, name).argtypes = None
    callbacks = CallbackFunctions(None, ctypes.cast(LIBC.calloc, ctypes.c_void_p).value,
                                  ctypes.cast(LIBC.free, ctypes.c_void_p).value, None, None)
    instance = ctypes.c_void_p(fmu.fmi2Instantiate(b"py", 1, description.get("guid").encode(),
                                                   b"", ctypes.byref(callbacks), 0, 0))
    assert instance.value is not None
    assert fmu.fmi2SetupExperiment(instance, 0, ctypes.c_double(0), ctypes.c_double(0), 0,
                                   ctypes.c_double(0)) == 0
    assert fmu.fmi2EnterInitializationMode(instance) == 0
    assert fmu.fmi2ExitInitializationMode(instance) == 0
    u_ref = (ctypes.c_uint * 1)(0)
    y_ref = (ctypes.c_uint * 1)(1)
    value = (ctypes.c_double * 1)()
    outputs = []
    for k, u in enumerate(inputs):
        value[0] = u
        assert fmu.fmi2SetReal(instance, u_ref, ctypes.c_size_t(1), value) == 0
        assert fmu.fmi2GetReal(instance, y_ref, ctypes.c_size_t(1), value) == 0
        outputs.append(value[0])
        assert fmu.fmi2DoStep(instance, ctypes.c_double(k * step), ctypes.c_double(step), 1) == 0
    fmu.fmi2FreeInstance(instance)
    return np.array(outputs), description


def test_fmu_of_a_fitted_pi_and_its_inverse(tmp_path):
    model = hyst.Model("pi", {"thresholds": [0.0, 0.3, 0.7, 1.0],
                              "weights": [0.8, 0.5, 0.3, 0.2], "offset": 0.1})
    files = hyst.export_fmu(model, tmp_path / "fmus", prefix="piezo", inverse=True,
                            input_unit="V", output_unit="um", source="test")
    assert files["model"].name == "piezo.fmu" and files["inverse"].name == "piezo_inverse.fmu"
    v = 2.0 * np.exp(-np.arange(3000) / 900.0) * np.sin(2 * np.pi * np.arange(3000) / 100.0)
    y, description = run_fmu(files["model"], tmp_path / "model", v)
    np.testing.assert_allclose(y, model.simulate(v), rtol=0, atol=1e-12)
    units = {u.get("name") for u in description.find("UnitDefinitions")}
    assert units == {"V", "um", "um/V"}
    back, _ = run_fmu(files["inverse"], tmp_path / "inverse", y)
    np.testing.assert_allclose(back, v, rtol=0, atol=1e-9)


def test_fmu_errors_are_hyst_errors(tmp_path):
    model = hyst.Model("pi", {"thresholds": [0.0, 0.5], "weights": [1.0, 0.5]})
    with pytest.raises(hyst.Error, match="variable name 'a b'"):
        hyst.export_fmu(model, tmp_path, input_name="a b")
    with pytest.raises(hyst.Error, match="cannot start the C compiler"):
        hyst.export_fmu(model, tmp_path, compiler=str(tmp_path / "none"))
