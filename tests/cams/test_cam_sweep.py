"""A one-quantity ``[sweep]`` in a cam file and in a shaft-line file: each variant run whole through the file's
stages, the named results tabulated with a status per variant; check and run refusing the same mistakes."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.errors import ProblemFileError
from machdyn.runner import check_problem, run_problem

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "feeder_cam_sweep.toml"
NOMINAL = ROOT / "examples" / "feeder_cam.toml"
COLUMNS = ("cam.max_pressure_angle", "cam.min_pitch_curvature_radius", "cam.max_normal_force")
runner = CliRunner()


@pytest.fixture(scope="module")
def swept():
    return run_problem(EXAMPLE)


def test_the_shipped_copy_of_the_example_is_the_same():
    shipped = ROOT / "src" / "machdyn" / "data" / "examples" / "feeder_cam_sweep.toml"
    assert shipped.read_text(encoding="utf-8") == EXAMPLE.read_text(encoding="utf-8")
    assert EXAMPLE.read_text(encoding="utf-8").startswith(NOMINAL.read_text(encoding="utf-8").split("[meta]")[0])


def test_each_column_of_the_sweep_is_what_a_run_of_that_variant_alone_reports(swept):
    """Every variant of the base-circle sweep run again on its own, as the feeder cam's file with that base
    radius: the same pressure angle, pitch-curve curvature and normal force (the same code on the same input:
    to rounding). The physics of the table: a larger base circle lowers the pressure angle (the same lift is
    climbed along a longer pitch curve), and with it the contact force along the common normal (F / cos phi),
    and flattens the pitch curve (a larger smallest radius of curvature)."""
    done = swept.outcomes["sweep"].results
    assert done.plan.parameter == "cam.base_radius"
    np.testing.assert_allclose(done.plan.values_display, np.linspace(20.0, 60.0, 9))
    assert list(done.columns["regular"]) == [True] * 9
    nominal = NOMINAL.read_text(encoding="utf-8")
    for i, radius in enumerate(done.plan.values_display):
        alone = run_problem(nominal.replace('base_radius = "45 mm"', f'base_radius = "{radius:g} mm"'))
        assert alone.results["cam.base_radius"] == pytest.approx(radius * 1e-3, rel=1e-12)
        # a variant whose run fails a design check says which, as its own run does; the others are regular
        status = done.columns["status"][i]
        assert status == (f"failed check: {alone.failed_checks[0]}" if alone.failed_checks else "regular")
        for key in COLUMNS:
            assert done.columns[key][i] == pytest.approx(alone.results[key], rel=1e-12), (radius, key)
    assert np.all(np.diff(done.columns["cam.max_pressure_angle"]) < 0)
    assert np.all(np.diff(done.columns["cam.max_normal_force"]) < 0)
    assert np.all(np.diff(done.columns["cam.min_pitch_curvature_radius"]) > 0)
    # the pressure-angle limit of 30 deg is exceeded below a base radius of ~31 mm: the first three variants
    assert [s.startswith("failed check: pressure angle") for s in done.columns["status"]] == [True] * 3 + [False] * 6
    # the nominal 45 mm cam is the sixth variant: the file's own run and its variant agree
    assert done.columns["cam.max_pressure_angle"][5] == pytest.approx(swept.results["cam.max_pressure_angle"],
                                                                      rel=1e-12)


def test_the_table_is_in_results_json_the_summary_and_its_labels(swept):
    values = swept.results.values
    assert values["sweep.designs"] == 9 and values["sweep.regular_count"] == 9
    assert values["sweep.cam.base_radius"] == pytest.approx(list(np.linspace(0.020, 0.060, 9)))  # SI
    shown = {row.key: row for row in swept.summary.rows}
    angles = shown["sweep.cam.max_pressure_angle"]
    assert angles.unit == "deg"
    assert angles.value == pytest.approx([math.degrees(v) for v in values["sweep.cam.max_pressure_angle"]])
    assert "Pressure angle" in angles.label or "pressure angle" in angles.label
    assert shown["sweep.cam.min_pitch_curvature_radius"].unit == "mm"


def _with_sweep(sweep: str) -> str:
    return NOMINAL.read_text(encoding="utf-8") + "\n[sweep]\n" + sweep


def test_a_variant_that_cannot_be_built_gets_a_status_not_a_silent_nan():
    """A follower offset by 70 mm misses the prime circle (45 mm base + 12 mm roller = 57 mm): that variant
    cannot be built. It has no values, its status names the field, it is not regular and a warning says so; the
    5 mm variant is the nominal cam."""
    ran = run_problem(_with_sweep('parameter = "cam.follower.offset"\nvalues = ["5 mm", "70 mm"]\n'
                                  'columns = ["cam.max_pressure_angle"]\n'))
    done = ran.outcomes["sweep"].results
    assert list(done.columns["regular"]) == [True, False]
    assert done.columns["status"][0] == "regular"
    assert done.columns["status"][1].startswith("not built: cam.base_radius ")
    assert "must exceed the offset" in done.columns["status"][1]
    assert math.isnan(done.columns["cam.max_pressure_angle"][1])
    assert done.columns["cam.max_pressure_angle"][0] == pytest.approx(ran.results["cam.max_pressure_angle"],
                                                                       rel=1e-12)
    assert ran.results.values["sweep.regular_count"] == 1
    assert ran.results.values["sweep.status"][1] == done.columns["status"][1]
    assert any(w.startswith("sweep variant 2 (cam.follower.offset = 70 mm) not built") for w in ran.warnings)


@pytest.mark.parametrize("sweep, field", [
    ('parameter = "cam.base_radius"\nvalues = ["40 mm", "50 mm"]\ncolumns = ["cam.pressure_angle.max"]\n',
     "sweep.columns[0]"),
    ('parameter = "cam.base_radius"\nvalues = ["40 mm", "50 mm"]\ncolumns = ["driving_torque.max_abs"]\n',
     "sweep.columns[0]"),
    ('parameter = "cam.base_radius"\nvalues = ["40 mm", "50 mm"]\n', "sweep.columns"),
    ('parameter = "cam.base_radus"\nvalues = ["40 mm", "50 mm"]\ncolumns = ["cam.max_pressure_angle"]\n',
     "sweep.parameter"),
    ('parameter = "cam.base_radius"\nvalues = ["40 mm", "50 deg"]\ncolumns = ["cam.max_pressure_angle"]\n',
     "sweep.values[1]"),
    ('parameter = "cam.base_radius"\nvalues = ["40 mm", "50 mm"]\ncolumns = ["cam.max_pressure_angle"]\n'
     'workers = 2\n', "sweep.workers"),
])
def test_a_mistake_of_the_sweep_is_refused_by_check_and_run_with_the_same_message(sweep, field):
    text = _with_sweep(sweep)
    with pytest.raises(ProblemFileError) as checked:
        check_problem(text)
    with pytest.raises(ProblemFileError) as ran:
        run_problem(text)
    assert str(checked.value) == str(ran.value)
    assert field in [path for path, _ in ran.value.problems]


def test_a_wrong_column_names_the_field_and_the_result_it_meant():
    with pytest.raises(ProblemFileError) as ran:
        run_problem(_with_sweep('parameter = "cam.base_radius"\nvalues = ["40 mm"]\ncolumns = ["cam.speeed"]\n'))
    [(path, message)] = ran.value.problems
    assert path == "sweep.columns[0]"
    assert message.startswith("'cam.speeed' is not a result of this cam file; did you mean 'cam.speed'? (results of "
                              "cam.*: ")  # and the cam's results to choose from


def test_the_command_line_runs_the_example_and_writes_the_table(tmp_path):
    checked = runner.invoke(app, ["check", str(EXAMPLE)])
    assert checked.exit_code == 0, checked.output
    out = tmp_path / "out"
    ran = runner.invoke(app, ["run", str(EXAMPLE), "--out", str(out), "-q"])
    assert ran.exit_code == 0, ran.output
    table = pd.read_csv(out / "sweep.csv")
    assert list(table.columns) == ["cam.base_radius [m]", "cam.max_pressure_angle [deg]",
                                   "cam.min_pitch_curvature_radius [m]", "cam.max_normal_force [N]", "regular",
                                   "status"]
    np.testing.assert_allclose(table["cam.base_radius [m]"], np.linspace(0.020, 0.060, 9))  # SI, as every column
    assert list(table["regular"]) == [True] * 9
    assert list(table["status"])[3:] == ["regular"] * 6 and table["status"][0].startswith("failed check")
    scalars = json.loads((out / "results.json").read_text())["scalars"]
    assert scalars["sweep.cam.max_pressure_angle"]["unit"] == "rad"  # results.json is SI; the CSV shows degrees
    np.testing.assert_allclose(np.degrees(scalars["sweep.cam.max_pressure_angle"]["value"]),
                               table["cam.max_pressure_angle [deg]"], rtol=1e-9)
    assert "Design sweep of cam.base_radius" in (out / "report.html").read_text()


def test_the_cli_refuses_a_bad_column_in_check_and_run_alike(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(EXAMPLE.read_text(encoding="utf-8").replace('"cam.max_normal_force"', '"cam.normal_force"'))
    checked = runner.invoke(app, ["check", str(path)])
    ran = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "o"), "-q"])
    assert checked.exit_code == 2 and ran.exit_code == 2, (checked.output, ran.output)
    for result in (checked, ran):
        assert "sweep.columns[2]: 'cam.normal_force' is not a result of this cam file" in result.output
    assert not (tmp_path / "o").exists()


def test_a_shaft_line_sweeps_a_crank_phase():
    """The in-line four with the second crank's phase swept from 0 to 180 deg (the others at 0, 180, 0): the
    primary part of each cylinder's reciprocating force is m r omega^2 cos(theta + phi_k), so the engine's is
    m r omega^2 |sum_k exp(i phi_k)| = m r omega^2 |1 + exp(i phi)| = 2 m r omega^2 |cos(phi / 2)|, and its couple
    about the central plane (cylinders at z = -135, -45, 45, 135 mm) m r omega^2 |sum_k z_k exp(i phi_k)| =
    m r omega^2 (90 mm) |cos(phi / 2)|. The engine takes the largest over 360 crank angles a degree apart, so a
    peak between two of them is read at most half a degree off: low by at most 1 - cos(0.5 deg) = 3.8e-5 of it
    (tolerance 4e-5). Each column also equals a run of that variant alone (to rounding)."""
    text = (ROOT / "examples" / "shaft_inline_four.toml").read_text(encoding="utf-8")
    ran = run_problem(text + '\n[sweep]\nparameter = "cylinders[1].phase"\nstart = "0 deg"\nstop = "180 deg"\n'
                             'count = 5\ncolumns = ["shaft.engine.primary_force", "shaft.engine.primary_couple"]\n')
    done = ran.outcomes["sweep"].results
    phi = np.radians(done.plan.values_display)
    unit = 0.6 * 0.045 * (4000 * math.pi / 30) ** 2  # m r omega^2 of one cylinder's reciprocating mass [N]
    np.testing.assert_allclose(done.columns["shaft.engine.primary_force"], 2 * unit * np.abs(np.cos(phi / 2)),
                               rtol=4e-5, atol=1e-9 * unit)
    np.testing.assert_allclose(done.columns["shaft.engine.primary_couple"], 0.09 * unit * np.abs(np.cos(phi / 2)),
                               rtol=4e-5, atol=1e-9 * unit)
    alone = run_problem(text.replace('phase = "180 deg"', 'phase = "90 deg"', 1))
    assert done.columns["shaft.engine.primary_couple"][2] == pytest.approx(
        alone.results["shaft.engine.primary_couple"], rel=1e-12)


def test_the_sweep_reports_its_progress_and_estimates_its_time(monkeypatch):
    """The command line's progress bar moves with each variant, and a long sweep is announced with an estimate
    from its first variant's time (announced here however short, the threshold set to 0 s)."""
    import importlib

    ex = importlib.import_module("machdyn.studies.exploration.execution")
    monkeypatch.setattr(ex, "ANNOUNCE_AFTER", 0.0)
    moved: list[tuple[int, int]] = []
    said: list[str] = []
    with ex.execution(progress=lambda done, total: moved.append((done, total)), estimate=said.append):
        run_problem(_with_sweep('parameter = "cam.speed"\nvalues = ["100 rpm", "200 rpm", "300 rpm"]\n'
                                'columns = ["cam.jump_speed"]\n'))
    assert moved == [(1, 3), (2, 3), (3, 3)]
    assert len(said) == 1 and said[0].startswith("3 variants of cam.speed, each run whole: about ")


def test_workers_asked_for_a_sweep_run_variant_by_variant_run_its_variants(tmp_path):
    """--workers spreads a cam sweep's variants over worker processes, and says so (two variants suffice)."""
    path = tmp_path / "two.toml"
    path.write_text(EXAMPLE.read_text(encoding="utf-8").replace("count = 9", "count = 2"), encoding="utf-8")
    ran = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "out"), "--workers", "2"])
    assert ran.exit_code == 0, ran.output
    assert "ran per design, 2 workers" in ran.output
