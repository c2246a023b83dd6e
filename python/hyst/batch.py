"""Batch fitting on a Dask distributed cluster: one fit per record, a model file each, one table.

    import hyst.batch
    rows = hyst.batch.fit("records/*.csv", "pi", input="v", output="y", out="fits/")

fits the model to every record on a local cluster of `workers` processes (started here, closed
at the end), on the cluster of `scheduler="tcp://host:8786"`, or with the caller's `client` (a
distributed.Client). `workers=0` fits the records one after another in this process, without
Dask: the reference the tests and the benchmark compare the cluster with. The local cluster's
workers are new Python processes that import the calling script's main module, so a script calls
fit() under `if __name__ == "__main__":`, as Dask requires.

A task carries a record's path, never its samples: the worker reads the file with hyst's reader
(hyst.data.extract, as `hyst fit --data` reads CSV, .mat, aixACCT and MicroMag files), fits it
with hyst.fit and writes the model file into the run's staging folder in `out`. Records and `out`
must therefore be on a file system that every worker sees at the same path. A record that fails
(unreadable, a column missing, a fit error, a worker that died, no result within
`record_timeout` seconds) becomes a "failed" row with the reason; the other records go on. The
rows go to out/batch.csv and out/batch.md.

The model files and the tables are published as one set (hyst.io.OutputSet, as `hyst compare`
does): each name in `out` is a link into the current set's folder, switched at once at the end,
so a run that is interrupted, killed or fails leaves the complete previous set, never a mix. An
output that is one of the records is refused before any work, and so is a record that is not a
regular file (a FIFO, a device, a folder). A run ends: a record over its time limit fails (its
worker is restarted), and a cluster left without workers for `timeout` seconds ends the run with
ClusterLost, after the rows fitted so far were published.
docs/scaling.md says how to run it on a real cluster and what limits its throughput.

Command line (`hyst batch fit ...` runs the same):

    python3 -m hyst.batch fit --model pi --data 'records/*.csv' --input v --output y --out fits/
"""

import argparse
import contextlib
import csv
import glob
import io
import json
import logging
import math
import os
import signal
import socket
import stat
import sys
import threading
import time
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import (Any, Callable, Dict, Iterator, List, Mapping, Optional, Sequence, Tuple,
                    Union)

import hyst
from . import _progress

_MISSING = "hyst.batch needs Dask distributed: apt-get install python3-distributed"
CSV_TABLE = "batch.csv"
MARKDOWN_TABLE = "batch.md"
#: Default limit of one record's read, fit and save [s]; over it the record is a failed row.
RECORD_TIMEOUT = 900.0
#: How often the cluster's progress, time limits and workers are looked at [s].
_POLL_SECONDS = 0.2
#: How long an ended run waits for its cancelled tasks that still execute [s].
_CANCEL_WAIT_SECONDS = 5.0

Records = Union[str, "os.PathLike[str]", Sequence[Union[str, "os.PathLike[str]"]]]


@dataclass(frozen=True)
class RecordResult:
    """One record's row of the results table."""

    record: str  #: the record as given (a path)
    status: str  #: "ok" or "failed"
    seconds: float  #: wall time of the record's task: read, fit, write [s]
    nrmse_percent: Optional[float] = None  #: NRMSE of the fitted model on the record [%]
    parameters: Optional[int] = None  #: number of fitted parameters
    fit_status: str = ""  #: the fit report's status: converged, iteration limit, ...
    model_file: Optional[str] = None  #: the model file written
    reason: str = ""  #: why the record failed

    @property
    def ok(self) -> bool:
        return self.status == "ok"


@dataclass(frozen=True)
class _Task:
    """What a worker gets for one record: paths and names, never samples."""

    record: str
    path: str  # absolute: a worker's working folder may differ from the caller's
    model_file: str  # absolute, where readers find it once the set is published
    staged_file: str  # absolute, where the worker writes it: in the run's staging folder
    topic: str  # the run's Dask event topic: a task reports its start there
    index: int  # the task's place in the run
    model: str
    input: str
    output: str
    options: Mapping[str, Any]
    time: Optional[str] = None  # the time column of every record, if given


def _metrics(metrics: Any) -> Dict[str, Any]:
    return {"samples": metrics.samples, "rmse": metrics.rmse,
            "nrmse_percent": metrics.nrmse_percent, "max_error": metrics.max_error}


def _fit_info(report: Any, task: _Task, samples: int) -> Dict[str, Any]:
    """The model file's "info" object, in the form `hyst fit` writes."""
    info = {"created_by": "hyst batch fit", "model": report.model, "method": report.method,
            "status": report.status, "termination": report.termination.name,
            "message": report.message, "iterations": report.iterations,
            "initial_cost": report.initial_cost, "final_cost": report.final_cost,
            "parameters": report.parameters, "fit": _metrics(report.fit),
            "seconds": report.seconds,
            "data": {"file": task.record, "input": task.input, "output": task.output,
                     "samples": samples},
            "options": dict(task.options)}
    if report.quality_note:
        info["simulation"] = report.quality_note
    if report.preprocessing:
        info["preprocessing"] = list(report.preprocessing)
    return info


