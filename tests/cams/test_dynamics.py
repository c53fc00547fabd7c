"""Cam dynamics: the spring sized for a speed keeps contact there and loses it just above its margin (the contact
force crossing zero, confirmed by a forward simulation with a one-sided contact), the camshaft torque's work over a
turn equals the damper's loss, and the reduced machine gives the same torque as the contact force."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.cams.dynamics import (
    FollowerTrain,
    Spring,
    cam_forces,
    cam_machine,
    jump_speed,
    simulate_follower,
    size_spring,
)
from machdyn.cams.profile import cam_angles
from machdyn.cams.program import Segment, program
from machdyn.errors import InputError

D = np.radians
PROG = program([Segment("rise", D(100), 0.03, "cycloidal"), Segment("dwell", D(80)),
                Segment("return", D(120), 0.03, "poly345"), Segment("dwell", D(60))])
SPEED = 2 * np.pi * 200 / 60  # 200 rpm
TH = cam_angles(3600)


def test_spring_sized_with_a_margin_keeps_contact_up_to_it_and_loses_it_above():
    train = FollowerTrain(mass=2.0, preload=50.0, damping=5.0)
    spring = size_spring(PROG, train, SPEED, margin=0.2)
    assert spring.preload == 50.0 and spring.rate > 0
    at_n = cam_forces(PROG, train, spring, SPEED, TH)
    assert at_n.jump_speed == pytest.approx(1.2 * SPEED, rel=1e-9)
    assert float(np.min(at_n.contact)) > 0
    assert float(np.min(cam_forces(PROG, train, spring, 1.19 * SPEED, TH).contact)) > 0
    assert float(np.min(cam_forces(PROG, train, spring, 1.21 * SPEED, TH).contact)) < 0
    # the forward simulation of the follower pressed on the cam by a stiff one-sided contact agrees, and the force
    # in its contact is the predicted F_c (the contact's own ringing, excited where the jerk jumps, stays < 0.5 %)
    sim = simulate_follower(PROG, train, spring, SPEED)
    assert sim.kept_contact
    predicted = cam_forces(PROG, train, spring, SPEED, sim.theta).contact
    np.testing.assert_allclose(sim.contact, predicted, atol=5e-3 * float(np.max(predicted)))
    assert simulate_follower(PROG, train, spring, 1.15 * SPEED).kept_contact
    above = simulate_follower(PROG, train, spring, 1.3 * SPEED)
    assert not above.kept_contact
    assert above.max_separation > 0.003 * PROG.stroke


def test_given_rate_sizes_the_preload_and_given_both_keeps_them():
    train = FollowerTrain(mass=1.5, spring_rate=2000.0, preload=None)
    spring = size_spring(PROG, train, SPEED, margin=0.3)
    assert spring.rate == 2000.0
    assert jump_speed(PROG.svaj(cam_angles(3600)), train, spring) == pytest.approx(1.3 * SPEED, rel=1e-9)
    fixed = FollowerTrain(mass=1.5, spring_rate=2000.0, preload=10.0)
    assert size_spring(PROG, fixed, SPEED) == Spring(2000.0, 10.0)


def test_a_preload_below_the_dwell_load_is_refused_naming_it():
    train = FollowerTrain(mass=1.0, preload=5.0, load=-20.0)  # a load pulling the follower off the cam
    with pytest.raises(InputError, match="cam.spring.preload"):
        size_spring(PROG, train, SPEED)


@pytest.mark.parametrize("damping", [0.0, 12.0])
def test_work_of_the_camshaft_torque_over_a_turn_is_the_dampers_loss(damping):
    train = FollowerTrain(mass=2.0, spring_rate=1500.0, preload=40.0, damping=damping, load=15.0)
    spring = size_spring(PROG, train, SPEED)
    f = cam_forces(PROG, train, spring, SPEED, TH)
    loss = damping * SPEED * float(np.mean(f.svaj.v**2)) * 2 * np.pi  # c omega * integral of v^2 dtheta
    assert f.work_per_cycle == pytest.approx(loss, rel=1e-9, abs=1e-9 * float(np.max(np.abs(f.torque))))


def test_the_reduced_machine_gives_the_camshaft_torque_at_constant_speed():
    """T = (J'/2) omega^2 + dV/dtheta + c_red omega (Lagrange, constant speed) equals F_c v."""
    train = FollowerTrain(mass=2.0, spring_rate=1500.0, preload=40.0, damping=8.0, load=15.0, cam_inertia=0.01)
    spring = size_spring(PROG, train, SPEED)
    machine = cam_machine(PROG, train, spring, positions=720)
    th = cam_angles(720)
    torque = (0.5 * machine.inertia.derivative(th) * SPEED**2 + machine.potential.derivative(th)
              + machine.damping(th) * SPEED)
    direct = cam_forces(PROG, train, spring, SPEED, th).torque
    np.testing.assert_allclose(np.ravel(torque), direct, atol=1e-9 * float(np.max(np.abs(direct))))
    np.testing.assert_allclose(np.ravel(machine.inertia(th)), 0.01 + 2.0 * PROG.svaj(th).v ** 2, rtol=1e-12)
