"""An exploration of a linkage with a capability's result among its columns goes through the studies' one
evaluator: the ``[parts]`` column from the table's population form (no design run), equal design for design to
each design's own run to 1e-12; a ``[flywheel]`` column (no population form) by a run of each design."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.reading import load_problem
from machdyn.runner import design_results, run_problem
from machdyn.studies.exploration.run import explore, read_exploration

FILE = """
[mechanism]
type = "four_bar"
crank = {length = "40 mm", mass = "0.5 kg"}
coupler = {length = "120 mm", mass = "2 kg"}
rocker = {length = "80 mm", mass = "1 kg"}
ground = {length = "100 mm"}

[drive]
speed = "60 rad/s"
positions = 36

[[loads.torques]]
body = "rocker"
torque = "-5 N*m"

[[parts.bearings]]
joint = "O"
kind = "ball"
capacity = "20 kN"
life = "20000 h"

[[parts.pins]]
joint = "B"
diameter = "10 mm"
length = "15 mm"
allowable_shear = "80 MPa"

[sweep]
method = "grid"
partition = 4
columns = COLUMNS

[[sweep.quantities]]
parameter = "mechanism.coupler.mass"
values = ["0.5 kg", "1.5 kg", "3 kg"]

[[sweep.quantities]]
parameter = "mechanism.crank.length"
values = ["30 mm", "45 mm"]
"""


def _rows(tmp_path, columns, run_design):
    problem = load_problem(FILE.replace("COLUMNS", repr(columns).replace("'", '"')))
    done = explore(problem, store=tmp_path / "store", run_design=run_design)
    table = read_exploration(done.store).sort_values("design")
    return problem, table


def test_a_parts_column_comes_from_the_population_form_and_equals_each_design_s_run(tmp_path):
    runs: list = []
    _problem, table = _rows(tmp_path, ["parts.utilisation.max"], lambda design: runs.append(design) or {})
    assert runs == [] and len(table) == 6  # every design's parts at once, in two partitions
    for _, row in table.iloc[[0, -1]].iterrows():  # the lightest coupler on the shortest crank, and the other end
        text = FILE.split("[sweep]")[0].replace('"2 kg"', f'"{row["mechanism.coupler.mass"]} kg"', 1) \
            .replace('"40 mm"', f'"{row["mechanism.crank.length"]} m"', 1)
        alone = run_problem(text).results["parts.utilisation.max"]
        assert row["parts.utilisation.max"] == pytest.approx(alone, rel=1e-12)


def test_a_column_of_a_capability_without_a_population_form_is_each_design_s_run(tmp_path):
    global FILE
    kept = FILE
    FILE = FILE.replace("[sweep]", '[flywheel]\ndelta = 0.05\nstart_up = false\n\n[sweep]') \
        .replace('values = ["0.5 kg", "1.5 kg", "3 kg"]', 'values = ["1.5 kg"]')
    try:
        runs: list = []

        def counted(design):
            runs.append(design)
            return design_results(design)

        _problem, table = _rows(tmp_path, ["flywheel.inertia"], counted)
    finally:
        FILE = kept
    regular = table["regular"].to_numpy(dtype=bool)
    assert len(table) == 2 and regular.all()
    assert len(runs) == 2 + 2  # each design, and the one design the plan and the store's columns are probed on
    assert np.isfinite(table["flywheel.inertia"].to_numpy()[regular]).all()
