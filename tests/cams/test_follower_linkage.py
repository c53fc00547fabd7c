"""``[follower_linkage]``: a linkage driven by an oscillating follower's arm, on the cam-driven rocker feeder example.

The checks are laws the result must obey, each computed independently of the quantity it checks:

* power balance (Norton, *Design of Machinery*, 5th ed., ch. 11; Uicker, Pennock & Shigley, *Theory of Machines and
  Mechanisms*, 4th ed., ch. 17): the camshaft torque the linkage adds times the cam speed equals the rate of change
  of the linkage's kinetic and potential energy (central differences of the energies over the cam angle) less the
  power of its external loads, at every position;
* a massless linkage without loads takes no torque;
* the output's velocity is the derivative of its position over the cam angle times the cam speed;
* over a turn the camshaft does the work of the linkage's loads: the feed resistance F over the slide's stroke.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

from machdyn.cams.follower_linkage import follower_drive, linkage_load, linkage_mechanism
from machdyn.cams.schema import FollowerLinkageLoads
from machdyn.cams.stage import build
from machdyn.cli import app
from machdyn.problem import dump_problem
from machdyn.reading import load_problem
from machdyn.runner import run_problem

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "cam_rocker_linkage.toml"
runner = CliRunner()


#: a translating follower (the press feeder cam) lifting a slide through a rod: its pitch point is 56.8 mm above the
#: cam centre at rest, 5 mm right of it; the rod's pin 50 mm above the roller, the slide's guide level 120 mm up
TRANSLATING = (ROOT / "examples" / "feeder_cam.toml").read_text() + """
[follower_linkage]
follower_points = { A = ["50 mm", "0 mm"] }
ground = { G = ["150 mm", "120 mm"] }

[[follower_linkage.bodies]]
name = "rod"
points = { A = ["0 mm", "0 mm"], B = ["150 mm", "0 mm"] }
mass = "0.5 kg"
inertia = "0.001 kg*m^2"
com = ["75 mm", "0 mm"]

[[follower_linkage.bodies]]
name = "slide"
points = { B = ["0 mm", "0 mm"] }
mass = "2 kg"

[[follower_linkage.dyads]]
type = "RRP"
a = "rod"
b = "slide"
pin_a = "follower.A"
inner = "B"
guide = { point = "ground.G", angle = "0 deg" }

[[follower_linkage.loads.forces]]
point = "slide.B"
fx = "-80 N"
active = ["0 deg", "110 deg"]
"""


def _setup(table=None, positions=720, text=None):
    problem = load_problem(text if text is not None else EXAMPLE)
    model, problems = build(problem)
    assert problems == []
    table = table or problem.follower_linkage
    mech = linkage_mechanism(table, model.follower, problem.cam.rotation == "cw", model.program)
    phi = np.arange(positions) * (2 * np.pi / positions)
    return problem, model, mech, phi


def _load(problem, model, mech, phi):
    drive = follower_drive(model.program, model.follower, problem.cam.rotation == "cw", phi)
    return linkage_load(mech, drive, float(problem.cam.speed))


def test_the_shipped_copy_of_the_example_is_the_same():
    assert (ROOT / "src" / "machdyn" / "data" / "examples" / EXAMPLE.name).read_text() == EXAMPLE.read_text()


@pytest.mark.parametrize("text", [None, TRANSLATING], ids=["oscillating", "translating"])
def test_camshaft_power_of_the_linkage_is_its_energy_rate_less_its_loads_power_at_every_position(text):
    """T_cam Omega = d(T + V)/dphi Omega - P_loads, the energy derivative by central differences (step 1e-6 rad,
    truncation error ~1e-12 of the terms); tolerance 1e-6 of the peak power, for the differences' rounding."""
    problem, model, mech, phi = _setup(positions=360, text=text)
    omega = float(problem.cam.speed)
    here = _load(problem, model, mech, phi)
    h = 1e-6
    ahead = _load(problem, model, mech, phi + h).energy.total
    behind = _load(problem, model, mech, phi - h).energy.total
    rate = (ahead - behind) / (2 * h) * omega
    power = here.camshaft_torque * omega
    scale = float(np.max(np.abs(power)))
    assert scale > 1.0  # the example's linkage takes a real torque
    np.testing.assert_allclose(power, rate - here.energy.load_power, atol=1e-6 * scale)


