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
with hyst.fit and writes the model file into `out` atomically (hyst.save_model). Records and
`out` must therefore be on a file system that every worker sees at the same path. A record that
fails (unreadable, a column missing, a fit error, a worker that died) becomes a "failed" row with
the reason; the other records go on. The rows go to out/batch.csv and out/batch.md.
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
import os
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable, Dict, Iterator, List, Mapping, Optional, Sequence, Union

import hyst
from . import _progress

_MISSING = "hyst.batch needs Dask distributed: apt-get install python3-distributed"
CSV_TABLE = "batch.csv"
MARKDOWN_TABLE = "batch.md"

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
    model_file: str
    model: str
    input: str
    output: str
    options: Mapping[str, Any]


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
        columns = hyst.data.extract(task.path, [task.input, task.output])
        input, output = columns[task.input], columns[task.output]
        if input.size == 0:
            raise hyst.Error(f"{task.path}: input '{task.input}' has no samples")
        result = hyst.fit(task.model, input, output, **task.options)
        report = result.report
        if report.status == "failed":
            raise hyst.Error(f"fitting '{task.model}' to {task.path} failed: {report.message}")
        os.makedirs(os.path.dirname(task.model_file), exist_ok=True)
        hyst.save_model(task.model_file, result.model, _fit_info(report, task, input.size))
    except Exception as error:  # a failed record must never stop the others
        return RecordResult(task.record, "failed", time.perf_counter() - start,
                            reason=_reason(task, error))
    return RecordResult(task.record, "ok", time.perf_counter() - start,
                        nrmse_percent=report.fit.nrmse_percent, parameters=report.parameters,
                        fit_status=report.status, model_file=task.model_file)


def _worker_version() -> str:
    """Runs on every worker before the tasks: it fails there when hyst is not importable."""
    return hyst.__version__


def _expand(records: Records) -> List[str]:
    """The record paths: a pattern with *, ? or [ ] is expanded (sorted; ** recurses) and must
    match a file; a plain path is taken as it is (an unreadable one becomes a failed row)."""
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
    return paths


def _model_files(paths: Sequence[str], out: Path) -> List[Path]:
    """Each record's model file: its path relative to the records' common folder with the
    extension .json (data/a/r1.csv -> out/a/r1.json), so that records of one name in different
    folders keep their own. Two records that would still share one (r1.csv and r1.mat in one
    folder, or a record given twice) are refused, naming both."""
    absolute = [os.path.abspath(path) for path in paths]
    common = os.path.commonpath([os.path.dirname(path) for path in absolute])
    files: List[Path] = []
    owners: Dict[Path, str] = {}
    for path, full in zip(paths, absolute):
        file = out / (os.path.splitext(os.path.relpath(full, common))[0] + ".json")
        if file in owners:
            raise ValueError(f"records '{owners[file]}' and '{path}' would both be fitted into "
                             f"{file}: give records whose names differ apart from their extension")
        owners[file] = path
        files.append(file)
    return files


def _distributed() -> Any:
    try:
        import distributed
    except ImportError as error:
        raise ImportError(_MISSING) from error
    return distributed


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


def _run_on_cluster(client: Any, tasks: Sequence[_Task],
                    progress: Optional[Callable[[int, int, str], None]]) -> List[RecordResult]:
    distributed = _distributed()
    futures = [client.submit(_run_task, task, pure=False) for task in tasks]
    index = {future.key: k for k, future in enumerate(futures)}
    rows: Dict[int, RecordResult] = {}
    for done, future in enumerate(distributed.as_completed(futures), start=1):
        k = index[future.key]
        try:
            rows[k] = future.result()
        except Exception as error:  # the task itself failed: its worker died, or unpickling
            rows[k] = RecordResult(tasks[k].record, "failed", 0.0, reason=_reason(tasks[k], error))
        future.release()
        if progress:
            progress(done, len(tasks), tasks[k].record)
    return [rows[k] for k in range(len(tasks))]


def _run_serially(tasks: Sequence[_Task],
                  progress: Optional[Callable[[int, int, str], None]]) -> List[RecordResult]:
    rows = []
    for done, task in enumerate(tasks, start=1):
        rows.append(_run_task(task))
        if progress:
            progress(done, len(tasks), task.record)
    return rows


def _write_atomically(path: Path, text: str) -> None:
    """A temporary file in the same folder, renamed over `path`: readers see old or new."""
    with tempfile.NamedTemporaryFile("w", encoding="utf-8", newline="", dir=path.parent,
                                     prefix=f".{path.name}.tmp.", delete=False) as file:
        temporary = file.name
        try:
            file.write(text)
            file.flush()
            os.fsync(file.fileno())
        except BaseException:
            file.close()
            os.unlink(temporary)
            raise
    try:
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise


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


