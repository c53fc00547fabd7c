"""Cams with specified contours (Khurmi & Gupta, *Theory of Machines*, 14th ed., ch. 20, §§20.13-20.14): the
closed forms checked by their own geometry, continuity where contact passes from flank to nose, and finite
differences of the displacement."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.cams.geometric import circular_arc_flat, tangent_roller
from machdyn.errors import InputError
from problem_texts import circular_arc_cam

R1, R2, H = 0.02, 0.005, 0.012
OMEGA = 50.0


@pytest.mark.parametrize("make", [
    lambda t: circular_arc_flat(R1, R2, H, 0.09, t, OMEGA),
    lambda t: tangent_roller(R1, R2, H, 0.008, t, OMEGA),
])
def test_rise_goes_from_base_to_full_lift_smoothly_and_its_derivatives_are_consistent(make):
    alpha = make([0.0]).alpha
    m = make(np.linspace(0.0, alpha, 4001))
    assert m.x[0] == pytest.approx(0.0, abs=1e-15) and m.x[-1] == pytest.approx(H, rel=1e-12)
    assert m.v[0] == pytest.approx(0.0, abs=1e-12) and m.v[-1] == pytest.approx(0.0, abs=1e-9)
    # across phi: position and speed continuous (the acceleration jumps there, as the book says)
    lo, hi = make([m.phi - 1e-10]), make([m.phi + 1e-10])
    assert hi.x[0] == pytest.approx(lo.x[0], abs=1e-10)  # 2e-10 rad apart at dx/dtheta < 0.05 m
    assert hi.v[0] == pytest.approx(lo.v[0], rel=1e-6)
    # finite differences of x give v / omega and of v give a / omega on each side
    h = 1e-6
    for t in (0.3 * m.phi, 0.5 * (m.phi + alpha), 0.9 * alpha):
        p, c, q = make([t - h]), make([t]), make([t + h])
        assert (q.x[0] - p.x[0]) / (2 * h) * OMEGA == pytest.approx(c.v[0], rel=1e-6)
        assert (q.v[0] - p.v[0]) / (2 * h) * OMEGA == pytest.approx(c.a[0], rel=1e-5)


def test_the_geometry_behind_the_angles():
    """Circular arc: the flank's centre, the nose's centre and O make the triangle of the formula; tangent cam:
    the flank line is tangent to both circles."""
    d = R1 + H - R2
    arc = circular_arc_flat(R1, R2, H, 0.09, [0.0])
    p = -(0.09 - R1) * np.exp(1j * 0.0)
    q = d * np.exp(1j * arc.alpha)
    assert abs(q - p) == pytest.approx(0.09 - R2, rel=1e-12)
    tan = tangent_roller(R1, R2, H, 0.0, [0.0])
    q = d * np.exp(1j * tan.alpha)
    # the flank line x = r1 (normal along the axis at the start of the rise) is at r2 from the nose centre
    assert R1 - q.real == pytest.approx(R2, rel=1e-12)


def test_bad_shapes_are_refused():
    with pytest.raises(InputError, match="nose radius"):
        tangent_roller(0.01, 0.02, 0.01, 0.0, [0.0])
    with pytest.raises(InputError, match="flank radius"):
        circular_arc_flat(R1, R2, H, 0.025, [0.0])
    with pytest.raises(InputError, match="rise"):
        tangent_roller(R1, R2, H, 0.0, [3.0])


def test_a_circular_arc_cam_file_gives_back_its_own_contour():
    """Two methods: the follower's motion from the contour's closed form, then the cam's profile from that motion
    by the cam module's own envelope (knowing nothing of the contour): its radius of curvature is the flank's
    90 mm on the flank, the nose's 5 mm on the nose and the base circle's 20 mm on the dwell."""
    from machdyn.runner import run_problem

    run = run_problem(circular_arc_cam())
    cam = run.outcomes["cam"].results.model
    rho = cam.profile.surface_curvature_radius
    phi = circular_arc_flat(0.02, 0.005, 0.012, 0.09, [0.0]).phi
    n = rho.size
    at = lambda deg: rho[int(round(deg / 360.0 * n))]  # noqa: E731
    assert at(0.5 * np.degrees(phi)) == pytest.approx(0.09, rel=1e-6)
    assert at(np.degrees(phi) + 10.0) == pytest.approx(0.005, rel=1e-6)
    assert at(250.0) == pytest.approx(0.02, rel=1e-6)
    # the acceleration jumps at the start of the flank and where contact passes to the nose are listed
    jumps = [j for j in cam.program.jumps if j.quantity == "acceleration"]
    assert any(abs(j.angle - phi) < 1e-9 for j in jumps)


@pytest.mark.parametrize(("contact", "angle", "field"), [
    ("roller", None, "cam.segments[0].law"),
    ("flat", 60.0, "cam.segments[0].angle"),
])
def test_check_and_run_refuse_a_contour_that_does_not_fit(contact, angle, field, tmp_path):
    from typer.testing import CliRunner

    from machdyn.cli import app

    path = tmp_path / "bad.toml"
    path.write_text(circular_arc_cam(contact, angle), encoding="utf-8")
    runner = CliRunner()
    checked = runner.invoke(app, ["check", str(path)])
    ran = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "out"), "--quiet"])
    assert checked.exit_code == 2 and ran.exit_code == 2
    assert field in checked.stderr and field in ran.stderr


def test_the_radius_a_given_angle_of_rise_needs():
    """The inverse of the rise angle: the flank radius (circular arc) and the nose radius (tangent cam) solved
    from the angle give back that angle; angles the shape cannot have are refused with the limit."""
    from machdyn.cams.geometric import flank_radius_for_angle, nose_radius_for_angle, rise_angle

    for flank in (0.04, 0.09, 0.5):
        alpha = rise_angle("circular_arc", R1, R2, H, flank)
        assert flank_radius_for_angle(R1, R2, H, alpha) == pytest.approx(flank, rel=1e-10)
    for nose in (0.002, 0.005, 0.015):
        alpha = rise_angle("tangent", R1, nose, H, 0.008)
        assert nose_radius_for_angle(R1, H, alpha) == pytest.approx(nose, rel=1e-10)
    straight = rise_angle("tangent", R1, R2, H, 0.008)  # a circular arc's flanks straighten as R grows
    assert flank_radius_for_angle(R1, R2, H, straight + 1e-6) > 100.0
    with pytest.raises(InputError, match="above"):
        flank_radius_for_angle(R1, R2, H, straight - 1e-3)
    with pytest.raises(InputError, match="too large"):
        flank_radius_for_angle(R1, R2, H, np.radians(179))
    with pytest.raises(InputError, match="above"):
        nose_radius_for_angle(R1, H, np.radians(10))
    with pytest.raises(InputError, match="90 deg"):
        nose_radius_for_angle(R1, H, np.radians(95))


def test_a_cam_file_may_give_the_angle_of_rise_instead_of_the_flank_radius(tmp_path):
    """A circular-arc segment without flank_radius takes the one its angle needs (the same cam as with the
    90 mm flank given); an angle no circular arc can have is refused by check and run, naming the angle."""
    from typer.testing import CliRunner

    from machdyn.cli import app
    from machdyn.runner import run_problem

    text = circular_arc_cam().replace('flank_radius = "90 mm"\n', "")
    run = run_problem(text)
    given = run_problem(circular_arc_cam())
    solved = run.outcomes["cam"].results.model.program
    assert np.allclose(solved.segments[0].contour, given.outcomes["cam"].results.model.program.segments[0].contour,
                       rtol=1e-9, atol=0.0)
    bad = tmp_path / "bad.toml"
    bad.write_text(circular_arc_cam(angle=30.0).replace('flank_radius = "90 mm"\n', ""), encoding="utf-8")
    checked = CliRunner().invoke(app, ["check", str(bad)])
    assert checked.exit_code == 2 and "cam.segments[0].angle" in checked.stderr and "above" in checked.stderr
