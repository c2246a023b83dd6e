"""Shared fixtures of the hyst Python tests (run: PYTHONPATH=build/python python3 -m pytest)."""

import os
from pathlib import Path

import numpy as np
import pytest

import hyst


def shared_data_dir() -> Path:
    """../shared/data next to the repository, or $HYST_SHARED_DATA_DIR."""
    if os.environ.get("HYST_SHARED_DATA_DIR"):
        return Path(os.environ["HYST_SHARED_DATA_DIR"])
    return Path(__file__).resolve().parents[3] / "shared" / "data"


@pytest.fixture
def data_dir() -> Path:
    path = shared_data_dir()
    if not path.is_dir():
        pytest.skip(f"shared data not found at {path}")
    return path


@pytest.fixture
def hand_pi() -> hyst.PrandtlIshlinskii:
    """The hand-calculated case: y = 0.1 + v + 0.5 F_0.3[v]."""
    return hyst.PrandtlIshlinskii(thresholds=[0.0, 0.3], weights=[1.0, 0.5], offset=0.1)


@pytest.fixture
def nested_loops() -> np.ndarray:
    """A decaying sine: a spiral of nested inner loops starting at 0."""
    grid = hyst.signals.TimeGrid(2000, 1e-3)
    return hyst.signals.generate(
        grid, hyst.signals.DecayingSine(amplitude=2.0, frequency=2.0, time_constant=0.8))
