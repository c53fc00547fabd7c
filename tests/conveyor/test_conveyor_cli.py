"""The conveyor's example files end to end through the command line: exit codes and warnings said once."""

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from machdyn.cli import app

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = sorted((ROOT / "examples").glob("*conveyor*.toml"))


@pytest.mark.parametrize("example", EXAMPLES, ids=lambda p: p.stem)
def test_conveyor_examples_run_and_report_si_results(example, tmp_path):
    result = CliRunner().invoke(app, ["run", str(example), "--out", str(tmp_path)])
    assert result.exit_code == 0, result.output
    scalars = json.loads((tmp_path / "results.json").read_text())["scalars"]
    assert scalars["shaft_power"]["value"] > 0
    assert (tmp_path / "report.html").read_text().count("<svg") >= 2  # power by method, bending along a span


def test_failed_check_exits_3_and_is_said_once(tmp_path):
    text = (ROOT / "examples" / "conveyor_lift_torque.toml").read_text().replace('torque = "140 N*m"',
                                                                                  'torque = "2000 N*m"')
    # the whole axial force on one flight turn (seed 004, eq 2.56), so that the flight fails too
    text = text.replace('[screw_conveyor.screw]\n', '[screw_conveyor.screw]\nflight_load = "one_turn"\n', 1)
    assert 'flight_load = "one_turn"' in text
    problem = tmp_path / "overloaded.toml"
    problem.write_text(text)
    result = CliRunner().invoke(app, ["run", str(problem), "--out", str(tmp_path / "out")])
    assert result.exit_code == 3, result.output
    output = result.output.replace("\n", " ")
    assert output.count("Pipe twist rate at the drive:") == 1
    assert output.count("Flight bending stress at the pipe:") == 1
