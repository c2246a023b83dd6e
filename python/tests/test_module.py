"""The module itself: the exception type, version, submodules and GIL-free batch calls."""

import threading

import numpy as np

import hyst


def test_error_is_an_exception_with_the_message():
    assert issubclass(hyst.Error, Exception)
    try:
        hyst.Play(-1.0)
    except hyst.Error as error:
        assert "-1" in str(error)
        assert error.args == (str(error),)
    else:
        raise AssertionError("hyst.Error not raised")


def test_version_and_submodules():
    assert hyst.__version__.count(".") == 2
    assert hyst.signals.__name__ == "hyst.signals" and hyst.io.__name__ == "hyst.io"
    assert "hysteresis" in hyst.__doc__


def test_batch_calls_from_threads_agree():
    model = hyst.PrandtlIshlinskii(hyst.uniform_thresholds(50, 0.04), np.linspace(1, 0.1, 50))
    v = hyst.signals.generate(hyst.signals.TimeGrid(20000, 1e-4),
                              hyst.signals.RandomWalk(max_step=0.05, seed=3))
    expected = model.simulate(v)
    results = [None] * 4

    def run(k):
        results[k] = model.simulate(v)

    threads = [threading.Thread(target=run, args=(k,)) for k in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    for result in results:
        np.testing.assert_array_equal(result, expected)
