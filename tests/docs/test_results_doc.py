"""docs/results.md is generated from the catalogue of results where it lists quantities; the page fails this
test while a declaration has changed and the page has not been regenerated
(``python -m machdyn.listing docs/results.md``). ``machdyn results FILE`` lists what a run reports."""

from __future__ import annotations

import json
import re
from pathlib import Path

from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.kinds import catalogue
from machdyn.listing import TABLES, regenerated
from machdyn.results.catalogue import MECHANISM
from machdyn.runner import run_problem

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "results.md"


def test_the_results_page_is_the_catalogue_written_out():
    text = PAGE.read_text(encoding="utf-8")
    assert set(re.findall(r"<!-- catalogue: (\w+) -->", text)) == set(TABLES)
    assert regenerated(text) == text, "docs/results.md is stale: run python -m machdyn.listing docs/results.md"
    for q in catalogue():
        assert f"`{q.key}`" in text, q.key
    # each mechanism quantity with its reduction and better direction
    for q in MECHANISM:
        row = next(line for line in text.splitlines() if line.startswith(f"| `{q.key}` |"))
        assert (q.better or "–") in row, q.key


def test_regenerating_a_stale_table_restores_it():
    text = PAGE.read_text(encoding="utf-8")
    stale = text.replace("| `driving_torque.max_abs` |", "| `driving_torque.peak` |", 1)
    assert stale != text and regenerated(stale) == text


def test_machdyn_results_lists_every_key_the_run_reports_with_unit_meaning_and_better():
    example = ROOT / "examples" / "four_bar.toml"
    out = CliRunner().invoke(app, ["results", str(example)], env={"COLUMNS": "250"})
    assert out.exit_code == 0, out.output
    reported = json.loads(json.dumps(run_problem(example).results_json()["scalars"]))
    lines = out.output.splitlines()
    assert f"({len(reported)} keys)" in out.output
    for key, entry in reported.items():
        row = next(line for line in lines if f" {key} " in line)
        assert entry["unit"] in row, key
    row = next(line for line in lines if " driving_torque.max_abs " in line)
    assert "Driving torque, max |T|" in row and "lower" in row and "N*m" in row and " max_abs " in row
    row = next(line for line in lines if " transmission_angle.worst " in line)
    assert "higher" in row and "deg" in row and " worst " in row


def test_machdyn_results_of_a_bad_file_exits_2(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text("[mechanism]\ntype = 'four_bar'\n", encoding="utf-8")
    out = CliRunner().invoke(app, ["results", str(bad)])
    assert out.exit_code == 2
