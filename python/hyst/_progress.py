"""Progress of long calls: a callback of the caller's, a tqdm bar, or lines on standard error."""

import sys
import time


class _Lines:
    """progress(done, total, current) as one line per step on standard error."""

    def __init__(self, task):
        self.task = task
        self.start = time.perf_counter()

    def __call__(self, done, total, current):
        elapsed = time.perf_counter() - self.start
        text = f"hyst.{self.task}: {done}/{total}"
        if current:
            text += f", now {current}"
        print(f"{text}; {elapsed:.1f} s elapsed", file=sys.stderr, flush=True)


class _Bar:
    """progress(done, total, current) as a tqdm bar, closed at the end."""

    def __init__(self, tqdm, task):
        self.tqdm = tqdm
        self.task = task
        self.bar = None

    def __call__(self, done, total, current):
        if self.bar is None:
            self.bar = self.tqdm(total=total, desc=f"hyst.{self.task}", unit="step")
        self.bar.update(done - self.bar.n)
        self.bar.set_postfix_str(current)
        if done >= total:
            self.bar.close()


def as_callback(progress, task):
    """None: no progress; a callable: itself; True: a tqdm bar when tqdm is installed, else
    lines on standard error."""
    if progress is None or progress is False:
        return None
    if callable(progress):
        return progress
    if progress is True:
        try:
            from tqdm.auto import tqdm
        except ImportError:
            return _Lines(task)
        return _Bar(tqdm, task)
    raise TypeError(f"progress must be None, True or a callable, not {type(progress).__name__}")
