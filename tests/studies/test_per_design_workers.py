"""The per-design path on worker processes (``--workers``): the designs' runs give the results they give in this
process, design for design, and a study says where its designs ran."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.problem.paths import design_problem
from machdyn.reading import load_problem
from machdyn.runner import design_results
from machdyn.studies.per_design import evaluate_designs

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "shaft_inline_four_phases_optimise.toml"
KEYS = ("shaft.engine.primary_couple", "shaft.engine.primary_force")


def test_designs_run_on_workers_give_the_results_of_this_process():
    problem = load_problem(EXAMPLE)
    designs = [design_problem(problem, {"cylinders[1].phase": phase}) for phase in (0.5, 1.5, math.pi, 4.0)]
    designs.insert(2, None)  # a design that could not be built: NaN, not run
    alone = evaluate_designs(design_results, designs, KEYS, len(designs))
    spread = evaluate_designs(design_results, designs, KEYS, len(designs), workers=2)
    for key in KEYS:
        np.testing.assert_array_equal(spread[key], alone[key], err_msg=key)
        assert np.isnan(alone[key][2]) and np.isfinite(np.delete(alone[key], 2)).all()
    # the 0-180 inner pair cancels the primary force of the outer pair (Khurmi & Gupta, ch. 22): a physics check
    # that the worker ran the design it was sent, not the file's own
    assert alone["shaft.engine.primary_couple"][3] != alone["shaft.engine.primary_couple"][0]


def test_an_optimisation_by_runs_says_it_ran_its_designs_on_workers(tmp_path):
    text = EXAMPLE.read_text(encoding="utf-8").replace("population = 12", "population = 5") \
        .replace("generations = 40", "generations = 2")
    path = tmp_path / "phases.toml"
    path.write_text(text, encoding="utf-8")
    ran = CliRunner().invoke(app, ["run", str(path), "--out", str(tmp_path / "out"), "--workers", "2"])
    assert ran.exit_code in (0, 3), ran.output
    flat = " ".join(ran.output.split())
    assert "evaluated per design, 2 workers (--workers)" in flat
    assert "ignored" not in flat
