"""Cams with specified contours against published worked examples with printed answers.

- A symmetrical tangent cam with a roller follower, reproduced with its answer at https://bissoy.com/mcq/375987
  (the textbook it comes from is not named there; the data are those of the tangent-cam worked example of Khurmi &
  Gupta, *Theory of Machines*, ch. 20, whose printout was not available here).
- A circular-arc cam with a flat-faced follower: T. Bevan, *The Theory of Machines*, 3rd ed. (CBS, Dorling
  Kindersley reprint 2005), ch. 9 "Cams", Example 5, p. 300. The book's data and its printed equations of motion
  (with their numbers) are read from the public FOSSEE Python Textbook Companion of the book
  (The_Theory_of_Machines_by_T._Bevan/ch9.ipynb, which plots them and prints nothing); the book works in inches and
  feet per second.

No other printed example of a contour cam was at hand: the tangent cam's flank-to-nose and apex values are checked
by closed forms and by the cam's own profile in tests/cams/test_geometric.py."""

from __future__ import annotations

import json
import math

import pytest
from typer.testing import CliRunner

from machdyn.cams.geometric import circular_arc_flat, contour_phi, flank_radius_for_angle, rise_angle, tangent_roller
from machdyn.cli import app


def test_tangent_cam_roller_follower_acceleration_at_the_beginning_of_the_lift():
    """Least radius 30 mm, roller 17.5 mm, angle of ascent 75°, lift 17.5 mm, 600 rpm. Printed: the
    follower's acceleration at the beginning of the lift, 187.6 m/s² (ω²(r1 + r2) on the straight flank). The nose
    radius is not given: the tangent cam's shape fixes it by the angle of ascent, cos α = (r1 − r_n)/(r1 + h −
    r_n), which machdyn's rise angle must return (r_n = 23.89 mm). Tolerance: half the last printed digit plus the
    book's ω = 62.84 rad/s (2π·600/60 = 62.832 rounded up: +0.026 % on ω², 0.05 m/s²)."""
    base, roller, lift, ascent = 0.030, 0.0175, 0.0175, math.radians(75)
    nose = (base - (base + lift) * math.cos(ascent)) / (1 - math.cos(ascent))
    assert rise_angle("tangent", base, nose, lift, roller) == pytest.approx(ascent, rel=1e-12)
    omega = 600 * math.pi / 30
    start = tangent_roller(base, nose, lift, roller, [0.0], omega)
    assert float(start.a[0]) == pytest.approx(187.6, abs=0.05 + 0.05)
    assert float(start.a[0]) == pytest.approx(omega**2 * (base + roller), rel=1e-12)
    # at full lift the roller sits on the nose's apex: the lift is the given one and the acceleration negative
    top = tangent_roller(base, nose, lift, roller, [start.alpha], omega)
    assert float(top.x[0]) == pytest.approx(lift, rel=1e-12) and float(top.a[0]) < 0


# Bevan's Example 5: base (least) radius 1.125 in, nose radius 0.125 in, lift 0.5 in, the rise over 55°, 1200 rpm.
INCH, FOOT = 0.0254, 0.3048
BEVAN_BASE, BEVAN_NOSE, BEVAN_LIFT = 1.125 * INCH, 0.125 * INCH, 0.5 * INCH
BEVAN_RISE = math.radians(55)
BEVAN_OMEGA = 1200 * math.pi / 30


def _bevan_flank_radius() -> float:
    """The flank radius R [m] whose rise lasts the book's 55°: machdyn's rise angle solved for R (it grows with R)."""
    from scipy.optimize import brentq

    def excess(flank: float) -> float:
        return rise_angle("circular_arc", BEVAN_BASE, BEVAN_NOSE, BEVAN_LIFT, flank) - BEVAN_RISE

    return float(brentq(excess, BEVAN_BASE + BEVAN_LIFT + 1e-6, 1.0, xtol=1e-15, rtol=1e-15))


