"""The one drive line of a problem file: the flywheel's inertia about its own shaft, the drive line's shafts in
the flywheel's steady state, and every value given twice refused by ``check`` and ``run`` alike.

Hand formulas: the reduced inertia J_c = Σ J_k r_k² with r_k = ω_k/ω_c (equal kinetic energy; Uicker, Pennock &
Shigley, *Theory of Machines and Mechanisms*, 4th ed., the chapter on the dynamics of machines; Khurmi & Gupta,
*Theory of Machines*, "torque required to accelerate a geared system"), and the coefficient of speed
fluctuation of a machine of constant inertia J under a constant-torque drive, δ = ΔE/(J ω²) (Khurmi & Gupta,
ch. 16, ΔE = I ω² C_s).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.reading import load_problem
from machdyn.runner import run_problem

ROOT = Path(__file__).resolve().parents[2]
PRESS = (ROOT / "examples" / "crank_press.toml").read_text().split("[flywheel]")[0]
runner = CliRunner()

FLYWHEEL = """
[flywheel]
inertia = "{inertia}"
positions = 256
start_up = false
{shaft}
[flywheel.motor]
kind = "constant_torque"
"""

TRAIN = """
[drivetrain]
motor_inertia = "0.004 kg*m^2"

[[drivetrain.stages]]
kind = "belt"
ratio = 4.0
inertia = "0.5 kg*m^2"
shaft = "flywheel shaft"

