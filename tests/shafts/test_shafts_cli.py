"""The [shaft_line] kind from the command line: examples run, bad input exits 2 naming the field, a missed grade
exits 3, check and run agree."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.errors import InputError
from machdyn.shafts.balance import Plane, correction_unbalances
from machdyn.shafts.field import Reading, TrialRun, single_plane, two_plane
from machdyn.shafts.rotating import Mass

ROOT = Path(__file__).resolve().parents[2]
ROTOR = ROOT / "examples" / "shaft_rotor_g63.toml"
ENGINE = ROOT / "examples" / "shaft_inline_four.toml"
FIELD = ROOT / "examples" / "shaft_field_balancing.toml"


@pytest.fixture
def runner():
    return CliRunner()


def _both(runner, path: Path, tmp_path: Path) -> tuple[int, int, str]:
    check = runner.invoke(app, ["check", str(path)])
    run = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "out"), "-q"])
    return check.exit_code, run.exit_code, check.output + run.output


def test_rotor_example_reports_corrections_grade_and_series(runner, tmp_path):
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(ROTOR), "--out", str(out), "-q"])
    assert result.exit_code == 0, result.output
    scalars = json.loads((out / "results.json").read_text())["scalars"]
    assert scalars["shaft.grade.U_per"]["unit"] == "kg*m" and scalars["shaft.grade.U_per"]["shown"]["unit"] == "g*mm"
    assert scalars["shaft.grade.margin"]["value"] > 1.0
    assert {"shaft.balance.L.mass", "shaft.balance.R.angle", "shaft.balance.L.hole6.mass"} <= set(scalars)
    rows = list(csv.reader((out / "shaft_loads.csv").read_text().splitlines()))
    assert rows[0][0].startswith("angle [") and any(h.startswith("fx_after") for h in rows[0])
    assert len(rows) == 361
    html = (out / "report.html").read_text()
    assert "Shaft line" in html and "Force polygon" in html


def test_engine_and_field_examples_run(runner, tmp_path):
    for path in (ENGINE, FIELD):
        result = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / path.stem), "-q"])
        assert result.exit_code == 0, result.output
    orders = list(csv.reader((tmp_path / ENGINE.stem / "shaft_orders.csv").read_text().splitlines()))
    assert len(orders) == 7
    scalars = json.loads((tmp_path / FIELD.stem / "results.json").read_text())["scalars"]
    assert scalars["shaft.field.drive_end.mass"]["unit"] == "kg"
    assert scalars["shaft.field.drive_end.mass"]["shown"]["unit"] == "g"  # in the file's unit


def test_correction_planes_at_one_position_are_refused(runner, tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text(ROTOR.read_text().replace('{ name = "R", position = "700 mm"', '{ name = "R", position = "100 mm"'))
    check, run, output = _both(runner, bad, tmp_path)
    assert check == run == 2, output
    assert "balance.planes[1].position" in output and "different axial positions" in output
    assert "Traceback" not in output
    with pytest.raises(InputError, match="different axial positions"):
        correction_unbalances([Mass("a", 1.0, 0.1, 0.0, 0.2)], Plane("L", 0.3, 0.1), Plane("M", 0.3, 0.1))


def test_readings_without_phase_are_refused(runner, tmp_path):
    bad = tmp_path / "nophase.toml"
    bad.write_text(FIELD.read_text().replace('{ amplitude = 8.6, phase = "62 deg" }', "{ amplitude = 8.6 }"))
    check, run, output = _both(runner, bad, tmp_path)
    assert check == run == 2, output
    assert "field_balancing.original[0].phase" in output and "phase reference" in output
    with pytest.raises(InputError, match="no phase"):
        single_plane(Reading(3.0, None), 0.01, 0.0, Reading(2.0, 0.4))


def test_a_singular_influence_matrix_is_named(runner, tmp_path):
    # the trial in plane 2 changes nothing: both trial runs read what the original run read
    text = FIELD.read_text()
    text = text.replace('{ amplitude = 7.4, phase = "49 deg" }', '{ amplitude = 8.6, phase = "62 deg" }')
    text = text.replace('{ amplitude = 3.3, phase = "196 deg" }', '{ amplitude = 6.1, phase = "147 deg" }')
    bad = tmp_path / "singular.toml"
    bad.write_text(text)
    check, run, output = _both(runner, bad, tmp_path)
    assert check == run == 2, output
    assert "influence matrix is nearly singular" in output
    o = [Reading(1.0, 0.0), Reading(1.0, 1.0)]
    same = TrialRun(0, 0.01, 0.0, (Reading(2.0, 0.0), Reading(2.0, 1.0)))
    alike = TrialRun(1, 0.01, 0.0, (Reading(2.0, 0.0), Reading(2.0, 1.0)))  # acts exactly like the first
    with pytest.raises(InputError, match="singular"):
        two_plane(o, [same, alike])
    with pytest.raises(InputError, match="singular"):
        single_plane(Reading(1.0, 0.3), 1e-3, 0.0, Reading(1.0, 0.3))


def test_a_rotor_missing_its_grade_exits_3(runner, tmp_path):
    text = ROTOR.read_text().replace('G = 6.3', 'G = 0.4').replace('state', 'state')
    text = text.replace('resolution = "0.5 g"', 'resolution = "5 g"')
    bad = tmp_path / "strict.toml"
    bad.write_text(text)
    result = runner.invoke(app, ["run", str(bad), "--out", str(tmp_path / "o"), "-q"])
    assert result.exit_code == 3, result.output
    assert "G 0.4" in result.output


def test_unknown_grade_and_one_bearing_are_refused(runner, tmp_path):
    bad = tmp_path / "grade.toml"
    text = ROTOR.read_text().replace("G = 6.3", "G = 5.0")
    text = text.replace('[[bearings]]\nname = "B"\nposition = "800 mm"\n', "")
    bad.write_text(text)
    check, run, output = _both(runner, bad, tmp_path)
    assert check == run == 2, output
    assert "grade.G" in output and "bearings" in output


def test_engine_on_mounts_reports_modes_and_a_free_frame_is_refused(runner, tmp_path):
    out = tmp_path / "e"
    result = runner.invoke(app, ["run", str(ENGINE), "--out", str(out), "-q"])
    assert result.exit_code == 0, result.output
    scalars = json.loads((out / "results.json").read_text())["scalars"]
    assert {f"shaft.frame.mode{k}.frequency" for k in range(1, 7)} <= set(scalars)
    assert scalars["shaft.frame.point.head.rms_velocity"]["unit"] == "m/s"
    assert scalars["shaft.frame.point.head.rms_velocity"]["shown"]["unit"] == "mm/s"
    text = ENGINE.read_text()
    start = text.index('[[frame.mounts]]\nname = "axial"')
    free = tmp_path / "free.toml"
    free.write_text(text[:start] + text[text.index("[[frame.points]]"):])  # nothing holds it along the shaft
    check, run, output = _both(runner, free, tmp_path)
    assert check == run == 2, output
    assert "free to move" in output


PHASES = """
[meta]
name = "three-cylinder phases"
[shaft_line]
speed = "3000 rpm"
reference = "90 mm"
""" + "".join(f"""
[[cylinders]]
name = "c{k}"
position = "{90 * (k - 1)} mm"
crank = "40 mm"
rod = "140 mm"
reciprocating_mass = "0.5 kg"
""" for k in (1, 2, 3)) + """
[phase_search]
cylinders = ["c2", "c3"]
objective = "primary_force"
"""


def test_phase_search_finds_the_three_throw_crank_and_writes_it_as_a_problem(runner, tmp_path):
    """Three cylinders on one crank line: the primary force vanishes only for cranks 120 deg apart (Khurmi & Gupta,
    14th ed., sec. 22.9); the best design is written as a problem file that runs with those phases."""
    src = tmp_path / "phases.toml"
    src.write_text(PHASES)
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(src), "--out", str(out), "-q"])
    assert result.exit_code == 0, result.output
    s = json.loads((out / "results.json").read_text())["scalars"]
    got = sorted([s["shaft.phases.c2.phase"]["value"], s["shaft.phases.c3.phase"]["value"]])
    assert got == pytest.approx([np.radians(120.0), np.radians(240.0)], abs=1e-11)
    assert s["shaft.phases.best.primary_force"]["value"] <= 1e-9 * s["shaft.phases.given.primary_force"]["value"]
    again = runner.invoke(app, ["run", str(out / "best_phases.toml"), "--out", str(tmp_path / "again"), "-q"])
    assert again.exit_code == 0, again.output
    s2 = json.loads((tmp_path / "again" / "results.json").read_text())["scalars"]
    assert s2["shaft.engine.primary_force"]["value"] <= 1e-9 * s["shaft.phases.given.primary_force"]["value"]
    bad = tmp_path / "bad.toml"
    bad.write_text(PHASES.replace('cylinders = ["c2", "c3"]', 'cylinders = ["c2", "c9"]'))
    check, run, output = _both(runner, bad, tmp_path)
    assert check == run == 2 and "phase_search" in output and "c9" in output


BK_17_227 = """
[meta]
name = "B&K 17-227, Table 2, example 6"

