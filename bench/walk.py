"""The walk of a problem file: how many of machdyn's modules ``machdyn run`` imports and enters, and how many
calls into machdyn it makes, for one example (default ``examples/four_bar.toml``, report included).

Counted in this process with :func:`sys.setprofile` (every Python-level call whose code lives under
``src/machdyn``, module bodies included). Run it with ``.venv/bin/python bench/walk.py [example.toml]``; the
last line printed is one JSON object.
"""

from __future__ import annotations

import collections
import json
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SRC = ROOT / "src"
sys.path.insert(0, str(SRC))


def walk(example: Path) -> dict:
    calls: collections.Counter[str] = collections.Counter()
    package = str(SRC / "machdyn")

    def profile(frame, event, _arg):
        if event == "call" and frame.f_code.co_filename.startswith(package):
            calls[frame.f_code.co_filename] += 1

    from typer.testing import CliRunner

    import machdyn.cli as cli

    with tempfile.TemporaryDirectory() as out:
        sys.setprofile(profile)
        try:
            result = CliRunner().invoke(cli.app, ["run", str(example), "--out", out, "--quiet"])
        finally:
            sys.setprofile(None)
    imported = sorted(m for m in sys.modules if m == "machdyn" or m.startswith("machdyn."))
    return {"example": example.name, "exit_code": result.exit_code, "modules_imported": len(imported),
            "modules_entered": len(calls), "calls": sum(calls.values())}


def main() -> None:
    example = Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "examples" / "four_bar.toml"
    found = walk(example)
    for key, value in found.items():
        print(f"{key:18s} {value}")  # noqa: T201
    print(json.dumps(found))  # noqa: T201


if __name__ == "__main__":
    main()
