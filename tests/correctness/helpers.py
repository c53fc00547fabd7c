"""Run a problem file through ``machdyn check`` and ``machdyn run`` and return what each said."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from typer.testing import CliRunner

from machdyn.cli import app

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"


@dataclass
class Said:
    code: int
    stderr: str
    stdout: str


def invoke(args: list[str]) -> Said:
    result = CliRunner().invoke(app, args)
    return Said(result.exit_code, result.stderr, result.stdout)


def check_and_run(tmp_path: Path, text: str, name: str = "problem.toml") -> tuple[Said, Said]:
    """``machdyn check`` and ``machdyn run`` of the problem ``text`` written to ``tmp_path``."""
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    check = invoke(["check", str(path)])
    run = invoke(["run", str(path), "--out", str(tmp_path / "out"), "-q"])
    return check, run
