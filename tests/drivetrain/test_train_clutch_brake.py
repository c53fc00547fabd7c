"""Physics of the drive train, the clutch and the brake, each against a second method."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from machdyn.drivetrain.clutch import engage, stop_constant, stop_machine
from machdyn.drivetrain.train import DriveTrain, Stage
from machdyn.dynamics.equivalent import EquivalentMachine, equivalent_machine
from machdyn.dynamics.tables import torque_table
from machdyn.errors import InputError
from machdyn.linkage import slider_crank

ratios = st.floats(0.2, 20.0)
inertias = st.floats(0.0, 5.0)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(ratios, st.floats(0.5, 1.0), inertias), min_size=1, max_size=4), inertias,
       st.floats(0.1, 100.0))
def test_the_reflected_inertia_has_the_trains_kinetic_energy(stages, motor, speed):
    train = DriveTrain(tuple(Stage(r, e) for r, e, _j in stages), (motor, *(j for _r, _e, j in stages)))
    assert 0.5 * train.reflected_inertia() * speed**2 == pytest.approx(float(train.kinetic_energy(speed)), rel=1e-12)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(ratios, st.floats(0.5, 1.0)), min_size=1, max_size=4), st.floats(-500.0, 500.0))
def test_shaft_torques_balance_power_through_every_lossy_stage(stages, crank_torque):
    train = DriveTrain(tuple(Stage(r, e) for r, e in stages), (0.0,) * (len(stages) + 1))
    torques = train.shaft_torques(crank_torque)
    speeds = train.speed_ratios  # per unit crank speed
    for k, s in enumerate(train.stages):
        p_in, p_out = torques[k] * speeds[k], torques[k + 1] * speeds[k + 1]
        # motoring: P_out = eta P_in; back-driven (negative power): P_in = eta P_out
        expected = s.efficiency * p_in if p_out >= 0 else p_in / s.efficiency
        assert p_out == pytest.approx(expected, rel=1e-12, abs=1e-12)


@settings(max_examples=100, deadline=None)
@given(st.floats(0.1, 50.0), st.floats(1.0, 300.0), st.floats(0.1, 50.0), st.floats(0.0, 0.9),
       st.floats(10.0, 500.0), st.floats(0.0, 0.9), st.floats(0.0, 0.9))
def test_a_clutch_engagement_conserves_energy(j1, w1, j2, share2, tc, motor_share, load_share):
    """Kinetic energy before + motor work = kinetic energy after + friction loss + load work."""
    w2 = share2 * w1
    e = engage(j1, w1, j2, w2, tc, driving_torque=motor_share * tc, load_torque=load_share * tc)
    before = 0.5 * j1 * w1**2 + 0.5 * j2 * w2**2 + e.driving_work
    after = 0.5 * (j1 + j2) * e.common_speed**2 + e.dissipated + e.load_work
    assert after == pytest.approx(before, rel=1e-10)
    assert e.dissipated > 0 and e.slip_time > 0


def test_without_motor_or_load_the_engagement_is_shigleys():
    """Shigley's MED, 8th ed., §16-8: t = I1 I2 (w1 - w2) / (T (I1 + I2)), E = I1 I2 (w1 - w2)^2 / (2 (I1 + I2))."""
    i1, i2, w1, w2, t = 3.0, 1.5, 150.0, 20.0, 80.0
    e = engage(i1, w1, i2, w2, t)
    assert e.slip_time == pytest.approx(i1 * i2 * (w1 - w2) / (t * (i1 + i2)), rel=1e-13)
    assert e.dissipated == pytest.approx(i1 * i2 * (w1 - w2) ** 2 / (2 * (i1 + i2)), rel=1e-12)
    assert e.common_speed == pytest.approx((i1 * w1 + i2 * w2) / (i1 + i2), rel=1e-13)  # momentum


def test_a_clutch_below_its_load_or_against_a_stronger_motor_is_refused():
    with pytest.raises(InputError, match="slips for ever"):
        engage(1.0, 100.0, 1.0, 0.0, 50.0, load_torque=60.0)
    with pytest.raises(InputError, match="exceeds the clutch's slip torque"):
        engage(1.0, 100.0, 1.0, 0.0, 50.0, driving_torque=60.0)


def test_the_stop_of_a_constant_inertia_machine_is_the_closed_form():
    machine = EquivalentMachine.from_tables(torque_table([0.0, np.pi, 2 * np.pi], [0.0, 0.0, 0.0]), inertia=2.0)
    numeric = stop_machine(machine, 0.5, 30.0, 40.0, 1.0)
    closed = stop_constant(2.5, 30.0, 40.0)
    assert numeric.time == pytest.approx(closed.time, rel=1e-7)
    assert numeric.angle == pytest.approx(closed.angle, rel=1e-7)


def test_a_linkage_brought_to_rest_has_spent_its_energy_on_the_brake_and_the_loads():
    """1/2 (J(phi0) + Jx) w0^2 + work of the loads over the stop = brake torque x stopping angle."""
    mech = slider_crank(0.1, 0.4, 0.0, masses=(2.0, 3.0, 8.0))
    machine = equivalent_machine(mech, 720)
    extra, w0, tb, phi0 = 0.05, 20.0, 60.0, 0.7
    stop = stop_machine(machine, extra, w0, tb, phi0)
    grid = np.linspace(phi0, phi0 + stop.angle, 4001)
    m = np.ravel(machine.position_moment(grid))
    load_work = float(np.sum(0.5 * (m[1:] + m[:-1]) * np.diff(grid)))
    kinetic = 0.5 * (float(np.ravel(machine.inertia(phi0))[0]) + extra) * w0**2
    assert kinetic + load_work == pytest.approx(tb * stop.angle, rel=1e-6)


def test_a_brake_weaker_than_the_load_that_drives_never_stops():
    machine = EquivalentMachine.from_tables(torque_table([0.0, np.pi, 2 * np.pi], [50.0, 50.0, 50.0]), inertia=1.0)
    with pytest.raises(InputError, match="never stops the machine"):
        stop_machine(machine, 0.0, 10.0, 20.0, 0.0)


def test_a_stop_longer_than_the_turns_integrated_is_finished_by_the_energy_balance():
    """A constant load of 30 N*m driving against a 40 N*m brake leaves 10 N*m: from 30 rad/s a 2.5 kg*m^2 machine
    needs J w^2 / (2 x 10) = 112.5 rad (17.9 turns). Integrated over 2 turns only, the rest is the energy balance,
    which is exact for a constant inertia and load (Newton's second law for rotation, stop_constant)."""
    machine = EquivalentMachine.from_tables(torque_table([0.0, np.pi, 2 * np.pi], [30.0, 30.0, 30.0]), inertia=2.0)
    stop = stop_machine(machine, 0.5, 30.0, 40.0, 1.0, max_turns=2)
    closed = stop_constant(2.5, 30.0, 40.0, resisting_torque=-30.0)
    assert stop.estimated and not stop_machine(machine, 0.5, 30.0, 40.0, 1.0).estimated
    assert stop.angle == pytest.approx(closed.angle, rel=1e-7)
    assert stop.time == pytest.approx(closed.time, rel=1e-7)


def test_bad_stages_are_named():
    with pytest.raises(InputError, match="efficiency must be in"):
        DriveTrain((Stage(2.0, 1.2),), (0.0, 0.0))
    with pytest.raises(InputError, match="ratio must be > 0"):
        DriveTrain((Stage(0.0),), (0.0, 0.0))
    with pytest.raises(InputError, match="has 2 shafts"):
        DriveTrain((Stage(2.0),), (0.0,))
