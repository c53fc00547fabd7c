"""The drive line in the dynamics, against hand formulas: an inertia on a faster shaft counts with the square of
its speed ratio, and a stage's efficiency acts in the direction of the power flow (a geared hoist).

Sources of the hand formulas:
- equivalent (reduced) inertia by equal kinetic energy, J_c = Σ J_k (ω_k/ω_c)²: J. J. Uicker, G. R. Pennock,
  J. E. Shigley, *Theory of Machines and Mechanisms*, 4th ed., Oxford 2011, the chapter on the dynamics of
  machines; R. S. Khurmi, J. K. Gupta, *Theory of Machines*, "torque required to accelerate a geared system";
- torque through a gear of efficiency η: the power balance P_out = η P_in when the input drives, P_in = η P_out
  when the output drives back (Khurmi & Gupta, as above, with the efficiency of the gearing).
"""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.dynamics import EquivalentMachine, PeriodicCurve, TorqueSpeedTable, simulate
from machdyn.dynamics.driveline import DriveLine, DriveTrain, Stage

G = 9.81


def test_an_inertia_on_a_shaft_turning_n_times_the_crank_counts_n_squared():
    line = DriveLine(DriveTrain((Stage(4.0, 0.95), Stage(10.0, 0.97)), (0.01, 0.5, 4.0)),
                     ("motor", "flywheel shaft", "crank"), flywheel_shaft=1)
    assert line.ratio(1) == 10.0 and line.ratio(0) == 40.0
    assert line.at_crank(6.0, line.flywheel_shaft) == pytest.approx(600.0, rel=1e-15)
    assert line.about_shaft(600.0, line.flywheel_shaft) == pytest.approx(6.0, rel=1e-15)
    # every shaft's inertia with its ratio squared: 0.01·40² + 0.5·10² + 4·1²
    assert line.shaft_inertia == pytest.approx(0.01 * 1600 + 0.5 * 100 + 4.0, rel=1e-15)
    # kinetic energy at a crank speed of 3 rad/s, shaft by shaft, is ½ J_red ω²
    energy = sum(0.5 * j * (r * 3.0) ** 2 for j, r in ((0.01, 40.0), (0.5, 10.0), (4.0, 1.0)))
    assert 0.5 * line.shaft_inertia * 9.0 == pytest.approx(energy, rel=1e-14)
    assert line.motor_ratio == 40.0 and line.motor_efficiency == pytest.approx(0.95 * 0.97, rel=1e-15)
    assert line.efficiency_between(1, 2) == pytest.approx(0.97, rel=1e-15)


def _hoist(drum_inertia: float, mass: float, radius: float) -> EquivalentMachine:
    """A drum of inertia J_d lifting a mass m on a rope of radius r: at the drum (the 'crank') the reduced
    inertia is J_d + m r² and the load's moment −m g r, whatever the angle."""
    return EquivalentMachine(PeriodicCurve.constant(drum_inertia + mass * radius**2), PeriodicCurve.constant(0.0),
                             PeriodicCurve.constant(-mass * G * radius), PeriodicCurve.constant(0.0))


@pytest.mark.parametrize("motor_torque", [30.0, -30.0])
def test_a_geared_hoist_accelerates_as_the_energy_balance_with_efficiency_says(motor_torque):
    # motor torque T_m through a gear of ratio n = 20 and efficiency η = 0.9 onto a drum (r = 0.25 m, J_d = 2 kg·m²)
    # lifting m = 150 kg; the motor's rotor has no inertia, so every torque that passes the gear is the motor's
    n, eta, r, j_drum, m = 20.0, 0.9, 0.25, 2.0, 150.0
    line = DriveLine(DriveTrain((Stage(n, eta),), (0.0, j_drum)), ("motor", "crank"), flywheel_shaft=1)
    constant = TorqueSpeedTable(speeds=(0.0, 1000.0), torques=(motor_torque, motor_torque))
    drive = line.motor_drive(constant)
    machine = _hoist(0.0, m, r)  # the drum's inertia is the line's crank shaft
    lifting = 10.0  # drum speed [rad/s]: lifting throughout (at −91 rad/s² it is still 5.5 rad/s after 0.05 s)
    trajectory = simulate(machine, drive, line.shaft_inertia, duration=0.05, omega0=lifting)
    omega = np.ravel(trajectory.omega)
    assert omega.min() > 0
    t = np.ravel(trajectory.t)
    simulated = np.polyfit(t, omega, 1)[0]  # constant torques: the speed is linear in time
    # power balance at the gear: driving (T_m > 0) the drum gets η·n·T_m; the drum turning the motor back
    # against a braking motor (T_m < 0, power from the drum to the motor) it must give n·|T_m|/η
    at_drum = n * motor_torque * (eta if motor_torque > 0 else 1.0 / eta)
    expected = (at_drum - m * G * r) / (j_drum + m * r**2)  # drum: a = α r, (η n T_m / r − m g)/(m + J_d/r²)/r
    # the integrator (DOP853, rtol 1e-9 or better) leaves the linear fit exact to round-off; 1e-7 covers it
    assert simulated == pytest.approx(expected, rel=1e-7)
    ideal = (n * motor_torque - m * G * r) / (j_drum + m * r**2)
    assert abs(simulated - ideal) > 0.05 * abs(ideal)  # the loss shows: an ideal gear would be 5 %+ off


def test_a_drive_line_leaves_a_drive_alone_where_the_file_has_no_drive_train():
    drive = TorqueSpeedTable(speeds=(0.0, 10.0), torques=(5.0, 5.0), ratio=3.0, efficiency=0.8, rotor_inertia=0.1)
    assert DriveLine.crank_only(8.0).motor_drive(drive) is drive
    assert DriveLine.crank_only(8.0).at_crank(2.0, 0) == pytest.approx(128.0, rel=1e-15)
    with pytest.raises(ValueError, match="flywheel's shaft"):
        DriveLine(DriveTrain((Stage(2.0),), (0.0, 0.0)), ("motor", "crank"), flywheel_shaft=5)
