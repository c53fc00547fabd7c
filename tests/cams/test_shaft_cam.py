"""A cam on the crank shaft of a linkage file (``[shaft_cam]``): one shaft, one driving torque (the cam's torque
adds to the linkage's), the flywheel sized for both (the cam's reduced inertia adds to the linkage's), bad input
named by its field in ``check`` and ``run`` alike."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from machdyn.cli import app

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "crank_press_feeder.toml"
runner = CliRunner()


@pytest.fixture(scope="module")
def run():
    """The feeder press with the flywheel and motor tables of crank_press.toml added."""
    from machdyn.runner import run_problem

    press = (ROOT / "examples" / "crank_press.toml").read_text()
    flywheel = press[press.index("[flywheel]"):]
    return run_problem(EXAMPLE.read_text() + "\n" + flywheel)


def test_the_shaft_carries_the_sum_of_the_linkage_and_cam_torques(run):
    from machdyn.cams.dynamics import cam_forces

    frames = run.frames
    shaft = frames["shaft_torque"]
    linkage = np.ravel(run.analysis.forces.driving_torque)
    np.testing.assert_allclose(shaft["linkage_torque [N*m]"], linkage, rtol=1e-12)
    r = run.outcomes["shaft_cam"].results
    phi = np.ravel(run.analysis.kinematics.crank_angle)
    cam = cam_forces(r.model.program, r.model.train, r.spring, r.speed, phi + np.radians(-20.0)).torque
    np.testing.assert_allclose(shaft["total_torque [N*m]"], linkage + cam, rtol=1e-12, atol=1e-12)
    assert run.results["shaft_cam.combined_peak_torque"] == pytest.approx(float(np.max(np.abs(linkage + cam))))


def test_the_flywheel_sees_the_cams_reduced_inertia_added_to_the_linkages(run):
    from machdyn.dynamics.equivalent import equivalent_machine

    machine = run.outcomes["flywheel"].results.machine
    alone = equivalent_machine(run.mechanism, 720)
    r = run.outcomes["shaft_cam"].results
    phi = np.linspace(0.0, 2 * np.pi, 97)[:-1]
    v = r.model.program.svaj(phi + np.radians(-20.0)).v
    added = np.ravel(machine.inertia(phi)) - np.ravel(alone.inertia(phi))
    np.testing.assert_allclose(added, 15.0 * v**2, atol=1e-6 * float(np.max(np.ravel(alone.inertia(phi)))))


def _variant(tmp_path: Path, old: str, new: str) -> Path:
    text = EXAMPLE.read_text()
    assert old in text
    path = tmp_path / "variant.toml"
    path.write_text(text.replace(old, new, 1))
    return path


@pytest.mark.parametrize("old, new, field", [
    ('[shaft_cam.dynamics]\nmass = "15 kg"', '[shaft_cam.notes]\nmass = "15 kg"', "shaft_cam"),
    ('angle = "50 deg"', 'angle = "50 deg"\nstart = "120 deg"', "shaft_cam.segments[1].start"),
    ('roller_radius = "15 mm"', 'roller_radius = "15 mm"\noffset = "90 mm"', "shaft_cam.base_radius"),
])
def test_bad_shaft_cam_input_exits_2_naming_the_field(tmp_path, old, new, field):
    path = _variant(tmp_path, old, new)
    checked = runner.invoke(app, ["check", str(path)])
    assert checked.exit_code == 2, checked.output
    assert field in checked.output
    ran = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "o"), "-q"])
    assert ran.exit_code == 2, ran.output
    assert field in ran.output and "Traceback" not in ran.output


def test_the_shipped_copy_is_the_same():
    shipped = ROOT / "src" / "machdyn" / "data" / "examples" / "crank_press_feeder.toml"
    assert shipped.read_text() == EXAMPLE.read_text()