[shaft_line]
speed = "1485 rpm"  # not transcribed with the readings; the influence-coefficient solution does not use it

[field_balancing]
unit = "mm/s"
planes = [ { name = "plane1" }, { name = "plane2" } ]
original = [ { amplitude = 170, phase = "112 deg" }, { amplitude = 53, phase = "78 deg" } ]

[[field_balancing.trials]]
plane = 1
mass = "1.15 g"
angle = "0 deg"
readings = [ { amplitude = 235, phase = "94 deg" }, { amplitude = 58, phase = "68 deg" } ]

[[field_balancing.trials]]
plane = 2
mass = "1.15 g"
angle = "0 deg"
readings = [ { amplitude = 185, phase = "115 deg" }, { amplitude = 77, phase = "104 deg" } ]
"""


def test_published_two_plane_field_readings_through_a_problem_file(runner, tmp_path):
    """The readings of Bruel & Kjaer application note 17-227, Table 2, example 6 (as transcribed by hsbalance's
    documentation; see tests/validation/test_shafts_published.py) entered as a [field_balancing] table give, from
    the command line, the corrections hsbalance publishes for them: 1.979 g at 236.2 deg and 1.071 g at
    121.8 deg (printed to 0.001 g and 0.1 deg)."""
    path = tmp_path / "bk.toml"
    path.write_text(BK_17_227)
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(path), "--out", str(out), "-q"])
    assert result.exit_code == 0, result.output
    scalars = json.loads((out / "results.json").read_text())["scalars"]
    assert scalars["shaft.field.plane1.mass"]["unit"] == "kg"
    assert scalars["shaft.field.plane1.mass"]["shown"]["unit"] == "g"
    assert scalars["shaft.field.plane1.mass"]["value"] == pytest.approx(1.979e-3, abs=5e-7)
    assert scalars["shaft.field.plane2.mass"]["value"] == pytest.approx(1.071e-3, abs=5e-7)
    assert scalars["shaft.field.plane1.angle"]["value"] == pytest.approx(np.radians(236.2), abs=np.radians(0.05))
    assert scalars["shaft.field.plane2.angle"]["value"] == pytest.approx(np.radians(121.8), abs=np.radians(0.05))