def _one_line(text: str) -> str:
    """Line breaks and runs of spaces as one space: every row, warning and error is one line."""
    return " ".join(text.split())


def _reason(task: _Task, error: BaseException) -> str:
    """The error's message, naming the record's file (hyst's readers name it themselves)."""
    text = str(error) if isinstance(error, hyst.Error) else f"{type(error).__name__}: {error}"
    return _one_line(text if task.path in text else f"{task.path}: {text}")


def _run_task(task: _Task) -> RecordResult:
    """Reads, fits and saves one record; every failure becomes a failed row. Runs on a worker."""
    start = time.perf_counter()
    try:
        names = [task.input, task.output] + ([task.time] if task.time else [])
        columns = hyst.data.extract(task.path, names)
        input, output = columns[task.input], columns[task.output]
        if input.size == 0:
            raise hyst.Error(f"{task.path}: input '{task.input}' has no samples")
        time_axis = columns[task.time] if task.time else None
        try:
            result = hyst.fit(task.model, input, output, time=time_axis, **task.options)
        except hyst.Error as error:
            if not task.time:
                raise
            raise hyst.Error(f"{task.path}: time column '{task.time}': {error}") from error
        report = result.report
        if report.status == "failed":
            raise hyst.Error(f"fitting '{task.model}' to {task.path} failed: {report.message}")
        # The driver made the folder; a run that ended has removed it, and a late task must not
        # make it again (the writer would create the missing folders).
        if not os.path.isdir(os.path.dirname(task.staged_file)):
            raise hyst.Error(f"{task.path}: the run ended before the model file was saved")
        hyst.save_model(task.staged_file, result.model, _fit_info(report, task, input.size))
    except Exception as error:  # a failed record must never stop the others
        return RecordResult(task.record, "failed", time.perf_counter() - start,
                            reason=_reason(task, error))
    return RecordResult(task.record, "ok", time.perf_counter() - start,
                        nrmse_percent=report.fit.nrmse_percent, parameters=report.parameters,
                        fit_status=report.status, model_file=task.model_file)


def _kind(mode: int) -> str:
    for test, kind in ((stat.S_ISDIR, "a folder"), (stat.S_ISFIFO, "a FIFO"),
                       (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
                       (stat.S_ISSOCK, "a socket")):
        if test(mode):
            return kind
    return "not a regular file"


def _refuse_special_files(paths: Sequence[str]) -> None:
    """Records must be regular files (through links): reading a FIFO or a device may never end.
    A record that does not exist is left to its row (the reader says why)."""
    for path in paths:
        try:
            mode = os.stat(path).st_mode
        except OSError:
            continue
        if not stat.S_ISREG(mode):
            raise ValueError(f"record '{path}' is {_kind(mode)}, not a regular file: records "
                             "must be files")


def _worker_version() -> str:
    """Runs on every worker before the tasks: it fails there when hyst is not importable."""
    return hyst.__version__


def _expand(records: Records) -> List[str]:
    """The record paths: a pattern with *, ? or [ ] is expanded (sorted; ** recurses; the
    folders it matches are left out) and must match a file; a plain path is taken as it is (a
    missing or unreadable one becomes a failed row). Anything but regular files is refused."""
    items = [records] if isinstance(records, (str, os.PathLike)) else list(records)
    paths: List[str] = []
    for item in items:
        text = os.fspath(item)
        if not glob.has_magic(text):
            paths.append(text)
            continue
        matches = sorted(path for path in glob.glob(text, recursive=True)
                         if not os.path.isdir(path))
        if not matches:
            raise ValueError(f"records '{text}': the pattern matches no file")
        paths += matches
    if not paths:
        raise ValueError("records: no record given")
    _refuse_special_files(paths)
    return paths


def _model_files(paths: Sequence[str], out: Path) -> List[str]:
    """Each record's model file, relative to `out`: its path relative to the records' common
    folder with the extension .json (data/a/r1.csv -> a/r1.json), so that records of one name in
    different folders keep their own. Two records that would still share one (r1.csv and r1.mat
    in one folder, or a record given twice) are refused, naming both."""
    absolute = [os.path.abspath(path) for path in paths]
    common = os.path.commonpath([os.path.dirname(path) for path in absolute])
    files: List[str] = []
    owners: Dict[str, str] = {}
    for path, full in zip(paths, absolute):
        file = os.path.splitext(os.path.relpath(full, common))[0] + ".json"
        if file in owners:
            raise ValueError(f"records '{owners[file]}' and '{path}' would both be fitted into "
                             f"{out / file}: give records whose names differ apart from their "
                             "extension")
        owners[file] = path
        files.append(file)
    return files


def _distributed() -> Any:
    try:
        import distributed
    except ImportError as error:
        raise ImportError(_MISSING) from error
    return distributed


def _probe_scheduler(scheduler: str, timeout: float) -> None:
    """A TCP connect to the scheduler's port first: a refused or unreachable port fails at once
    (Dask's client would retry it until `timeout`). Addresses other than tcp:// are left to Dask."""
    protocol, _, location = scheduler.rpartition("://")
    if protocol not in ("", "tcp", "tls"):
        return
    host, colon, port = location.rpartition(":")
    if not colon or not port.isdigit():
        raise ConnectionError(f"cannot connect to the Dask scheduler at '{scheduler}': expected "
                              "tcp://HOST:PORT")
    try:
        socket.create_connection((host.strip("[]"), int(port)), timeout=timeout).close()
    except OSError as error:
        why = error.strerror or str(error) or type(error).__name__
        raise ConnectionError(f"cannot connect to the Dask scheduler at '{scheduler}': "
                              f"{why}") from error


@contextlib.contextmanager
def _cluster(client: Any, scheduler: Optional[str], workers: int,
             timeout: float) -> Iterator[Any]:
    """The caller's client, a client of the scheduler, or one of a local cluster started here;
    what is started here is closed at the end."""
    if client is not None:
        yield client
        return
    distributed = _distributed()
    if scheduler is None:
        # Processes, one thread each: a fit holds a core. The scheduler's HTTP server on a free
        # port: the default, 8787, may be taken (by another cluster), which would be warned about.
        with distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                      dashboard_address=":0") as cluster, \
                distributed.Client(cluster) as local:
            yield local
        return
    _probe_scheduler(scheduler, timeout)
    try:
        remote = distributed.Client(scheduler, timeout=timeout)
    except (OSError, ValueError, TypeError) as error:
        raise ConnectionError(f"cannot connect to the Dask scheduler at '{scheduler}': "
                              f"{error}") from error
    with remote:
        yield remote


