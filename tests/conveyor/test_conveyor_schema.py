"""The ``[screw_conveyor]`` kind in the shape of every kind: its pydantic schema from the shared field types,
every mistake of a file said at once (path, rule, value) by ``check`` and ``run`` alike, the problem written
back as TOML by the generic dumper, speeds in rad/s inside, and the drive chosen by the shared motor selection."""

import math
from pathlib import Path

import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.errors import ProblemFileError

ROOT = Path(__file__).resolve().parents[2]
CONVEYORS = sorted((ROOT / "examples").glob("*conveyor*.toml"))

#: A file with one mistake in each of four tables, a rule across fields broken in a fifth place and a
#: misspelt key: each (path, words of the rule, the value) must be said in the one error.
BAD = """
[meta]
name = "bad conveyor"

[screw_conveyor]
throughput = "7.2 kg"
length = "-21 m"
lift = "3 m"
inclination = "10 deg"

[screw_conveyor.material]
bulk_density = "5e4 kg/m^3"
filling = 1.4
resistance = 2.5

[screw_conveyor.screw]
speed = "150"
pich_ratio = 0.8

[screw_conveyor.strength]
allowable_stress = "-5 MPa"
"""

EXPECTED = [
    ("screw_conveyor.throughput", "mass flow", "7.2 kg"),
    ("screw_conveyor.length", "must be > 0 m", "-21 m"),
    ("screw_conveyor.material.bulk_density", "must be <= 30000 kg/m^3", "got 50000 kg/m^3"),
    ("screw_conveyor.material.filling", "must be in (0, 1]", "1.4"),
    ("screw_conveyor.material.speed_coefficient", "required", "speed_class"),
    ("screw_conveyor.screw.speed", "must be in units of 1 / [time] (like rad/s)", "'150'"),
    ("screw_conveyor.screw.pich_ratio", "unknown key", "did you mean 'pitch_ratio'"),
    ("screw_conveyor.strength.allowable_stress", "must be > 0 Pa", "-5 MPa"),
    ("screw_conveyor.lift", "either the lift or the inclination", ""),
]


def _said(problems, path):
    return [message for p, message in problems if p == path]


def test_every_mistake_of_a_conveyor_file_is_said_at_once_with_path_rule_and_value():
    from machdyn.reading import load_problem

    with pytest.raises(ProblemFileError) as caught:
        load_problem(BAD)
    problems = caught.value.problems
    for path, rule, value in EXPECTED:
        messages = _said(problems, path)
        assert messages, f"{path} not said; said: {problems}"
        assert any(rule in m and value in m for m in messages), (path, messages)
    assert len(problems) == len(EXPECTED), problems


def test_check_and_run_refuse_the_bad_file_alike(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text(BAD, encoding="utf-8")
    checked = CliRunner().invoke(app, ["check", str(bad)])
    ran = CliRunner().invoke(app, ["run", str(bad), "--out", str(tmp_path / "out")])
    assert checked.exit_code == ran.exit_code == 2, (checked.output, ran.output)
    assert "Traceback" not in checked.output + ran.output
    for path, _rule, _value in EXPECTED:
        assert path in checked.output and path in ran.output, path
    assert not (tmp_path / "out" / "results.json").exists()


def test_a_rule_across_fields_of_valid_tables_is_said_by_the_build():
    """The lift longer than the screw needs both values valid: the kind's build says it, check and run alike."""
    from machdyn.reading import load_problem
    from machdyn.runner import check_problem

    text = (ROOT / "examples" / "conveyor_lift_torque.toml").read_text(encoding="utf-8")
    assert 'length = "' in text
    start = text.index('length = "')
    text = text[:start] + 'length = "0.5 m"' + text[text.index("\n", start):]
    for read in (load_problem, check_problem):
        with pytest.raises(ProblemFileError) as caught:
            read(text)
        assert any(p == "screw_conveyor.lift" and "must be <= the length 0.5 m" in m
                   for p, m in caught.value.problems), caught.value.problems


@pytest.mark.parametrize("example", CONVEYORS, ids=lambda p: p.stem)
def test_a_conveyor_problem_is_written_back_and_read_to_the_same_problem_and_results(example):
    from machdyn.problem import dump_problem
    from machdyn.reading import load_problem
    from machdyn.runner import run_problem

    spec = load_problem(example)
    text = dump_problem(spec)
    assert load_problem(text) == spec
    first, again = run_problem(example), run_problem(text)
    assert again.results.as_json() == first.results.as_json()


def test_the_screw_speed_is_read_in_rpm_and_kept_in_rad_per_s(base_problem):
    from machdyn.conveyor import validate

    base_problem["screw_conveyor"]["screw"].update(diameter="200 mm", speed="90 rpm")
    problem = validate(base_problem)
    assert problem.speed == pytest.approx(90 * math.pi / 30, rel=1e-15)
    base_problem["screw_conveyor"]["screw"]["speed"] = "9.42477796076938 rad/s"
    assert validate(base_problem).speed == pytest.approx(problem.speed, rel=1e-14)


@pytest.mark.parametrize("example", CONVEYORS, ids=lambda p: p.stem)
def test_the_conveyor_drive_is_the_shared_selection_from_the_one_motor_table(example):
    """The motor rating of every shipped conveyor is the shared selection's smallest IEC 60072-1 rating that
    gives the power the drive needs; the conveyor keeps no table or selection of its own (its old name
    ``select_motor`` is a deprecated alias of the shared selection)."""
    import machdyn.conveyor as conveyor
    from machdyn.dynamics.motors import smallest_rating, standard_ratings
    from machdyn.runner import run_problem

    results = run_problem(example).results
    needed, rating = results["motor_power_required"], results["motor_rating"]
    assert rating == smallest_rating(needed)
    assert rating >= needed and rating in standard_ratings()
    smaller = [r for r in standard_ratings() if r < rating]
    assert not smaller or smaller[-1] < needed
    with pytest.warns(DeprecationWarning, match="smallest_rating"):
        assert conveyor.select_motor(needed) == rating
    assert not (Path(conveyor.__file__).parent / "data" / "motor_ratings_iec.csv").exists()
