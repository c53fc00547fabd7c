"""A link whose ultimate strength is below its endurance limit is an input mistake, named with both fields by
check and run alike (it used to give a fatigue safety factor and exit 0)."""

from __future__ import annotations

import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.drivetrain.strength import goodman_safety
from machdyn.errors import InputError
from reproductions import swapped_strengths


def test_an_ultimate_strength_below_the_endurance_limit_is_refused(tmp_path):
    bad = tmp_path / "swapped.toml"
    bad.write_text(swapped_strengths())
    runner = CliRunner()
    check = runner.invoke(app, ["check", str(bad)])
    run = runner.invoke(app, ["run", str(bad), "--out", str(tmp_path / "o"), "-q"])
    assert check.exit_code == run.exit_code == 2, check.output + run.output
    for output in (check.output, run.output):
        flat = " ".join(output.split())
        assert "parts.links[0]" in flat
        assert "endurance_limit 150 MPa exceeds ultimate_strength 120 MPa" in flat


def test_goodman_refuses_the_same_and_accepts_equal_values():
    with pytest.raises(InputError, match="exceeds ultimate_strength"):
        goodman_safety(100e6, 0.0, 300e6, 200e6)
    # Se = Sut is the limit of what can hold: a fully reversed 100 MPa gives n = Se / sigma_a = 2
    assert goodman_safety(100e6, -100e6, 200e6, 200e6) == pytest.approx(2.0)
