"""Through the command line: the diagnostics of a partial crank range, and the double slider-crank's figures
per slider."""

from __future__ import annotations

import json
from pathlib import Path

from typer.testing import CliRunner

from machdyn.cli import app

ROOT = Path(__file__).resolve().parents[2]
FOUR_BAR = (ROOT / "examples" / "four_bar.toml").read_text(encoding="utf-8")
TAMPER = ROOT / "examples" / "tamper_on_tyres.toml"


def _run(tmp_path: Path, text: str):
    path = tmp_path / "p.toml"
    path.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(out), "-q"])
    return result, out


def test_a_quarter_turn_is_described_not_the_full_turn(tmp_path):
    # A non-Grashof four-bar (crank 40, coupler 100, rocker 60, ground 130 mm) cannot turn fully: its dead
    # positions lie either side of 180 deg, outside the 0-90 deg asked for.
    text = FOUR_BAR.replace('rocker]\nlength = "100 mm"', 'rocker]\nlength = "60 mm"')
    text = text.replace('length = "120 mm"', 'length = "100 mm"')
    text = text.replace("positions = 360", 'positions = 91\nstart = "0 deg"\nstop = "90 deg"')
    result, out = _run(tmp_path, text)
    assert result.exit_code == 0, result.output
    data = json.loads((out / "results.json").read_text(encoding="utf-8"))
    said = " ".join(data["warnings"])
    assert "Dead" not in said and "cannot assemble" not in said
    assert "no time ratio is given (it needs a full turn)" in said
    assert "time_ratio" not in data["scalars"]
    assert data["scalars"]["dead_positions.count"]["value"] == 0
    report = (out / "report.html").read_text(encoding="utf-8")
    assert "needs a full turn" in report


def test_double_slider_crank_names_each_slider(tmp_path):
    result, out = _run(tmp_path, TAMPER.read_text(encoding="utf-8"))
    assert result.exit_code in (0, 3), result.output
    scalars = json.loads((out / "results.json").read_text(encoding="utf-8"))["scalars"]
    per_slider = [k for k in scalars if k.startswith("time_ratio.")]
    assert len(per_slider) == 2, per_slider
    assert sum(k.startswith("transmission_angle.") and k.count(".") == 2 for k in scalars) == 4
    report = (out / "report.html").read_text(encoding="utf-8")
    for key in per_slider:
        assert f"of {key.split('.')[1]}" in report


def test_model_mistakes_are_said_with_the_schema_mistakes(tmp_path):
    # A bad [drive] value (schema) and a load on a body that does not exist (found building the model).
    text = FOUR_BAR.replace('body = "rocker"', 'body = "rockr"').replace("positions = 360", "positions = -5")
    path = tmp_path / "p.toml"
    path.write_text(text, encoding="utf-8")
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 2, result.output
    assert "drive.positions" in result.output
    assert "rockr" in result.output