def _check_workers(client: Any, timeout: float) -> None:
    """Waits for a worker, then checks that every worker imports this hyst."""
    where = client.scheduler.address
    try:
        client.wait_for_workers(1, timeout=timeout)
    except _distributed().TimeoutError as error:
        raise RuntimeError(f"the Dask scheduler at {where} has no worker after {timeout:g} s "
                           f"(start some: dask-worker {where} --nthreads 1)") from error
    try:
        versions = client.run(_worker_version)
    except Exception as error:
        raise RuntimeError(f"the Dask workers of {where} cannot run hyst.batch: {error} (hyst "
                           "must be importable on every worker: docs/scaling.md)") from error
    for worker, version in versions.items():
        if version != hyst.__version__:
            raise RuntimeError(f"the Dask worker {worker} has hyst {version}, this process "
                               f"{hyst.__version__}: give every worker the same hyst")


class ClusterLost(RuntimeError):
    """The cluster had no worker for `timeout` seconds: the run ended early. The rows (records
    not fitted are failed rows) were published; they are in `rows`."""

    def __init__(self, message: str, rows: Sequence[RecordResult]) -> None:
        super().__init__(message)
        self.rows = list(rows)


def _overdue(task: _Task, limit: float) -> RecordResult:
    return RecordResult(task.record, "failed", limit,
                        reason=f"{task.path}: not finished within {limit:g} s (record_timeout, "
                               "--record-timeout)")


def _task_on_worker(task: _Task) -> RecordResult:
    """What the cluster runs: tells the caller that the task started (an event of the run's
    topic: the record's time limit counts from here), then runs _run_task, looked up when the
    task runs (tests replace it)."""
    with contextlib.suppress(ImportError, ValueError):  # ValueError: not on a worker
        from distributed import get_worker
        get_worker().log_event(task.topic, task.index)
    return _run_task(task)


def _end_overdue(client: Any, future: Any) -> None:
    """Cancels an overdue task and restarts the worker stuck in it (its nanny starts a new
    process): a thread cannot be stopped, and a cancelled task holds its thread until it ends.
    A worker without a nanny is left as it is; the task's result is dropped."""
    stuck = [worker for worker, keys in client.processing().items() if future.key in keys]
    future.cancel()
    with contextlib.suppress(Exception):
        client.restart_workers(stuck, timeout=10)


def _known(keys: Sequence[str], dask_worker: Any) -> int:
    """Runs on every worker: how many of the tasks `keys` it still holds (queued, executing, or
    cancelled but still executing)."""
    return sum(key in dask_worker.tasks for key in keys)


def _known_to_scheduler(keys: Sequence[str], dask_scheduler: Any) -> int:
    return sum(key in dask_scheduler.tasks for key in keys)