@pytest.mark.parametrize("text", [None, TRANSLATING], ids=["oscillating", "translating"])
def test_a_massless_linkage_without_loads_adds_no_camshaft_torque(text):
    problem = load_problem(text if text is not None else EXAMPLE)
    table = problem.follower_linkage
    bare = table.model_copy(update={
        "bodies": [b.model_copy(update={"mass": 0.0, "inertia": 0.0}) for b in table.bodies],
        "loads": FollowerLinkageLoads(gravity="off")})
    problem, model, mech, phi = _setup(bare, text=text)
    load = _load(problem, model, mech, phi)
    assert np.max(np.abs(load.camshaft_torque)) == pytest.approx(0.0, abs=1e-12)
    assert np.max(np.abs(load.moment)) == pytest.approx(0.0, abs=1e-12)


@pytest.mark.parametrize("text", [None, TRANSLATING], ids=["oscillating", "translating"])
def test_the_output_velocity_is_the_derivative_of_its_position_times_the_cam_speed(text):
    """Central differences of the slide's travel over the cam angle (step 1e-6 rad); tolerance 1e-7 of the peak
    velocity. For the translating follower, the rod's pin also moves exactly with the follower: its height is the
    roller's, 56.78 mm + s, plus 50 mm."""
    problem, model, mech, phi = _setup(positions=360, text=text)
    omega = float(problem.cam.speed)
    h = 1e-6

    def travel(angles):
        return _load(problem, model, mech, angles).forces.kinematics.slide("slide")

    here = travel(phi)
    slope = (travel(phi + h).s - travel(phi - h).s) / (2 * h)
    peak = float(np.max(np.abs(here.v)))
    assert peak > 0.01
    np.testing.assert_allclose(here.v, slope * omega, atol=1e-7 * peak)
    if text is not None:
        pin = _load(problem, model, mech, phi).forces.kinematics.point("follower.A")
        s = model.program.svaj(phi).s
        np.testing.assert_allclose(pin.y, np.sqrt(0.057**2 - 0.005**2) + s + 0.05, atol=1e-12)
        np.testing.assert_allclose(pin.x, 0.005, atol=1e-12)


def test_over_a_turn_the_camshaft_does_the_work_of_the_feed_resistance_over_the_stroke():
    """The feed resistance F = 150 N acts over the cam's rise (0-100 deg), the whole forward stroke of the slide;
    gravity and the links' inertia give back what they take. Work of the added camshaft torque per turn =
    F x stroke; the rectangle rule over 720 positions (the power vanishes at the window's edges, in the dwells);
    tolerance 1e-5."""
    problem, model, mech, phi = _setup()
    load = _load(problem, model, mech, phi)
    work = float(np.mean(load.camshaft_torque)) * 2 * np.pi
    slide = load.forces.kinematics.slide("slide").s
    stroke = float(np.ptp(slide))
    assert stroke == pytest.approx(0.052, rel=0.01)  # 2 x 150 mm x sin(10 deg)
    assert work == pytest.approx(150.0 * stroke, rel=1e-5)
    omega = float(problem.cam.speed)
    load_work = float(np.mean(load.energy.load_power)) * 2 * np.pi / omega
    assert work == pytest.approx(-load_work, rel=1e-9)