def test_bevan_example_5_circular_arc_cam_with_a_flat_faced_follower():
    """Bevan, *The Theory of Machines*, 3rd ed., ch. 9, Example 5, p. 300: a circular-arc cam with a flat-faced
    follower, least radius 1.125 in, nose radius 0.125 in, lift 0.5 in over 55° of cam angle at 1200 rpm; the
    flank radius follows from the triangle of the cam's, the flank's and the nose's centres. Printed, the book's
    equations of motion with their numbers: on the flank x = 4.477 (1 − cos θ) in (so R − r1 = 4.477 in), on the
    nose x = 1.5 cos(α − θ) − 1 in, v = 15.71 sin(α − θ) ft/s, a = −1974 cos(α − θ) ft/s².

    machdyn's rise angle solved for the flank radius gives R − r1 = 4.4759 in: the book's 4.477 comes from cos 55°
    rounded to 0.5736 (which gives 4.4771), so its tolerance is 0.002 in. The nose's amplitudes ω d = 15.708 ft/s
    and ω² d = 1973.9 ft/s² are checked at three nose angles to half a unit of the last printed digit."""
    flank = _bevan_flank_radius()
    assert (flank - BEVAN_BASE) / INCH == pytest.approx(4.477, abs=0.002)
    # the closed form of the book's triangle agrees with the root of the rise angle
    assert flank_radius_for_angle(BEVAN_BASE, BEVAN_NOSE, BEVAN_LIFT, BEVAN_RISE) == pytest.approx(flank, rel=1e-12)
    phi = contour_phi("circular_arc", BEVAN_BASE, BEVAN_NOSE, BEVAN_LIFT, flank)
    on_flank = [0.2 * phi, 0.6 * phi, phi]
    m = circular_arc_flat(BEVAN_BASE, BEVAN_NOSE, BEVAN_LIFT, flank, on_flank, BEVAN_OMEGA)
    for theta, x in zip(on_flank, m.x, strict=True):
        assert x / INCH / (1 - math.cos(theta)) == pytest.approx(4.477, abs=0.002)
    on_nose = [phi + f * (BEVAN_RISE - phi) for f in (0.1, 0.5, 0.9)]
    m = circular_arc_flat(BEVAN_BASE, BEVAN_NOSE, BEVAN_LIFT, flank, on_nose, BEVAN_OMEGA)
    for theta, x, v, a in zip(on_nose, m.x, m.v, m.a, strict=True):
        back = BEVAN_RISE - theta
        assert x / INCH == pytest.approx(1.5 * math.cos(back) - 1.0, abs=1e-12)
        assert v / FOOT / math.sin(back) == pytest.approx(15.71, abs=0.005)
        assert a / FOOT / math.cos(back) == pytest.approx(-1974.0, abs=0.5)
    top = circular_arc_flat(BEVAN_BASE, BEVAN_NOSE, BEVAN_LIFT, flank, [BEVAN_RISE], BEVAN_OMEGA)
    assert float(top.x[0]) == pytest.approx(BEVAN_LIFT, rel=1e-12) and float(top.v[0]) == pytest.approx(0, abs=1e-12)


def _bevan_problem() -> str:
    rest = 360 - 2 * 55
    segment = """
[[cam.segments]]
motion = "{motion}"
angle = "55 deg"                # the book's angle of rise: the flank radius follows from it
lift = "0.5 in"
law = "circular_arc"
nose_radius = "0.125 in"
"""
    return ("""[meta]
name = "Bevan, The Theory of Machines, ch. 9, Example 5"

[cam]
speed = "1200 rpm"
base_radius = "1.125 in"

[cam.follower]
motion = "translating"
contact = "flat"
""" + segment.format(motion="rise") + segment.format(motion="return")
            + f"""
[[cam.segments]]
motion = "dwell"
angle = "{rest} deg"
""")


def test_bevan_example_5_through_a_problem_file_and_the_command_line(tmp_path):
    """Bevan, *The Theory of Machines*, 3rd ed., ch. 9, Example 5, p. 300 (above), typed as the book gives it — the
    radii, the lift and the angle of rise, no flank radius — and run by ``machdyn run``. The rise's largest
    acceleration is at the start of the flank, ω² (R − r1): with the book's R − r1 = 4.477 in it is 5891 ft/s²
    (tolerance 0.05 %, the book's rounding of R − r1); its largest velocity is where contact passes to the nose, the
    book's
    15.71 ft/s × sin(α − φ) (half a unit of the printed digit); the return mirrors the rise."""
    flank = _bevan_flank_radius()
    path = tmp_path / "bevan5.toml"
    path.write_text(_bevan_problem())
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(out), "-q"])
    assert result.exit_code in (0, 3), result.output
    scalars = json.loads((out / "results.json").read_text())["scalars"]
    rise, back = scalars["cam.segment1.max_acceleration"], scalars["cam.segment2.max_acceleration"]
    assert rise["unit"] == "m/s^2"
    assert rise["value"] / FOOT == pytest.approx(BEVAN_OMEGA**2 * 4.477 * INCH / FOOT, rel=5e-4)
    assert back["value"] == pytest.approx(rise["value"], rel=1e-9)
    phi = contour_phi("circular_arc", BEVAN_BASE, BEVAN_NOSE, BEVAN_LIFT, flank)
    top_speed = scalars["cam.segment1.max_velocity"]["value"] / FOOT
    assert top_speed == pytest.approx(15.71 * math.sin(BEVAN_RISE - phi), abs=0.005 * math.sin(BEVAN_RISE - phi))
