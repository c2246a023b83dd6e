"""Batch fitting on Dask (hyst.batch): 200 generated records fitted on a local cluster of two
workers, every result checked against a serial fit of the same record; broken records listed
as failed with their reason while the others go on; model-file names, tables, errors and the
command line."""

import csv
import json
import os
import signal
import stat
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import hyst
import hyst.batch

distributed = pytest.importorskip("distributed", reason="hyst.batch needs python3-distributed")
import dask  # noqa: E402  (a dependency of distributed)

RECORDS = 200
OPTIONS = {"operators": 6}
BROKEN = {
    "broken_missing_column.csv": ("v,z\n0,1\n1,2\n", "no column 'y'"),
    "broken_malformed_number.csv": ("v,y\n0,1\n0.5,abc\n1,2\n", ":3: column 2 ('y'): 'abc'"),
    "broken_empty.csv": ("", "file is empty"),
}


def write_records(folder, count, seed=7):
    """PI models with random weights, each driven by a decaying sine of its own amplitude, plus
    seeded noise: short records that every fit can tell apart."""
    rng = np.random.default_rng(seed)
    grid = hyst.signals.TimeGrid(300, 1e-3)
    for k in range(count):
        amplitude = rng.uniform(1.0, 2.0)
        v = hyst.signals.generate(grid, hyst.signals.DecayingSine(
            amplitude=amplitude, frequency=10.0, time_constant=0.2))
        truth = hyst.PrandtlIshlinskii([0.0, 0.25, 0.5, 0.75], rng.uniform(0.1, 1.0, 4))
        y = truth.simulate(v) + rng.normal(0.0, 0.01, v.size)
        hyst.io.write_csv(folder / f"r{k:03d}.csv", {"v": v, "y": y})


def serial_fit(path):
    columns = hyst.data.extract(path, ["v", "y"])
    return hyst.fit("pi", columns["v"], columns["y"], **OPTIONS)


def assert_same(batch, serial, where):
    """Equal to 1e-12 relative (in practice bit for bit: the same code on the same samples)."""
    if isinstance(serial, dict):
        assert batch.keys() == serial.keys(), where
        for key in serial:
            assert_same(batch[key], serial[key], f"{where}.{key}")
    elif isinstance(serial, (list, float, int)):
        np.testing.assert_allclose(batch, serial, rtol=1e-12, atol=0.0, err_msg=where)
    else:
        assert batch == serial, where


@pytest.fixture(scope="module")
def records(tmp_path_factory):
    folder = tmp_path_factory.mktemp("records")
    write_records(folder, RECORDS)
    for name, (text, _) in BROKEN.items():
        (folder / name).write_text(text)
    return folder


@pytest.fixture(scope="module")
def on_cluster(records, tmp_path_factory):
    out = tmp_path_factory.mktemp("cluster") / "fits"
    rows = hyst.batch.fit(str(records / "*.csv"), "pi", input="v", output="y", out=out,
                          options=OPTIONS, workers=2)
    return rows, out


def test_every_record_fitted_on_the_cluster_equals_its_serial_fit(records, on_cluster):
    rows, out = on_cluster
    assert len(rows) == RECORDS + len(BROKEN)
    assert [row.record for row in rows] == sorted(str(path) for path in records.glob("*.csv"))
    fitted = [row for row in rows if not Path(row.record).name.startswith("broken")]
    assert len(fitted) == RECORDS
    for row in fitted:
        assert row.status == "ok" and row.reason == "", row
        model, report = serial_fit(row.record)
        assert row.nrmse_percent == pytest.approx(report.fit.nrmse_percent, rel=1e-12, abs=0.0)
        assert row.parameters == report.parameters and row.fit_status == report.status
        assert row.model_file == str(out / (Path(row.record).stem + ".json"))
        saved = hyst.load_model(row.model_file)
        assert_same(saved.params, model.params, f"{row.record} params")
        assert_same(saved.state, model.state, f"{row.record} state")
        info = json.loads(Path(row.model_file).read_text())["info"]
        assert info["created_by"] == "hyst batch fit" and info["options"] == OPTIONS
        assert info["data"] == {"file": row.record, "input": "v", "output": "y", "samples": 300}
        assert info["fit"]["nrmse_percent"] == row.nrmse_percent


