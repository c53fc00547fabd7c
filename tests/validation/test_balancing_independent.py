"""The frame loads of balanced models against an independent sum over the bodies, from the engine's kinematics
only (no kinetostatics): shaking force F = -sum(m a_G) over every body and point mass, shaking moment about the
crank pivot M = -sum(I_G alpha + r_G x m a_G) minus the driving torque's reaction (Uicker, Pennock & Shigley,
*Theory of Machines and Mechanisms*, 5th ed., sec. 13.9: the shaking force and moment are the negatives of
the resultant inertia force and moment)."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.balancing.berkof_lowen import berkof_lowen
from machdyn.balancing.counterweights import crank_counterweight
from machdyn.balancing.frame import cycle
from machdyn.linkage import four_bar, kinematics, slider_crank

SPEED = 20.0  # [rad/s]


def _inertia_sums(mech, phi):
    kin = kinematics(mech, phi, SPEED, 0.0)
    fx = np.zeros_like(phi)
    fy = np.zeros_like(phi)
    mz = np.zeros_like(phi)
    for body in mech.bodies:
        st, g = kin.body(body.name), kin.com(body.name)
        m = float(body.mass)
        fx -= m * np.asarray(g.ax)
        fy -= m * np.asarray(g.ay)
        mz -= float(body.inertia) * np.asarray(st.alpha) + m * (np.asarray(g.x) * np.asarray(g.ay)
                                                               - np.asarray(g.y) * np.asarray(g.ax))
    for pm in mech.point_masses:
        p = kin.local_point(pm.body, pm.position)
        m = float(pm.mass)
        fx -= m * np.asarray(p.ax)
        fy -= m * np.asarray(p.ay)
        mz -= m * (np.asarray(p.x) * np.asarray(p.ay) - np.asarray(p.y) * np.asarray(p.ax))
    return fx, fy, mz


@pytest.fixture
def fourbar():
    return four_bar(0.1, 0.35, 0.3, 0.4, masses=(1.0, 2.0, 1.5), coms=((0.05, 0.01), (0.15, 0.04), (0.12, -0.02)),
                    inertias=(0.002, 0.03, 0.015), gravity=(0.0, 0.0))


def test_berkof_lowen_shaking_force_from_the_sum_over_bodies(fourbar):
    phi = cycle(180)
    result = berkof_lowen(fourbar, 0.08, 0.1, phi, speed=SPEED)
    fx0, fy0, _ = _inertia_sums(fourbar, phi)
    fx1, fy1, _ = _inertia_sums(result.model, phi)
    scale = np.max(np.hypot(fx0, fy0))
    # the frame's (kinetostatic) force agrees with the independent sum to round-off before and after
    assert np.allclose(result.before.fx, fx0, atol=1e-9 * scale)
    assert np.allclose(result.after.fy, fy1, atol=1e-9 * scale)
    # and the independent sum confirms the full balance: nothing left but round-off
    assert np.max(np.hypot(fx1, fy1)) < 1e-9 * scale


def test_shaking_moment_from_the_sum_over_bodies_plus_the_motor_reaction(fourbar):
    phi = cycle(180)
    result = berkof_lowen(fourbar, 0.08, 0.1, phi, speed=SPEED)
    for mech, loads in ((fourbar, result.before), (result.model, result.after)):
        _, _, mz = _inertia_sums(mech, phi)
        # the frame takes the pin forces at the pivots plus the reaction -T of the motor; by d'Alembert their
        # resultant moment about the crank pivot is the inertia moment of the moving masses alone
        scale = np.max(np.abs(mz))
        assert np.allclose(loads.moment, mz, atol=1e-9 * scale)
    # the counterweights' inertia makes the shaking moment grow (Berkof & Lowen's price of force balance)
    assert np.max(np.abs(result.after.moment)) > np.max(np.abs(result.before.moment))


def test_crank_counterweight_formula_and_first_harmonic_by_the_sum():
    # balance mass = (m_rot + c m_rec) r / r_cw; with c = 1 the first harmonic along the stroke vanishes
    mech = slider_crank(0.05, 0.2, masses=(1.0, 2.0, 3.0), inertias=(0.001, 0.012, 0.0),
                        coms=((0.01, 0.0), (0.06, 0.0), (0.0, 0.0)), gravity=(0.0, 0.0))
    m_rot = 1.0 * 0.01 / 0.05 + 2.0 * 0.14 / 0.2
    m_rec = 3.0 + 2.0 * 0.06 / 0.2
    phi = cycle(360)
    for c in (0.0, 0.5, 1.0):
        result = crank_counterweight(mech, c, 0.06, phi, speed=SPEED)
        (cw,) = result.counterweights
        assert cw.mass == pytest.approx((m_rot + c * m_rec) * 0.05 / 0.06, rel=1e-12)
        fx, fy, _ = _inertia_sums(result.model, phi)
        first_x = 2 * np.mean(fx * np.cos(phi))
        # left along the stroke: (1 - c) m_rec r w^2 at the first harmonic (the rod's inertia does not enter)
        assert first_x == pytest.approx((1 - c) * m_rec * 0.05 * SPEED**2, abs=1e-6 * m_rec * 0.05 * SPEED**2)
