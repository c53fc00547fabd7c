"""The designer's other questions as modes of one problem file: check an existing screw, lift and torque given
directly, and the search for the best design (verified candidate by candidate)."""

import copy
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from machdyn.conveyor import evaluate, validate
from machdyn.conveyor.optimise import evaluate_candidates
from machdyn.errors import InputError, ProblemFileError


def test_check_an_existing_conveyor_from_diameter_pitch_speed_and_filling(base_problem):
    sc = base_problem["screw_conveyor"]
    del sc["throughput"]
    sc["screw"].update({"diameter": "250 mm", "speed": "80 rpm"})
    result = evaluate(validate(base_problem))
    s = result.scalars
    # the duty is the screw's capacity: 15π·(D² − d_o²)·S·n·φ·C·ρ [t/h] (seed 004, eq 2.83, with the pipe
    # deducted as in CEMA 350: the base problem's 100 mm pipe)
    cap = 15 * math.pi * (0.25**2 - 0.1**2) * 0.8 * 0.25 * 80 * 0.4 * 0.8 * 1.2 / 3.6  # kg/s
    assert s["mass_flow"] == pytest.approx(cap, rel=1e-12)
    assert s["check_throughput_<=_capacity_utilisation"] == pytest.approx(1.0)
    assert s["torque"] == pytest.approx(s["shaft_power"] / (80 * math.pi / 30))


def test_check_mode_needs_the_screw(base_problem):
    del base_problem["screw_conveyor"]["throughput"]
    with pytest.raises(ProblemFileError, match="required unless the screw is given"):
        validate(base_problem)


def test_lift_given_directly(base_problem):
    sc = base_problem["screw_conveyor"]
    del sc["inclination"]
    sc["lift"] = "3 m"
    sc["power_method"] = "textbook_367"
    result = evaluate(validate(base_problem))
    assert result.scalars["lift"] == 3.0
    assert result.scalars["inclination"] == pytest.approx(math.asin(3 / 21))
    m = 2.0  # 7.2 t/h
    assert result.shaft_power == pytest.approx(m * 9.80665 * (2.5 * 21 + 3.0))
    sc["inclination"] = "10 deg"
    with pytest.raises(ProblemFileError, match="either the lift or the inclination"):
        validate(base_problem)
    del sc["inclination"]
    sc["lift"] = "30 m"
    with pytest.raises(ProblemFileError, match="must be <= the length"):
        validate(base_problem)


def test_torque_given_directly_drives_the_axial_force_and_shaft_checks(base_problem):
    plain = evaluate(validate(base_problem))
    base_problem["screw_conveyor"]["torque"] = "300 N*m"
    measured = evaluate(validate(base_problem))
    assert measured.torque == 300.0
    assert measured.scalars["axial_force"] == pytest.approx(plain.scalars["axial_force"] * 300 / plain.torque)
    assert measured.shaft_power == pytest.approx(plain.shaft_power)  # the power methods are unchanged
    assert any("Torque given directly" in w for w in measured.warnings)


SEARCH = {"diameters": ["160 mm", "200 mm", "250 mm", "315 mm"], "pitch_ratios": [1.0, 0.75, 0.5],
          "speed_fractions": [0.5, 0.75, 1.0], "fillings": [0.25, 0.4]}


def _search_problem(base_problem, objective, throughput="7.2 t/h"):
    data = copy.deepcopy(base_problem)
    data["screw_conveyor"]["throughput"] = throughput
    data["screw_conveyor"]["power_method"] = "cema"  # depends on diameter, speed and filling alike
    data["screw_conveyor"]["screw"] = {}  # the search sizes the flights of each candidate
    # a heavy motor per kW, so that the cost proxy weighs the drive against the screw
    data["screw_conveyor"]["optimise"] = dict(SEARCH, objective=objective, motor_mass_per_kw=300.0)
    return validate(data)


def _single(problem, row):
    """One candidate analysed on its own (scalar path), as the search sees it."""
    p = problem.replace(search=None, diameter=row["diameter"], speed=row["speed"], pitch_ratio=row["pitch_ratio"],
                        filling=row["filling"], pipe_outer_diameter=None, pipe_wall=None, flight_thickness=None)
    return evaluate(p, bending=False)


@pytest.mark.parametrize(("objective", "duty"), [("power", "7.2 t/h"), ("cost", "12 t/h")])
def test_best_design_meets_duty_and_checks_and_no_cheaper_candidate_does(base_problem, objective, duty):
    problem = _search_problem(base_problem, objective, duty)
    result = evaluate(problem)
    r = result.ranking
    assert r.candidates == 4 * 3 * 3 * 2 and r.feasible >= 1
    assert result.passed and result.scalars["capacity"] >= result.scalars["mass_flow"]
    best = r.best
    assert result.scalars["diameter"] == best["diameter"]
    # every candidate of lower objective fails a check when analysed on its own (the scalar path)
    cheaper = np.flatnonzero(r.value < best["objective"])
    assert cheaper.size >= 5  # the property is not vacuous on this grid
    for i in cheaper:
        assert not _single(problem, r.row(int(i))).passed
    # and the ranking is ordered
    assert np.all(np.diff(r.value[r.order]) >= 0)


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(t_h=st.floats(1.0, 40.0), length=st.floats(3.0, 30.0))
def test_vectorised_candidates_agree_with_single_runs(base_problem, t_h, length):
    data = copy.deepcopy(base_problem)  # a fresh copy per example: the fixture itself is never changed
    data["screw_conveyor"]["length"] = f"{length} m"
    problem = _search_problem(data, "power", f"{t_h} t/h")
    grid, states = evaluate_candidates(problem)
    for i in (0, 7, 40, 71):
        row = {k: float(v[i]) for k, v in grid.items()}
        single = _single(problem, row)
        assert states["shaft_power"][i] == pytest.approx(single.shaft_power, rel=1e-12)
        assert states["check.stress"][i] == pytest.approx(single.checks[5].value, rel=1e-12)


def test_search_without_feasible_candidate_is_an_error(base_problem):
    problem = _search_problem(base_problem, "power", "400 t/h")
    with pytest.raises(InputError, match="No candidate of the design search"):
        evaluate(problem)
