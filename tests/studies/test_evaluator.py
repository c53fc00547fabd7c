"""The studies' one evaluator: a population evaluated at once agrees with its designs evaluated alone, keeps the
work balance of each design, and runs exactly the regular, buildable designs for the results only a run gives."""

from __future__ import annotations

import math

import numpy as np
import pytest

from machdyn.linkage import stack_designs
from machdyn.problem.build import build_mechanism, crank_angles
from machdyn.reading import load_problem
from machdyn.studies import PopulationEvaluator
from problem_texts import four_bar

CRANKS = ("30 mm", "40 mm", "50 mm")
KEYS = ("driving_torque.max_abs", "transmission_angle.min", "input_power.mean")


@pytest.fixture(scope="module")
def problems():
    return [load_problem(four_bar(positions=36).replace('"40 mm"', f'"{c}"', 1)) for c in CRANKS]


def _evaluator(problem, **kw) -> PopulationEvaluator:
    return PopulationEvaluator(crank_angles(problem), float(problem.drive.speed), 0.0, **kw)


def test_a_population_at_once_is_its_designs_alone(problems):
    evaluator = _evaluator(problems[0])
    together = evaluator(stack_designs([build_mechanism(p) for p in problems]), KEYS, len(problems))
    for i, p in enumerate(problems):
        alone = evaluator(build_mechanism(p), KEYS, 1)
        for key in KEYS:
            assert together[key][i] == pytest.approx(alone[key][0], rel=1e-12), (key, i)
    assert together["regular"].all()


def test_the_mean_input_power_is_the_load_s_for_every_design():
    """At constant speed the kinetic and potential energies are periodic, so the mean input power is the power
    of the 0.5 N*m resisting torque at 10 rad/s: 5 W (energy balance over a cycle). The mean of the samples of a
    smooth periodic power converges spectrally: 72 crank angles leave it within 1e-10 (36 within 2e-6)."""
    designs = [load_problem(four_bar(positions=72).replace('"40 mm"', f'"{c}"', 1)) for c in CRANKS]
    together = _evaluator(designs[0])(stack_designs([build_mechanism(p) for p in designs]), KEYS, len(designs))
    assert together["input_power.mean"] == pytest.approx(np.full(len(designs), 0.5 * 10.0), rel=1e-10)


def test_only_regular_buildable_designs_are_run(problems):
    ran = []

    def run_design(problem):
        ran.append(float(problem.mechanism.crank.length))
        return {"crank": float(problem.mechanism.crank.length)}

    evaluator = _evaluator(problems[0], run_design=run_design)
    out = evaluator(build_mechanism(problems[0]), KEYS, 3, ("crank",), problems.__getitem__,
                    buildable=np.array([True, False, True]))
    assert ran == [0.030, 0.050]
    assert out["crank"][0] == 0.030 and math.isnan(out["crank"][1]) and out["crank"][2] == 0.050
    # three alike designs stacked into one model: their vectorised results are repeated
    assert out["driving_torque.max_abs"].shape == (3,) and np.ptp(out["driving_torque.max_abs"]) == 0.0


def test_per_design_results_need_a_way_to_run_a_design(problems):
    with pytest.raises(RuntimeError, match="run a design"):
        _evaluator(problems[0])(build_mechanism(problems[0]), KEYS, 1, ("crank",), problems.__getitem__)