def test_the_flywheel_sees_the_linkage_reduced_inertia_and_the_work_of_its_loads():
    """The camshaft's reduced machine with the linkage (for [flywheel]) adds J = 2 T / Omega^2 of the linkage
    (its kinetic energy at the running speed), with the slope of central differences of it, and a reduced moment
    whose work per turn is the feed resistance's, -F x stroke (rectangle rule over 360 nodes, tolerance 1e-5)."""
    text = EXAMPLE.read_text().replace("positions = 720", "positions = 360")
    result = run_problem(load_problem(text)).outcomes["follower_linkage"].results
    base = result.cam.machine(360)
    machine = result.added_to(base, 360)
    problem, model, mech, phi = _setup(positions=360)
    omega = float(problem.cam.speed)
    here = _load(problem, model, mech, phi)
    j = 2 * here.energy.kinetic_total / omega**2
    np.testing.assert_allclose(machine.inertia(phi) - base.inertia(phi), j, rtol=1e-9, atol=1e-15)
    h = 1e-6
    ahead = 2 * _load(problem, model, mech, phi + h).energy.kinetic_total / omega**2
    behind = 2 * _load(problem, model, mech, phi - h).energy.kinetic_total / omega**2
    slope = machine.inertia.derivative(phi) - base.inertia.derivative(phi)
    np.testing.assert_allclose(slope, (ahead - behind) / (2 * h), atol=1e-6 * float(np.max(np.abs(slope))))
    work = float(np.mean(machine.position_moment(phi) - base.position_moment(phi))) * 2 * np.pi
    stroke = float(np.ptp(here.forces.kinematics.slide("slide").s))
    assert work == pytest.approx(-150.0 * stroke, rel=1e-5)


def test_a_clockwise_cam_with_the_mirrored_linkage_takes_the_same_torque():
    """A clockwise cam is the mirror image of the counter-clockwise one about the y axis (the follower's pivot at
    (-120 mm, 0)); the linkage mirrored with it (its points' y in the arm's frame, the guide and the load's x
    reversed) moves the same way and, gravity along -y being symmetric, takes the same camshaft torque."""
    text = EXAMPLE.read_text()
    for a, b in (('rotation = "ccw"', 'rotation = "cw"'), ('"-109.7 mm"', '"109.7 mm"'),
                 ('G = ["370 mm"', 'G = ["-370 mm"'), ('angle = "0 deg" }', 'angle = "180 deg" }'),
                 ('fx = "-150 N"', 'fx = "150 N"')):
        assert a in text
        text = text.replace(a, b)
    mirrored = _load(*_setup(text=text))
    original = _load(*_setup())
    scale = float(np.max(np.abs(original.camshaft_torque)))
    np.testing.assert_allclose(mirrored.camshaft_torque, original.camshaft_torque, atol=1e-12 * scale)
    np.testing.assert_allclose(mirrored.forces.kinematics.point("slide.B").x,
                               -original.forces.kinematics.point("slide.B").x, atol=1e-12)


def test_the_translating_follower_runs_from_the_command_line(tmp_path):
    path = tmp_path / "translating.toml"
    path.write_text(TRANSLATING)
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(path), "--out", str(out), "-q"])
    assert result.exit_code in (0, 3), result.output
    scalars = json.loads((out / "results.json").read_text())["scalars"]
    assert scalars["follower_linkage.camshaft_torque.max"]["value"] > 0
    # the follower's load at the roller is a force along its path: the linkage's part of the contact force
    forces = pd.read_csv(out / "cam_forces.csv")
    series = pd.read_csv(out / "follower_linkage.csv")
    np.testing.assert_allclose(series["contact_force [N]"],
                               forces["contact_force [N]"] + series["follower_load [N]"], atol=1e-9)


def _variant(tmp_path: Path, old: str, new: str) -> Path:
    """The example with ``old`` replaced by ``new`` (several pairs separated by '|', each replaced once)."""
    text = EXAMPLE.read_text()
    for a, b in zip(old.split("|"), new.split("|"), strict=True):
        assert a in text
        text = text.replace(a, b, 1)
    path = tmp_path / "variant.toml"
    path.write_text(text)
    return path


