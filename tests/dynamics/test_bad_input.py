"""Bad input is refused with the field, the rule and the value; a drive too weak is named with its numbers."""

from dataclasses import replace

import numpy as np
import pytest

from machdyn.dynamics import (
    ConstantTorque,
    EquivalentMachine,
    HydraulicMotor,
    InductionMotor,
    NotSettledError,
    RotaryDamper,
    disc_flywheel,
    equivalent_machine,
    flywheel_inertia_classic,
    size_flywheel,
    start_up,
    steady_state,
    torque_table,
)
from machdyn.errors import InputError
from machdyn.linkage import BodyTorque, PointForce

RPM = np.pi / 30


def test_negative_flywheel_inertia(bench_machine, motor):
    with pytest.raises(InputError, match=r"flywheel inertia must be >= 0 kg\*m\^2; got -1"):
        steady_state(bench_machine, motor, -1.0)


def test_negative_reduced_inertia_from_a_table():
    table = torque_table([0.0, np.pi], [1.0, -1.0])
    with pytest.raises(InputError, match="must be >= 0"):
        EquivalentMachine.from_tables(table, -2.0)


@pytest.mark.parametrize("delta", [0.0, -0.1, 1.0, 1.5])
def test_delta_out_of_range(bench_machine, delta):
    with pytest.raises(InputError, match=f"delta must be > 0 and < 1; got {delta:g}"):
        size_flywheel(bench_machine, 10.0, delta)
    with pytest.raises(InputError, match="delta"):
        flywheel_inertia_classic(100.0, 10.0, delta)


def test_motor_that_stalls_under_load_names_peak_load_and_breakdown_torque(bench_mech):
    # a press force of 40 kN over 34° of the cycle: the mean load is within the motor's breakdown torque, the
    # peak is ten times it, and a 0.001 kg*m^2 flywheel cannot carry the machine through
    mech = replace(bench_mech, forces=(PointForce("press", "rocker.B", 0.0, -40000.0, active=(4.0, 4.6)),))
    machine = equivalent_machine(mech, 180, speed_loads=(RotaryDamper("friction", "crank", 0.05),))
    small = InductionMotor(rated_power=200.0, rated_speed=1440 * RPM, synchronous_speed=1500 * RPM,
                           breakdown_ratio=2.0, ratio=15.0)
    with pytest.raises(InputError, match=r"(?s)stalls.*peak load torque 3\d\d\.\d N\*m.*breakdown torque 39.79 N\*m"):
        steady_state(machine, small, 0.001)


def test_motor_too_weak_for_the_mean_load(bench_mech):
    mech = replace(bench_mech, torques=(BodyTorque("load", "crank", -60.0),))
    machine = equivalent_machine(mech, 180, speed_loads=(RotaryDamper("friction", "crank", 0.05),))
    tiny = InductionMotor(rated_power=200.0, rated_speed=1440 * RPM, synchronous_speed=1500 * RPM,
                          breakdown_ratio=2.0, ratio=15.0)
    with pytest.raises(InputError, match=r"(?s)cannot carry the load.*breakdown torque"):
        steady_state(machine, tiny, 0.05)


def test_motor_that_cannot_start(bench_mech):
    # gravity holds the crank: a weak hydraulic motor at a low relief pressure cannot lift it from rest
    machine = equivalent_machine(bench_mech, 180, speed_loads=(RotaryDamper("friction", "crank", 0.01),))
    weak = HydraulicMotor(displacement=1e-6, flow=1e-6 * 10 / (2 * np.pi), pressure_limit=2e5)
    phi0 = float(machine.inertia.x[np.argmin(machine.position_moment(machine.inertia.x))])
    with pytest.raises(InputError, match=r"(?s)cannot start .* starting torque .* static torque"):
        start_up(machine, weak, 0.05, phi0=phi0, steady=None)


def test_unbalanced_constant_torque_has_no_steady_state(bench_machine):
    with pytest.raises(InputError, match="balancing drive torque"):
        steady_state(bench_machine, ConstantTorque(0.5), 0.05, mean_speed=10.0)


def test_shooting_that_does_not_settle(bench_machine, motor):
    with pytest.raises(NotSettledError, match="not found in 1 shooting steps"):
        steady_state(bench_machine, motor, 0.04, max_iterations=1, tolerance=1e-300)


def test_start_up_that_does_not_settle(bench_machine, motor):
    with pytest.raises(NotSettledError, match="did not reach steady running"):
        start_up(bench_machine, motor, 0.04, max_time=0.05)


@pytest.mark.parametrize("kwargs, message", [
    (dict(rated_power=-1.0, rated_speed=150.0, synchronous_speed=157.0), "rated power"),
    (dict(rated_power=1e3, rated_speed=160.0, synchronous_speed=157.0), "below its synchronous speed"),
    (dict(rated_power=1e3, rated_speed=150.0, synchronous_speed=157.0, breakdown_ratio=0.9), "breakdown-torque"),
    (dict(rated_power=1e3, rated_speed=150.0, synchronous_speed=157.0, efficiency=1.2), "efficiency"),
])
def test_bad_motor_data(kwargs, message):
    with pytest.raises(InputError, match=message):
        InductionMotor(**kwargs)


def test_bad_flywheel_part():
    with pytest.raises(InputError, match="flywheel inertia must be > 0"):
        disc_flywheel(0.0, 10.0)


def test_overloaded_induction_motor_is_warned(bench_mech):
    machine = equivalent_machine(bench_mech, 180, speed_loads=(RotaryDamper("friction", "crank", 50.0),))
    tiny = InductionMotor(rated_power=200.0, rated_speed=1440 * RPM, synchronous_speed=1500 * RPM,
                          breakdown_ratio=2.0, ratio=15.0)
    ss = steady_state(machine, tiny, 0.05)  # it turns, slowly, far beyond its breakdown slip
    assert ss.warnings and "beyond its breakdown slip" in ss.warnings[0]


def test_constant_torque_mean_speed_too_low_to_pass_the_cycle(bench_machine):
    """Too little flywheel for the mean speed: the machine would stop in the cycle; a clear error, not a root
    finder's failure."""
    from machdyn.dynamics import ConstantTorque, size_flywheel, steady_state

    drive = ConstantTorque(float(size_flywheel(bench_machine, 10.0, 0.05).drive_torque[0]))
    with pytest.raises(InputError, match="mean_speed.*cannot turn through its cycle"):
        steady_state(bench_machine, drive, 1e-6, mean_speed=10.0)


def test_torque_speed_table_with_non_increasing_speeds_names_the_entry():
    from machdyn.dynamics import TorqueSpeedTable, torque_table

    with pytest.raises(InputError, match=r"speeds\[2\] = 100 rad/s after speeds\[1\] = 120 rad/s"):
        TorqueSpeedTable((0.0, 120.0, 100.0), (10.0, 8.0, 0.0))
    with pytest.raises(InputError, match="angles of a torque table must increase strictly; got 90°"):
        torque_table(np.radians([0.0, 120.0, 90.0]), [1.0, 2.0, 3.0])
