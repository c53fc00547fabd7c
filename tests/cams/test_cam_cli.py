"""The ``[cam]`` problem kind through the command line: the feeder example's results, CSV series and DXF, bad
input (exit 2) named by its field with ``check`` and ``run`` agreeing, and a failed design check (exit 3)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

from machdyn.cams.dxf import read_polylines
from machdyn.cli import app

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "feeder_cam.toml"
runner = CliRunner()


def _variant(tmp_path: Path, old: str, new: str) -> Path:
    """The example with ``old`` replaced by ``new`` (several pairs separated by '|')."""
    text = EXAMPLE.read_text()
    for a, b in zip(old.split("|"), new.split("|"), strict=True):
        assert a in text
        text = text.replace(a, b, 1)
    path = tmp_path / "variant.toml"
    path.write_text(text)
    return path


def test_the_shipped_copy_of_the_example_is_the_same():
    assert (ROOT / "src" / "machdyn" / "data" / "examples" / "feeder_cam.toml").read_text() == EXAMPLE.read_text()


def test_the_feeder_cam_runs_with_its_results_series_dxf_and_report(tmp_path):
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(EXAMPLE), "--out", str(out), "-q"])
    assert result.exit_code == 0, result.output
    scalars = json.loads((out / "results.json").read_text())["scalars"]
    for key in ("cam.max_pressure_angle", "cam.min_pitch_curvature_radius", "cam.min_base_radius_pressure",
                "cam.spring_rate", "cam.jump_speed", "cam.min_contact_force", "cam.peak_torque",
                "cam.work_per_cycle", "cam.simulated_max_separation"):
        assert key in scalars, key
    assert scalars["cam.jump_speed"]["unit"] == "rad/s" and scalars["cam.jump_speed"]["shown"]["unit"] == "rpm"
    assert scalars["cam.jump_speed"]["value"] == pytest.approx(250.0 * np.pi / 30, rel=1e-4)  # 200 rpm x 1.25
    assert scalars["cam.jump_speed"]["shown"]["value"] == pytest.approx(250.0, rel=1e-4)
    assert scalars["cam.min_contact_force"]["value"] > 0
    # the work of the camshaft torque over a turn is the damper's loss, c omega * integral v^2 dtheta
    svaj = pd.read_csv(out / "cam_svaj.csv")
    omega = 200 * np.pi / 30
    loss = 15.0 * omega * float(np.mean(svaj["v [m/rad]"] ** 2)) * 2 * np.pi
    assert scalars["cam.work_per_cycle"]["value"] == pytest.approx(loss, rel=1e-6)
    prof = pd.read_csv(out / "cam_profile.csv")
    dxf = read_polylines((out / "cam_profile.dxf").read_text())
    assert set(dxf) == {"CAM", "PITCH", "CUTTER"}
    np.testing.assert_allclose(dxf["CAM"][0], prof["surface_x [m]"] * 1e3, atol=1e-6)
    np.testing.assert_allclose(dxf["CAM"][1], prof["surface_y [m]"] * 1e3, atol=1e-6)
    forces = pd.read_csv(out / "cam_forces.csv")
    assert {"contact_force [N]", "camshaft_torque [N*m]"} <= set(forces.columns)
    html = (out / "report.html").read_text()
    assert "Cam profile and pressure angle" in html and "Contact force and camshaft torque" in html


@pytest.mark.parametrize("old, new, field", [
    ('angle = "70 deg"', 'angle = "70 deg"\nstart = "100 deg"', "cam.segments[1].start"),
    ('angle = "60 deg"', 'angle = "50 deg"', "cam.segments"),
    # a 30 mm rise in 30 deg: the pitch curve's nose is sharper than the 12 mm roller (undercut)
    ('angle = "110 deg"|angle = "70 deg"', 'angle = "30 deg"|angle = "150 deg"', "cam.follower.roller_radius"),
    ('offset = "5 mm"', 'offset = "70 mm"', "cam.base_radius"),
    ('lift = "30 mm"\nlaw = "poly345"', 'lift = "25 mm"\nlaw = "poly345"', "cam.segments"),
    ('law = "cycloidal"', 'law = "bezier"', "cam.segments[0].law"),
    ('load = "20 N"', 'load = "-50 N"', "cam.spring.preload"),  # pulls harder than the preload at rest
])
def test_bad_input_exits_2_naming_the_field_and_check_agrees(tmp_path, old, new, field):
    path = _variant(tmp_path, old, new)
    ran = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "o"), "-q"])
    checked = runner.invoke(app, ["check", str(path)])
    assert ran.exit_code == 2, ran.output
    assert checked.exit_code == 2, checked.output
    assert field in ran.output and field in checked.output
    assert "Traceback" not in ran.output


def test_a_pressure_angle_over_its_limit_fails_the_design_with_exit_3(tmp_path):
    path = _variant(tmp_path, 'pressure_angle_limit = "30 deg"', 'pressure_angle_limit = "15 deg"')
    result = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "o"), "-q"])
    assert result.exit_code == 3, result.output
    assert "pressure angle" in result.output


def test_a_given_spring_too_weak_for_the_margin_fails_with_exit_3(tmp_path):
    path = _variant(tmp_path, 'preload = "40 N"', 'preload = "40 N"\nrate = "0.5 N/mm"')
    result = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "o"), "-q"])
    assert result.exit_code == 3, result.output
    assert "follower jump" in result.output


def test_the_example_round_trips_through_the_dumper():
    from machdyn.problem import dump_problem
    from machdyn.reading import load_problem

    problem = load_problem(EXAMPLE)
    assert load_problem(dump_problem(problem)) == problem


FLYWHEEL = '\n[flywheel]\ndelta = 0.02\nstart_up = false\n[flywheel.motor]\nkind = "constant_torque"\n'


def test_the_cam_machine_sizes_its_flywheel_from_its_reduced_inertia_and_moment(tmp_path):
    """The camshaft as the crank of [flywheel]: the simulated speed fluctuation meets the target, and the drive's
    mean power is the damper's loss (the spring and the follower's inertia give back what they take)."""
    path = tmp_path / "with_flywheel.toml"
    path.write_text(EXAMPLE.read_text() + FLYWHEEL)
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(path), "--out", str(out), "-q"])
    assert result.exit_code == 0, result.output
    scalars = json.loads((out / "results.json").read_text())["scalars"]
    assert scalars["flywheel.delta"]["value"] == pytest.approx(0.02, rel=0.05)
    assert scalars["flywheel.mean_power"]["value"] == pytest.approx(scalars["cam.mean_power"]["value"], rel=0.02)
    cycle = pd.read_csv(out / "flywheel_cycle.csv")
    svaj = pd.read_csv(out / "cam_svaj.csv")
    crank = next(c for c in cycle.columns if c.startswith("crank_angle"))
    cam = next(c for c in svaj.columns if c.startswith("cam_angle"))
    assert crank.split("[")[1] == cam.split("[")[1], "both angles in the same unit"
    j = np.interp(cycle[crank], svaj[cam], 0.004 + 4.0 * svaj["v [m/rad]"] ** 2)
    np.testing.assert_allclose(cycle["reduced_inertia [kg*m^2]"], j, rtol=2e-3)
    assert "Flywheel and drive" in (out / "report.html").read_text()


def test_a_flywheel_without_the_follower_train_is_refused(tmp_path):
    text = EXAMPLE.read_text() + FLYWHEEL
    text = text.replace('[cam.dynamics]\nmass = "4 kg"\ndamping = "15 N*s/m"\nload = "20 N"\n'
                        'cam_inertia = "0.004 kg*m^2"\n\n[cam.spring]\npreload = "40 N"\nmargin = 0.25\n', "")
    path = tmp_path / "no_train.toml"
    path.write_text(text)
    for args in (["check", str(path)], ["run", str(path), "--out", str(tmp_path / "o"), "-q"]):
        result = runner.invoke(app, args)
        assert result.exit_code == 2, result.output
        assert "flywheel" in result.output and "[cam.dynamics]" in result.output


def test_the_flat_faced_valve_cam_sizes_its_spring_and_checks_its_face(tmp_path):
    valve = ROOT / "examples" / "valve_cam_flat.toml"
    assert (ROOT / "src" / "machdyn" / "data" / "examples" / "valve_cam_flat.toml").read_text() == valve.read_text()
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(valve), "--out", str(out), "-q"])
    assert result.exit_code == 0, result.output
    scalars = json.loads((out / "results.json").read_text())["scalars"]
    assert scalars["cam.jump_speed"]["value"] == pytest.approx(3600.0 * np.pi / 30, rel=1e-4)  # 3000 rpm x 1.2
    assert scalars["cam.max_pressure_angle"]["value"] == 0.0
    svaj = pd.read_csv(out / "cam_svaj.csv")
    span = float(svaj["v [m/rad]"].max() - svaj["v [m/rad]"].min())
    assert scalars["cam.face_width"]["value"] == pytest.approx(span + 0.002, rel=1e-9)  # m
    narrow = tmp_path / "narrow.toml"
    narrow.write_text(valve.read_text().replace('face_width = "30 mm"', 'face_width = "16 mm"'))
    failed = runner.invoke(app, ["run", str(narrow), "--out", str(tmp_path / "o2"), "-q"])
    assert failed.exit_code == 3 and "too narrow" in failed.output


OSCILLATING = """[meta]
name = "Oscillating follower cam"
[cam]
speed = "120 rpm"
base_radius = "40 mm"
[cam.follower]
motion = "oscillating"
contact = "roller"
roller_radius = "10 mm"
pivot_distance = "120 mm"
arm_length = "90 mm"
[[cam.segments]]
motion = "rise"
angle = "90 deg"
swing = "15 deg"
law = "cycloidal"
[[cam.segments]]
motion = "dwell"
angle = "90 deg"
[[cam.segments]]
motion = "return"
angle = "90 deg"
swing = "15 deg"
law = "poly345"
[[cam.segments]]
motion = "dwell"
angle = "90 deg"
[cam.dynamics]
mass = "1.5 kg"
[cam.spring]
preload = "30 N"
"""


def test_an_oscillating_follower_reports_angles_and_its_pressure_limit(tmp_path):
    """Swing in degrees, the default 35 deg limit for an oscillating follower (failed here: exit 3), met with a
    larger base circle; the follower's contact force is reduced to the roller (the spring's moment / arm)."""
    path = tmp_path / "oscillating.toml"
    path.write_text(OSCILLATING)
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(path), "--out", str(out), "-q"])
    assert result.exit_code == 3, result.output
    assert "exceeds the limit 35 deg" in result.output
    scalars = json.loads((out / "results.json").read_text())["scalars"]
    assert scalars["cam.stroke"] == {"value": pytest.approx(np.radians(15.0)), "unit": "rad",
                                     "shown": {"value": pytest.approx(15.0), "unit": "deg"}}
    bigger = scalars["cam.min_base_radius_pressure"]["value"]  # m
    path.write_text(OSCILLATING.replace('base_radius = "40 mm"', f'base_radius = "{bigger * 1.001:.9f} m"'))
    again = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "o2"), "-q"])
    assert again.exit_code == 0, again.output
    forces = pd.read_csv(tmp_path / "o2" / "cam_forces.csv")
    assert float(forces["spring_force [N]"].min()) == pytest.approx(30.0)  # the preload at the roller
