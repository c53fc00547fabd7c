"""The optimiser over results no population group computes — a capability's (here the flywheel's): each design of
the population is run through the file's own stages, so the optimum's figure is the one a run of the optimum
reports."""

from __future__ import annotations

import math

import numpy as np
import pytest

from machdyn.errors import ProblemFileError
from machdyn.reading import load_problem
from machdyn.runner import check_problem, run_problem
from machdyn.studies.per_design import capability_results, evaluate_designs

STUDY = """
[meta]
name = "flywheel study"

[mechanism]
type = "four_bar"
crank = {length = "40 mm", mass = "0.2 kg"}
coupler = {length = "120 mm", mass = "2 kg"}
rocker = {length = "80 mm", mass = "1 kg"}
ground = {length = "100 mm"}

[drive]
speed = "30 rad/s"
positions = 36

[[loads.torques]]
body = "rocker"
torque = "-5 N*m"

[flywheel]
delta = 0.05
start_up = false

[flywheel.motor]
kind = "constant_torque"

[optimise]
population = 5
generations = 2
seed = 1

[[optimise.variables]]
name = "m"
parameter = "mechanism.coupler.mass"
lower = "0.5 kg"
upper = "3 kg"
"""


def test_the_optimum_of_a_capability_result_is_what_a_run_of_the_optimum_reports():
    text = STUDY + '\n[[optimise.objectives]]\nresult = "flywheel.inertia"\nsense = "minimise"\n'
    run = run_problem(text)
    best = run.outcomes["optimise"].results
    assert best.verified and best.evaluations > 0
    alone = run_problem(best.problem_text)  # the best design written out, run on its own
    assert best.results["flywheel.inertia"] == pytest.approx(alone.results["flywheel.inertia"], rel=1e-12)
    assert run.results["optimise.best.flywheel.inertia"] == best.results["flywheel.inertia"]
    assert run.results.label("optimise.best.flywheel.inertia").unit == "kg*m^2"


def test_a_constraint_on_a_capability_result_holds_for_the_optimum():
    """A limit on the flywheel between the figures of the range's two ends: the optimum meets it."""
    plain = STUDY.split("[optimise]")[0]
    light = run_problem(plain.replace('"2 kg"', '"0.5 kg"', 1)).results["flywheel.inertia"]
    heavy = run_problem(plain.replace('"2 kg"', '"3 kg"', 1)).results["flywheel.inertia"]
    assert abs(light - heavy) > 0.05 * max(light, heavy)  # the coupler's mass matters to the flywheel
    limit = 0.5 * (light + heavy)
    text = (STUDY + '\n[[optimise.objectives]]\nresult = "kinetic_energy.max"\nsense = "maximise"\n'
            f'\n[[optimise.constraints]]\nresult = "flywheel.inertia"\nmax = "{limit} kg*m^2"\n')
    best = run_problem(text).outcomes["optimise"].results
    assert best.verified
    assert best.results["flywheel.inertia"] <= limit * (1 + 1e-9)


def test_a_result_of_a_table_the_file_lacks_is_refused_by_check_and_run_alike():
    text = STUDY + '\n[[optimise.objectives]]\nresult = "parts.pin.B.shear_stress"\nsense = "minimise"\n'
    with pytest.raises(ProblemFileError) as checked:
        check_problem(text)
    with pytest.raises(ProblemFileError) as ran:
        run_problem(text)
    assert [p for p, _ in checked.value.problems] == [p for p, _ in ran.value.problems]
    assert "names no result" in str(ran.value)


def test_the_capability_results_are_those_of_the_tables_the_file_has():
    keys = capability_results(load_problem(STUDY + '\n[[optimise.objectives]]\nresult = "flywheel.inertia"\n'))
    assert keys["flywheel.inertia"] == "kg*m^2" and keys["flywheel.mass"] == "kg"
    assert not any(k.startswith(("balance.", "parts.", "optimise.")) for k in keys)


def test_a_design_whose_run_fails_gets_nan_and_the_others_their_values():
    def run_design(problem):
        if problem == "bad":
            raise ProblemFileError([("drive.speed", "must be > 0")])
        return {"flywheel.inertia": 2.0, "flywheel.mass": math.inf}

    out = evaluate_designs(run_design, ["good", "bad", None], ["flywheel.inertia", "flywheel.mass"], 3)
    np.testing.assert_array_equal(out["flywheel.inertia"], [2.0, np.nan, np.nan])
    assert np.isnan(out["flywheel.mass"]).all()  # not a finite figure: never a value to optimise


def test_a_sweep_column_of_a_capability_result_is_each_variants_own_run():
    plain = STUDY.split("[optimise]")[0]
    text = plain + ('\n[sweep]\nparameter = "mechanism.coupler.mass"\nvalues = ["0.5 kg", "2 kg"]\n'
                    'columns = ["flywheel.inertia"]\n')
    check_problem(text)
    run = run_problem(text)
    swept = run.outcomes["sweep"].results.columns["flywheel.inertia"]
    for mass, value in zip(("0.5 kg", "2 kg"), swept, strict=True):
        alone = run_problem(plain.replace('"2 kg"', f'"{mass}"', 1)).results["flywheel.inertia"]
        assert value == pytest.approx(alone, rel=1e-12)
