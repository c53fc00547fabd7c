"""A clutch and a brake given by their geometry through the command line: the example's results follow the
handbook formulas, the report shows them, and bad geometry is refused by ``check`` and ``run`` alike, named by its
path."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.drivetrain import brakes, clutches

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "press_brake_clutch.toml"
runner = CliRunner()


def _variant(tmp_path: Path, changes: list[tuple[str, str]]) -> Path:
    text = EXAMPLE.read_text()
    for old, new in changes:
        assert old in text, old
        text = text.replace(old, new, 1)
    path = tmp_path / "variant.toml"
    path.write_text(text)
    return path


CENTRIFUGAL = """[drivetrain.clutch.geometry]
kind = "centrifugal"
friction = 0.3
shoes = 4
shoe_mass = "8 kg"
shoe_radius = "200 mm"
drum_radius = "220 mm"
spring_force = "200 N"
"""

INTERNAL_SHOES = """[drivetrain.brake.geometry]
kind = "internal_shoe"
friction = 0.32
max_pressure = "0.3 MPa"
drum_radius = "150 mm"
width = "32 mm"
shoe_start = "0 deg"
shoe_end = "126 deg"
hinge = "123 mm"
force_arm = "100 mm"
max_allowed_pressure = "1 MPa"
"""


def _section(text: str, header: str) -> str:
    start = text.index(header)
    return text[start: text.index("\n\n", start) + 2]


def test_a_centrifugal_clutch_and_internal_shoes_through_the_command_line(tmp_path):
    """One run of the example with a centrifugal clutch and Shigley's internal shoes (Example 16-2 geometry at
    0.3 MPa), without its flywheel, parts and single stroke (not needed here), and with a drum limit it cannot meet:
    a failed design check (exit 3) whose results follow the formulas."""
    text = EXAMPLE.read_text()
    text = text[: text.index("[flywheel]")] + text[text.index("[drivetrain]"): text.index("[drivetrain.single_stroke]")]
    text = text.replace(_section(text, "[drivetrain.clutch.geometry]"), CENTRIFUGAL)
    text = text.replace(_section(text, "[drivetrain.brake.geometry]"), INTERNAL_SHOES)
    text = text.replace('max_temperature_rise = "100 K"', 'max_temperature_rise = "0.5 K"')
    path = tmp_path / "hot.toml"
    path.write_text(text)
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(path), "--out", str(out), "-q"])
    assert result.exit_code == 3, result.output
    assert "brake.heating.max_temperature_rise" in result.output
    scalars = {k: v["value"] for k, v in json.loads((out / "results.json").read_text())["scalars"].items()}
    shaft_speed = 40 * math.pi / 30 * 8.0  # the clutch's shaft turns 8 times as fast as the crank
    clutch = clutches.centrifugal_clutch(0.3, 4, 8.0, 0.2, 0.22, 200.0, shaft_speed)
    assert scalars["clutch.torque"] == pytest.approx(clutch.torque, rel=1e-9)
    assert scalars["clutch.engagement_speed"] == pytest.approx(clutch.engagement_speed, rel=1e-9)  # rad/s
    moments = brakes.shoe_moments(0.32, 0.15, 0.032, 0.0, math.radians(126), 0.123)
    force = 0.3e6 * (moments.normal - moments.friction) / 0.1
    assert scalars["brake.lever_force"] == pytest.approx(force, rel=1e-9)
    assert scalars["brake.max_pressure"] == pytest.approx(0.3e6, rel=1e-9)  # Pa
    assert scalars["brake.torque"] == pytest.approx(
        brakes.internal_shoe_brake(0.32, force, 0.15, 0.032, 0.0, math.radians(126), 0.123, 0.1).torque, rel=1e-9)
    # the worst stop's energy is the brake's work at the crank: T_b·(gear ratio)·stop angle
    assert scalars["brake.stop_energy"] == pytest.approx(
        scalars["brake.torque"] * 8.0 * scalars["brake.stop_angle"], rel=1e-9)  # the angle in rad
    assert scalars["brake.temperature_rise"] == pytest.approx(scalars["brake.stop_energy"] / (12 * 460), rel=1e-9)
    assert scalars["brake.temperature_rise_steady"] > scalars["brake.temperature_rise"]
    assert scalars["clutch.driven_acceleration"] > 0 and scalars["clutch.driving_deceleration"] > 0
    report = (out / "report.html").read_text()
    assert "drum temperature rise" in report and "clutch: shoes touch the drum at" in report


def test_the_example_rates_its_plate_clutch_and_double_block_brake_by_the_handbook_formulas():
    from machdyn.drivetrain.geometry_tables import rate_brake, rate_clutch
    from machdyn.reading import load_problem

    table = load_problem(EXAMPLE).drivetrain
    rating = rate_clutch(table.clutch.geometry, 100.0)
    assert rating.torque == pytest.approx(clutches.plate_clutch_torque(0.3, 4500.0, 0.08, 0.125, 2), rel=1e-12)
    assert rating.max_pressure == pytest.approx(4500.0 / (2 * math.pi * 0.08 * 0.045), rel=1e-12)
    assert rate_brake(table.brake.geometry).torque == pytest.approx(
        brakes.double_block_brake(0.35, 500.0, 0.15, 0.6, 0.2, 0.03).torque, rel=1e-12)


@pytest.mark.parametrize("changes, path, words", [
    ([("[drivetrain.clutch]\n", '[drivetrain.clutch]\nslip_torque = "250 N*m"\n')],
     "drivetrain", "either clutch.slip_torque or clutch.geometry, not both"),
    ([('[drivetrain.brake]\n', '[drivetrain.brake]\ntorque = "150 N*m"\n')],
     "drivetrain", "either brake.torque or brake.geometry, not both"),
    ([('inner_radius = "80 mm"', 'inner_radius = "130 mm"')],
     "drivetrain.clutch.geometry", "must be smaller than outer_radius"),
    ([('offset = "30 mm"', 'offset = "700 mm"')], "drivetrain.brake.geometry", "locks itself"),
    ([('force = "4.5 kN"', 'force = "0.5 kN"')], "drivetrain.clutch.geometry", "must exceed the largest torque"),
    ([('max_temperature_rise = "100 K"', 'max_temperature_rise = "100 degC"')],
     "drivetrain.brake.heating.max_temperature_rise", "temperature difference"),
])
def test_bad_geometry_is_refused_by_check_and_run_with_its_path(tmp_path, changes, path, words):
    bad = _variant(tmp_path, changes)
    for command in (["check", str(bad)], ["run", str(bad), "--out", str(tmp_path / "o"), "-q"]):
        result = runner.invoke(app, command)
        assert result.exit_code == 2, result.output
        assert path in result.output and words in result.output, result.output
