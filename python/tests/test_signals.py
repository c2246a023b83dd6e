"""hyst.signals: grids, every generator, and parameter errors."""

import math

import numpy as np
import pytest

import hyst
from hyst import signals


def test_time_grid_and_times():
    grid = signals.TimeGrid(5, 0.5)
    assert (grid.samples, grid.dt) == (5, 0.5)
    np.testing.assert_allclose(signals.times(grid), [0, 0.5, 1.0, 1.5, 2.0])
    assert repr(grid) == "TimeGrid(samples=5, dt=0.5)"
    with pytest.raises(hyst.Error):
        signals.times(signals.TimeGrid(0, 1.0))


def test_sine_and_triangle_start_at_zero_rising():
    grid = signals.TimeGrid(101, 0.01)
    t = signals.times(grid)
    sine = signals.generate(grid, signals.Sine(amplitude=2.0, frequency=1.0, offset=0.5))
    np.testing.assert_allclose(sine, 2 * np.sin(2 * np.pi * t) + 0.5, atol=1e-12)
    triangle = signals.generate(grid, signals.Triangle(amplitude=1.0, frequency=1.0))
    assert triangle[0] == pytest.approx(0.0, abs=1e-12)
    assert triangle[25] == pytest.approx(1.0) and triangle[75] == pytest.approx(-1.0)
    shifted = signals.generate(grid, signals.Sine(phase=np.pi / 2))
    np.testing.assert_allclose(shifted, np.cos(2 * np.pi * t), atol=1e-12)
    assert signals.Sine(phase=0.5).phase == signals.Triangle(phase=0.5).phase == 0.5
    assert signals.DecayingSine(phase=1.0).phase == signals.GrowingSine(phase=1.0).phase == 1.0
    assert signals.Chirp(phase=2.0).phase == 2.0
    assert "Sine(amplitude=2" in repr(signals.Sine(amplitude=2.0))
    assert "Triangle(" in repr(signals.Triangle())


def test_decaying_and_growing_sine():
    grid = signals.TimeGrid(1000, 1e-3)
    t = signals.times(grid)
    decaying = signals.generate(grid, signals.DecayingSine(frequency=3.0, time_constant=0.2))
    np.testing.assert_allclose(decaying, np.exp(-t / 0.2) * np.sin(6 * np.pi * t), atol=1e-12)
    growing = signals.generate(grid, signals.GrowingSine(frequency=3.0, time_constant=0.2))
    np.testing.assert_allclose(growing, (1 - np.exp(-t / 0.2)) * np.sin(6 * np.pi * t),
                               atol=1e-12)
    assert "time_constant=0.2" in repr(signals.DecayingSine(time_constant=0.2))
    assert "GrowingSine(" in repr(signals.GrowingSine())
    with pytest.raises(hyst.Error, match="time_constant"):
        signals.generate(grid, signals.DecayingSine(time_constant=-1.0))


def test_multisine_with_given_and_schroeder_phases():
    grid = signals.TimeGrid(500, 1e-3)
    t = signals.times(grid)
    given = signals.Multisine(frequencies=[1.0, 3.0], amplitudes=[1.0, 0.5], phases=[0.0, 0.3])
    np.testing.assert_allclose(
        signals.generate(grid, given),
        np.sin(2 * np.pi * t) + 0.5 * np.sin(6 * np.pi * t + 0.3), atol=1e-12)
    schroeder = signals.Multisine(frequencies=[1.0, 2.0], amplitudes=[1.0, 1.0])
    assert schroeder.phases == []
    expected = np.sin(2 * np.pi * t) + np.sin(4 * np.pi * t - math.pi)
    np.testing.assert_allclose(signals.generate(grid, schroeder), expected, atol=1e-12)
    assert "phases=None" in repr(schroeder)
    with pytest.raises(hyst.Error):
        signals.generate(grid, signals.Multisine(frequencies=[1.0], amplitudes=[]))


def test_chirp_and_random_walk():
    grid = signals.TimeGrid(1001, 1e-3)
    chirp = signals.generate(grid, signals.Chirp(amplitude=1.0, start_frequency=1.0,
                                                 end_frequency=5.0))
    assert chirp.shape == (1001,) and np.abs(chirp).max() <= 1.0
    assert "Chirp(" in repr(signals.Chirp())
    walk = signals.RandomWalk(max_step=0.05, lower=-1.0, upper=1.0, seed=7)
    a, b = signals.generate(grid, walk), signals.generate(grid, walk)
    np.testing.assert_array_equal(a, b)  # reproducible
    assert a[0] == 0.0 and a.min() >= -1.0 and a.max() <= 1.0
    assert np.abs(np.diff(a)).max() <= 0.05 + 1e-15
    assert "seed=7" in repr(walk)
    walk.seed = 8
    assert not np.array_equal(signals.generate(grid, walk), a)


def test_submodule_imports():
    import hyst.signals as s  # noqa: F401  (registered in sys.modules)
    from hyst.signals import Sine  # noqa: F401
    assert s is hyst.signals
