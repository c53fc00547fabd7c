"""Corrections rounded to a ``resolution`` are reported as fitted (the masses the residual is computed with), and
masses are shown in the unit the file writes them in."""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.shafts.rotating import Mass, rotating_loads

ROOT = Path(__file__).resolve().parents[2]
ROTOR = ROOT / "examples" / "shaft_rotor_g63.toml"


def _run(text: str, tmp_path: Path) -> tuple[dict, str, str]:
    path = tmp_path / "rotor.toml"
    path.write_text(text)
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(tmp_path / "o")])
    assert result.exit_code == 0, result.output
    scalars = json.loads((tmp_path / "o" / "results.json").read_text())["scalars"]
    return scalars, result.output, (tmp_path / "o" / "report.html").read_text()


def test_rounded_masses_are_reported_in_grams_and_give_the_residual(tmp_path):
    scalars, output, report = _run(ROTOR.read_text().replace('resolution = "0.5 g"', 'resolution = "1 g"'), tmp_path)
    fitted = {k: v for k, v in scalars.items() if k.endswith("fitted_mass")}
    assert set(fitted) == {"shaft.balance.L.hole5.fitted_mass", "shaft.balance.L.hole6.fitted_mass",
                           "shaft.balance.R.hole2.fitted_mass", "shaft.balance.R.hole3.fitted_mass"}
    for key, v in fitted.items():
        assert v["unit"] == "kg" and v["shown"]["unit"] == "g"  # SI, shown in the file's unit
        assert v["shown"]["value"] == pytest.approx(round(v["shown"]["value"]), abs=1e-9)  # whole grams
        exact = scalars[key.replace("fitted_mass", "mass")]
        assert exact["shown"]["unit"] == "g" and abs(v["value"] - exact["value"]) <= 0.5e-3 + 1e-12
    assert "rounded to 1 g" in output  # the summary's label
    assert re.search(r"as fitted in plane L, rounded to 1 g.*hole 5: \d+ g at 180°", report)
    # the residual is the one of the fitted masses, computed here on its own: 8 holes 45 deg apart from 0 deg
    discs = [Mass("d1", 0.040, 0.25, np.radians(0), 0.15), Mass("d2", 0.060, 0.25, np.radians(75), 0.32),
             Mass("d3", 0.045, 0.25, np.radians(200), 0.48), Mass("d4", 0.030, 0.25, np.radians(290), 0.65)]
    holes = [Mass(k, fitted[k]["value"], 0.24, np.radians(45 * (int(k.split("hole")[1][0]) - 1)),
                  0.1 if ".L." in k else 0.7) for k in fitted]
    speed = 1480 * np.pi / 30
    after = rotating_loads(discs + holes, speed)
    assert scalars["shaft.balance.after.force.peak"]["value"] == pytest.approx(after.peak_force, rel=1e-9)


def test_masses_written_in_kg_are_shown_in_kg(tmp_path):
    text = ROTOR.read_text().replace('resolution = "0.5 g"', 'resolution = "0.001 kg"')
    for grams in ("40", "60", "45", "30"):
        text = text.replace(f'mass = "{grams} g"', f'mass = "{int(grams) / 1000} kg"')
    scalars, _, report = _run(text, tmp_path)
    assert scalars["shaft.balance.L.mass"]["unit"] == "kg"
    assert scalars["shaft.balance.L.hole5.fitted_mass"]["unit"] == "kg"
    assert scalars["shaft.balance.L.hole5.fitted_mass"]["value"] == pytest.approx(0.003)  # 3.27 g to whole grams
    assert "rounded to 0.001 kg" in report
