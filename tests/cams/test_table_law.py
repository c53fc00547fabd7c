"""A follower motion given as a table: the quintic spline through the designer's points, its continuity up to the
jerk, its ends that join dwells, its agreement with the law it was sampled from, and the problem file."""

from __future__ import annotations

import numpy as np
import pytest
from typer.testing import CliRunner

from machdyn.cams.laws import normalised
from machdyn.cams.program import Segment, program
from machdyn.cams.table_law import table_law
from machdyn.cli import app
from machdyn.runner import run_problem
from problem_texts import table_cam

POINTS = ((0.2, 0.06), (0.45, 0.4), (0.7, 0.85))


def test_the_spline_passes_its_points_and_joins_dwells_at_rest():
    law = table_law(POINTS)
    x = np.array([0.0, *(p[0] for p in POINTS), 1.0])
    y, y1, y2, _ = law(x)
    assert np.allclose(y, [0.0, *(p[1] for p in POINTS), 1.0], atol=1e-12)
    assert np.allclose([y1[0], y1[-1], y2[0], y2[-1]], 0.0, atol=1e-10)


def test_derivatives_are_those_of_the_displacement_and_continuous_through_the_knots():
    """Finite differences of y give y' and of y' give y'' (to the step's error), and each of y, y', y'', y'''
    is continuous across the interior points (degree 5: continuous to the fourth derivative)."""
    law = table_law(POINTS)
    x = np.linspace(0.01, 0.99, 300)
    h = 1e-5
    y, y1, y2, y3 = law(x)
    assert np.allclose((law(x + h)[0] - law(x - h)[0]) / (2 * h), y1, atol=1e-7)
    assert np.allclose((law(x + h)[1] - law(x - h)[1]) / (2 * h), y2, atol=1e-5)
    assert np.allclose((law(x + h)[2] - law(x - h)[2]) / (2 * h), y3, atol=1e-3)
    for knot, _ in POINTS:
        before, after = law(np.array([knot - 1e-9])), law(np.array([knot + 1e-9]))
        for b, a in zip(before, after, strict=True):
            assert a[0] == pytest.approx(b[0], abs=1e-5)


def test_points_sampled_from_a_known_law_give_that_law_back():
    """Limit check: the table law through seven points of the 4-5-6-7 polynomial (zero velocity and acceleration at
    the ends, as the spline's) follows it within 0.1 % of the lift and 2 % of its peak acceleration."""
    xs = np.linspace(0.0, 1.0, 9)[1:-1]
    ref = normalised("poly4567", xs)[0]
    law = table_law(tuple(zip(xs.tolist(), ref.tolist(), strict=True)))
    x = np.linspace(0.0, 1.0, 401)
    y, _, y2, _ = law(x)
    want, _, want2, _ = normalised("poly4567", x)
    assert np.max(np.abs(y - want)) < 1e-3
    assert np.max(np.abs(y2 - want2)) < 0.02 * np.max(np.abs(want2))


def test_a_program_with_a_table_rise_has_no_jumps():
    segs = [Segment("rise", np.radians(120), 0.03, "table", points=POINTS), Segment("dwell", np.radians(60)),
            Segment("return", np.radians(120), 0.03, "poly345"), Segment("dwell", np.radians(60))]
    prog = program(segs)
    assert prog.jumps == ()
    s = prog.svaj(np.radians([0.0, 120.0 * 0.45, 120.0])).s
    assert np.allclose(s, [0.0, 0.03 * 0.4, 0.03], atol=1e-12)


def test_the_problem_file_runs_with_a_table_law():
    run = run_problem(table_cam("points = [[0.2, 0.06], [0.45, 0.4], [0.7, 0.85]]"))
    s = run.scalars
    assert s["cam.stroke"]["value"] == pytest.approx(0.025, rel=1e-9) and s["cam.jumps"]["value"] == 0
    # the largest follower speed: the table rise's peak y' or the 3-4-5 return's 15/8, each h omega / beta
    omega, h, beta = 200 * np.pi / 30, 0.025, np.radians(120)
    peak_table = float(np.max(np.abs(table_law(POINTS)(np.linspace(0, 1, 20001))[1])))
    want = max(peak_table, 15 / 8) * h * omega / beta
    assert s["cam.max_velocity"]["value"] == pytest.approx(want, rel=1e-4)  # the run samples 720 positions


@pytest.mark.parametrize("points", ["points = []", "points = [[0.5, 0.5], [0.4, 0.7]]", "points = [[1.2, 0.5]]"])
def test_check_and_run_refuse_bad_points(points, tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(table_cam(points), encoding="utf-8")
    runner = CliRunner()
    checked = runner.invoke(app, ["check", str(path)])
    ran = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "out"), "--quiet"])
    assert checked.exit_code == 2 and ran.exit_code == 2
    assert "cam.segments[0].points" in checked.stderr and "cam.segments[0].points" in ran.stderr
    assert "Traceback" not in checked.output + ran.output
