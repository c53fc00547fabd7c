"""Design sweeps in problem files: every variant analysed in one vectorised call, equal to analysing each
variant's own file; mistakes reported with their paths."""

import re
import subprocess
import sys

import numpy as np
import pytest

from machdyn.errors import ProblemFileError
from machdyn.linkage import crank_angles, kinetostatics
from machdyn.problem import load_problem
from machdyn.problem.build import build_mechanism
from machdyn.runner import run_problem

BASE = """
[meta]
name = "sweep"

[mechanism]
type = "four_bar"
crank = {length = "40 mm", mass = "0.2 kg"}
coupler = {length = "120 mm", mass = "0.5 kg"}
rocker = {length = "80 mm", mass = "0.4 kg"}
ground = {length = "100 mm"}

[drive]
speed = "10 rad/s"
positions = 72

[[loads.torques]]
body = "crank"
torque = "-0.5 N*m"
"""


def _single(text: str, replace: tuple[str, str]) -> float:
    """Peak |driving torque| of one design written out as its own problem file."""
    problem = load_problem(text.replace(*replace))
    forces = kinetostatics(build_mechanism(problem), crank_angles(72), problem.drive.speed)
    return float(np.max(np.abs(forces.driving_torque)))


def test_sweep_of_a_link_length_equals_each_variant_alone():
    text = BASE + '\n[sweep]\nparameter = "mechanism.crank.length"\nvalues = ["30 mm", "35 mm", "40 mm"]\n'
    result = run_problem(load_problem(text))
    frame = result.frames["sweep"]
    assert list(frame["mechanism.crank.length [mm]"]) == pytest.approx([30.0, 35.0, 40.0])
    for i, value in enumerate(("30 mm", "35 mm", "40 mm")):
        expected = _single(BASE, ('"40 mm", mass = "0.2 kg"', f'"{value}", mass = "0.2 kg"'))
        assert frame["max_driving_torque [N*m]"][i] == pytest.approx(expected, rel=1e-12)
    assert result.scalars["sweep.max_driving_torque"]["unit"] == "N*m"
    assert any(row[0].startswith("Sweep: lowest peak driving torque") for row in result.summary_rows)


def test_sweep_of_the_speed_and_of_a_load_item():
    speeds = BASE + '\n[sweep]\nparameter = "drive.speed"\nstart = "60 rpm"\nstop = "120 rpm"\ncount = 3\n'
    frame = run_problem(load_problem(speeds)).frames["sweep"]
    assert list(frame["drive.speed [rpm]"]) == pytest.approx([60.0, 90.0, 120.0])
    for rpm, peak in zip((60, 90, 120), frame["max_driving_torque [N*m]"], strict=True):
        assert peak == pytest.approx(_single(BASE, ('"10 rad/s"', f'"{rpm} rpm"')), rel=1e-12)
    loads = BASE + '\n[sweep]\nparameter = "loads.torques[0].torque"\nvalues = ["-1 N*m", "-2 N*m"]\n'
    frame = run_problem(load_problem(loads)).frames["sweep"]
    # The mean power over a turn is the work of the resisting torque on the shaft: -T * mean speed.
    assert list(frame["mean_input_power [W]"]) == pytest.approx([10.0, 20.0], rel=1e-9)


def test_variants_that_cannot_assemble_are_kept_but_not_regular():
    text = BASE + '\n[sweep]\nparameter = "mechanism.crank.length"\nvalues = ["40 mm", "90 mm"]\n'
    frame = run_problem(load_problem(text)).frames["sweep"]
    assert list(frame["regular"]) == [True, False]
    assert np.isnan(frame["max_driving_torque [N*m]"][1])


@pytest.mark.parametrize(
    ("sweep", "path", "message"),
    [
        ('parameter = "mechanism.crnk.length"\nvalues = ["1 mm"]', "sweep.parameter",
         "'mechanism.crnk.length' is not a quantity of this file: mechanism has no key 'crnk'; "
         "did you mean 'crank'?"),
        ('parameter = "mechanism.crank.length"\nvalues = ["30 mm", "3 kg"]', "sweep.values[1]",
         "must be in units of [length] (like m); got '3 kg', which is [mass] (for mechanism.crank.length)"),
        ('parameter = "mechanism.crank.length"\nvalues = ["-30 mm"]', "sweep.values[0]",
         "must be > 0 m; got '-30 mm' (for mechanism.crank.length)"),
        ('parameter = "loads.torques[3].torque"\nvalues = ["1 N*m"]', "sweep.parameter",
         "'loads.torques[3].torque' refers to item 3 of 'torques', which has 1 item(s)"),
        ('parameter = "drive.start"\nvalues = ["10 deg"]', "sweep.parameter",
         "'drive.start' sets the crank angles, which every variant of a sweep shares"),
    ],
)
def test_sweep_mistakes_name_their_path(sweep, path, message):
    with pytest.raises(ProblemFileError) as info:
        run_problem(load_problem(BASE + "\n[sweep]\n" + sweep + "\n"))
    assert (path, message) in info.value.problems


def test_sweep_needs_values_or_a_range():
    with pytest.raises(ProblemFileError, match=re.escape("give either values = [...] or all of start, stop and count")):
        load_problem(BASE + '\n[sweep]\nparameter = "mechanism.crank.length"\nstart = "1 mm"\n')


def test_cli_writes_the_sweep_table(tmp_path):
    path = tmp_path / "sweep.toml"
    path.write_text(BASE + '\n[sweep]\nparameter = "mechanism.coupler.mass"\nvalues = ["0.5 kg", "1 kg"]\n')
    done = subprocess.run([sys.executable, "-m", "machdyn.cli", "run", str(path), "--out", str(tmp_path / "out"),
                           "--quiet"], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    lines = (tmp_path / "out" / "sweep.csv").read_text().splitlines()
    assert lines[0].startswith("mechanism.coupler.mass [kg],assembled,regular,max_driving_torque [N*m]")
    assert len(lines) == 3
    assert "Design sweep of mechanism.coupler.mass" in (tmp_path / "out" / "report.html").read_text()
