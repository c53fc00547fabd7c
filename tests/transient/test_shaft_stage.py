"""[transient] in a shaft-line file: the compressor example from its problem file through the command line, its
results in the catalogue, and the mistakes check and run refuse alike."""

import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.errors import ProblemFileError
from machdyn.kinds import catalogue
from machdyn.results.catalogue import find
from machdyn.runner import check_problem, run_problem

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "shaft_compressor_run_up.toml"


def _text(**changes) -> str:
    text = EXAMPLE.read_text(encoding="utf-8")
    for key, value in changes.items():
        text, count = re.subn(rf"(?m)^{key} = .*$", f"{key} = {value}", text)
        assert count, key
    return text


#: a shorter run of the example: up through every mode in 1.1 s, then braked harder to rest
SHORT = {"duration": '"2.2 s"', "switch_off": '"1.1 s"', "brake_time": '"1.1 s"', "brake_torque": '"30 N*m"'}


@pytest.fixture(scope="module")
def compressor():
    return run_problem(_text(**SHORT))


def test_the_command_line_checks_the_example_and_refuses_a_mistake_with_exit_2(tmp_path):
    runner = CliRunner()
    done = runner.invoke(app, ["check", str(EXAMPLE)])
    assert done.exit_code == 0, done.output
    wrong = tmp_path / "wrong.toml"
    wrong.write_text(_text(point='"tail"'), encoding="utf-8")
    done = runner.invoke(app, ["run", str(wrong), "--out", str(tmp_path / "out")])
    assert done.exit_code == 2 and "transient.point" in done.output


def test_the_compressor_runs_up_through_its_mounts_resonances_and_stops(compressor):
    scalars = compressor.results_json()["scalars"]
    assert not compressor.failed_checks
    hz = sorted(v["value"] for k, v in scalars.items() if k.startswith("shaft.frame.mode"))
    crossings = [k for k in scalars if re.fullmatch(r"transient\.passage_\d+\.time", k)]
    assert len(crossings) >= 2 * len(hz) - 1  # each mode passed on the way up and (but the one it stops in) down
    assert scalars["transient.energy_error"]["value"] < 1e-6
    assert scalars["transient.stop_time"]["value"] < 2.2
    # a peak force for every mount; the largest is the run's peak
    peaks = {k: v["value"] for k, v in scalars.items() if re.fullmatch(r"transient\.mount\..+\.peak_force", k)}
    assert len(peaks) == 7
    assert max(peaks.values()) == pytest.approx(scalars["transient.peak_mount_force"]["value"])
    assert scalars["transient.peak_rotation"]["value"] > 0
    outcome = compressor.outcomes["transient"]
    assert {"frame_x", "frame_rz", "mount_force_axial_z", "displacement_head"} <= set(outcome.series["transient"])
    entries = catalogue()
    for key in scalars:  # every result has one name in the catalogue (for sweeps and the optimiser)
        assert find(key, entries) is not None, key


def test_check_and_run_refuse_a_shaft_line_without_motor_or_frame():
    no_motor = re.sub(r"(?ms)^\[transient\.drive\.motor\].*", "", EXAMPLE.read_text(encoding="utf-8"))
    for step in (check_problem, run_problem):
        with pytest.raises(ProblemFileError, match=r"transient\.drive\.motor: a shaft line needs a motor"):
            step(no_motor)
    wrong_kind = _text(kind='"select"')
    with pytest.raises(ProblemFileError, match=r"transient\.drive\.motor\.kind: must be \"induction\""):
        check_problem(wrong_kind)
    with pytest.raises(ProblemFileError, match=r"transient\.point: no point 'tail'"):
        check_problem(_text(point='"tail"'))
    with pytest.raises(ProblemFileError, match=r"transient\.duration: a run of 5000 s would take about"):
        check_problem(_text(duration='"5000 s"'))


def test_a_mechanism_file_refuses_a_shaft_lines_drive():
    text = (ROOT / "examples" / "rotary_screen_start_stop.toml").read_text(encoding="utf-8")
    text += '\n[transient.drive]\ninertia = "0.1 kg*m^2"\n'
    with pytest.raises(ProblemFileError, match=r"transient\.drive: is a shaft line's motor"):
        check_problem(text)