def test_broken_records_fail_with_their_reason_and_stop_nothing(records, on_cluster):
    rows, _ = on_cluster
    failed = {Path(row.record).name: row for row in rows if row.status == "failed"}
    assert failed.keys() == BROKEN.keys()
    for name, row in failed.items():
        assert str(records / name) in row.reason, row.reason
        assert BROKEN[name][1] in row.reason, row.reason
        assert row.model_file is None and row.nrmse_percent is None


def test_the_tables_list_every_record(records, on_cluster):
    rows, out = on_cluster
    with open(out / "batch.csv", newline="") as file:
        table = list(csv.DictReader(file))
    assert [line["record"] for line in table] == [row.record for row in rows]
    for line, row in zip(table, rows):
        assert line["status"] == row.status and line["reason"] == row.reason
        if row.status == "ok":
            assert float(line["nrmse_percent"]) == row.nrmse_percent  # written with repr()
            assert line["model_file"] == Path(row.record).stem + ".json"
    markdown = (out / "batch.md").read_text()
    assert f"{RECORDS} of {RECORDS + len(BROKEN)} records fitted, {len(BROKEN)} failed" in markdown
    assert "on a local cluster of 2 workers" in markdown
    assert markdown.count("\n| ") == 1 + len(rows)  # the header and a line per record
    assert not list(out.glob(".*.tmp.*"))


def test_the_serial_run_gives_the_same_rows(records, on_cluster, tmp_path):
    rows, _ = on_cluster
    calls = []
    serial = hyst.batch.fit(str(records / "*.csv"), "pi", input="v", output="y",
                            out=tmp_path, options=OPTIONS, workers=0,
                            progress=lambda done, total, record: calls.append((done, total)))
    assert calls == [(k, len(rows)) for k in range(1, len(rows) + 1)]
    for row, reference in zip(rows, serial):
        assert (row.record, row.status, row.nrmse_percent, row.parameters, row.reason) == (
            reference.record, reference.status, reference.nrmse_percent, reference.parameters,
            reference.reason)
        if row.status == "ok":
            cluster, alone = hyst.load_model(row.model_file), hyst.load_model(reference.model_file)
            assert (cluster.params, cluster.state) == (alone.params, alone.state)
    assert "in one process, serially" in (tmp_path / "batch.md").read_text()


def exit_on(record_suffix):
    """A function for client.run: on the worker, the task of the record ending in
    `record_suffix` ends the worker's process; the others run as usual."""
    def patch():
        import os
        import time
        import hyst.batch
        run = hyst.batch._run_task

        def run_or_exit(task):
            if not task.record.endswith(record_suffix):
                return run(task)
            time.sleep(0.5)  # the worker reports the tasks it has finished before it goes
            os._exit(1)

        hyst.batch._run_task = run_or_exit
    return patch


def test_a_worker_that_dies_fails_its_record_only(tmp_path):
    write_records(tmp_path, 4)
    hyst.io.write_csv(tmp_path / "zz_kills_its_worker.csv", {"v": [0.0, 1.0], "y": [0.0, 1.0]})

    # One worker runs the tasks in the order submitted, so the record submitted last dies alone;
    # with no retry, one death is its failure.
    with dask.config.set({"distributed.scheduler.allowed-failures": 0}), \
            distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True,
                                     dashboard_address=":0") as cluster, \
            distributed.Client(cluster) as client:
        client.run(exit_on("zz_kills_its_worker.csv"))
        rows = hyst.batch.fit(str(tmp_path / "*.csv"), "pi", input="v", output="y",
                              out=tmp_path / "fits", client=client)
    assert [row.status for row in rows] == ["ok"] * 4 + ["failed"], rows
    assert rows[-1].reason.startswith(f"{tmp_path / 'zz_kills_its_worker.csv'}: KilledWorker")