[[drivetrain.stages]]
kind = "gear"
ratio = 10.0
inertia = "{bull}"
"""


def _flywheel_run(tmp_path: Path, text: str):
    path = tmp_path / "press.toml"
    path.write_text(PRESS + text)
    return run_problem(load_problem(path)).outcomes["flywheel"]


def test_a_flywheel_on_a_shaft_turning_ten_times_the_crank_counts_a_hundred_times(tmp_path):
    at_crank = _flywheel_run(tmp_path, FLYWHEEL.format(inertia="600 kg*m^2", shaft=""))
    on_shaft = _flywheel_run(tmp_path, FLYWHEEL.format(inertia="6 kg*m^2", shaft='shaft = "flywheel shaft"')
                             + TRAIN.format(bull="0 kg*m^2").replace('motor_inertia = "0.004 kg*m^2"', "")
                             .replace('inertia = "0.5 kg*m^2"', ""))
    # the flywheel's own 6 kg·m² on a shaft at 10 × the crank's speed: 6·10² = 600 kg·m² at the crank
    assert on_shaft.scalars["flywheel.own_inertia"] == pytest.approx(6.0, rel=1e-15)
    assert on_shaft.scalars["flywheel.inertia"] == pytest.approx(600.0, rel=1e-15)
    assert on_shaft.scalars["flywheel.shaft_speed_ratio"] == 10.0
    # nothing else turns (shafts of no inertia): the same machine, the same steady state
    assert on_shaft.scalars["flywheel.delta"] == pytest.approx(at_crank.scalars["flywheel.delta"], rel=1e-9)


def test_the_drive_lines_shafts_lower_the_fluctuation_as_the_reduced_inertia_predicts(tmp_path):
    deltas = {}
    for bull in (4.0, 400.0):
        fly = _flywheel_run(tmp_path, FLYWHEEL.format(inertia="6 kg*m^2", shaft='shaft = "flywheel shaft"')
                            + TRAIN.format(bull=f"{bull} kg*m^2"))
        s, run = fly.scalars, fly.results
        line = 0.004 * 40.0**2 + 0.5 * 10.0**2 + bull  # motor shaft at 40 ×, flywheel shaft at 10 ×, crank
        assert s["flywheel.line_inertia"] == pytest.approx(line, rel=1e-12)
        total = 6.0 * 10.0**2 + line + float(run.sizing.mean_inertia[0])  # flywheel + shafts + linkage (mean)
        predicted = s["flywheel.sizing_energy_fluctuation"] / (total * s["flywheel.mean_speed"] ** 2)
        # δ = ΔE/(J ω²) is exact for a constant J under a constant torque; here J(φ) varies by about 0.1 kg·m²
        # (0.02 % of J) and the linkage's inertia loads follow the real speed, which varies by δ (≤ 1.4 %):
        # measured agreement 0.1 %, tolerance 0.5 %
        assert s["flywheel.delta"] == pytest.approx(predicted, rel=5e-3)
        deltas[bull] = s["flywheel.delta"]
    # the bull gear from 4 to 400 kg·m²: the fluctuation falls (it stayed the same before the shafts counted)
    assert deltas[400.0] < 0.7 * deltas[4.0]


def test_a_flywheel_inertia_on_a_faster_shaft_without_a_drive_train_is_its_own_and_says_so(tmp_path):
    fly = _flywheel_run(tmp_path, FLYWHEEL.format(inertia="6 kg*m^2", shaft="speed_ratio = 10.0"))
    assert fly.scalars["flywheel.inertia"] == pytest.approx(600.0, rel=1e-15)
    assert any("is the flywheel's own" in w and "0.06 kg*m^2" in w for w in fly.warnings), fly.warnings


DRIVE_EXAMPLE = ROOT / "examples" / "crank_press_drive.toml"


def _variant(tmp_path: Path, *replacements: tuple[str, str]) -> Path:
    text = DRIVE_EXAMPLE.read_text()
    for old, new in replacements:
        assert old in text, old
        text = text.replace(old, new, 1)
    path = tmp_path / "variant.toml"
    path.write_text(text)
    return path


def _refused_alike(tmp_path: Path, path: Path) -> str:
    """The output of ``check`` and ``run`` on ``path``: both refuse it as bad input (exit 2)."""
    outputs = []
    for command in (["check", str(path)], ["run", str(path), "--out", str(tmp_path / "out"), "-q"]):
        result = runner.invoke(app, command)
        assert result.exit_code == 2, (command[0], result.output)
        outputs.append(" ".join(result.output.split()))
    return " | ".join(outputs)


def test_the_motor_ratio_and_efficiency_given_twice_are_refused_naming_both_fields(tmp_path):
    # the user's press: stages of 5 and 10, a [flywheel.motor] ratio of 40 and efficiency of 0.7
    path = _variant(tmp_path, ("ratio = 4.6875 ", "ratio = 5.0 "), ("ratio = 8.0 ", "ratio = 10.0 "),
                    ('synchronous_speed = "1500 rpm"', 'synchronous_speed = "1500 rpm"\nratio = 40.0\n'
                                                       'efficiency = 0.7\nrotor_inertia = "0.01 kg*m^2"'))
    both = _refused_alike(tmp_path, path)
    for check, run in [both.split(" | ")]:
        for text in (check, run):
            assert "flywheel.motor.ratio = 40 and drivetrain.stages[*].ratio (5 × 10 = 50)" in text
            assert "flywheel.motor.efficiency = 0.7 and drivetrain.stages[*].efficiency (0.95 × 0.97 = 0.9215)" \
                in text
            assert "flywheel.motor.rotor_inertia = 0.01 kg*m^2 and drivetrain.motor_inertia = 0.004 kg*m^2" in text


def test_a_flywheel_speed_ratio_beside_a_drive_train_is_refused_with_the_shaft_to_name(tmp_path):
    path = _variant(tmp_path, ('shaft = "flywheel shaft"     #', 'speed_ratio = 8.0     #'))
    text = _refused_alike(tmp_path, path)
    assert "flywheel.speed_ratio = 8 and drivetrain.stages[*].ratio both give the speed of the flywheel's shaft" \
        in text
    assert 'flywheel.shaft = "flywheel shaft"' in text


def test_the_flywheel_counts_on_the_side_of_the_clutch_its_shaft_is_on():
    from machdyn.drivetrain.stage import _sides
    from machdyn.dynamics.driveline import DriveLine, DriveTrain, Stage

    train = DriveTrain((Stage(4.0), Stage(8.0)), (0.01, 0.02, 6.0))
    names = ("motor", "flywheel shaft", "crank")
    # shafts at the crank: 0.01·32² = 10.24 and 0.02·8² = 1.28 before the clutch (on shaft 1), 6 after it
    before = DriveLine(train, names, flywheel_shaft=1, clutch_shaft=1)
    assert _sides(before, 1, 50.0) == pytest.approx((10.24 + 1.28 + 50.0, 6.0), rel=1e-12)
    after = DriveLine(train, names, flywheel_shaft=2, clutch_shaft=1)
    assert _sides(after, 1, 50.0) == pytest.approx((10.24 + 1.28, 6.0 + 50.0), rel=1e-12)


@pytest.mark.parametrize(("replacements", "expected"), [
    ((('slip_torque = "250 N*m"', 'slip_torque = "250 N*m"\nmotor_torque = "20 N*m"'),),
     "drivetrain.clutch.motor_torque = 20 N*m and [flywheel.motor] both give the motor's torque"),
    ((('shaft = "flywheel shaft"     #', 'shaft = 7     #'),), "must be a shaft number 0 (the motor) to 2"),
    ((('shaft = "flywheel shaft"         # the name', 'shaft = "crank"         # the name'),),
     "stages[*].shaft must name each shaft once"),
], ids=["clutch_motor_torque_twice", "flywheel_shaft_out_of_range", "a_stage_shaft_named_crank"])
def test_other_drive_line_mistakes_are_refused_by_check_and_run(tmp_path, replacements, expected):
    assert expected in _refused_alike(tmp_path, _variant(tmp_path, *replacements))


def test_a_flywheel_shaft_name_without_a_drive_train_is_refused_by_check_and_run(tmp_path):
    path = tmp_path / "press.toml"
    path.write_text(PRESS + FLYWHEEL.format(inertia="6 kg*m^2", shaft='shaft = "flywheel shaft"'))
    text = _refused_alike(tmp_path, path)
    assert "flywheel.shaft: names a shaft of [drivetrain], but the file has no [drivetrain]" in text
