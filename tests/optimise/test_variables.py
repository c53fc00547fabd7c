"""Design variables: paths of the file, bounds with units, derived formulas, the stacked population model."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.errors import ProblemFileError
from machdyn.linkage import stack_designs
from machdyn.problem.build import build_mechanism
from machdyn.studies.optimisation import OptimiseSpec
from machdyn.studies.optimisation.variables import assign, search_space

from .conftest import FOUR_BAR, problem_with

OBJECTIVE = '[[optimise.objectives]]\nresult = "driving_torque.max_abs"\n'


def _spec(variables: str, derived: str = "") -> OptimiseSpec:
    problem = problem_with(variables + derived + OBJECTIVE)
    return problem, problem.optimise


def test_unknown_quantity_is_reported_with_did_you_mean():
    with pytest.raises(ProblemFileError) as err:
        _spec('[[optimise.variables]]\nparameter = "mechanism.crank.lenght"\nlower = "1 mm"\nupper = "2 mm"\n')
    text = str(err.value)
    assert "optimise.variables[0].parameter" in text and "did you mean 'length'" in text


def test_bounds_in_the_wrong_unit_and_reversed_bounds_are_reported_together():
    with pytest.raises(ProblemFileError) as err:
        _spec('[[optimise.variables]]\nparameter = "mechanism.crank.length"\nlower = "10 kg"\nupper = "2 mm"\n'
              '[[optimise.variables]]\nparameter = "mechanism.rocker.length"\nlower = "90 mm"\nupper = "80 mm"\n')
    paths = [p for p, _ in err.value.problems]
    assert "optimise.variables[0].lower" in paths and "optimise.variables[1].upper" in paths


def test_a_lower_bound_breaking_the_quantitys_rule_is_refused():
    with pytest.raises(ProblemFileError, match="must be > 0"):
        _spec('[[optimise.variables]]\nparameter = "mechanism.crank.length"\nlower = "-5 mm"\nupper = "50 mm"\n')


def test_a_formula_naming_no_variable_is_refused_with_did_you_mean():
    with pytest.raises(ProblemFileError) as err:
        _spec('[[optimise.variables]]\nname = "r"\nparameter = "mechanism.crank.length"\nlower = "20 mm"\n'
              'upper = "50 mm"\n', '[optimise.derived]\n"mechanism.rocker.length" = "2.5 * rr"\n')
    assert "did you mean 'r'" in str(err.value)


def test_a_formula_may_not_run_code():
    with pytest.raises(ProblemFileError, match="a formula may use"):
        _spec('[[optimise.variables]]\nname = "r"\nparameter = "mechanism.crank.length"\nlower = "20 mm"\n'
              'upper = "50 mm"\n', '[optimise.derived]\n"mechanism.rocker.length" = "r.__class__"\n')


def test_stacked_population_equals_each_design_built_alone_and_stacked(monkeypatch):
    """The fast path (arrays handed to the builder) builds the same model as building each variant."""
    from machdyn.studies.optimisation.variables import SearchSpace

    def no_fallback(*_args):
        raise AssertionError("the population was built design by design, not in one build")

    monkeypatch.setattr(SearchSpace, "_build_each", no_fallback)
    problem, spec = _spec(
        '[[optimise.variables]]\nname = "r"\nparameter = "mechanism.crank.length"\nlower = "20 mm"\nupper = "50 mm"\n'
        '[[optimise.variables]]\nparameter = "mechanism.coupler_point[1]"\nlower = "-30 mm"\nupper = "30 mm"\n'
        '[[optimise.variables]]\nname = "h"\nunit = "m"\nlower = "0 mm"\nupper = "40 mm"\n',
        '[optimise.derived]\n"mechanism.ground.angle" = "atan2(h, 0.15)"\n"mechanism.ground.length" = '
        '"hypot(0.15, h)"\n')
    space = search_space(problem, spec)
    x = space.lower + np.random.default_rng(4).random((7, 3)) * (space.upper - space.lower)
    fast = space.population(x).mechanism
    slow = []
    for row in x:
        variant = problem
        for path, arr in space.values(row[None, :]).items():
            variant = assign(variant, path, float(arr[0]))
        slow.append(build_mechanism(variant))
    stacked = stack_designs(slow)
    leaves_fast, leaves_slow = dict(_leaves(fast)), dict(_leaves(stacked))
    assert leaves_fast.keys() == leaves_slow.keys()
    for key, value in leaves_fast.items():
        np.testing.assert_allclose(np.broadcast_to(value, (7,)), np.broadcast_to(leaves_slow[key], (7,)),
                                   rtol=1e-15, atol=1e-18, err_msg=key)


def _leaves(obj, path="model"):
    """(path, value) of every number of an engine model (floats and design arrays alike)."""
    from dataclasses import fields, is_dataclass

    if isinstance(obj, np.ndarray | float | int) and not isinstance(obj, bool):
        yield path, np.asarray(obj, dtype=float)
    elif is_dataclass(obj) and not isinstance(obj, type):
        for f in fields(obj):
            if f.init:
                yield from _leaves(getattr(obj, f.name), f"{path}.{f.name}")
    elif isinstance(obj, dict):
        for k, v in obj.items():
            yield from _leaves(v, f"{path}[{k}]")
    elif isinstance(obj, tuple | list):
        for i, v in enumerate(obj):
            yield from _leaves(v, f"{path}[{i}]")


def test_designs_whose_derived_quantities_break_a_rule_are_marked_unbuildable():
    problem, spec = _spec(
        '[[optimise.variables]]\nname = "r"\nparameter = "mechanism.crank.length"\nlower = "20 mm"\nupper = "50 mm"\n',
        '[optimise.derived]\n"mechanism.rocker.length" = "r - 0.03"\n')
    space = search_space(problem, spec)
    pop = space.population(np.array([[0.02], [0.04], [0.05]]))
    assert pop.buildable.tolist() == [False, True, True]
    assert "mechanism.rocker.length" in pop.reasons[0]


def test_best_design_problem_is_validated_and_has_no_optimise_table():
    problem, spec = _spec('[[optimise.variables]]\nparameter = "mechanism.crank.length"\nlower = "20 mm"\n'
                          'upper = "50 mm"\n')
    best = search_space(problem, spec).problem_at(np.array([0.0325]))
    assert best.mechanism.crank.length == 0.0325 and best.optimise is None
    assert FOUR_BAR.count("[mechanism") == 5


def test_the_compactor_examples_population_is_built_in_one_go(monkeypatch, compactor):
    """Free variables, derived link lengths, a derived coupler-point coordinate and derived loads: one build."""
    from machdyn.studies.optimisation import setup
    from machdyn.studies.optimisation.variables import SearchSpace

    def no_fallback(*_args):
        raise AssertionError("the population was built design by design, not in one build")

    monkeypatch.setattr(SearchSpace, "_build_each", no_fallback)
    ev = setup(compactor, compactor.optimise)
    x = ev.space.lower + np.random.default_rng(1).random((20, 4)) * (ev.space.upper - ev.space.lower)
    pop = ev.space.population(x)
    assert pop.mechanism.design_count == 20 and pop.buildable.all()
    np.testing.assert_allclose(pop.mechanism.forces[1].fy, 2000 * (x[:, 1] - 0.1) / x[:, 1], rtol=1e-15)