def test_records_of_one_name_in_different_folders_keep_their_own_model_file(tmp_path):
    for folder in ("a", "b"):
        (tmp_path / folder).mkdir()
    write_records(tmp_path / "a", 1)
    write_records(tmp_path / "b", 1, seed=8)
    out = tmp_path / "fits"
    rows = hyst.batch.fit(str(tmp_path / "*" / "r000.csv"), "pi", input="v", output="y",
                          out=out, workers=0)
    assert [row.model_file for row in rows] == [str(out / "a" / "r000.json"),
                                                str(out / "b" / "r000.json")]
    assert hyst.load_model(rows[0].model_file).params != hyst.load_model(rows[1].model_file).params
    # One name apart from the extension in one folder, or a record twice: refused before any fit.
    (tmp_path / "a" / "r000.mat").write_bytes(b"")
    with pytest.raises(ValueError, match=r"records '.*a/r000.csv' and '.*a/r000.mat' would both"):
        hyst.batch.fit(str(tmp_path / "a" / "r000.*"), "pi", input="v", output="y",
                       out=tmp_path / "clash", workers=0)
    record = str(tmp_path / "a" / "r000.csv")
    with pytest.raises(ValueError, match="would both be fitted into"):
        hyst.batch.fit([record, record], "pi", input="v", output="y", out=out, workers=0)
    assert not (tmp_path / "clash").exists()


def test_bad_arguments_are_named(tmp_path):
    write_records(tmp_path, 1)
    record = str(tmp_path / "r000.csv")
    with pytest.raises(ValueError, match=r"records '.*nothing/\*.csv': the pattern matches no"):
        hyst.batch.fit(str(tmp_path / "nothing" / "*.csv"), "pi", input="v", output="y",
                       out=tmp_path / "o", workers=0)
    with pytest.raises(hyst.Error, match="nosuch"):
        hyst.batch.fit(record, "nosuch", input="v", output="y", out=tmp_path / "o", workers=0)
    with pytest.raises(hyst.Error, match="model 'ikuta_sma' cannot be fitted"):
        hyst.batch.fit(record, "ikuta_sma", input="v", output="y", out=tmp_path / "o", workers=0)
    with pytest.raises(ValueError, match="workers = -1 must be >= 0"):
        hyst.batch.fit(record, "pi", input="v", output="y", out=tmp_path / "o", workers=-1)
    with pytest.raises(ValueError, match="client or scheduler, not both"):
        hyst.batch.fit(record, "pi", input="v", output="y", out=tmp_path / "o",
                       client=object(), scheduler="tcp://127.0.0.1:8786")
    with pytest.raises(ConnectionError, match="cannot connect to the Dask scheduler at "
                                              "'tcp://127.0.0.1:9'"):
        hyst.batch.fit(record, "pi", input="v", output="y", out=tmp_path / "o",
                       scheduler="tcp://127.0.0.1:9", timeout=1.0)


def test_without_dask_the_error_says_what_to_install(tmp_path, monkeypatch):
    write_records(tmp_path, 1)
    monkeypatch.setitem(sys.modules, "distributed", None)  # import distributed fails
    with pytest.raises(ImportError, match="apt-get install python3-distributed"):
        hyst.batch.fit(str(tmp_path / "r000.csv"), "pi", input="v", output="y",
                       out=tmp_path / "o")


