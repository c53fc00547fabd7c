"""Crank counterweights and the partial-balance trade-off, checked against the closed-form primary forces."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from machdyn.balancing.counterweights import (
    balance_mass,
    crank_counterweight,
    primary_unbalanced_force,
    secondary_unbalanced_force,
    slider_crank_masses,
    tradeoff_curve,
)
from machdyn.errors import InputError
from machdyn.linkage import PointMass, four_bar, slider_crank


def _point_engine(rod_ratio: float):
    """Revolving 4 kg at the 0.1 m crank pin, 6 kg reciprocating, massless rod of rod_ratio x crank."""
    mech = slider_crank(0.1, 0.1 * rod_ratio, masses=(0.0, 0.0, 6.0), inertias=(0.0, 0.0, 0.0), gravity=(0.0, 0.0))
    return replace(mech, point_masses=(PointMass("revolving", "crank", 4.0, (0.1, 0.0)),))


def test_split_of_the_rod_is_the_static_two_point_substitute(engine):
    masses = slider_crank_masses(engine)
    assert masses.rotating_mass == pytest.approx(2.0 * 0.14 / 0.2)
    assert masses.reciprocating_mass == pytest.approx(2.0 * 0.06 / 0.2 + 3.0)
    assert masses.rotating_moment == pytest.approx((1.0 * 0.01 + masses.rotating_mass * 0.05, 0.0))


@pytest.mark.parametrize("fraction", [0.0, 0.5, 2.0 / 3.0, 1.0])
def test_engine_residual_is_the_primary_formula_plus_the_secondary(fraction):
    # exact kinematics: along = primary + secondary + O(1/n^3); across = primary exactly (massless rod)
    n, w = 40.0, 25.0
    mech = _point_engine(n)
    result = crank_counterweight(mech, fraction, 0.2, np.linspace(0, 2 * np.pi, 37), speed=w)
    assert result.counterweights[0].mass == pytest.approx(balance_mass(4.0, 6.0, 0.1, fraction, 0.2))
    theta = result.after.crank_angle
    along, across = primary_unbalanced_force(theta, 6.0, 0.1, w, fraction)
    along = along + secondary_unbalanced_force(theta, 6.0, 0.1, w, n)
    amplitude = 6.0 * 0.1 * w**2
    # the engine's frame force is the inertia force -m a, the textbook's unbalanced force is +m r w^2 cos:
    # same magnitude along the stroke; the across component of the counterweight is -c m r w^2 sin(theta)
    assert np.max(np.abs(result.after.fx - along)) < 2.0 / n**3 * amplitude
    assert np.max(np.abs(result.after.fy + across)) < 1e-9 * amplitude


def test_tradeoff_curve_moves_force_from_along_to_across(engine):
    curve = tradeoff_curve(engine, 0.08, np.linspace(0, 1, 11), speed=50.0)
    assert np.all(np.diff(curve.peak_along) < 0)
    assert np.all(np.diff(curve.peak_across) > 0)
    # each fraction of the vectorised call equals a separate balance
    single = crank_counterweight(engine, 0.3, 0.08, speed=50.0)
    one = tradeoff_curve(engine, 0.08, [0.3], speed=50.0)
    assert one.peak_total[0] == pytest.approx(single.after.peak_force, rel=1e-12)
    # with the rotating masses fully balanced and c = 0 nothing is left across the stroke but the rod's
    # own (non-substituted) inertia; c = 1/2 has the lowest peak of the primary force
    assert curve.peak_total[np.argmin(curve.peak_total)] < curve.peak_total[0]


def test_full_rotating_balance_leaves_reciprocating_force_only(engine):
    result = crank_counterweight(engine, 0.0, 0.08, speed=50.0)
    assert result.table.row("rms_force").after < result.table.row("rms_force").before
    assert result.model.point_masses[-1].body == "crank"


def test_bad_input():
    with pytest.raises(InputError, match="fraction"):
        balance_mass(1.0, 1.0, 0.1, 1.5, 0.2)
    with pytest.raises(InputError, match="no slider-crank"):
        slider_crank_masses(four_bar(1, 3, 3, 3))
    with pytest.raises(InputError, match="radius"):
        crank_counterweight(_point_engine(4.0), 0.5, 0.0)


def test_crank_counterweight_costs_no_driving_torque_at_constant_speed(engine):
    # a mass on the uniformly turning crank keeps its kinetic energy (gravity off): the drive feels nothing,
    # while the crank bearing carries the counterweight's centrifugal force
    result = crank_counterweight(engine, 0.5, 0.08, speed=80.0)
    assert np.max(np.abs(result.after.torque - result.before.torque)) < 1e-9 * np.max(np.abs(result.before.torque))
    cw = result.counterweights[0]
    assert result.after.joint_peaks["O"] != pytest.approx(result.before.joint_peaks["O"])
    assert cw.mass * 0.08 == pytest.approx(slider_crank_masses(engine).rotating_moment[0]
                                           + 0.5 * slider_crank_masses(engine).reciprocating_mass * 0.05)
