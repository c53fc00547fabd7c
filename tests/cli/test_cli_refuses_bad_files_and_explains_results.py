"""The command line with broken files and abuse (each refused plainly, with the field named), and the results a
new user misread until they were named apart (time ratio, inertial shaking force, a rocker through 180 deg)."""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from machdyn.cli import EXIT_BAD_INPUT, EXIT_OK, app

ROOT = Path(__file__).resolve().parents[2]
FOUR_BAR = (ROOT / "examples" / "four_bar.toml").read_text(encoding="utf-8")
SLIDER = (ROOT / "examples" / "slider_crank.toml").read_text(encoding="utf-8")


@pytest.fixture
def runner():
    return CliRunner()


def _file(tmp_path: Path, text: str, name: str = "p.toml") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def _both(runner, path: Path, tmp_path: Path):
    return (runner.invoke(app, ["check", str(path)]),
            runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "out"), "-q"]))


def test_a_change_point_four_bar_is_bad_input_for_check_and_run(runner, tmp_path):
    """Crank 40, coupler 120, rocker 100, ground 60 mm: s + l = p + q, the links fall in line at 0 deg."""
    path = _file(tmp_path, FOUR_BAR.replace('length = "130 mm"', 'length = "60 mm"'))
    for result in _both(runner, path, tmp_path):
        assert result.exit_code == EXIT_BAD_INPUT, result.output
        assert "Traceback" not in result.output and "dead (toggle)" in result.stderr and "0.00°" in result.stderr
    assert not (tmp_path / "out").exists()


def test_a_quantity_repeated_a_thousand_times_is_refused_plainly(runner, tmp_path):
    path = _file(tmp_path, FOUR_BAR.replace('speed = "120 rpm"', 'speed = "120' + " rpm" * 1000 + '"'))
    result = runner.invoke(app, ["check", str(path)])
    assert result.exit_code == EXIT_BAD_INPUT and "drive.speed" in result.stderr
    assert "recursion" not in result.stderr and "characters" in result.stderr


@pytest.mark.parametrize("positions", [2, 3, 7])
def test_too_few_positions_are_refused(runner, tmp_path, positions):
    path = _file(tmp_path, FOUR_BAR.replace("positions = 360", f"positions = {positions}"))
    for result in _both(runner, path, tmp_path):
        assert result.exit_code == EXIT_BAD_INPUT and "drive.positions: must be >= 8" in result.stderr


@pytest.mark.parametrize(("old", "new", "field"), [
    ('speed = "120 rpm"', 'speed = "1e300 rpm"', "drive.speed"),
    ('length = "40 mm"', 'length = "1e300 mm"', "mechanism.crank.length"),
])
def test_huge_values_are_refused_before_they_overflow(runner, tmp_path, old, new, field):
    path = _file(tmp_path, FOUR_BAR.replace(old, new))
    for result in _both(runner, path, tmp_path):
        assert result.exit_code == EXIT_BAD_INPUT and field in result.stderr and "at most 1e+12" in result.stderr


def test_huge_torque_and_stiffness_and_slide_angle_are_refused(runner, tmp_path):
    text = re.sub(r'torque = "[^"]*"', 'torque = "1e300 N*m"', FOUR_BAR, count=1)
    text = re.sub(r'stiffness = "[^"]*"', 'stiffness = "1e300 N/m"', text, count=1)
    result = runner.invoke(app, ["check", str(_file(tmp_path, text))])
    assert result.exit_code == EXIT_BAD_INPUT
    assert "loads.torques[0]" in result.stderr and "loads.springs[0].stiffness" in result.stderr
    assert "RuntimeWarning" not in result.output and "inf" not in result.stdout
    slide = _file(tmp_path, re.sub(r'slide_angle = "[^"]*"', 'slide_angle = "1e300 deg"', SLIDER), "s.toml")
    result = runner.invoke(app, ["check", str(slide)])
    assert result.exit_code == EXIT_BAD_INPUT and "mechanism.slide_angle" in result.stderr