def _wait_for_cancelled(client: Any, keys: Sequence[str]) -> None:
    """A cancelled task runs on to its end (a thread cannot be stopped), and a worker may start
    one before it hears of the cancel: waits (up to _CANCEL_WAIT_SECONDS) until the scheduler
    has forgotten them and no worker holds them, twice in a row, so that none writes into the
    staging folder while it is removed. Only for clusters this run does not close."""
    deadline = time.monotonic() + _CANCEL_WAIT_SECONDS
    quiet = 0
    with contextlib.suppress(Exception):
        while quiet < 2 and time.monotonic() < deadline:
            busy = client.run_on_scheduler(_known_to_scheduler, list(keys)) or \
                sum(client.run(_known, list(keys)).values())
            quiet = 0 if busy else quiet + 1
            time.sleep(0.05)


def _row_of(future: Any, task: _Task) -> Optional[RecordResult]:
    """The row of a finished task, or None when its result cannot be had now: it was held by a
    worker that died since, and the scheduler computes it again (a blocking result() would then
    wait for ever on a cluster without workers)."""
    if future.status == "lost":
        return None
    try:
        return future.result(timeout=_POLL_SECONDS)
    except TimeoutError:  # also distributed.TimeoutError, the same class
        return None
    except Exception as error:  # the task failed: its worker died, unpickling
        return RecordResult(task.record, "failed", 0.0, reason=_reason(task, error))


def _run_on_cluster(client: Any, tasks: Sequence[_Task],
                    progress: Optional[Callable[[int, int, str], None]], record_timeout: float,
                    worker_timeout: float, stays: bool) -> Tuple[List[RecordResult], str]:
    """Runs the tasks; returns the rows in the tasks' order and, when the cluster was left
    without workers for `worker_timeout` seconds, why the run ended early (else ""). `stays`:
    the cluster outlives the run (the caller's or a scheduler's), so that cancelled tasks that
    still execute are waited for."""
    distributed = _distributed()
    started: Dict[int, float] = {}  # task index -> when its start was reported (this clock)
    client.subscribe_topic(tasks[0].topic,
                           lambda event: started.__setitem__(event[1], time.monotonic()))
    futures = [client.submit(_task_on_worker, task, pure=False) for task in tasks]
    running = {future: k for k, future in enumerate(futures)}
    completed = distributed.as_completed(futures)
    again: set = set()  # done once, but the result went with its worker: waited for again
    rows: Dict[int, RecordResult] = {}
    checked = no_worker_since = 0.0
    lost = ""

    def finish(k: int, row: RecordResult) -> None:
        rows[k] = row
        started.pop(k, None)
        if progress:
            progress(len(rows), len(tasks), tasks[k].record)

    try:
        while running and not lost:
            done = completed.next_batch(block=False) if completed.has_ready() else []
            now = time.monotonic()
            look = now - checked >= _POLL_SECONDS  # at limits and workers, a few times a second
            if look:
                checked = now
                done += [future for future in again if future.done()]
            for future in done:
                k = running.get(future)
                if k is None:  # cancelled: its row is written
                    continue
                row = _row_of(future, tasks[k])
                if row is None:  # its result was lost with its worker: computed again
                    again.add(future)
                    continue
                again.discard(future)
                del running[future]
                future.release()
                finish(k, row)
            if look:
                for k, start in list(started.items()):
                    if now - start > record_timeout and futures[k] in running:
                        del running[futures[k]]
                        _end_overdue(client, futures[k])
                        finish(k, _overdue(tasks[k], record_timeout))
                if client.nthreads():
                    no_worker_since = 0.0
                elif not no_worker_since:
                    no_worker_since = now
                elif now - no_worker_since > worker_timeout:
                    lost = (f"the Dask cluster at {client.scheduler.address} has had no worker "
                            f"for {worker_timeout:g} s")
            if not done:
                time.sleep(0.01)
    finally:  # also on an interrupt: the cluster drops what this run asked of it
        with contextlib.suppress(Exception):
            client.unsubscribe_topic(tasks[0].topic)
        if running:
            with contextlib.suppress(Exception):
                client.cancel(list(running))
            if stays:
                _wait_for_cancelled(client, [future.key for future in running])
    for k in running.values():
        rows[k] = RecordResult(tasks[k].record, "failed", 0.0,
                               reason=f"{tasks[k].path}: not fitted: {lost}")
    return [rows[k] for k in range(len(tasks))], lost


def _run_with_limit(task: _Task, limit: float) -> RecordResult:
    """_run_task in a thread of this process, waited for at most `limit` seconds; a thread cannot
    be stopped, so one over the limit is left to run on (a daemon: it ends with the process)."""
    result: List[RecordResult] = []
    thread = threading.Thread(target=lambda: result.append(_run_task(task)), daemon=True,
                              name=f"hyst.batch {task.record}")
    thread.start()
    thread.join(limit)
    return result[0] if result else _overdue(task, limit)


