"""Honest optimiser reports: NSGA-II is called converged only by its stated criterion (hypervolume stagnation),
the front's size and spread are reported, and an infeasible search lists every constraint with the smallest
violation any design reached (exit 3, as documented)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from machdyn.reading import load_problem
from machdyn.studies.optimisation import optimise
from machdyn.studies.optimisation.pareto import hypervolume_converged, hypervolumes, spacing

from .helpers import ROOT, check_and_run, invoke

BASE = """
[mechanism]
type = "four_bar"
[mechanism.crank]
length = "40 mm"
mass = "0.3 kg"
[mechanism.coupler]
length = "120 mm"
mass = "0.5 kg"
[mechanism.rocker]
length = "100 mm"
mass = "0.4 kg"
[mechanism.ground]
length = "150 mm"
[drive]
speed = "120 rpm"
positions = 60
[[loads.torques]]
body = "rocker"
torque = "-2 N*m"

[optimise]
population = 12
generations = {generations}
positions = 60
seed = 1
[[optimise.variables]]
parameter = "mechanism.crank.length"
lower = "20 mm"
upper = "55 mm"
"""

TWO_OBJECTIVES = """
[[optimise.objectives]]
result = "driving_torque.max_abs"
[[optimise.objectives]]
result = "stroke.rocker"
sense = "maximise"
"""


def test_hypervolume_criterion_on_known_sequences():
    # a front that stops improving converges; one still improving by 1 % per generation does not
    assert hypervolume_converged(np.array([0.1, 0.5, 0.8, 0.9] + [0.95] * 6), 1e-3, 5)[0]
    growing = 0.5 * 1.01 ** np.arange(12)
    done, why = hypervolume_converged(growing, 1e-3, 5)
    assert not done and "still grew by 5.1 %" in why
    assert not hypervolume_converged(np.array([np.nan, np.nan, 0.3]), 1e-3, 5)[0]


def test_hypervolume_of_a_known_front():
    # two fronts normalised together: the better one dominates the unit square up to the reference 1.1 except the
    # corner of each point; (0, 1), (1, 0), (0.5, 0.5) against 1.1: 1.1^2 - (area not dominated) = 0.46
    f = [np.array([[0.0, 1.0], [1.0, 0.0], [0.5, 0.5]])]
    assert hypervolumes(f)[0] == pytest.approx(0.46, rel=1e-12)


def test_spacing_is_zero_for_an_evenly_spread_front():
    front = np.column_stack([np.linspace(0, 1, 6), np.linspace(1, 0, 6)])
    assert spacing(front) == pytest.approx(0.0, abs=1e-12)
    assert spacing(np.array([[0.0, 1.0], [0.1, 0.9], [1.0, 0.0]])) > 0.1


def test_nsga2_short_run_is_not_called_converged():
    problem = load_problem(BASE.format(generations=3) + TWO_OBJECTIVES)
    result = optimise(problem, problem.optimise)
    assert not result.converged
    assert "hypervolume" in result.message
    assert any("did not converge" in w for w in result.warnings)


def test_nsga2_converges_by_hypervolume_stagnation_and_reports_front_spread(tmp_path):
    check, run = check_and_run(tmp_path, BASE.format(generations=40) + TWO_OBJECTIVES)
    assert run.code == 0, run
    scalars = json.loads((tmp_path / "out" / "results.json").read_text())["scalars"]
    assert scalars["optimise.converged"]["value"] == 1.0
    size = scalars["optimise.front_size"]["value"]
    assert size >= 3
    assert np.isfinite(scalars["optimise.front_spacing"]["value"])
    low = scalars["optimise.front.driving_torque.max_abs.min"]["value"]
    high = scalars["optimise.front.driving_torque.max_abs.max"]["value"]
    assert 0 < low < high
    history = (tmp_path / "out" / "optimise_history.csv").read_text().splitlines()
    assert "hypervolume" in history[0]


def test_infeasible_search_lists_every_constraint_with_its_smallest_violation(tmp_path):
    # each constraint alone is met at one end of the crank range, never both: a short crank keeps the torque low,
    # a long one gives the stroke
    text = BASE.format(generations=4) + """
[[optimise.objectives]]
result = "driving_torque.max_abs"
[[optimise.constraints]]
result = "driving_torque.max_abs"
max = "0.5 N*m"
[[optimise.constraints]]
result = "stroke.rocker"
min = "50 deg"
"""
    check, run = check_and_run(tmp_path, text)
    assert (check.code, run.code) == (0, 3), (check, run)
    said = run.stderr
    assert "closes at every crank angle without a dead position" in said
    assert "driving_torque.max_abs <= 0.5 N*m" in said and "stroke.rocker >= 50 deg" in said
    assert said.count("met by some designs, but not together with the others") + said.count("violated by") >= 3
    assert "the closest design has" in said


def test_exit_code_of_an_infeasible_search_is_documented_once():
    doc = (ROOT / "docs" / "optimise.md").read_text(encoding="utf-8")
    assert "exit code 3" in doc and "stops with exit code 2 and lists the constraints" not in doc
    for page in ("README.md", "docs/architecture.md", "docs/problem-files.md"):
        rows = [r for r in (ROOT / page).read_text(encoding="utf-8").splitlines() if r.startswith("| 3 |")]
        assert len(rows) == 1 and "no design meets" in rows[0], page
    text = " ".join(invoke(["run", "--help"]).stdout.split())
    assert "3 the design fails a check (an infeasible optimisation included)" in text
