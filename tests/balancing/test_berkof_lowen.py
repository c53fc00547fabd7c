"""Full force balance of the four-bar: the centre of mass stands still, and what it costs."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from machdyn.balancing.berkof_lowen import berkof_lowen, required_first_moments
from machdyn.balancing.frame import frame_loads
from machdyn.balancing.general import CounterweightSlot, least_squares_counterweights
from machdyn.errors import InputError
from machdyn.linkage import four_bar, slider_crank


def test_centre_of_mass_stands_still_and_force_vanishes(fourbar):
    result = berkof_lowen(fourbar, 0.08, 0.1, speed=20.0)
    assert result.after.com_spread < 1e-12
    assert result.before.com_spread > 0.05
    assert result.after.peak_force < 1e-12 * result.before.peak_force * 1e3  # zero to rounding
    # at any speed and crank acceleration: the centre of mass does not depend on the motion
    fast = frame_loads(result.model, np.linspace(0, 2 * np.pi, 50), 300.0)
    assert fast.peak_force < 1e-9 * frame_loads(fourbar, fast.crank_angle, 300.0).peak_force


def test_cost_shaking_moment_torque_and_joints_reported(fourbar):
    table = berkof_lowen(fourbar, 0.08, 0.1, speed=20.0).table
    for row in ("rms_moment", "rms_torque", "peak_joint_force"):
        assert table.row(row).after > table.row(row).before  # the counterweights' price for this linkage


def test_least_squares_finds_the_berkof_lowen_counterweights(fourbar):
    bl = berkof_lowen(fourbar, 0.08, 0.1, speed=20.0)
    ls = least_squares_counterweights(fourbar, [CounterweightSlot("crank", radius=0.08),
                                                CounterweightSlot("rocker", radius=0.1)], speed=20.0)
    for a, b in zip(bl.counterweights, ls.counterweights, strict=True):
        assert a.mass == pytest.approx(b.mass, rel=1e-9)
        assert np.allclose(a.position, b.position, atol=1e-12)


def test_required_first_moments_closed_form():
    # uniform coupler: half its mass at each end, so crank and rocker each carry m3/2 at their pins
    m2g2, m4g4 = required_first_moments(3.0, 0.5, 0.2, 0.5)
    assert m2g2 == pytest.approx(-0.3) and m4g4 == pytest.approx(-0.75)


def test_bad_input(fourbar):
    with pytest.raises(InputError, match="four-bar"):
        berkof_lowen(slider_crank(0.1, 0.4), 0.1, 0.1)
    with pytest.raises(InputError, match="radius"):
        berkof_lowen(fourbar, -0.1, 0.1)


@settings(max_examples=20, deadline=None)
@given(crank=st.floats(0.05, 0.12), coupler=st.floats(0.3, 0.5), rocker=st.floats(0.25, 0.45),
       px=st.floats(0.0, 0.3), py=st.floats(-0.1, 0.1), m=st.floats(0.5, 5.0))
def test_property_any_crank_rocker_is_fully_force_balanced(crank, coupler, rocker, px, py, m):
    ground = 0.4
    lengths = sorted([crank, coupler, rocker, ground])
    assume(crank == lengths[0] and lengths[0] + lengths[3] < lengths[1] + lengths[2])  # Grashof crank-rocker
    mech = four_bar(crank, coupler, rocker, ground, masses=(1.0, m, 1.2), coms=(None, (px, py), None),
                    gravity=(0.0, 0.0))
    result = berkof_lowen(mech, 0.05, 0.05, np.linspace(0, 2 * np.pi, 48, endpoint=False), speed=10.0)
    assert result.after.com_spread < 1e-12
    assert result.after.peak_force <= 1e-10 * max(result.before.peak_force, 1.0)


@pytest.mark.parametrize("args", [(2.0, complex("nan"), 0.1, 0.3), (2.0, 0.5, float("inf"), 0.3),
                                  (2.0, 0.5, 0.1, complex(0.3, float("nan")))])
def test_required_first_moments_rejects_non_finite_input(args):
    with pytest.raises(InputError, match="must be a finite complex number"):
        required_first_moments(*args)


@pytest.mark.parametrize("angles", [np.array([]), np.zeros((3, 4))])
def test_empty_or_2d_crank_angles_are_an_input_error(fourbar, angles):
    with pytest.raises(InputError, match="crank_angle must be a non-empty 1-D array"):
        berkof_lowen(fourbar, 0.08, 0.1, crank_angle=angles)
