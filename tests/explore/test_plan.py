"""Planning an exploration from a problem file: a grid of several quantities is every combination in product
order, in the units the file wrote; sizes beyond the limits are refused naming the key."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from machdyn.errors import ProblemFileError
from machdyn.reading import load_problem
from machdyn.studies.exploration import explore, plan_exploration

from .conftest import BASE

GRID = """
[sweep]
partition = 4

[[sweep.quantities]]
parameter = "mechanism.crank.length"
values = ["30 mm", "35 mm", "40 mm"]

[[sweep.quantities]]
parameter = "drive.speed"
start = "60 rpm"
stop = "120 rpm"
count = 3
"""


def test_grid_of_two_quantities_is_every_combination(tmp_path):
    problem = load_problem(BASE + GRID)
    plan = plan_exploration(problem)
    assert plan.space.method == "grid" and plan.space.size == 9 and plan.space.partitions == 3
    assert [q.display_unit for q in plan.space.quantities] == ["mm", "rpm"]
    frame = explore(problem, store=tmp_path / "s").frame()
    rpm = 2 * np.pi / 60
    expected = list(itertools.product([0.030, 0.035, 0.040], [60 * rpm, 90 * rpm, 120 * rpm]))
    np.testing.assert_allclose(frame[["mechanism.crank.length", "drive.speed"]].to_numpy(), expected, rtol=1e-14)


def test_too_many_partitions_or_designs_are_refused():
    many = BASE + GRID.replace("partition = 4", "partition = 1").replace("count = 3", "count = 400000")
    with pytest.raises(ProblemFileError) as info:
        load_problem(many)
    assert info.value.problems == [("sweep.partition", "1,200,000 designs in partitions of 1 make more than "
                                                       "1,000,000 partitions; give a partition of at least 2 designs")]
    huge = BASE + GRID.replace("count = 3", "count = 1000000").replace(
        'values = ["30 mm", "35 mm", "40 mm"]', 'start = "30 mm"\nstop = "40 mm"\ncount = 101')
    with pytest.raises(ProblemFileError) as info:
        load_problem(huge)
    assert info.value.problems == [("sweep", "a sweep may have at most 100,000,000 designs; this grid has "
                                             "101,000,000 (101 x 1000000)")]
