"""The optimised design is written beside the other outputs as a problem file that runs on its own."""

from __future__ import annotations

import tomllib
from pathlib import Path

from typer.testing import CliRunner

from machdyn.cli import EXIT_OK, app

ROOT = Path(__file__).resolve().parents[2]


def test_best_design_is_written_and_runs(tmp_path):
    runner = CliRunner()
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(ROOT / "examples" / "compactor_optimise.toml"), "--out", str(out), "-q"])
    assert result.exit_code == EXIT_OK, result.output
    best = out / "best_design.toml"
    data = tomllib.loads(best.read_text(encoding="utf-8"))
    assert "optimise" not in data, "the best design is a plain problem, ready to run"
    again = runner.invoke(app, ["run", str(best), "--out", str(tmp_path / "again"), "-q"])
    assert again.exit_code == EXIT_OK, again.output
