"""Cams with specified contours against published worked examples with printed answers.

Only one printed answer was at hand: a symmetrical tangent cam with a roller follower, reproduced with its
answer at https://bissoy.com/mcq/375987 (the textbook it comes from is not named there; the data are those of the
tangent-cam worked example of Khurmi & Gupta, *Theory of Machines*, ch. 20, whose printout was not available
here). The circular-arc cam with a flat-faced follower has no printed example here: it is checked by closed forms
and by its own cam profile in tests/cams/test_geometric.py."""

from __future__ import annotations

import math

import pytest

from machdyn.cams.geometric import rise_angle, tangent_roller


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
