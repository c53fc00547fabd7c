"""Files that ``check`` used to accept and ``run`` then refused (exit 2), crashed on (exit 1 or 4) or worked on
for minutes: each is now classified the same way by both, with a message naming the field and the rule."""

from __future__ import annotations

import pytest

from reproductions import (
    compactor_derived,
    empty_speed_fractions,
    example,
    press_with_brake,
    replaced,
    stalling_compactor,
    synthesis,
    tiny_cam_segments,
)

from .helpers import check_and_run

REFUSED = [
    ("empty_conveyor_speed_fractions",
     empty_speed_fractions,
     "screw_conveyor.optimise.speed_fractions: must have at least 1 item"),
    ("derived_formula_divides_by_zero", lambda: compactor_derived("2000 * 0.1 / (l - l)"),
     "optimise.derived.loads.forces[0].fy: '2000 * 0.1 / (l - l)' is not finite anywhere"),
    ("derived_formula_overflows", lambda: compactor_derived("*".join(["1e12"] * 30) + " * l"),
     "optimise.derived.loads.forces[0].fy: "),
    ("derived_length_negative_everywhere",
     lambda: replaced(example("compactor_optimise"), '"mechanism.ground.length" = "hypot(l, h)"',
                      '"mechanism.ground.length" = "l - 1"'),
     "optimise.derived.mechanism.ground.length: 'l - 1' must be >0"),
    ("cam_segment_of_1e-300_deg", tiny_cam_segments,
     "cam.segments[4].angle must be at least 0.001 deg"),
    ("synthesis_reciprocal_across_zero", lambda: synthesis("reciprocal", "[-1.0, 2.0]"),
     "synthesis.x_range: the function reciprocal must be defined and finite over its whole range: "
     "reciprocal(x) = 1/x is undefined at x = 0"),
    ("synthesis_nan_range", lambda: synthesis("log10", "[nan, 2.0]"),
     "synthesis.x_range: the function log10 must be defined and finite over its whole range: the range must be "
     "finite"),
    ("synthesis_tan_across_its_pole", lambda: synthesis("tan", "[1.0, 2.0]"),
     "tan(x) is undefined at x = 1.5708"),
    ("synthesis_exp_overflows", lambda: synthesis("exp", "[1.0, 800.0]"), "exp(x) is not finite at x = 710"),
    ("brake_weaker_than_an_overhauling_load", lambda: press_with_brake("2000 N*m"),
     "drivetrain.brake.torque: the brake's 1200 N*m at the crank does not exceed the mean driving moment of the "
     "loads over a turn"),
]


@pytest.mark.parametrize(("make", "message"), [c[1:] for c in REFUSED], ids=[c[0] for c in REFUSED])
def test_check_refuses_what_run_refuses_naming_the_field(tmp_path, make, message):
    check, run = check_and_run(tmp_path, make())
    assert (check.code, run.code) == (2, 2), (check, run)
    for said in (check, run):
        assert message in said.stderr, said.stderr
        assert "Warning" not in said.stderr and "LinAlgError" not in said.stderr and "internal" not in said.stderr
    assert not (tmp_path / "out").exists()


def test_a_brake_just_stronger_than_the_overhauling_load_stops_the_press(tmp_path):
    """1150 N*m driving against the brake's 1200 N*m: the balance holds, the stop is integrated, and at about a
    third of a turn it fails the brake's 30 deg limit (exit 3)."""
    text = replaced(press_with_brake("1150 N*m"), "positions = 360", "positions = 90")
    text = replaced(text, 'shaft = "flywheel shaft"\nmax_angle', 'shaft = "flywheel shaft"\nat = ["0 deg"]\nmax_angle')
    check, run = check_and_run(tmp_path, text)
    assert check.code == 0 and run.code == 3, (check, run)
    assert "brake: the crank overruns" in run.stderr


def test_a_motor_that_stalls_against_a_damper_is_a_failed_check_not_bad_input(tmp_path):
    """The compactor's 0.75 kW motor against a 200 N*m*s/rad damper stalls in the cycle: a design that fails
    (exit 3, the figures said), as for a drive too small for its load, since check cannot know it."""
    check, run = check_and_run(tmp_path, stalling_compactor())
    assert check.code == 0 and run.code == 3, (check, run)
    assert "The machine stalls: its speed falls to zero" in run.stderr and "breakdown torque" in run.stderr
    assert (tmp_path / "out" / "report.html").is_file()


def _single_stroke_press(extra: str = "", overhauling: str | None = None) -> str:
    """The drive-train press without its parts, at 90 positions, with ``extra`` after its single-stroke table."""
    text = example("crank_press_drive")
    text = text[: text.index("[[parts.bearings]]")] + extra
    text = replaced(text, "positions = 360", "positions = 90")
    text = replaced(text, "[flywheel.motor]", "start_up = false\n\n[flywheel.motor]")
    if overhauling is not None:
        text = replaced(text, "[flywheel]\n", f'[[loads.torques]]\nname = "overhauling"\nbody = "crank"\n'
                                               f'torque = "{overhauling}"\n\n[flywheel]\n')
    return text


def test_a_brake_angle_outside_the_single_stroke_is_refused_by_check_and_run(tmp_path):
    text = replaced(_single_stroke_press(), 'start = "90 deg"', 'start = "90 deg"\nbrake_at = "45 deg"')
    check, run = check_and_run(tmp_path, text)
    assert (check.code, run.code) == (2, 2), (check, run)
    assert "single_stroke.brake_at must lie within the stroke" in check.stderr


def test_a_single_stroke_the_brake_cannot_end_is_a_failed_check(tmp_path):
    """1150 N*m driving the crank against the brake's 1200 N*m (no flywheel: the clutch's own motor torque): the
    brake stops the machine (the balance holds) but not within the half turn a single stroke leaves it: a failed
    check of a valid file (exit 3), not bad input after check said OK."""
    text = _single_stroke_press(overhauling="1150 N*m")
    text = text[: text.index("[flywheel]")] + text[text.index("[drivetrain]"):]
    text = replaced(text, "strokes_per_minute = 20", "strokes_per_minute = 20\nmotor_torque = \"100 N*m\"")
    check, run = check_and_run(tmp_path, text)
    assert check.code == 0 and run.code == 3, (check, run)
    assert "single stroke: The brake torque 1200 N*m (at the crank) cannot stop the crank within half a turn" \
        in run.stderr