def _run_serially(tasks: Sequence[_Task], progress: Optional[Callable[[int, int, str], None]],
                  record_timeout: float) -> List[RecordResult]:
    rows = []
    for done, task in enumerate(tasks, start=1):
        rows.append(_run_with_limit(task, record_timeout))
        if progress:
            progress(done, len(tasks), task.record)
    return rows


def _write_table(path: str, text: str) -> None:
    """A table into the staging folder, which no reader sees before the set is published: written
    in place, with the usual file mode (0644 under umask 022), and flushed to the disk."""
    with open(path, "w", encoding="utf-8", newline="") as file:
        file.write(text)
        file.flush()
        os.fsync(file.fileno())


def _csv_table(rows: Sequence[RecordResult], out: Path) -> str:
    text = io.StringIO()
    writer = csv.writer(text, lineterminator="\n")
    writer.writerow(["record", "status", "fit_status", "nrmse_percent", "parameters", "seconds",
                     "model_file", "reason"])
    for row in rows:
        writer.writerow([row.record, row.status, row.fit_status,
                         "" if row.nrmse_percent is None else repr(row.nrmse_percent),
                         "" if row.parameters is None else row.parameters, f"{row.seconds:.6f}",
                         "" if row.model_file is None else os.path.relpath(row.model_file, out),
                         row.reason])
    return text.getvalue()


def _cell(text: str) -> str:
    return text.replace("|", "\\|")


def _markdown_table(rows: Sequence[RecordResult], out: Path, title: str, summary: str) -> str:
    lines = [f"# {title}", "", summary, "",
             "| record | status | fit status | NRMSE [%] | parameters | time [s] | model file | "
             "reason |", "|---|---|---|---:|---:|---:|---|---|"]
    for row in rows:
        cells = [row.record, row.status, row.fit_status,
                 "" if row.nrmse_percent is None else f"{row.nrmse_percent:.4g}",
                 "" if row.parameters is None else str(row.parameters), f"{row.seconds:.3g}",
                 "" if row.model_file is None else os.path.relpath(row.model_file, out),
                 row.reason]
        lines.append("| " + " | ".join(_cell(cell) for cell in cells) + " |")
    return "\n".join(lines) + "\n"