@pytest.mark.parametrize("old, new, field", [
    ('a = "rod"', 'a = "rdo"', "follower_linkage.dyads[0].a"),
    ('point = "slide.B"', 'point = "slider.B"', "follower_linkage.loads.forces[0].point"),
    ('output = "slide"', 'output = "ram"', "follower_linkage.output"),
    # the guide 248 mm above the pin's mid position: the 250 mm rod reaches it only near mid-swing
    ('G = ["370 mm", "150 mm"]', 'G = ["370 mm", "398 mm"]', "follower_linkage.dyads"),
    ('name = "slide"', 'name = "follower"', "follower_linkage.bodies[1].name"),
    ('G = ["370 mm", "150 mm"] }', 'G = ["370 mm", "150 mm"], pivot = ["0 mm", "0 mm"] }',
     "follower_linkage.ground.pivot"),
])
def test_a_bad_table_is_refused_by_check_and_run_naming_the_field(tmp_path, old, new, field):
    path = _variant(tmp_path, old, new)
    checked = runner.invoke(app, ["check", str(path)])
    ran = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "o"), "-q"])
    assert checked.exit_code == 2, checked.output
    assert ran.exit_code == 2, ran.output
    assert field in checked.output and field in ran.output
    assert "Traceback" not in ran.output


def test_the_linkage_that_cannot_close_is_named_with_the_cam_angles(tmp_path):
    path = _variant(tmp_path, 'G = ["370 mm", "150 mm"]', 'G = ["370 mm", "398 mm"]')
    checked = runner.invoke(app, ["check", str(path)])
    assert "cannot be assembled at cam angles" in checked.output


def test_the_example_runs_from_the_command_line(tmp_path):
    """The camshaft's mean power with the linkage is the feed resistance's work per turn times the turns per
    second, F x stroke x n; the flywheel stage sees the same machine (its drive's mean power, from the steady
    state at the real speed, agrees to 1 %)."""
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(EXAMPLE), "--out", str(out), "-q"])
    assert result.exit_code == 0, result.output
    scalars = json.loads((out / "results.json").read_text())["scalars"]
    for key in ("follower_linkage.camshaft_torque.max", "follower_linkage.output_stroke", "follower_linkage.jump_speed",
                "follower_linkage.joint_force.max", "follower_linkage.follower_load.max"):
        assert key in scalars, key
    stroke = scalars["follower_linkage.output_stroke"]["value"]  # m
    assert scalars["follower_linkage.mean_power"]["value"] == pytest.approx(150.0 * stroke * 2.0, rel=1e-4)
    assert scalars["flywheel.mean_power"]["value"] == pytest.approx(
        scalars["follower_linkage.mean_power"]["value"], rel=0.01)
    assert scalars["follower_linkage.camshaft_torque.max"]["value"] > scalars["cam.peak_torque"]["value"]
    series = pd.read_csv(out / "follower_linkage.csv")
    np.testing.assert_allclose(series["camshaft_torque [N*m]"],
                               series["cam_torque [N*m]"] + series["linkage_torque [N*m]"], atol=1e-9)
    assert "Camshaft torque with the linkage" in (out / "report.html").read_text()


def test_an_output_that_turns_reports_its_swing_in_degrees(tmp_path):
    """With the rod as the output, output_stroke is its swing: the range of its angle over the turn."""
    path = _variant(tmp_path, 'output = "slide"', 'output = "rod"')
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(path), "--out", str(out), "-q"])
    assert result.exit_code == 0, result.output
    swing = json.loads((out / "results.json").read_text())["scalars"]["follower_linkage.output_stroke"]
    assert swing["unit"] == "rad" and swing["shown"]["unit"] == "deg"
    problem, model, mech, phi = _setup()
    angle = _load(problem, model, mech, phi).forces.kinematics.body("rod").angle
    assert swing["value"] == pytest.approx(np.ptp(np.unwrap(angle)), rel=1e-9)
    assert swing["shown"]["value"] == pytest.approx(np.degrees(swing["value"]), rel=1e-12)
    assert 0.0 < swing["shown"]["value"] < 20.0  # less than the arm's swing: the rod stays nearly along the guide


def test_a_spring_too_weak_for_the_linkage_fails_the_design_with_exit_3(tmp_path):
    path = _variant(tmp_path, 'preload = "130 N"', 'preload = "60 N"')
    result = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "o"), "-q"])
    assert result.exit_code == 3, result.output
    assert "follower jump with the linkage" in result.output


def test_the_example_round_trips_through_the_dumper():
    problem = load_problem(EXAMPLE)
    assert load_problem(dump_problem(problem)) == problem
