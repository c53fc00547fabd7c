"""Geared systems and hoists against printed textbook answers."""

from __future__ import annotations

import pytest

from machdyn.drivetrain.hoist import Shaft, acceleration, optimum_ratio


def test_khurmi_gupta_example_3_14_gear_ratio_for_the_largest_load_acceleration():
    """Khurmi & Gupta, *Theory of Machines* (14th ed.), ch. 3, example 3.14, p. 51: motor torque 100 N m, motor
    inertia 2 kg m^2, load inertia 32 kg m^2; printed: optimum ratio 4, load acceleration 6.25 rad/s^2, motor
    acceleration 25 rad/s^2 (exact values: tolerance rounding)."""
    g = optimum_ratio(2.0, 32.0)
    assert g == pytest.approx(4.0, rel=1e-12)
    train = (Shaft("motor", inertia=2.0), Shaft("load", "motor", g, 1.0, 32.0))
    alpha_motor = acceleration(train, 100.0)
    assert alpha_motor == pytest.approx(25.0, rel=1e-10)
    assert alpha_motor / g == pytest.approx(6.25, rel=1e-10)
    # and it is the optimum: the same train with a ratio 5 % either side accelerates the load less
    for other in (0.95 * g, 1.05 * g):
        near = (Shaft("motor", inertia=2.0), Shaft("load", "motor", other, 1.0, 32.0))
        assert acceleration(near, 100.0) / other < 6.25
