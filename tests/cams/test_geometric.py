"""Cams with specified contours (Khurmi & Gupta, *Theory of Machines*, 14th ed., ch. 20, §§20.13-20.14): the
closed forms checked by their own geometry, continuity where contact passes from flank to nose, and finite
differences of the displacement."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.cams.geometric import circular_arc_flat, tangent_roller
from machdyn.errors import InputError

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