def test_the_command_line(tmp_path, capsys):
    write_records(tmp_path, 2)
    (tmp_path / "r_empty.csv").write_text("")
    arguments = ["fit", "--model", "pi", "--input", "v", "--output", "y", "--workers", "0",
                 "--option", "operators=5"]
    status = hyst.batch.main(arguments + ["--data", str(tmp_path / "*.csv"),
                                          "--out", str(tmp_path / "fits")])
    printed = capsys.readouterr()
    assert status == 0
    assert "2 of 3 records fitted, 1 failed" in printed.out
    assert printed.err.startswith("hyst: warning: ") and "r_empty.csv" in printed.err
    assert hyst.load_model(tmp_path / "fits" / "r000.json").parameter_count() == 6
    # Every record failed: status 1, one error line naming the first reason.
    status = hyst.batch.main(arguments + ["--data", str(tmp_path / "r_empty.csv"),
                                          "--out", str(tmp_path / "none")])
    printed = capsys.readouterr()
    assert status == 1
    assert printed.err.count("\n") == 1
    assert printed.err.startswith("hyst: error: no record was fitted (1 failed")
    # Usage errors: status 2, one line.
    with pytest.raises(SystemExit) as raised:
        hyst.batch.main(["fit", "--model", "pi", "--option", "operators"])
    assert raised.value.code == 2
    error = capsys.readouterr().err
    assert error.count("\n") == 1 and error.startswith("hyst: error: ")
    assert "expected key=value" in error and "see 'hyst batch fit --help'" in error


# --- Runs that never damage and always end -------------------------------------------------------

def published_files(folder):
    """{name: bytes} of every file a reader sees in `folder` (through the set's links), below it
    too; the set's own folders (.hyst-*) are left out."""
    files = {}
    for where, folders, names in os.walk(folder, followlinks=True):
        folders[:] = [name for name in folders if not name.startswith(".hyst-")]
        for name in names:
            if not name.startswith(".hyst-"):
                path = Path(where) / name
                files[str(path.relative_to(folder))] = path.read_bytes()
    return files


def set_folders(folder):
    return sorted(path.name for path in Path(folder).iterdir()
                  if path.name.startswith(".hyst-set."))


def test_an_output_that_is_a_record_is_refused_before_any_work(tmp_path):
    records = tmp_path / "rec"
    records.mkdir()
    write_records(records, 2)
    (records / "batch.csv").write_text("v,y\n0,0\n1,1\n")  # a record named like the table
    before = published_files(records)
    with pytest.raises(hyst.Error, match=rf"out '{records}/batch.csv' is the same file as the "
                                         rf"input record '{records}/batch.csv'"):
        hyst.batch.fit(str(records / "*.csv"), "pi", input="v", output="y", out=records,
                       workers=0)
    assert published_files(records) == before and not set_folders(records)
    # Through a hard link: fits/r001.json is the record r001.csv under another name.
    out = tmp_path / "fits"
    out.mkdir()
    (records / "r001.json").hardlink_to(records / "r001.csv")
    with pytest.raises(hyst.Error, match=r"out '.*r001.json' is the same file as the input "
                                         r"record '.*rec/r001.csv'"):
        hyst.batch.fit([str(records / "r000.csv"), str(records / "r001.csv")], "pi", input="v",
                       output="y", out=records, workers=0)
    assert (records / "r001.csv").read_bytes() == before["r001.csv"]


def test_records_that_are_not_regular_files_are_refused_up_front(tmp_path):
    write_records(tmp_path, 1)
    fifo = tmp_path / "r_fifo.csv"
    os.mkfifo(fifo)  # reading it would block forever: no writer
    out = tmp_path / "new" / "fits"
    for workers in (0, 2):
        with pytest.raises(ValueError, match=rf"record '{fifo}' is a FIFO, not a regular file"):
            hyst.batch.fit(str(tmp_path / "*.csv"), "pi", input="v", output="y", out=out,
                           workers=workers)
    (tmp_path / "folder.csv").mkdir()
    with pytest.raises(ValueError, match=r"record '.*folder.csv' is a folder, not a regular"):
        hyst.batch.fit([str(tmp_path / "r000.csv"), str(tmp_path / "folder.csv")], "pi",
                       input="v", output="y", out=out, workers=0)
    assert not (tmp_path / "new").exists()