def test_an_invisible_character_in_a_quantity_is_refused(runner, tmp_path):
    path = _file(tmp_path, FOUR_BAR.replace('length = "40 mm"', 'length = "4\u202e0 mm"'))
    result = runner.invoke(app, ["check", str(path)])
    assert result.exit_code == EXIT_BAD_INPUT
    assert "U+202E" in result.stderr and "mechanism.crank.length" in result.stderr


def test_gravity_errors_name_the_field_without_validator_internals(runner, tmp_path):
    text = re.sub(r"\ngravity = [^\n]*", "", FOUR_BAR).replace("[loads]", '[loads]\ngravity = ["1 m", "2 m"]')
    result = runner.invoke(app, ["check", str(_file(tmp_path, text))])
    assert result.exit_code == EXIT_BAD_INPUT and "loads.gravity[0]: must be in units of" in result.stderr
    assert "function-before" not in result.stderr and "literal[" not in result.stderr


def test_the_harmonics_plot_shows_the_orders_asked_for(runner, tmp_path):
    text = re.sub(r"harmonics = \d+", "harmonics = 3", FOUR_BAR)
    result = runner.invoke(app, ["run", str(_file(tmp_path, text)), "--out", str(tmp_path / "o"), "-q"])
    assert result.exit_code == EXIT_OK, result.output
    html = (tmp_path / "o" / "report.html").read_text(encoding="utf-8")
    assert "orders 1 to 3" in html
    scalars = json.loads((tmp_path / "o" / "results.json").read_text())["scalars"]
    assert "driving_torque.harmonic_3.amplitude" in scalars and "driving_torque.harmonic_4.amplitude" not in scalars


def test_the_time_ratio_has_one_name(runner, tmp_path):
    result = runner.invoke(app, ["run", str(_file(tmp_path, FOUR_BAR)), "--out", str(tmp_path / "o"), "-q"])
    assert result.exit_code == EXIT_OK
    html = (tmp_path / "o" / "report.html").read_text(encoding="utf-8")
    names = set(re.findall(r"Time ratio[^<]*", html))
    assert names == {"Time ratio (the longer over the shorter stroke time, &gt;= 1)"}, names


def test_a_sweep_whose_designs_tie_says_so(runner, tmp_path):
    """Sweeping the name of the file changes nothing: every variant ties, and the summary says how many."""
    text = FOUR_BAR + '\n[sweep]\nparameter = "mechanism.crank.mass"\nvalues = ["0.25 kg", "0.25 kg", "0.25 kg"]\n'
    result = runner.invoke(app, ["run", str(_file(tmp_path, text)), "--out", str(tmp_path / "o"),
                                 "--format", "json"])
    assert result.exit_code == EXIT_OK, result.output
    rows = {r["key"]: r for r in json.loads(result.stdout)["summary"]}
    assert "3 designs tie" in rows["sweep.lowest_driving_torque.max_abs"]["quantity"]


def test_a_rocker_through_180_deg_is_plotted_without_a_jump():
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    from machdyn.linkage import analyse, crank_angles, four_bar
    from machdyn.report import plots

    # ground at 60 deg: the rocker swings through 180 deg, where atan2 wraps
    mech = four_bar(crank=0.04, coupler=0.12, rocker=0.08, ground=0.10, ground_angle=np.radians(60.0))
    result = analyse(mech, crank_angles(360), 10.0)
    raw = np.degrees(np.asarray(result.kinematics.body("rocker").angle))
    assert np.max(np.abs(np.diff(raw))) > 180, "the test needs a rocker that wraps"
    ax = Figure().add_subplot()
    plots.plot_point_motion(ax, result.kinematics, "rocker")
    drawn = ax.get_lines()[0].get_ydata()
    assert np.max(np.abs(np.diff(drawn))) < 10