def fit(records: Records, model: str, *, input: str, output: str,
        out: Union[str, "os.PathLike[str]"], options: Optional[Mapping[str, Any]] = None,
        client: Any = None, scheduler: Optional[str] = None, workers: int = 2,
        timeout: float = 30.0, progress: Any = None) -> List[RecordResult]:
    """Fits `model` to every record, one task each, and returns the rows in the records' order.

    records: a path or glob pattern ("data/*.csv", "data/**/*.mat"), or a list of them.
    input, output: the columns (variables) of each record.
    out: the folder of the model files (created with its parents) and of the tables batch.csv
      and batch.md; a record's model file is its path below the records' common folder with the
      extension .json.
    options: keyword arguments of hyst.fit: the model's fit options (operators=12) and the
      record's preparation (detrend=True, cycles="2-3").
    client: a distributed.Client to run on; scheduler: the address of a Dask scheduler
      ("tcp://host:8786") to connect to; neither: a local cluster of `workers` processes with a
      thread each, started and closed here. workers=0: no Dask, the records are fitted one after
      another in this process.
    timeout: seconds to wait for the scheduler and for its first worker.
    progress: progress(done, total, record) after each record, or True (a tqdm bar, or lines on
      standard error).

    Raises ValueError for records that match nothing or clash, hyst.Error for a model that
    cannot be fitted, ImportError without Dask distributed, ConnectionError or RuntimeError for
    a cluster that cannot be used. A record that fails is a row with status "failed".
    """
    if workers < 0:
        raise ValueError(f"workers = {workers} must be >= 0 (0: fit in this process)")
    if client is not None and scheduler is not None:
        raise ValueError("give client or scheduler, not both")
    if workers == 0 and (client is not None or scheduler is not None):
        raise ValueError("workers=0 fits in this process: give no client or scheduler")
    entry = hyst.model_entry(model)
    if not entry.can_fit:
        fittable = ", ".join(other.name for other in hyst.models() if other.can_fit)
        raise hyst.Error(f"model '{model}' cannot be fitted (models that can: {fittable})")
    paths = _expand(records)
    folder = Path(out)
    chosen = dict(options or {})
    tasks = [_Task(record, os.path.abspath(record), os.path.abspath(file), model, input, output,
                   chosen)
             for record, file in zip(paths, _model_files(paths, folder))]
    folder.mkdir(parents=True, exist_ok=True)
    callback = _progress.as_callback(progress, "batch.fit")

    start = time.perf_counter()
    if workers == 0:
        rows = _run_serially(tasks, callback)
        where = "in one process, serially"
    else:
        with _cluster(client, scheduler, workers, timeout) as running:
            _check_workers(running, timeout)
            rows = _run_on_cluster(running, tasks, callback)
            where = (f"on a local cluster of {workers} workers"
                     if client is None and scheduler is None
                     else f"on the Dask cluster at {running.scheduler.address}")
    elapsed = time.perf_counter() - start

    failed = sum(not row.ok for row in rows)
    summary = (f"{len(rows) - failed} of {len(rows)} records fitted, {failed} failed, in "
               f"{elapsed:.3g} s {where}; input '{input}', output '{output}'"
               + (f", options {json.dumps(chosen)}" if chosen else "") + ".")
    _write_atomically(folder / CSV_TABLE, _csv_table(rows, folder))
    _write_atomically(folder / MARKDOWN_TABLE,
                      _markdown_table(rows, folder, f"Batch fit of '{model}'", summary))
    return rows


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
Exit status: 0 when at least one record was fitted, 1 when none was (or the cluster could not
be used), 2 for usage errors.""")
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
    fit_command.add_argument("--option", action="append", default=[], type=_option,
                             metavar="KEY=VALUE",
                             help="a fit option or hyst.fit keyword (repeatable; the value is "
                                  "JSON if it parses, else text)")
    fit_command.add_argument("--timeout", type=float, default=30.0, metavar="SECONDS",
                             help="seconds to wait for the scheduler and its first worker "
                                  "(default 30)")
    shown = fit_command.add_mutually_exclusive_group()
    shown.add_argument("--progress", action="store_true",
                       help="report progress on standard error also when it is not a terminal")
    shown.add_argument("--quiet", action="store_true", help="no progress report")
    return parser


def main(argv: Optional[Sequence[str]] = None) -> int:
    """The command line; returns the exit status."""
    arguments = _parser().parse_args(argv)
    # As the other long commands: a bar on a terminal, one line per record in a pipe when asked.
    progress: Any = None
    if not arguments.quiet and sys.stderr.isatty():
        progress = True
    elif arguments.progress:
        progress = _progress._Lines("batch.fit")
    try:
        rows = fit(arguments.data, arguments.model, input=arguments.input,
                   output=arguments.output, out=arguments.out, options=dict(arguments.option),
                   scheduler=arguments.scheduler, workers=arguments.workers,
                   timeout=arguments.timeout, progress=progress)
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
    sys.exit(_main())
