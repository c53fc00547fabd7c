"""A population of designs given by the caller (an optimiser's generation) is evaluated by the same engine call
as an exploration: the same numbers for the same designs; bad values are refused naming the parameter."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.errors import InputError, ProblemFileError
from machdyn.reading import load_problem
from machdyn.studies.exploration import explore
from machdyn.studies.exploration.population import evaluate_population

from .conftest import explore_text

PARAMETERS = ["mechanism.crank.length", "mechanism.coupler.mass", "drive.speed", "loads.torques[0].torque"]


def test_population_equals_the_exploration_of_the_same_designs(tmp_path):
    problem = load_problem(explore_text(samples=100, partition=64))
    frame = explore(problem, store=tmp_path / "s").frame()
    values = frame[PARAMETERS].to_numpy()[::-1]  # any order, any chunking
    out = evaluate_population(problem, PARAMETERS, values, chunk=30)
    expected = frame.iloc[::-1]
    for name in ("regular", "driving_torque.max_abs", "input_power.mean", "joint.B.max_force"):
        np.testing.assert_array_equal(out[name], expected[name].to_numpy())


def test_population_values_are_checked():
    problem = load_problem(explore_text())
    with pytest.raises(InputError, match=r"Every value of mechanism.crank.length must be > 0 m; design 1 has -0.01"):
        evaluate_population(problem, PARAMETERS[:1], [[0.04], [-0.01]])
    with pytest.raises(InputError, match=r"values must be an \(n designs, 2 parameters\) array; got shape \(3,\)"):
        evaluate_population(problem, PARAMETERS[:2], [0.04, 0.5, 1.0])
    with pytest.raises(ProblemFileError, match="mechanism has no key 'crnk'; did you mean 'crank'"):
        evaluate_population(problem, ["mechanism.crnk.length"], [[0.04]])