def test_a_run_publishes_one_set_with_the_usual_file_mode(tmp_path):
    (tmp_path / "a").mkdir()
    write_records(tmp_path / "a", 2)
    write_records(tmp_path, 1)
    out = tmp_path / "fits"
    old_umask = os.umask(0o022)
    try:
        rows = hyst.batch.fit([str(tmp_path / "r000.csv"), str(tmp_path / "a" / "r001.csv")],
                              "pi", input="v", output="y", out=out, workers=0)
    finally:
        os.umask(old_umask)
    assert [row.status for row in rows] == ["ok", "ok"]
    assert sorted(published_files(out)) == ["a/r001.json", "batch.csv", "batch.md", "r000.json"]
    for name in ("batch.csv", "batch.md", "r000.json", "a"):  # every name is a link of the set
        assert os.readlink(out / name) == f".hyst-current/{name}"
    for name in ("batch.csv", "batch.md", "r000.json", "a/r001.json"):
        assert stat.S_IMODE(os.stat(out / name).st_mode) == 0o644, name
    assert len(set_folders(out)) == 1


def test_bad_time_limits_are_refused_naming_them(tmp_path, capsys):
    write_records(tmp_path, 1)
    record = str(tmp_path / "r000.csv")
    for name, value in (("timeout", -1), ("record_timeout", float("nan")), ("timeout", 0)):
        with pytest.raises(ValueError, match=rf"{name} = {value!r} must be a number of seconds"):
            hyst.batch.fit(record, "pi", input="v", output="y", out=tmp_path / "o", workers=0,
                           **{name: value})
    for option, value in (("--timeout", "-1"), ("--record-timeout", "nan"), ("--timeout", "1s")):
        with pytest.raises(SystemExit) as raised:
            hyst.batch.main(["fit", "--model", "pi", "--data", record, "--input", "v",
                             "--output", "y", "--out", str(tmp_path / "o"), option, value])
        assert raised.value.code == 2
        error = capsys.readouterr().err
        assert error.count("\n") == 1, error
        assert f"argument {option}: '{value}' is not a number of seconds > 0" in error
    assert not (tmp_path / "o").exists()


def closed_port():
    """A port of 127.0.0.1 that nothing listens on (bound, then closed)."""
    import socket
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def test_an_unreachable_scheduler_fails_at_once_and_leaves_no_folder(tmp_path):
    write_records(tmp_path, 1)
    address = f"tcp://127.0.0.1:{closed_port()}"
    start = time.monotonic()
    with pytest.raises(ConnectionError, match=rf"cannot connect to the Dask scheduler at "
                                              rf"'{address}': Connection refused"):
        hyst.batch.fit(str(tmp_path / "r000.csv"), "pi", input="v", output="y",
                       out=tmp_path / "new" / "fits", scheduler=address)  # timeout 30 s
    assert time.monotonic() - start < 3.0
    assert not (tmp_path / "new").exists()


def slow_on(record_suffix, seconds):
    """A function for client.run (or to call here): the task of the record ending in
    `record_suffix` sleeps `seconds` first; the others run as usual."""
    def patch():
        import time
        import hyst.batch
        run = hyst.batch._run_task

        def run_slowly(task):
            if task.record.endswith(record_suffix):
                time.sleep(seconds)
            return run(task)

        hyst.batch._run_task = run_slowly
    return patch


def test_a_record_over_its_time_limit_fails_in_this_process(tmp_path, monkeypatch):
    write_records(tmp_path, 2)
    hyst.io.write_csv(tmp_path / "r_slow.csv", {"v": [0.0, 1.0], "y": [0.0, 1.0]})
    monkeypatch.setattr(hyst.batch, "_run_task", hyst.batch._run_task)  # restored afterwards
    slow_on("r_slow.csv", 30.0)()
    start = time.monotonic()
    rows = hyst.batch.fit(str(tmp_path / "*.csv"), "pi", input="v", output="y",
                          out=tmp_path / "fits", workers=0, record_timeout=0.5)
    assert time.monotonic() - start < 5.0
    assert [row.status for row in rows] == ["ok", "ok", "failed"]
    assert rows[2].reason == (f"{tmp_path / 'r_slow.csv'}: not finished within 0.5 s "
                              "(record_timeout, --record-timeout)")
    assert not (tmp_path / "fits" / "r_slow.json").exists()


def one_worker_cluster():
    return distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True,
                                    dashboard_address=":0")


