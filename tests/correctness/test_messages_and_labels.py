"""Messages and labels that say what they mean: the cam program's jumps (grammar and unit), the defaults a bare
custom body takes, the custom mechanism's points as design variables, the time ratio's label, a lever that turns
fully, the curvature-limit label, the synthesis table's headers and the sweep table in SI."""

from __future__ import annotations

import re

import numpy as np
import pytest

from machdyn.cams.program import Jump
from machdyn.linkage.diagnostics import full_turn_stroke
from machdyn.problem.paths import assign, quantity_unit, value_at
from machdyn.reading import load_problem
from machdyn.results.catalogue import label
from machdyn.runner import check_problem, run_problem

from .helpers import EXAMPLES, ROOT

CUSTOM = re.search(r'```toml\n(\[mechanism\]\ntype = "custom".*?)```',
                   (ROOT / "docs" / "problem-files.md").read_text(encoding="utf-8"), re.S).group(1) + \
    '\n[drive]\nspeed = "60 rpm"\npositions = 36\n'


def test_a_jump_is_said_with_its_article_and_the_unit_of_the_lift():
    jump = Jump("acceleration", np.radians(110.0), 0.0, 0.18, (0, 1))
    assert jump.describe("m") == ("an acceleration jump from 0 to 0.18 m/rad^2 at cam angle 110 deg (segments 1 "
                                  "to 2)")
    assert Jump("velocity", 0.0, 0.0, 0.5, (3, 0)).describe("rad").startswith("a velocity jump from 0 to 0.5 rad/rad ")


def test_the_feeder_cams_warnings_name_its_jumps_in_metres():
    text = (EXAMPLES / "feeder_cam.toml").read_text(encoding="utf-8").replace('law = "poly345"', 'law = "harmonic"')
    warnings = [w for w in check_problem(text) if "jump" in w]
    assert warnings and all(w.startswith("the motion program has an acceleration jump from ") for w in warnings)
    assert all(" m/rad^2 at cam angle " in w for w in warnings)


@pytest.mark.parametrize(("given", "said", "unsaid"), [
    ('inertia = "0.01 kg*m^2"', "without com; its centre of mass is taken at the body's origin", "inertia is taken"),
    ('com = ["10 mm", "0 mm"]', "without inertia; its inertia is taken as 0 kg*m^2", "centre of mass is taken"),
    ("", "without inertia or com; its inertia is taken as 0 kg*m^2 (a point mass) and its centre of mass", "\0"),
])
def test_a_bare_custom_body_is_told_only_what_it_left_out(given, said, unsaid):
    text = CUSTOM.replace('name = "lever"\nmass = "1.2 kg"', f'name = "lever"\nmass = "1.2 kg"\n{given}')
    warnings = [w for w in run_problem(text).warnings if "('lever')" in w]
    assert len(warnings) == 1 and said in warnings[0] and unsaid not in warnings[0], warnings


def test_the_points_of_a_custom_mechanism_are_quantities_of_the_file():
    problem = load_problem(CUSTOM)
    assert quantity_unit(problem, "mechanism.ground.C[1]").unit == "m"
    assert quantity_unit(problem, "mechanism.bodies[0].points.A[0]").unit == "m"
    moved = assign(problem, "mechanism.bodies[0].points.A[0]", 0.06)
    assert value_at(moved, "mechanism.bodies[0].points.A[0]") == 0.06
    assert value_at(problem, "mechanism.bodies[0].points.A[0]") == pytest.approx(0.05)
    with pytest.raises(ValueError, match="points has no entry 'Q'"):
        quantity_unit(problem, "mechanism.bodies[0].points.Q[0]")


def test_a_custom_mechanisms_point_is_an_optimise_variable():
    text = CUSTOM + '''
[optimise]
population = 6
generations = 2
seed = 1

[[optimise.variables]]
parameter = "mechanism.ground.C[1]"
lower = "-200 mm"
upper = "-100 mm"

[[optimise.objectives]]
result = "driving_torque.max_abs"
'''
    best = run_problem(text).outcomes["optimise"].results
    assert -0.2 <= best.x[0] <= -0.1


def test_the_time_ratio_is_labelled_as_it_is_computed():
    assert label("time_ratio").text == "Time ratio (the longer over the shorter stroke time, >= 1)"
    assert "advance" not in label("time_ratio.lever").text


def test_a_lever_that_turns_fully_has_a_stroke_of_a_full_turn():
    step = np.radians(1.0)
    assert full_turn_stroke(2 * np.pi - step, step) == 2 * np.pi
    assert full_turn_stroke(np.radians(300.0), step) == pytest.approx(np.radians(300.0))
    whitworth = '''
[mechanism]
type = "inverted_slider_crank"
[mechanism.crank]
length = "100 mm"
mass = "1 kg"
[mechanism.ground]
length = "50 mm"
[mechanism.block]
mass = "1 kg"
[mechanism.rocker]
length = "200 mm"
mass = "2 kg"
[drive]
speed = "60 rpm"
positions = 360
'''
    assert run_problem(whitworth).results["stroke.rocker"] == pytest.approx(2 * np.pi, abs=1e-12)


def test_the_smallest_base_circle_of_the_curvature_limit_is_not_called_undercut():
    from machdyn.cams.stage import LABELS

    text = LABELS["cam.min_base_radius_curvature"].text
    assert "curvature limit" in text and "undercut" not in text


def test_the_sweep_table_is_in_si_with_units_in_its_headers(tmp_path):
    result = run_problem((EXAMPLES / "four_bar_sweep.toml").read_text(encoding="utf-8").replace("count = 31",
                                                                                                 "count = 3"))
    frame = result.frames["sweep"]
    assert "mechanism.crank.length [m]" in frame.columns
    assert frame["mechanism.crank.length [m]"].tolist() == pytest.approx([0.025, 0.04, 0.055])


def test_the_synthesis_table_gives_each_error_in_its_unit_and_the_defects_as_a_count():
    result = run_problem((EXAMPLES / "synthesis_function_log10.toml").read_text(encoding="utf-8"))
    columns = list(result.frames["synthesis_candidates"].columns)
    assert {"position_error [m]", "angle_error [deg]", "defect_count"} <= set(columns)
    assert "error" not in columns and "defects" not in columns