def _seconds(value: Any, name: str) -> float:
    """A time limit: a finite number of seconds > 0, else ValueError naming it and the value."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or \
            not math.isfinite(value) or value <= 0:
        raise ValueError(f"{name} = {value!r} must be a number of seconds > 0")
    return float(value)


def _missing_folders(folder: Path) -> List[Path]:
    """`folder` and its parents that do not exist yet, the deepest first."""
    missing = []
    path = Path(os.path.abspath(folder))
    while not path.exists() and path.parent != path:
        missing.append(path)
        path = path.parent
    return missing


def _remove_if_empty(folders: Sequence[Path]) -> None:
    """Removes the folders a failed run created, the deepest first, as long as they are empty."""
    for path in folders:
        try:
            path.rmdir()
        except OSError:
            return


def _check_outputs(paths: Sequence[str], folder: Path, files: Sequence[str]) -> None:
    """No output may be a record (also through links and hard links): hyst.Error naming both."""
    outputs = [(str(folder / name), "out") for name in (CSV_TABLE, MARKDOWN_TABLE, *files)]
    hyst.io.check_outputs([(path, "record") for path in paths], outputs)


def _with_sample_time(options: Dict[str, Any], sample_time: Optional[float]) -> Dict[str, Any]:
    """--sample-time as the fit option sample_time (refused when --option gives it too)."""
    if sample_time is None:
        return options
    if "sample_time" in options:
        raise ValueError("--sample-time and --option sample_time both give the sample time")
    return {**options, "sample_time": sample_time}


def fit(records: Records, model: str, *, input: str, output: str,
        out: Union[str, "os.PathLike[str]"], options: Optional[Mapping[str, Any]] = None,
        client: Any = None, scheduler: Optional[str] = None, workers: int = 2,
        timeout: float = 30.0, record_timeout: float = RECORD_TIMEOUT,
        progress: Any = None, time_column: Optional[str] = None) -> List[RecordResult]:
    """Fits `model` to every record, one task each, and returns the rows in the records' order.

    records: a path or glob pattern ("data/*.csv", "data/**/*.mat"), or a list of them; each
      must be a regular file (a FIFO, a device or a folder is refused).
    input, output: the columns (variables) of each record.
    out: the folder of the model files (created with its parents) and of the tables batch.csv
      and batch.md; a record's model file is its path below the records' common folder with the
      extension .json. They are published as one set at the end (hyst.io.OutputSet): a run that
      is interrupted or fails leaves the previous set; a folder it created is removed again.
    options: keyword arguments of hyst.fit: the model's fit options (operators=12) and the
      record's preparation (detrend=True, cycles="2-3"); sample_time=0.01 gives every record
      that sample time.
    time_column: the time column of every record [s]: a model with time in it is fitted at each
      record's own (uniform) step, as hyst.fit(time=...); a record without it fails.
    client: a distributed.Client to run on; scheduler: the address of a Dask scheduler
      ("tcp://host:8786") to connect to; neither: a local cluster of `workers` processes with a
      thread each, started and closed here. workers=0: no Dask, the records are fitted one after
      another in this process.
    timeout: seconds to wait for the scheduler and its first worker, and for a worker again when
      the cluster has none left during the run.
    record_timeout: seconds a record's read, fit and save may take (from the task's start);
      over it the record is a failed row and its worker is restarted (in this process, with
      workers=0, its thread is left to run on).
    progress: progress(done, total, record) after each record, or True (a tqdm bar, or lines on
      standard error).

    Raises ValueError for records that match nothing, clash or are not regular files, and for
    bad limits; hyst.Error for a model that cannot be fitted or an output that is a record;
    ImportError without Dask distributed; ConnectionError or RuntimeError for a cluster that
    cannot be used; ClusterLost (after publishing) for a cluster that lost every worker. A
    record that fails is a row with status "failed".
    """
    if workers < 0:
        raise ValueError(f"workers = {workers} must be >= 0 (0: fit in this process)")
    if client is not None and scheduler is not None:
        raise ValueError("give client or scheduler, not both")
    if workers == 0 and (client is not None or scheduler is not None):
        raise ValueError("workers=0 fits in this process: give no client or scheduler")
    timeout = _seconds(timeout, "timeout")
    record_timeout = _seconds(record_timeout, "record_timeout")
    entry = hyst.model_entry(model)
    if not entry.can_fit:
        fittable = ", ".join(other.name for other in hyst.models() if other.can_fit)
        raise hyst.Error(f"model '{model}' cannot be fitted (models that can: {fittable})")
    paths = _expand(records)
    folder = Path(out)
    files = _model_files(paths, folder)
    _check_outputs(paths, folder, files)
    chosen = dict(options or {})
    if time_column is not None and "sample_time" in chosen:
        raise ValueError("time_column and the option sample_time both give the sample time: "
                         "give one")
    timed = any(option.name == "sample_time" for option in entry.fit_options)
    if time_column is not None and not timed:
        raise hyst.Error(f"time_column: model '{model}' has no sample time (its output depends "
                         "on the order of the samples only)")
    callback = _progress.as_callback(progress, "batch.fit")

    created = _missing_folders(folder)
    published = False
    top_names = sorted({CSV_TABLE, MARKDOWN_TABLE} | {file.split(os.sep)[0] for file in files})
    try:
        with hyst.io.OutputSet(folder, top_names) as output_set:
            staging = Path(output_set.staged())
            for file in files:  # the workers write into these folders and never create them
                (staging / file).parent.mkdir(parents=True, exist_ok=True)
            topic = f"hyst-batch-{os.getpid()}-{time.time_ns()}"
            tasks = [_Task(record, os.path.abspath(record), os.path.abspath(folder / file),
                           os.path.abspath(staging / file), topic, k, model, input, output,
                           chosen, time_column)
                     for k, (record, file) in enumerate(zip(paths, files))]
            rows, lost, where, elapsed = _run(tasks, client, scheduler, workers, timeout,
                                              record_timeout, callback)
            failed = sum(not row.ok for row in rows)
            summary = (f"{len(rows) - failed} of {len(rows)} records fitted, {failed} failed, in "
                       f"{elapsed:.3g} s {where}; input '{input}', output '{output}'"
                       + (f", options {json.dumps(chosen)}" if chosen else "")
                       + (f"; the run ended early: {lost}" if lost else "") + ".")
            for row, task in zip(rows, tasks):  # a model file a failed record's task left late
                if not row.ok:
                    with contextlib.suppress(FileNotFoundError):
                        os.unlink(task.staged_file)
            _write_table(output_set.staged(CSV_TABLE), _csv_table(rows, folder))
            _write_table(output_set.staged(MARKDOWN_TABLE),
                         _markdown_table(rows, folder, f"Batch fit of '{model}'", summary))
            output_set.publish()
            published = True
    finally:
        if not published:
            _remove_if_empty(created)
    if lost:
        raise ClusterLost(f"{lost}; the run ended with {len(rows) - failed} of {len(rows)} "
                          f"records fitted, published in {folder / CSV_TABLE}", rows)
    return rows


def _run(tasks: Sequence[_Task], client: Any, scheduler: Optional[str], workers: int,
         timeout: float, record_timeout: float,
         callback: Optional[Callable[[int, int, str], None]]) -> Tuple[List[RecordResult], str,
                                                                      str, float]:
    """Runs the tasks serially or on the cluster: (rows, why it ended early or "", where, s)."""
    start = time.perf_counter()
    if workers == 0:
        rows = _run_serially(tasks, callback, record_timeout)
        return rows, "", "in one process, serially", time.perf_counter() - start
    with _cluster(client, scheduler, workers, timeout) as running:
        _check_workers(running, timeout)
        rows, lost = _run_on_cluster(running, tasks, callback, record_timeout, timeout,
                                     stays=client is not None or scheduler is not None)
        where = (f"on a local cluster of {workers} workers"
                 if client is None and scheduler is None
                 else f"on the Dask cluster at {running.scheduler.address}")
    return rows, lost, where, time.perf_counter() - start


# The command line: python3 -m hyst.batch fit ... (and `hyst batch fit ...`, which runs it).

class _Parser(argparse.ArgumentParser):
    """Usage errors as one line, like every error of the hyst command line; exit status 2."""

    def error(self, message: str) -> Any:
        print(f"hyst: error: {message} (see '{self.prog} --help')", file=sys.stderr)
        sys.exit(2)


def _option(text: str) -> Any:
    """--option key=value: the value is JSON when it parses (12, true, [0, 0.5]), else text."""
    key, equals, value = text.partition("=")
    if not equals or not key:
        raise argparse.ArgumentTypeError(f"'{text}': expected key=value, e.g. operators=12")
    try:
        return key, json.loads(value)
    except ValueError:
        return key, value


def _seconds_argument(text: str) -> float:
    """--timeout, --record-timeout: a number of seconds > 0 ("-1", "nan", "1s" are refused)."""
    try:
        return _seconds(float(text), "")
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not a number of seconds > 0") from None


def _parser() -> _Parser:
    parser = _Parser(prog="hyst batch", description=(
        "Many records, one fit each, on a Dask distributed cluster (python3 -m hyst.batch; "
        "'hyst batch' runs it)."))
    commands = parser.add_subparsers(dest="command", required=True, metavar="command")
    fit_command = commands.add_parser(
        "fit", formatter_class=argparse.RawDescriptionHelpFormatter,
        help="fit a model to every record",
        description="Fits a model to every record on a Dask cluster: a model file per record in "
                    "--out and the tables batch.csv and batch.md (record, status, NRMSE, "
                    "parameters, time, reason).",
        epilog="""Examples:
  hyst batch fit --model pi --data 'records/*.csv' --input v --output y --out fits/
  hyst batch fit --model pi --data 'records/**/*.mat' --input v --output y --out fits/ \\
      --scheduler tcp://head:8786 --option operators=12 --option initial_state=periodic