def test_a_record_over_its_time_limit_fails_and_its_worker_is_restarted(tmp_path):
    write_records(tmp_path, 3)
    hyst.io.write_csv(tmp_path / "a_slow.csv", {"v": [0.0, 1.0], "y": [0.0, 1.0]})
    with one_worker_cluster() as cluster, distributed.Client(cluster) as client:
        client.run(slow_on("a_slow.csv", 600.0))  # submitted first: it holds the one worker
        start = time.monotonic()
        rows = hyst.batch.fit(str(tmp_path / "*.csv"), "pi", input="v", output="y",
                              out=tmp_path / "fits", client=client, record_timeout=1.0)
        assert time.monotonic() - start < 15.0
    assert [row.status for row in rows] == ["failed", "ok", "ok", "ok"], rows
    assert "not finished within 1 s (record_timeout" in rows[0].reason


def test_a_cluster_left_without_workers_ends_the_run_and_publishes_the_rows(tmp_path):
    write_records(tmp_path, 3)
    hyst.io.write_csv(tmp_path / "zz_last.csv", {"v": [0.0, 1.0], "y": [0.0, 1.0]})
    with one_worker_cluster() as cluster, distributed.Client(cluster) as client:
        client.run(exit_on("zz_last.csv"))
        for nanny in cluster.workers.values():
            nanny.close_gracefully()  # the worker that exits is not started again
        start = time.monotonic()
        with pytest.raises(hyst.batch.ClusterLost, match=r"has had no worker for 1 s; the run "
                                                         r"ended with 3 of 4 records fitted"):
            hyst.batch.fit(str(tmp_path / "*.csv"), "pi", input="v", output="y",
                           out=tmp_path / "fits", client=client, timeout=1.0)
        assert time.monotonic() - start < 15.0
    with open(tmp_path / "fits" / "batch.csv", newline="") as file:
        table = list(csv.DictReader(file))
    assert [line["status"] for line in table] == ["ok", "ok", "ok", "failed"]
    assert "not fitted: the Dask cluster at" in table[3]["reason"]
    assert sorted(published_files(tmp_path / "fits")) == [
        "batch.csv", "batch.md", "r000.json", "r001.json", "r002.json"]


def start_batch(records, out, *extra):
    """`python3 -m hyst.batch fit` as the command line runs it, with a progress line per record."""
    command = [sys.executable, "-m", "hyst.batch", "fit", "--model", "pi", "--data",
               str(records / "*.csv"), "--input", "v", "--output", "y", "--out", str(out),
               "--option", "operators=12", "--progress", *extra]
    return subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            text=True)


def stop_after(process, records_done, signal_number):
    """Sends the signal once `records_done` progress lines were printed; returns (status,
    the lines of standard error)."""
    lines = []
    while len(lines) < records_done:
        line = process.stderr.readline()
        assert line, f"the run ended early: {lines}"
        lines.append(line)
    process.send_signal(signal_number)
    rest = process.stderr.read()  # through the same buffer as readline()
    return process.wait(timeout=30), lines + rest.splitlines(keepends=True)


@pytest.fixture(scope="module")
def previous_set(tmp_path_factory):
    """A finished run of 5 records, and 100 records for a rerun into the same folder (about
    1 s to fit in one process, so that a signal after 50 progress lines stops it half-way)."""
    folder = tmp_path_factory.mktemp("previous")
    small, large = folder / "small", folder / "large"
    small.mkdir()
    large.mkdir()
    write_records(small, 5)
    write_records(large, 100, seed=9)
    return small, large


@pytest.mark.parametrize("signal_number, records_done", [
    (signal.SIGINT, 1), (signal.SIGTERM, 20), (signal.SIGKILL, 2), (signal.SIGKILL, 50)])
