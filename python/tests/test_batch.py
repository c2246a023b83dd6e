"""Batch fitting on Dask (hyst.batch): 200 generated records fitted on a local cluster of two
workers, every result checked against a serial fit of the same record; broken records listed
as failed with their reason while the others go on; model-file names, tables, errors and the
command line."""

import csv
import json
import sys
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


def test_a_worker_that_dies_fails_its_record_only(tmp_path):
    write_records(tmp_path, 4)
    hyst.io.write_csv(tmp_path / "zz_kills_its_worker.csv", {"v": [0.0, 1.0], "y": [0.0, 1.0]})

    def kill_on_that_record():  # runs on the worker: that record's task ends its process
        import os
        import time
        import hyst.batch
        run = hyst.batch._run_task

        def run_or_die(task):
            if not task.record.endswith("zz_kills_its_worker.csv"):
                return run(task)
            time.sleep(0.5)  # the worker reports the tasks it has finished before it dies
            os._exit(1)

        hyst.batch._run_task = run_or_die

    # One worker runs the tasks in the order submitted, so the record submitted last dies alone;
    # with no retry, one death is its failure.
    with dask.config.set({"distributed.scheduler.allowed-failures": 0}), \
            distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True,
                                     dashboard_address=":0") as cluster, \
            distributed.Client(cluster) as client:
        client.run(kill_on_that_record)
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
