"""The search: the optimum is verified feasible; bad input and a search that does not converge are reported."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.errors import InputError, ProblemFileError
from machdyn.machines.compactor import GAMMA_LIMIT, Compactor
from machdyn.reading import load_problem
from machdyn.studies.optimisation import NoFeasibleDesign, optimise

from .conftest import problem_with

CRANK = """
[[optimise.variables]]
parameter = "mechanism.crank.length"
lower = "20 mm"
upper = "55 mm"
"""


def _quick(spec):
    return spec.model_copy(update={"population": 16, "generations": 40, "positions": 120})


def test_compactor_optimum_is_feasible_by_an_independent_check(compactor):
    """The best design, read back from its own problem file, meets gamma < 20 deg by the machine layer's own
    refined check (machines.compactor.Compactor.gamma_check), and improves on the starting design."""
    result = optimise(compactor, _quick(compactor.optimise))
    assert result.verified
    best = load_problem(result.problem_text)
    mech = best.mechanism
    l, r, big_r = mech.coupler.length, mech.crank.length, mech.rocker.length
    h = mech.ground.length * np.sin(mech.ground.angle)
    assert mech.ground.length * np.cos(mech.ground.angle) == pytest.approx(l, rel=1e-12)  # eq 6 kept
    check = Compactor(r=r, l=l, h=h, R=big_r, branch=-1).gamma_check(samples=3601)
    assert check["gamma_max"] < GAMMA_LIMIT * (1 + 1e-3)  # 120 positions in the search vs a refined maximum
    assert result.results["compactor.force_gain.min"] > 6.28  # the starting design: 1.26 * 5
    assert result.results["driving_torque.max_abs"] <= 60.0


def test_objective_naming_no_result_gets_did_you_mean():
    with pytest.raises(ProblemFileError) as err:
        problem_with(CRANK + '[[optimise.objectives]]\nresult = "driving_torque.max_ab"\n')
    text = str(err.value)
    assert "optimise.objectives[0].result" in text and "did you mean 'driving_torque.max_abs'" in text


def test_constraint_naming_no_result_and_a_limit_in_the_wrong_unit_are_reported_together():
    with pytest.raises(ProblemFileError) as err:
        problem_with(CRANK + '[[optimise.objectives]]\nresult = "driving_torque.max_abs"\n'
                     '[[optimise.constraints]]\nresult = "stroke.rockr"\nmin = "30 deg"\n'
                     '[[optimise.constraints]]\nresult = "transmission_angle.worst"\nmin = "40 mm"\n')
    paths = [p for p, _ in err.value.problems]
    assert paths == ["optimise.constraints[0].result", "optimise.constraints[1].min"]
    assert "did you mean 'stroke.rocker'" in str(err.value)


def test_constraints_no_design_meets_name_the_tightest_first():
    problem = problem_with(CRANK + '[[optimise.objectives]]\nresult = "driving_torque.max_abs"\n'
                           '[[optimise.constraints]]\nresult = "stroke.rocker"\nmin = "120 deg"\n'
                           '[[optimise.constraints]]\nresult = "transmission_angle.worst"\nmin = "20 deg"\n')
    with pytest.raises(NoFeasibleDesign) as err:
        optimise(problem, _quick(problem.optimise))
    lines = str(err.value).splitlines()
    assert "No design within the bounds meets every constraint" in lines[0]
    assert lines[1].strip().startswith("stroke.rocker >= 120 deg: violated by")
    assert "the closest design has" in lines[1]
    assert isinstance(err.value, InputError)


def test_bounds_that_exclude_every_design_that_closes_are_reported():
    """Cranks of 75-100 mm cannot turn fully in this four-bar (Grashof: s + l > p + q, 225 > 220 mm)."""
    problem = problem_with('[[optimise.variables]]\nparameter = "mechanism.crank.length"\nlower = "75 mm"\n'
                           'upper = "100 mm"\n[[optimise.objectives]]\nresult = "driving_torque.max_abs"\n')
    with pytest.raises(NoFeasibleDesign, match="closes at every crank angle without a dead position: violated"):
        optimise(problem, _quick(problem.optimise))


def test_a_search_that_does_not_converge_says_so():
    problem = problem_with(CRANK + '[[optimise.variables]]\nparameter = "mechanism.rocker.length"\n'
                           'lower = "80 mm"\nupper = "140 mm"\n'
                           '[[optimise.objectives]]\nresult = "shaking_force.max"\n')
    result = optimise(problem, problem.optimise.model_copy(update={"generations": 2, "population": 8,
                                                                    "positions": 60}))
    assert not result.converged
    assert "did not converge within 2 generations" in result.warnings[0]
    assert len(result.history.generation) == 2


def test_history_is_monotone_and_counts_every_design():
    problem = problem_with(CRANK + '[[optimise.objectives]]\nresult = "driving_torque.max_abs"\n')
    result = optimise(problem, _quick(problem.optimise))
    best = result.history.best[np.isfinite(result.history.best)]
    assert np.all(np.diff(best) <= 0)  # differential evolution keeps the best design of each generation
    assert result.evaluations == result.history.evaluations[-1]
    assert result.designs_per_second > 0


def test_pareto_front_is_mutually_non_dominated_and_feasible():
    problem = problem_with(CRANK + '[[optimise.variables]]\nparameter = "mechanism.coupler.length"\n'
                           'lower = "110 mm"\nupper = "160 mm"\n'
                           '[[optimise.objectives]]\nresult = "driving_torque.max_abs"\n'
                           '[[optimise.objectives]]\nresult = "stroke.rocker"\nsense = "maximise"\n'
                           '[[optimise.constraints]]\nresult = "transmission_angle.worst"\nmin = "35 deg"\n')
    result = optimise(problem, problem.optimise.model_copy(update={"population": 24, "generations": 15,
                                                                    "positions": 90}))
    f = result.front_f * np.array([1.0, -1.0])  # both as costs
    assert len(f) >= 3
    for i in range(len(f)):
        others = np.delete(f, i, axis=0)
        dominated = np.any(np.all(others <= f[i], axis=1) & np.any(others < f[i], axis=1))
        assert not dominated
    assert result.verified and result.results["transmission_angle.worst"] >= np.radians(35) * (1 - 1e-9)
