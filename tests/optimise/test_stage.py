"""The ``[optimise]`` table through the command line: outputs, report, exit codes, the best design's file."""

from __future__ import annotations

import csv
import json
import math

from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.reading import load_problem
from machdyn.runner import run_problem

from .conftest import ROOT

EXAMPLE = ROOT / "examples" / "compactor_optimise.toml"


def test_compactor_example_runs_end_to_end(tmp_path):
    out = tmp_path / "out"
    res = CliRunner().invoke(app, ["run", str(EXAMPLE), "--out", str(out)])
    assert res.exit_code == 0, res.output
    scalars = json.loads((out / "results.json").read_text(encoding="utf-8"))["scalars"]
    assert scalars["optimise.verified"]["value"] == 1.0
    assert scalars["optimise.best.compactor.plate_angle.max"]["unit"] == "rad"
    assert scalars["optimise.best.compactor.plate_angle.max"]["value"] <= math.radians(20.0) * (1 + 1e-9)
    assert scalars["optimise.best.compactor.plate_angle.max"]["shown"]["unit"] == "deg"
    assert scalars["optimise.best.variable.r"]["unit"] == "m"
    assert scalars["optimise.best.variable.r"]["shown"]["unit"] == "mm"  # as the file writes it
    with open(out / "optimise_history.csv", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == scalars["optimise.generations"]["value"]
    html = (out / "report.html").read_text(encoding="utf-8")
    assert "Design optimisation" in html and "optimise-history" in html


def test_best_design_file_is_ready_to_run():
    outcome = run_problem(EXAMPLE).outcomes["optimise"]
    text = outcome.results.problem_text
    best = load_problem(text)
    assert best.optimise is None
    again = run_problem(best)
    assert again.scalars  # the best design analyses like any problem file


def test_check_reports_an_unknown_objective_with_exit_code_2(tmp_path):
    text = EXAMPLE.read_text(encoding="utf-8").replace('result = "compactor.force_gain.min"',
                                                        'result = "compactor.force_gain"')
    path = tmp_path / "bad.toml"
    path.write_text(text, encoding="utf-8")
    res = CliRunner().invoke(app, ["check", str(path)])
    assert res.exit_code == 2
    assert "did you mean 'compactor.force_gain.min'" in res.output


def test_constraints_no_design_meets_fail_the_run_with_the_tightest_listed(tmp_path):
    """A well-formed table that no design satisfies: exit 3 (the design fails its checks), outputs written."""
    text = EXAMPLE.read_text(encoding="utf-8").replace('max = "20 deg"', 'max = "0.5 deg"')
    text = text.replace("generations = 300", "generations = 5")
    path = tmp_path / "tight.toml"
    path.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    res = CliRunner().invoke(app, ["run", str(path), "--out", str(out)])
    assert res.exit_code == 3, res.output
    assert "compactor.plate_angle.max <= 0.5 deg: violated by" in res.output
    scalars = json.loads((out / "results.json").read_text(encoding="utf-8"))["scalars"]
    assert scalars["optimise.feasible"]["value"] == 0.0


def test_two_objectives_write_the_pareto_front(tmp_path):
    from .conftest import FOUR_BAR

    text = FOUR_BAR + """
[optimise]
population = 12
generations = 5
positions = 60
[[optimise.variables]]
parameter = "mechanism.crank.length"
lower = "20 mm"
upper = "55 mm"
[[optimise.objectives]]
result = "driving_torque.max_abs"
[[optimise.objectives]]
result = "stroke.rocker"
sense = "maximise"
"""
    path = tmp_path / "front.toml"
    path.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    res = CliRunner().invoke(app, ["run", str(path), "--out", str(out)])
    assert res.exit_code == 0, res.output
    with open(out / "optimise_front.csv", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    scalars = json.loads((out / "results.json").read_text(encoding="utf-8"))["scalars"]
    assert len(rows) == scalars["optimise.front_size"]["value"] >= 2
    assert "optimise-pareto" in (out / "report.html").read_text(encoding="utf-8")
