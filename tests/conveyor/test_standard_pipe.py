"""Without ``pipe_outer_diameter`` the screw's pipe is CEMA 350's standard pipe for its size (not half the screw,
which deducted 25 % of the capacity), said in a warning; beyond the table the file is refused asking for it."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.conveyor.design import volume_capacity
from machdyn.conveyor.tables import standard_pipe, standard_pipes
from machdyn.errors import InputError

ROOT = Path(__file__).resolve().parents[2]
EXISTING = ROOT / "examples" / "conveyor_check_existing.toml"
IN = 0.0254


def test_the_table_gives_each_size_its_standard_pipe_and_the_next_size_up_between_rows():
    # a 12 in screw on its 3 in pipe (outer diameter 3.5 in = 0.29 D); 100 mm counts as 4 in (within 2 %)
    assert standard_pipe(12 * IN) == pytest.approx(3.5 * IN)
    assert standard_pipe(12 * IN) / (12 * IN) == pytest.approx(0.29, abs=0.005)
    assert standard_pipe(0.100) == pytest.approx(1.660 * IN)
    assert standard_pipe(0.200) == pytest.approx(2.875 * IN)  # 7.87 in: the 9 in screw's 2 1/2 in pipe
    assert standard_pipe(0.250) == pytest.approx(2.875 * IN)  # 9.84 in: the 10 in screw's
    assert np.all(np.isnan(standard_pipes(np.array([0.08, 0.63]))))
    for size in (0.080, 0.630):
        with pytest.raises(InputError, match="give screw.pipe_outer_diameter"):
            standard_pipe(size)


def test_the_standard_pipe_deducts_what_cemas_capacity_table_deducts():
    """CEMA's capacity table gives a 12 in screw at 45 % loading 19.4 ft3/h per rpm on its pipe against 21.2 for
    the whole circle (the figures cited in machdyn.conveyor.design.volume_capacity): the standard pipe deducts
    8.5 %, as the table does to its three figures (0.05 %), where half the screw deducted 25 %."""
    d = 12 * IN
    whole = volume_capacity(d, d, angular_speed=2 * math.pi / 60, filling=0.45)
    ft3_per_h = whole * 3600 / 0.3048**3
    assert ft3_per_h == pytest.approx(21.2, abs=0.05)
    annulus = volume_capacity(d, d, angular_speed=2 * math.pi / 60, filling=0.45, pipe_diameter=standard_pipe(d))
    assert annulus / whole == pytest.approx(19.4 / 21.2, abs=5e-4)
    half = volume_capacity(d, d, angular_speed=1.0, filling=0.45, pipe_diameter=d / 2)
    assert half / volume_capacity(d, d, angular_speed=1.0, filling=0.45) == 0.75


def _without_pipe(diameter: str, tmp_path: Path) -> Path:
    text = EXISTING.read_text().replace('diameter = "250 mm"', f'diameter = "{diameter}"')
    lines = [ln for ln in text.splitlines() if not ln.startswith(("pipe_outer_diameter", "pipe_wall"))]
    path = tmp_path / f"screw_{diameter.replace(' ', '')}.toml"
    path.write_text("\n".join(lines) + "\n")
    return path


def test_a_screw_without_its_pipe_takes_the_standard_pipe_and_says_so(tmp_path):
    path = _without_pipe("250 mm", tmp_path)
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(tmp_path / "o")])
    assert result.exit_code in (0, 3), result.output
    flat = " ".join(result.output.split())
    assert "taken from CEMA 350's standard screw conveyor components" in flat
    assert "10 in screw's 2½ in pipe, outer diameter 73.0 mm" in flat
    scalars = json.loads((tmp_path / "o" / "results.json").read_text())["scalars"]
    assert scalars["pipe_outer_diameter"]["value"] == pytest.approx(0.073025)  # m: 2.875 in


def test_a_screw_beyond_the_table_without_its_pipe_is_refused_by_check_and_run(tmp_path):
    path = _without_pipe("700 mm", tmp_path)
    runner = CliRunner()
    check = runner.invoke(app, ["check", str(path)])
    run = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "o"), "-q"])
    assert check.exit_code == run.exit_code == 2, check.output + run.output
    for output in (check.output, run.output):
        flat = " ".join(output.split())
        assert "screw_conveyor.screw.pipe_outer_diameter" in flat and "4 to 24 in" in flat
        assert "give screw.pipe_outer_diameter" in flat
