"""Throughput of batch fitting (hyst.batch): records per second fitted serially in one process and
on a Dask cluster, for fits of a few milliseconds to a few tenths of a second (docs/performance.md,
docs/scaling.md).

Usage (from the checkout, after `make`):

    PYTHONPATH=build/python /usr/bin/python3 bench/batch_throughput.py \
        [--cases pi:300:200,pi:20000:200,gpi:2000:60] [--workers 2] [--scheduler tcp://host:8786]

A case MODEL:SAMPLES:RECORDS fits MODEL (default options) to RECORDS records of SAMPLES samples
each: a PI model with random weights driven by a decaying sine, plus seeded noise. Three runs per
case, each into a fresh output folder: serially in this process (workers=0), on a cluster that
is already running (a local one of --workers processes with a thread each, or the one of
--scheduler), and, without --scheduler, as `hyst batch fit` runs: the local cluster started and
closed within the call. Prints a Markdown table; every run must fit every record.
"""

import argparse
import tempfile
import time
from pathlib import Path

import numpy as np

import hyst
import hyst.batch


def write_records(folder, count, samples, seed=1):
    rng = np.random.default_rng(seed)
    grid = hyst.signals.TimeGrid(samples, 1e-3)
    for k in range(count):
        v = hyst.signals.generate(grid, hyst.signals.DecayingSine(
            amplitude=rng.uniform(1.0, 2.0), frequency=10.0, time_constant=samples * 1e-3 / 3))
        truth = hyst.PrandtlIshlinskii([0.0, 0.25, 0.5, 0.75], rng.uniform(0.1, 1.0, 4))
        y = truth.simulate(v) + rng.normal(0.0, 0.01, v.size)
        hyst.io.write_csv(folder / f"r{k:04d}.csv", {"v": v, "y": y})


def timed(records, model, out, **where):
    start = time.perf_counter()
    rows = hyst.batch.fit(str(records / "*.csv"), model, input="v", output="y", out=out, **where)
    seconds = time.perf_counter() - start
    failed = [row for row in rows if not row.ok]
    if failed:
        raise SystemExit(f"batch_throughput: {len(failed)} records failed: {failed[0].reason}")
    return len(rows) / seconds, float(np.mean([row.seconds for row in rows]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cases", default="pi:300:200,pi:20000:200,gpi:2000:60",
                        help="MODEL:SAMPLES:RECORDS, comma-separated")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--scheduler", help="a running Dask scheduler instead of a local cluster")
    arguments = parser.parse_args()
    import distributed

    running = (distributed.Client(arguments.scheduler) if arguments.scheduler else
               distributed.Client(distributed.LocalCluster(
                   n_workers=arguments.workers, threads_per_worker=1, processes=True,
                   dashboard_address=":0")))
    cluster = (f"the cluster at {arguments.scheduler}" if arguments.scheduler
               else f"local cluster, {arguments.workers} workers")
    print(f"| model | samples per record | records | mean task time [ms] | serial [records/s] | "
          f"{cluster}, running [records/s] | speed-up |" + ("" if arguments.scheduler else
                                                            " incl. start and close [records/s] |"))
    print("|---|---:|---:|---:|---:|---:|---:|" + ("" if arguments.scheduler else "---:|"))
    with running, tempfile.TemporaryDirectory() as scratch:
        for case in arguments.cases.split(","):
            model, samples, count = case.split(":")
            folder = Path(scratch) / case.replace(":", "_")
            records = folder / "records"
            records.mkdir(parents=True)
            write_records(records, int(count), int(samples))
            serial, task = timed(records, model, folder / "serial", workers=0)
            parallel, _ = timed(records, model, folder / "running", client=running)
            line = (f"| {model} | {samples} | {count} | {task * 1e3:.3g} | {serial:.4g} | "
                    f"{parallel:.4g} | {parallel / serial:.2f} |")
            if not arguments.scheduler:
                whole, _ = timed(records, model, folder / "whole", workers=arguments.workers)
                line += f" {whole:.4g} |"
            print(line, flush=True)


if __name__ == "__main__":
    main()
