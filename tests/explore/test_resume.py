"""An interrupted exploration resumes from the partitions on disk: the same results as an uninterrupted run,
finished partitions not recomputed; a folder of another exploration is never mixed in."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pyarrow.parquet as pq
import pytest

from machdyn.reading import load_problem
from machdyn.studies.exploration import explore

from .conftest import explore_text


class Stop(Exception):
    pass


def _stop_after(k: int):
    seen: list[int] = []

    def on_partition(index: int) -> None:
        seen.append(index)
        if len(seen) == k:
            raise Stop(f"stopped after {k} partitions")

    return on_partition


def test_interrupted_run_resumes_without_recomputing(tmp_path):
    problem = load_problem(explore_text(method="lhs", samples=300, partition=50))
    whole = explore(problem, store=tmp_path / "whole")
    assert (whole.computed, whole.reused) == (6, 0)

    folder = tmp_path / "interrupted"
    with pytest.raises(Stop):
        explore(problem, store=folder, on_partition=_stop_after(2))
    parts = sorted(folder.glob("part-*.parquet"))
    assert [p.name for p in parts] == ["part-000000.parquet", "part-000001.parquet"]
    stamps = {p.name: p.stat().st_mtime_ns for p in parts}

    computed: list[int] = []
    resumed = explore(problem, store=folder, on_partition=computed.append)
    assert (resumed.computed, resumed.reused) == (4, 2)
    assert computed == [2, 3, 4, 5]  # only the missing partitions were evaluated
    assert {p.name: p.stat().st_mtime_ns for p in parts} == stamps
    pd.testing.assert_frame_equal(resumed.frame(), whole.frame())
    pd.testing.assert_frame_equal(resumed.best_frame(), whole.best_frame())
    pd.testing.assert_frame_equal(resumed.sample_frame(), whole.sample_frame())
    assert (resumed.digest.designs, resumed.digest.regular) == (whole.digest.designs, whole.digest.regular)

    again = explore(problem, store=folder)
    assert (again.computed, again.reused) == (0, 6)


def test_a_store_of_another_exploration_is_emptied_first(tmp_path):
    folder = tmp_path / "s"
    explore(load_problem(explore_text(samples=128, partition=64)), store=folder)
    other = explore(load_problem(explore_text(samples=64, partition=64).replace('"30 mm"', '"31 mm"')), store=folder)
    assert (other.computed, other.reused) == (1, 0)
    assert sorted(p.name for p in folder.glob("part-*")) == ["part-000000.parquet"]
    assert other.frame()["mechanism.crank.length"].min() >= 0.031


def test_parquet_columns_carry_their_units(tmp_path):
    done = explore(load_problem(explore_text(samples=64, partition=64)), store=tmp_path / "s")
    schema = pq.read_schema(tmp_path / "s" / "part-000000.parquet")
    units = {f.name: f.metadata[b"unit"].decode() for f in schema}
    assert units["mechanism.crank.length"] == "m"
    assert units["mechanism.coupler.mass"] == "kg"
    assert units["drive.speed"] == "rad/s"
    assert units["loads.torques[0].torque"] == "N*m"
    assert units["driving_torque.max_abs"] == "N*m" and units["input_power.mean"] == "W"
    assert units["joint.B.max_force"] == "N"
    manifest = json.loads((tmp_path / "s" / "_exploration.json").read_text())
    assert manifest["designs"] == 64 and manifest["columns"]["frame_force.max"]["unit"] == "N"
    # The folder reads back as one table with pandas.
    frame = pd.read_parquet(tmp_path / "s")
    assert len(frame) == 64 and np.array_equal(frame["design"], np.arange(64))
    assert done.units["driving_torque.max_abs"][0] == "N*m"


def test_store_named_in_the_file_is_relative_to_the_file(tmp_path):
    from machdyn.studies.exploration import execution

    path = tmp_path / "problem.toml"
    path.write_text(explore_text(samples=64, partition=64, extra='store = "designs.parquet"\n'))
    with execution(store=tmp_path / "default.parquet"):  # the file's store wins over the default
        done = explore(path)
    assert done.store == tmp_path / "designs.parquet"
    assert (tmp_path / "designs.parquet" / "part-000000.parquet").exists()
    assert not (tmp_path / "default.parquet").exists()


def test_progress_reports_designs_done_as_partitions_finish(tmp_path):
    problem = load_problem(explore_text(samples=150, partition=64))
    calls: list[tuple[int, int]] = []
    explore(problem, store=tmp_path / "s", progress=lambda done, total: calls.append((done, total)))
    assert calls == [(0, 150), (64, 150), (128, 150), (150, 150)]
    explore(problem, store=tmp_path / "t", progress=True)  # a rich bar on stderr; the same run otherwise