def test_a_load_that_drives_the_machine_is_warned_about():
    """A process force acting over half a turn does net work; the sign that helps the motion is warned about,
    the sign that resists it is not. (A constant force does no net work over a closed cycle: no warning.)"""
    from machdyn.runner import run_problem

    def run(fy: str):
        text = FOUR_BAR + ('\n[[loads.forces]]\nname = "process"\npoint = "coupler.P"\nfx = "0 N"\n'
                           f'fy = "{fy}"\nactive = ["0 deg", "180 deg"]\n')
        result = run_problem(text)
        warned = any("'process' does positive work" in w for w in result.warnings)
        return result.results["load.process.mean_power"], warned

    (down, warned_down), (up, warned_up) = run("-50 N"), run("50 N")
    assert down == pytest.approx(-up, rel=1e-9) and abs(down) > 0.1
    assert warned_down == (down > 0) and warned_up == (up > 0) and warned_down != warned_up
    constant = run_problem(FOUR_BAR + '\n[[loads.forces]]\nname = "weight"\npoint = "coupler.P"\nfy = "-50 N"\n')
    assert not any("'weight' does positive work" in w for w in constant.warnings)


def test_the_rotary_screen_names_its_joints_as_the_paper_does():
    """Seed 002, fig 2: A is the crank centre, B the crank-rod joint, C the rod-slider joint."""
    from machdyn.runner import run_problem

    rows = {r.key: r.label for r in run_problem(ROOT / "examples" / "rotary_screen.toml").summary.rows}
    assert rows["joint.O.max_force"].startswith("Joint A, the crank centre")
    assert rows["joint.A.max_force"].startswith("Joint B, crank to rod")
    assert rows["joint.B.max_force"].startswith("Joint C, rod to slider")


def test_energy_fluctuation_over_two_turns_and_a_note_for_a_partial_range():
    """A 720 deg cycle (a four-stroke engine's) keeps its flywheel figure; a partial range says why it has none."""
    from machdyn.runner import run_problem

    two = FOUR_BAR.replace("positions = 360", 'positions = 721\nstart = "0 deg"\nstop = "720 deg"')
    one = run_problem(FOUR_BAR).results["flywheel.energy_fluctuation"]
    assert run_problem(two).results["flywheel.energy_fluctuation"] == pytest.approx(one, rel=1e-4)
    part = run_problem(FOUR_BAR.replace("positions = 360", 'positions = 91\nstart = "0 deg"\nstop = "90 deg"'))
    assert "flywheel.energy_fluctuation" not in part.results
    assert any(w.startswith("No energy fluctuation for a flywheel") for w in part.warnings)


def test_inertial_shaking_force_is_told_apart_from_the_frame_load():
    """A four-bar carrying a process force and its weight: the frame load is not the inertial shaking force."""
    from machdyn.linkage import mass_centre
    from machdyn.runner import run_problem

    result = run_problem(FOUR_BAR + '\n[[loads.forces]]\nname = "process"\npoint = "coupler.P"\nfy = "-50 N"\n'
                                    'active = ["0 deg", "180 deg"]\n')
    rows = {r.key: r for r in result.summary.rows}
    inertial, frame = rows["inertial_shaking_force.max"], rows["frame_force.max"]
    assert "inertial" in inertial.label and "Frame force" in frame.label
    ix, iy = mass_centre(result.analysis.kinematics).inertia_force
    # the run's peak is the closed form's, between the samples: at least the largest sample, within a step of it
    sampled = float(np.max(np.hypot(ix, iy)))
    assert sampled * (1 - 1e-12) <= inertial.value == pytest.approx(sampled, rel=1e-4)
    assert abs(frame.value - inertial.value) > 1e-3 * frame.value


def test_check_reads_a_record_named_relative_to_the_problem_file(runner, tmp_path):
    """check and run agree on a [signals] record given by a relative path: both read it, both refuse it if
    it is missing, naming the field."""
    import shutil

    text = (ROOT / "examples" / "vibration_record.toml").read_text(encoding="utf-8")
    records = re.findall(r'"machdyn:(examples/signals/[^"]+)"', text)
    assert records, "the example names shipped records"
    for name in records:
        shutil.copy(ROOT / name, tmp_path / Path(name).name)
        text = text.replace(f'"machdyn:{name}"', f'"{Path(name).name}"')
    good = _file(tmp_path, text, "relative.toml")
    assert runner.invoke(app, ["check", str(good)]).exit_code == EXIT_OK
    (tmp_path / Path(records[0]).name).unlink()
    for result in _both(runner, good, tmp_path):
        assert result.exit_code == EXIT_BAD_INPUT and "signals." in result.stderr, result.output
