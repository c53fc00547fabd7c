"""Result keys named in studies: keys made from a file's names (a shaft line's bearings and frame points) are
checked against the file, with the nearest key and the family of results to choose from; the shaft line's keys
carry their units; the parts' keys follow a grammar and their old names still read."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from machdyn.errors import ProblemFileError
from machdyn.kinds import catalogue
from machdyn.reading import load_problem
from machdyn.results.catalogue import canonical, find
from machdyn.results.names import nearest, results_to_choose
from machdyn.runner import check_problem
from reproductions import (
    PARTS,
    SHAFT_LINE,
    SHAFT_OPTIMISE,
    parts_column,
    parts_objective,
    shaft_column,
    shaft_objective,
)

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

LINE, OPTIMISE = SHAFT_LINE, SHAFT_OPTIMISE


def _refused(text: str) -> list[tuple[str, str]]:
    with pytest.raises(ProblemFileError) as info:
        check_problem(text)
    return info.value.problems


@pytest.mark.parametrize("key", ["shaft.bearing.frnt.peak", "shaft.frame.point.nowhere.rms_velocity"])
def test_a_typo_under_a_shaft_lines_named_keys_is_refused_in_a_sweep_column(key):
    [(path, message)] = _refused(shaft_column(key))
    assert path == "sweep.columns[0]" and f"'{key}' is not a result of this shaft-line file" in message


def test_a_typo_under_a_shaft_lines_bearings_is_refused_in_an_objective_with_the_bearings_listed():
    [(path, message)] = _refused(shaft_objective("shaft.bearing.frnt.peak"))
    assert path == "optimise.objectives[0].result"
    assert "did you mean 'shaft.bearing.front.peak'?" in message and "angles" not in message
    assert ("results of shaft.bearing.*: shaft.bearing.centre.peak, shaft.bearing.front.peak, "
            "shaft.bearing.rear.peak;") in message


def test_an_engine_couple_takes_a_limit_in_newton_metres():
    text = LINE + OPTIMISE.replace('result = "shaft.engine.primary_force"\nmax = "1 N"',
                                   'result = "shaft.engine.order1.couple"\nmax = "1000 N*m"')
    assert 'max = "1000 N*m"' in text
    check_problem(text)  # accepted: the couple is in N*m


@pytest.mark.parametrize(("key", "unit"), [
    ("shaft.engine.order2.couple", "N*m"), ("shaft.engine.order2.force", "N"), ("shaft.balance.A.angle", "rad"),
    ("shaft.balance.A.mass", "kg"), ("shaft.frame.point.P.rms_velocity", "m/s"), ("shaft.field.L.angle", "rad"),
    ("shaft.locomotive.left.balance_angle", "rad"), ("shaft.grade.front.residual", "kg*m"),
    ("parts.bearing.O.rating_life", "s"), ("parts.pin.B.peak_shear_stress", "Pa"),
])
def test_the_keys_made_from_names_have_their_units_in_the_catalogue(key, unit):
    found = find(key, catalogue())
    assert found is not None and found[0].unit == unit


@pytest.mark.parametrize(("old", "new"), [
    ("parts.bearing.O.rating_life_l5_p_3_33", "parts.bearing.O.rating_life"),
    ("parts.bearing.O.rating_life_l10_p_3", "parts.bearing.O.rating_life"),
    ("parts.bearing.O.rating_life_no_requirement", "parts.bearing.O.rating_life"),
    ("parts.bearing.A.mean_p_v_over_the_cycle", "parts.bearing.A.mean_pv"),
    ("parts.bearing.A.peak_pressure_p", "parts.bearing.A.peak_pressure"),
    ("parts.link.rod.fatigue_safety_factor_modified_goodman", "parts.link.rod.fatigue_safety"),
    ("optimise.best.parts.bearing.O.rating_life_l5_p_3_33", "optimise.best.parts.bearing.O.rating_life"),
])
def test_the_old_parts_keys_still_read(old, new):
    assert canonical(old) == new


def test_a_weight_is_read_as_a_mass_and_the_family_is_listed_whole():
    names = [f"flywheel.{n}" for n in ("delta", "diameter", "inertia", "mass", "width", "max_speed")] + [
        f"joint.J{k}.max_force" for k in range(40)]
    assert nearest("flywheel.weight", names) == "flywheel.mass"
    listed = results_to_choose("flywheel.weight", names)
    assert "flywheel.mass" in listed and "joint." not in listed and "40 other results" in listed


def test_the_flywheel_weight_objective_proposes_the_mass(tmp_path):
    text = (EXAMPLES / "compactor_flywheel.toml").read_text(encoding="utf-8").replace("[flywheel.motor]", '''
[[optimise.variables]]
parameter = "mechanism.crank.length"
lower = "40 mm"
upper = "60 mm"

[[optimise.objectives]]
result = "flywheel.weight"

[flywheel.motor]''', 1)
    [(path, message)] = _refused(text)
    assert path == "optimise.objectives[0].result" and "did you mean 'flywheel.mass'?" in message
    assert "flywheel.mass" in message.split("(results of flywheel.*: ")[1]  # listed, not cut before it


def test_a_linkage_sweeps_unknown_column_lists_the_results():
    text = (EXAMPLES / "four_bar_sweep.toml").read_text(encoding="utf-8").replace(
        "count = 31", 'count = 31\ncolumns = ["driving_torque.maxx"]', 1)
    [(path, message)] = _refused(text)
    assert path == "sweep.columns[0]" and "did you mean 'driving_torque.max'?" in message
    assert "results of driving_torque.*: driving_torque.max_abs, driving_torque.max, " in message


def test_the_shaft_line_lists_only_what_it_reports():
    from machdyn.studies.per_design import capability_results

    keys = capability_results(load_problem(LINE))
    assert {"shaft.bearing.front.peak", "shaft.engine.order1.couple"} <= set(keys)
    assert keys["shaft.engine.order1.couple"] == "N*m"
    assert not any(k.startswith("shaft.balance.") for k in keys)  # the file has no balancing planes


def test_an_infeasible_shaft_line_search_speaks_of_runs_not_of_crank_angles():
    from machdyn.runner import run_problem

    text = LINE + OPTIMISE.replace('result = "shaft.engine.primary_force"', 'result = "shaft.engine.gross_force"')
    text = re.sub(r"generations = \d+", "generations = 1", text).replace("population = 12", "population = 6")
    result = run_problem(text)
    [failed] = [c for c in result.failed_checks if c.startswith("No design within the bounds")]
    assert "builds and runs, reporting every result named" in failed and "the closest design ran" in failed
    assert "angles" not in failed and "shaft.engine.gross_force <= 1 N: violated" in failed


@pytest.mark.parametrize(("key", "meant"), [
    ("parts.bearing.Q.rating_life", "parts.bearing.O.rating_life"),      # a bearing the file does not declare
    ("parts.bearing.A.peak_presure", "parts.bearing.A.peak_pressure"),   # a figure misspelt
    ("parts.pin.D.peak_shear_stress", "parts.pin.B.peak_shear_stress"),  # a joint with no pin
    ("parts.bearing.A.mean_pv", "parts.bearing.A.peak_pressure"),        # a figure the bearing has no limit for
])
@pytest.mark.parametrize(("study", "path"), [(parts_column, "sweep.columns[0]"),
                                             (parts_objective, "optimise.objectives[0].result")])
def test_a_part_the_file_does_not_declare_is_refused_by_check_and_run_alike(key, meant, study, path):
    """The parts' keys are made from the file's own names; a key of a part (or a figure) the file does not declare
    is refused with the nearest of the file's parts and its family listed, by check and by run in the same words."""
    text = study(key)
    [(where, message)] = _refused(text)
    assert where == path and f"'{key}'" in message and f"did you mean '{meant}'?" in message
    assert meant in message.split("(results of parts.")[1]  # the family of the file's parts, listed
    from machdyn.runner import run_problem

    with pytest.raises(ProblemFileError) as info:
        run_problem(text)
    assert info.value.problems == [(where, message)]


@pytest.mark.parametrize("study", [parts_column, parts_objective])
def test_the_parts_the_file_declares_are_results_a_study_may_name(study):
    for key in ("parts.bearing.O.rating_life", "parts.bearing.A.peak_pressure", "parts.pin.B.peak_shear_stress"):
        check_problem(study(key))


def test_the_parts_keys_are_those_a_run_reports_with_their_units():
    from machdyn.runner import run_problem
    from machdyn.studies.per_design import capability_results

    listed = {k: u for k, u in capability_results(load_problem(PARTS)).items() if k.startswith("parts.")}
    run = run_problem(PARTS).results
    reported = {k for k in run.values if k.startswith("parts.")}
    # a link broken in its first cycle reports its peak stress instead; this file has no link
    assert set(listed) == reported
    assert all(run.label(k).unit == u for k, u in listed.items())
