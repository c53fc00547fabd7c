"""The drive train and parts tables through the command line: results, failed checks (exit 3), bad input
(exit 2) named by their field, and ``check`` agreeing with ``run``."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from machdyn.cli import app

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "crank_press_drive.toml"
runner = CliRunner()


def _variant(tmp_path: Path, old: str, new: str) -> Path:
    text = EXAMPLE.read_text()
    assert old in text
    path = tmp_path / "variant.toml"
    path.write_text(text.replace(old, new, 1))
    return path


def test_the_press_example_runs_with_its_drive_train_and_parts(tmp_path):
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(EXAMPLE), "--out", str(out), "-q"])
    assert result.exit_code == 0, result.output
    scalars = json.loads((out / "results.json").read_text())["scalars"]
    for key in ("clutch.energy", "brake.stop_angle", "drivetrain.reflected_inertia", "parts.utilisation.max",
                "parts.bearing.O.rating_life"):
        assert key in scalars, key
    report = (out / "report.html").read_text()
    assert 'id="drive-train"' in report and 'id="parts"' in report
    # the flywheel's own inertia on the shaft turning 8 times the crank counts 8² times at the crank, and the
    # report says which shaft it is on
    own, at_crank = scalars["flywheel.own_inertia"]["value"], scalars["flywheel.inertia"]["value"]
    assert at_crank == pytest.approx(64.0 * own, rel=1e-12)
    assert "flywheel inertia about its own shaft" in report and "flywheel shaft" in report
    assert scalars["flywheel.gear_ratio"]["value"] == 37.5  # the motor's ratio is the stages' (4.6875 × 8)
    assert (out / "drivetrain_torques.csv").exists() and (out / "parts_bearings.csv").exists()


def test_an_overloaded_pin_and_a_long_stop_are_failed_design_checks(tmp_path):
    weak = _variant(tmp_path, 'allowable_shear = "80 MPa"', 'allowable_shear = "5 MPa"')
    result = runner.invoke(app, ["run", str(weak), "--out", str(tmp_path / "a"), "-q"])
    assert result.exit_code == 3, result.output
    assert "pin B: peak shear stress" in result.output
    slow = _variant(tmp_path, 'torque = "150 N*m"', 'torque = "2 N*m"')
    result = runner.invoke(app, ["run", str(slow), "--out", str(tmp_path / "b"), "-q"])
    assert result.exit_code == 3, result.output
    assert "brake.max_angle" in result.output


def test_a_clutch_weaker_than_the_torque_it_carries_is_bad_input_for_check_and_run(tmp_path):
    weak = _variant(tmp_path, 'slip_torque = "250 N*m"', 'slip_torque = "50 N*m"')
    for command in (["check", str(weak)], ["run", str(weak), "--out", str(tmp_path / "o"), "-q"]):
        result = runner.invoke(app, command)
        assert result.exit_code == 2, result.output
        assert "drivetrain.clutch.slip_torque" in result.output and "must exceed" in result.output


def test_bad_drive_train_tables_are_named(tmp_path):
    cases = [
        ('efficiency = 0.97', 'efficiency = 1.5', "efficiency"),
        ('joint = "B"', 'joint = "Q"', "parts.pins[0].joint"),
        ('shaft = "flywheel shaft"     #', 'shaft = "fly shaft"     #', "names no shaft of [drivetrain]"),
        ('capacity = "120 kN"', 'capacity = "120"', "capacity"),
    ]
    for old, new, expected in cases:
        bad = _variant(tmp_path, old, new)
        result = runner.invoke(app, ["check", str(bad)])
        assert result.exit_code == 2, (old, result.output)
        assert expected in result.output, (old, result.output)
