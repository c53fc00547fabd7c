"""An objective whose sense works against its result's declared better direction is warned of, by check and run
alike, naming the key."""

from __future__ import annotations

from machdyn.runner import check_problem, run_problem

from .conftest import problem_with

OPTIMISE = """
[optimise]
population = 6
generations = 1
positions = 36
[[optimise.variables]]
parameter = "mechanism.crank.length"
lower = "35 mm"
upper = "45 mm"
[[optimise.objectives]]
result = "transmission_angle.worst"
sense = "{sense}"
"""


def test_an_objective_against_its_declared_direction_is_warned_by_check_and_run_alike():
    problem = problem_with(OPTIMISE.format(sense="minimise"))
    said = [w for w in check_problem(problem) if "transmission_angle.worst" in w]
    assert len(said) == 1 and "higher" in said[0] and "optimise.objectives[0]" in said[0]
    run = run_problem(problem)
    assert said[0] in run.warnings
    # the study's own result shows itself in a notebook: its variables with units and its convergence plot
    html = run.outcomes["optimise"].results._repr_html_()
    assert "<th>variable</th>" in html and "mm</td>" in html and "<svg" in html


def test_an_objective_along_its_declared_direction_is_not_questioned():
    problem = problem_with(OPTIMISE.format(sense="maximise"))
    assert not [w for w in check_problem(problem) if "better direction" in w]
