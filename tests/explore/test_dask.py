"""Explorations on Dask: a local cluster of two worker processes (loopback only), started by the exploration
or running already and given by address, gives results identical to the run in this process; so does the
evaluation of a population of given designs."""

from __future__ import annotations

import os
import time

import numpy as np
import pandas as pd

from machdyn.reading import load_problem
from machdyn.studies.exploration import explore
from machdyn.studies.exploration.population import evaluate_population

from .conftest import explore_text

#: Starting two worker processes and importing machdyn in each takes seconds; far more means something hangs.
BOUND_SECONDS = 120


def test_local_cluster_of_two_workers_equals_serial(tmp_path):
    problem = load_problem(explore_text(samples=256, partition=32))
    serial = explore(problem, store=tmp_path / "serial")
    assert serial.where == "in process"
    started = time.perf_counter()
    parallel = explore(problem, store=tmp_path / "dask", workers=2)
    assert time.perf_counter() - started < BOUND_SECONDS
    assert parallel.where == "local Dask cluster of 2 worker process(es)"
    assert (parallel.computed, parallel.reused) == (8, 0)
    pd.testing.assert_frame_equal(parallel.frame(), serial.frame(), check_exact=True)
    pd.testing.assert_frame_equal(parallel.best_frame(), serial.best_frame(), check_exact=True)


def test_existing_cluster_by_address_equals_serial(tmp_path):
    from distributed import LocalCluster

    problem = load_problem(explore_text(method="lhs", samples=96, partition=32))
    serial = explore(problem, store=tmp_path / "serial")
    started = time.perf_counter()
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address="127.0.0.1:0", silence_logs=40) as cluster:
        pids = {nanny.process.pid for nanny in cluster.workers.values()}
        assert len(pids) == 2 and os.getpid() not in pids  # two worker processes besides this one
        done = explore(problem, store=tmp_path / "dask", scheduler=cluster.scheduler_address)
        assert cluster.scheduler_address.startswith("tcp://127.0.0.1:")
        names = list(serial.plan.space.names)
        population = evaluate_population(problem, names, serial.frame()[names].to_numpy(), chunk=40,
                                         scheduler=cluster.scheduler_address)
    assert time.perf_counter() - started < BOUND_SECONDS
    assert done.where.startswith("Dask cluster at tcp://127.0.0.1:")
    pd.testing.assert_frame_equal(done.frame(), serial.frame(), check_exact=True)
    # An optimiser's population on the same cluster: the same numbers as the serial exploration.
    for name, column in population.items():
        np.testing.assert_array_equal(column, serial.frame()[name].to_numpy())
