"""The [balance] table end to end: problem files through the command line, their results, and bad input."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.runner import run_problem

ROOT = Path(__file__).resolve().parents[2]

ENGINE = """
[mechanism]
type = "slider_crank"
[mechanism.crank]
length = "50 mm"
mass = "1 kg"
[mechanism.rod]
length = "200 mm"
mass = "2 kg"
[mechanism.slider]
mass = "3 kg"
[drive]
speed = "3000 rpm"
positions = 36
[loads]
gravity = "off"
"""


def _run(tmp_path, text, *args):
    path = tmp_path / "p.toml"
    path.write_text(text, encoding="utf-8")
    return CliRunner().invoke(app, ["run", str(path), "--out", str(tmp_path / "out"), *args])


def test_crank_example_through_the_command_line(tmp_path):
    result = CliRunner().invoke(app, ["run", str(ROOT / "examples" / "slider_crank_balance.toml"),
                                      "--out", str(tmp_path)])
    assert result.exit_code == 0, result.output
    data = json.loads((tmp_path / "results.json").read_text())["scalars"]
    assert data["balance.rms_force_after"]["value"] < data["balance.rms_force_before"]["value"]
    assert data["balance.counterweight.mass"]["unit"] == "kg"
    tradeoff = (tmp_path / "balance_tradeoff.csv").read_text().splitlines()
    assert tradeoff[0].startswith("fraction") and len(tradeoff) == 22
    report = (tmp_path / "report.html").read_text()
    assert "Shaking force before and after" in report and "Partial balance trade-off" in report


def test_four_bar_example_is_fully_balanced():
    run = run_problem(ROOT / "examples" / "four_bar_balance.toml")
    scalars = run.outcomes["balance"].scalars
    assert scalars["balance.com_travel_after"] < 1e-12
    assert scalars["balance.rms_force_after"] < 1e-12 * scalars["balance.rms_force_before"] * 1e3
    assert scalars["balance.rms_moment_after"] > scalars["balance.rms_moment_before"]


def test_tamper_example_equals_the_python_model_state_by_state():
    # the file sets strokes, phases, sleeve positions and crank turns for each state; the Python model places the
    # pins on the shaft directly: the same machine, so the same balance (the file's values carry 9 digits)
    from machdyn.machines.tamper.balance import corrected_balance

    run = run_problem(ROOT / "examples" / "double_tamper_balance.toml")
    from_file = run.outcomes["balance"].results.result
    direct = corrected_balance(crank_angle=np.linspace(0, 2 * np.pi, 120, endpoint=False))
    for a, b in zip(from_file.rows, direct.rows, strict=True):
        assert a.state == b.state
        assert a.rms_before == pytest.approx(b.rms_before, rel=1e-6)
        assert a.rms_after == pytest.approx(b.rms_after, rel=1e-6)
    html = "".join(h for _, h in run.report_sections())
    assert "Shaking force per state" in html and "43 %" in html  # the paper's reduction next to each state's


def test_counterweights_with_objective_and_spring(tmp_path):
    objective = ENGINE + """
[balance]
method = "counterweights"
positions = 24
[[balance.counterweights]]
body = "crank"
mass_max = "5 kg"
radius_max = "60 mm"
[balance.objective]
force = 1.0
torque = 0.5
"""
    result = _run(tmp_path, objective)
    assert result.exit_code == 0, result.output
    spring = ENGINE + """
[balance]
method = "spring"
[balance.spring]
body = "slider"
point = ["0 mm", "0 mm"]
anchor = ["0 mm", "0 mm"]
"""
    result = _run(tmp_path, spring)
    assert result.exit_code == 0, result.output
    data = json.loads((tmp_path / "out" / "results.json").read_text())["scalars"]
    assert data["balance.torque_fluctuation_after"]["value"] < 0.2 * data["balance.torque_fluctuation_before"]["value"]


@pytest.mark.parametrize(("table", "expected"), [
    ('method = "crank"\nradius = "60 mm"', "needs fraction"),
    ('method = "crank"\nfraction = 1.5\nradius = "60 mm"', "fraction"),
    ('method = "berkof_lowen"\ncrank_radius = "1 cm"\nrocker_radius = "1 cm"', "four-bar"),
    ('method = "counterweights"', "needs [[balance.counterweights]]"),
    ('method = "counterweights"\n[[balance.masses]]\nname = "nothing"', "no [[counterweights]] entry named"),
    ('method = "counterweights"\n[[balance.counterweights]]\nbody = "crank"\nradius = "5 cm"\n'
     '[[balance.states]]\nname = "a"\nset = { "mechanism.crank.lenght" = "40 mm" }', "did you mean"),
    ('method = "counterweights"\n[[balance.counterweights]]\nbody = "crank"', "needs a radius"),
    ('metod = "crank"', "metod"),
])
def test_bad_balance_tables_exit_2_with_a_message(tmp_path, table, expected):
    result = _run(tmp_path, ENGINE + "\n[balance]\n" + table + "\n")
    assert result.exit_code == 2, result.output
    assert expected in result.output
    assert "Traceback" not in result.output


def test_misspelled_counterweight_body_is_reported_once_under_its_field(tmp_path):
    table = ('method = "counterweights"\n[[balance.counterweights]]\nbody = "crnk"\nradius = "5 cm"\n'
             '[[balance.states]]\nname = "a"\nset = { "mechanism.crank.length" = "40 mm" }\n'
             '[[balance.states]]\nname = "b"\nset = { "mechanism.crank.length" = "45 mm" }')
    result = _run(tmp_path, ENGINE + "\n[balance]\n" + table + "\n")
    assert result.exit_code == 2, result.output
    assert "balance.counterweights[0].body" in result.output
    assert result.output.count("no body 'crnk'") == 1
    assert "Traceback" not in result.output