def test_a_stopped_rerun_leaves_the_complete_previous_set(previous_set, tmp_path, signal_number,
                                                          records_done):
    small, large = previous_set
    out = tmp_path / "fits"
    hyst.batch.fit(str(small / "*.csv"), "pi", input="v", output="y", out=out, workers=0,
                   options={"operators": 12})
    before = published_files(out)
    status, stderr = stop_after(start_batch(large, out, "--workers", "0"), records_done,
                                signal_number)
    assert published_files(out) == before  # no new model file beside the old tables
    if signal_number == signal.SIGKILL:
        assert status == -signal.SIGKILL
        rows = hyst.batch.fit(str(large / "*.csv"), "pi", input="v", output="y", out=out,
                              workers=0, options={"operators": 12})  # the next run cleans up
        assert len(published_files(out)) == len(rows) + 2 and len(set_folders(out)) == 1
        return
    name = signal.Signals(signal_number).name
    assert status == 128 + signal_number, stderr
    assert stderr[-1] == f"hyst: error: stopped by {name}; {out} keeps its previous files\n"
    assert not any("Traceback" in line for line in stderr), stderr
    assert len(set_folders(out)) == 1  # the stopped run's staging folder is gone


def test_an_interrupted_cluster_run_ends_at_once_with_one_line(previous_set, tmp_path):
    _, large = previous_set
    process = start_batch(large, tmp_path / "fits", "--workers", "1")
    start = time.monotonic()
    status, stderr = stop_after(process, 1, signal.SIGINT)
    assert status == 130 and time.monotonic() - start < 15.0
    assert stderr[-1].startswith("hyst: error: stopped by SIGINT; ")
    assert all(line.startswith("hyst.batch.fit: ") for line in stderr[:-1]), stderr  # progress
    assert not (tmp_path / "fits").exists()  # the folder it created is removed again


def test_an_interrupt_cancels_the_runs_tasks_on_the_callers_cluster(tmp_path):
    write_records(tmp_path, 8)

    def interrupt(done, total, record):  # as SIGINT would, after the first record
        raise KeyboardInterrupt

    with one_worker_cluster() as cluster, distributed.Client(cluster) as client:
        with pytest.raises(KeyboardInterrupt):
            hyst.batch.fit(str(tmp_path / "*.csv"), "pi", input="v", output="y",
                           out=tmp_path / "fits", client=client, progress=interrupt)

        def tasks_left(dask_scheduler):
            return len(dask_scheduler.tasks)

        deadline = time.monotonic() + 5.0
        while client.run_on_scheduler(tasks_left) and time.monotonic() < deadline:
            time.sleep(0.05)
        assert client.run_on_scheduler(tasks_left) == 0  # the other seven were cancelled
    assert not (tmp_path / "fits").exists(), list(os.walk(tmp_path / "fits"))


def test_a_time_column_gives_each_record_its_own_sample_time(tmp_path):
    creep = hyst.Model("pi_creep", {"thresholds": [0.0, 0.5], "weights": [1.0, 0.5],
                                    "time_constants": [0.05, 0.3],
                                    "creep_weights": [0.2, 0.1, 0.1, 0.05], "sample_time": 0.01})
    for name, step in (("fast", 0.01), ("slow", 0.02)):
        v = np.repeat([(k % 4) - 1.5 for k in range(12)], 25)
        t = step * np.arange(v.size)
        hyst.io.write_csv(tmp_path / f"{name}.csv",
                          {"t": t, "v": v, "y": creep.simulate(v, sample_time=step)})
    out = tmp_path / "fits"
    rows = hyst.batch.fit(str(tmp_path / "*.csv"), "pi_creep", input="v", output="y", out=out,
                          workers=0, time_column="t", options={"time_constants": [0.05, 0.3]})
    assert [row.status for row in rows] == ["ok", "ok"]
    steps = [hyst.load_model(row.model_file).sample_time for row in rows]
    assert steps == [pytest.approx(0.01), pytest.approx(0.02)]
    with pytest.raises(hyst.Error, match="time_column: model 'pi' has no sample time"):
        hyst.batch.fit(str(tmp_path / "*.csv"), "pi", input="v", output="y", out=out,
                       workers=0, time_column="t")
    rows = hyst.batch.fit(str(tmp_path / "fast.csv"), "pi_creep", input="v", output="y",
                          out=tmp_path / "missing", workers=0, time_column="time")
    assert rows[0].status == "failed" and "time" in rows[0].reason