Without --scheduler a local cluster of --workers processes runs on this machine; --workers 0
fits in this process, without Dask. Workers read the records and write the model files
themselves, so both must be on a file system every worker sees at the same path
(docs/scaling.md). A record that fails is listed with its reason (also as a warning on
standard error); the others go on.
The model files and tables are published as one set at the end: each name in --out is a link
into .hyst-current, switched at once, so an interrupted or failed run leaves the previous set.
An output that is a record, and a record that is not a regular file, are refused first.
Exit status: 0 when at least one record was fitted, 1 when none was (or the cluster could not
be used, or lost every worker: the rows fitted so far are published), 2 for usage errors, 130
and 143 when stopped by SIGINT or SIGTERM (the previous set stays).""")
    fit_command.add_argument("--model", required=True, help="model name (see 'hyst models')")
    fit_command.add_argument("--data", required=True, nargs="+", metavar="RECORDS",
                             help="record files or glob patterns (quoted: 'folder/*.csv'; ** "
                                  "recurses): CSV, .mat, aixACCT or MicroMag loop files")
    fit_command.add_argument("--input", required=True, help="input column (variable)")
    fit_command.add_argument("--output", required=True, help="output column (variable)")
    fit_command.add_argument("--out", required=True,
                             help="folder of the model files and tables (created if missing)")
    where = fit_command.add_mutually_exclusive_group()
    where.add_argument("--scheduler", metavar="ADDRESS",
                       help="a running Dask scheduler, e.g. tcp://host:8786")
    where.add_argument("--workers", type=int, default=2, metavar="N",
                       help="processes of the local cluster (default 2; 0: no cluster)")
    timing = fit_command.add_mutually_exclusive_group()
    timing.add_argument("--time", metavar="COLUMN",
                        help="time column of every record [s]: a model with time in it is "
                             "fitted at each record's own step")
    timing.add_argument("--sample-time", type=_seconds_argument, metavar="SECONDS",
                        help="sample time of every record [s], for files without a time column")
    fit_command.add_argument("--option", action="append", default=[], type=_option,
                             metavar="KEY=VALUE",
                             help="a fit option or hyst.fit keyword (repeatable; the value is "
                                  "JSON if it parses, else text)")
    fit_command.add_argument("--timeout", type=_seconds_argument, default=30.0,
                             metavar="SECONDS",
                             help="seconds to wait for the scheduler and its first worker, and "
                                  "for a worker when the cluster has none left (default 30)")
    fit_command.add_argument("--record-timeout", type=_seconds_argument,
                             default=RECORD_TIMEOUT, metavar="SECONDS",
                             help="seconds one record's read, fit and save may take; over it "
                                  "the record fails and its worker is restarted (default "
                                  f"{RECORD_TIMEOUT:g})")
    shown = fit_command.add_mutually_exclusive_group()
    shown.add_argument("--progress", action="store_true",
                       help="report progress on standard error also when it is not a terminal")
    shown.add_argument("--quiet", action="store_true", help="no progress report")
    return parser


class Interrupted(KeyboardInterrupt):
    """SIGINT or SIGTERM ended the run (the command line's exit status: 128 + signal)."""

    def __init__(self, signum: int) -> None:
        super().__init__(signal.Signals(signum).name)
        self.signum = signum


@contextlib.contextmanager
def _signals_end_the_run() -> Iterator[None]:
    """SIGINT and SIGTERM raise Interrupted, so that the run cleans up on its way out (the
    cluster's tasks cancelled, the staged set removed); a second signal ends the process at
    once (what it left is removed by the next run)."""
    def end_now(signum: int, _: Any) -> None:
        os._exit(128 + signum)

    def interrupt(signum: int, _: Any) -> None:
        for number in (signal.SIGINT, signal.SIGTERM):
            signal.signal(number, end_now)
        raise Interrupted(signum)

    previous = {number: signal.signal(number, interrupt)
                for number in (signal.SIGINT, signal.SIGTERM)}
    try:
        yield
    finally:
        for number, handler in previous.items():
            signal.signal(number, handler)


def _quiet_dask_logs() -> None:
    """Dask's own log lines and warnings (a worker restarted, a cluster closed early) would break
    the rule of one line per error; what matters reaches the rows and the error message. Its loggers have
    levels of their own (dask's logging configuration), set when distributed is imported."""
    with contextlib.suppress(ImportError):
        import distributed  # noqa: F401  (configures its loggers)
    for name in list(logging.root.manager.loggerDict):
        if name.split(".")[0] in ("distributed", "tornado", "asyncio"):
            logging.getLogger(name).setLevel(logging.CRITICAL)
    # A signal that interrupts a wait on the cluster leaves Dask's coroutine of it unawaited.
    warnings.filterwarnings("ignore", message="coroutine .* was never awaited",
                            category=RuntimeWarning)


def main(argv: Optional[Sequence[str]] = None) -> int:
    """The command line; returns the exit status."""
    arguments = _parser().parse_args(argv)
    _quiet_dask_logs()
    # As the other long commands: a bar on a terminal, one line per record in a pipe when asked.
    progress: Any = None
    if not arguments.quiet and sys.stderr.isatty():
        progress = True
    elif arguments.progress:
        progress = _progress._Lines("batch.fit")
    try:
        with _signals_end_the_run():
            rows = fit(arguments.data, arguments.model, input=arguments.input,
                       output=arguments.output, out=arguments.out,
                       options=_with_sample_time(dict(arguments.option), arguments.sample_time),
                       time_column=arguments.time, scheduler=arguments.scheduler,
                       workers=arguments.workers, timeout=arguments.timeout,
                       record_timeout=arguments.record_timeout, progress=progress)
    except Interrupted as stop:
        print(f"hyst: error: stopped by {stop}; {arguments.out} keeps its previous files",
              file=sys.stderr)
        return 128 + stop.signum
    except (hyst.Error, ValueError, OSError, ImportError, RuntimeError) as error:
        print(f"hyst: error: {_one_line(str(error))}", file=sys.stderr)
        return 1
    failed = [row for row in rows if not row.ok]
    tables = f"{Path(arguments.out) / CSV_TABLE} and {Path(arguments.out) / MARKDOWN_TABLE}"
    if len(failed) == len(rows):
        print(f"hyst: error: no record was fitted ({len(rows)} failed; {tables}); the first: "
              f"{failed[0].reason}", file=sys.stderr)
        return 1
    for row in failed:
        print(f"hyst: warning: {row.record} failed: {row.reason}", file=sys.stderr)
    print(f"hyst batch fit: {len(rows) - len(failed)} of {len(rows)} records fitted, "
          f"{len(failed)} failed")
    print(f"wrote {len(rows) - len(failed)} model files in {arguments.out}, {tables}")
    return 0


if __name__ == "__main__":
    # Run as the module hyst.batch, not as __main__, so that the tasks pickle as references to
    # it, which every worker imports.
    from hyst.batch import main as _main
    status = _main()
    # A thread of a record over its time limit, or of an interrupted run, may still be inside a
    # fit (C++): the interpreter's exit would end it by unwinding, which aborts. Everything of
    # the run is closed by now, so the process ends at once.
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(status)
