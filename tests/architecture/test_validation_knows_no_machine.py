"""Validation knows no machine: no module of ``src/machdyn/problem/`` imports the registry of kinds, a kind's
package or a machine, at any level (inside functions too); and each problem kind's package stands on its own."""

from __future__ import annotations

import ast
from pathlib import Path

SRC = Path(__file__).resolve().parents[2] / "src" / "machdyn"

#: What validation must not import: the registry, the reading of a file of any kind, the kinds' packages.
ABOVE_VALIDATION = ("machdyn.kinds", "machdyn.reading", "machdyn.machines", "machdyn.screen", "machdyn.conveyor",
                    "machdyn.pipelines", "machdyn.runner", "machdyn.cli")


def _targets(path: Path, package: str) -> set[str]:
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[: len(package.split(".")) - (node.level - 1)]
                found.add(".".join(base + ([node.module] if node.module else [])))
            else:
                found.add(node.module or "")
    return found


def test_problem_package_imports_no_kind_and_no_machine():
    wrong = []
    for path in sorted((SRC / "problem").glob("*.py")):
        for target in _targets(path, "machdyn.problem"):
            if target.startswith(ABOVE_VALIDATION):
                wrong.append(f"{path.name} imports {target}")
    assert wrong == []


def test_the_rotary_screen_is_one_package():
    """Its schema, model, formulas and kind live in machdyn.screen; only the drawing is in the report."""
    from machdyn.kinds import KINDS, kind

    assert KINDS["rotary_screen"] == "machdyn.screen.kind:KIND"
    screen = kind("rotary_screen")
    assert screen.schema.__module__ == "machdyn.screen.schema"
    assert screen.report == "machdyn.report.rotary_screen:sections"
    assert not (SRC / "machines" / "rotary_screen").exists()
    assert not (SRC / "problem" / "rotary.py").exists()
    assert not (SRC / "pipelines" / "rotary_screen.py").exists()
    for path in (SRC / "screen").glob("*.py"):
        assert "matplotlib" not in path.read_text(encoding="utf-8"), path.name
