"""A file named as a record that is not one (a ``.env`` beside the problem file) is refused naming the file and
the rule, never quoting its text: neither ``[signals]`` (a machine's or on its own) nor ``[field_records]``."""

from __future__ import annotations

from pathlib import Path

import pytest
from typer.testing import CliRunner

from machdyn.cli import app

from .conftest import ROOT

SECRET = "API_KEY=s3cr3t-value-of-the-user"
EXAMPLES = ROOT / "examples"

#: (example file, the record it names, the field reported)
CASES = {
    "signals": ("vibration_records_alone.toml", "machdyn:examples/signals/tamper_before.csv", "signals.record"),
    "field_records": ("shaft_field_records.toml", "machdyn:examples/field_records/original.csv",
                      "field_records.original"),
}

#: first lines a private file may have: no header at all, one in the record's grammar with a bad unit, a
#: comma-separated one, and one the parser stumbles on
FIRST_LINES = {
    "plain": f"{SECRET}\nSECOND=line\n",
    "header_like": f"time [s], {SECRET} [furlong]\n" + "".join(f"{i}, {i % 2}\n" for i in range(12)),
    "two_fields": f"{SECRET},other\n1,2,3,4\n",
    "not_time": f"{SECRET} [mm/s], b [mm/s]\n0, 1\n1, 2\n",
}


def _problem(folder: Path, case: str) -> Path:
    example, record, _ = CASES[case]
    path = folder / "problem.toml"
    path.write_text((EXAMPLES / example).read_text().replace(f'"{record}"', '".env"'))
    return path


@pytest.mark.parametrize("lines", list(FIRST_LINES))
@pytest.mark.parametrize("case", list(CASES))
def test_a_file_that_is_not_a_record_is_named_never_quoted(tmp_path, case, lines):
    (tmp_path / ".env").write_text(FIRST_LINES[lines])
    problem = _problem(tmp_path, case)
    for command in (["check", str(problem)], ["run", str(problem), "--out", str(tmp_path / "out")]):
        result = CliRunner().invoke(app, command)
        assert result.exit_code == 2, result.output
        assert CASES[case][2] in result.output and ".env" in result.output
        assert "s3cr3t" not in result.output and "API_KEY" not in result.output
