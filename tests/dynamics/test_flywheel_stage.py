"""The [flywheel] table end to end: the shipped examples through the command line and the runner, bad tables."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.errors import ProblemFileError
from machdyn.reading import load_problem
from machdyn.runner import run_problem

ROOT = Path(__file__).resolve().parents[2]


def test_compactor_example_runs_from_the_command_line(tmp_path):
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["run", str(ROOT / "examples" / "compactor_flywheel.toml"), "--out", str(out)])
    assert result.exit_code == 0, result.output
    data = json.loads((out / "results.json").read_text())
    text = json.dumps(data)
    assert "flywheel.inertia" in text and "flywheel.delta" in text
    for name in ("flywheel_cycle.csv", "start_up.csv", "report.html"):
        assert (out / name).exists()
    report = (out / "report.html").read_text()
    assert "Energy–mass diagram" in report and "Start-up from rest" in report


def test_the_screens_spring_lowers_speed_fluctuation_and_motor_torque():
    runs = {}
    for name in ("rotary_screen_drive", "rotary_screen_drive_spring"):
        res = run_problem(load_problem(ROOT / "examples" / f"{name}.toml"))
        runs[name] = res.outcomes["flywheel"].scalars
    plain, spring = runs["rotary_screen_drive"], runs["rotary_screen_drive_spring"]
    # seed 002: the spring stores the translating mass's kinetic energy; the drive no longer pays the swing
    assert spring["flywheel.delta"] < 0.2 * plain["flywheel.delta"]
    assert spring["flywheel.peak_drive_torque"] < 0.5 * plain["flywheel.peak_drive_torque"]
    # both dissipate only in the bearings: the same mean power within the change of the mean speed
    assert spring["flywheel.mean_power"] == pytest.approx(plain["flywheel.mean_power"], rel=0.01)


def _problem(tmp_path, flywheel: str) -> Path:
    text = (ROOT / "examples" / "four_bar.toml").read_text() + "\n" + flywheel
    path = tmp_path / "p.toml"
    path.write_text(text)
    return path


@pytest.mark.parametrize("table, message", [
    ("[flywheel]\ndelta = 1.5\n", "delta"),
    ("[flywheel]\ndelta = 0.02\ninertia = \"1 kg*m^2\"\n", "exactly one of delta"),
    ("[flywheel]\ninertia = \"-1 kg*m^2\"\n", "inertia"),
    ("[flywheel]\ndelta = 0.02\n[flywheel.motor]\nkind = \"induction\"\n", "rated_power"),
])
def test_bad_flywheel_tables_are_reported_with_their_path(tmp_path, table, message):
    with pytest.raises(ProblemFileError) as info:
        load_problem(_problem(tmp_path, table))
    assert any(path.startswith("flywheel") and message in text for path, text in info.value.problems) or \
        message in str(info.value)


def test_sizing_in_a_problem_file_meets_its_target(tmp_path):
    path = _problem(tmp_path, "[flywheel]\ndelta = 0.02\nstart_up = false\n[flywheel.motor]\nkind = "
                              "\"constant_torque\"\n")
    res = run_problem(load_problem(path))
    s = res.outcomes["flywheel"].scalars
    assert s["flywheel.delta"] == pytest.approx(0.02, rel=1e-3)
    assert np.isfinite(s["flywheel.method_difference"])


@pytest.mark.parametrize("delta, rule", [("0", "must be > 0"), ("1", "must be < 1"), ("nan", "finite"),
                                         ("inf", "finite")])
def test_bad_target_delta_through_the_command_line(tmp_path, delta, rule):
    """A target coefficient of speed fluctuation of 0, 1 or NaN: exit code 2 and a message naming the field and
    the rule (NaN was reported as 'must be < 1')."""
    path = _problem(tmp_path, f"[flywheel]\ndelta = {delta}\n")
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(tmp_path / "out")])
    assert result.exit_code == 2, result.output
    text = " ".join(result.output.split())
    assert "flywheel.delta" in text
    assert rule in text
