"""Physics of the simulation: energy conservation, periodicity, the flywheel sized for delta, the limit of a
very large flywheel, forces at the real speed, design variants."""

import numpy as np
import pytest

from machdyn.dynamics import (
    ConstantSpeed,
    ConstantTorque,
    HydraulicMotor,
    LinearDamper,
    RotaryDamper,
    TorqueSpeedTable,
    equivalent_machine,
    simulate,
    size_flywheel,
    start_up,
    steady_state,
)
from machdyn.dynamics.realspeed import forces_at_speed
from machdyn.linkage import energy, four_bar, kinetostatics, stack_designs


def test_free_loss_free_motion_conserves_energy(bench_mech, bench_machine):
    # no drive, no losses, gravity on: T + V constant; one crank revolution takes about 0.6 s at 10 rad/s
    traj = simulate(bench_machine, None, 0.002, duration=0.7, omega0=10.0, samples=200)
    assert traj.phi[-1] > 2 * np.pi  # more than one cycle
    e = traj.energy
    assert np.max(np.abs(e - e[0])) / e[0] < 1e-9
    # the same energy from the engine at the simulated angles and speeds (flywheel added by hand)
    en = energy(bench_mech, traj.phi, traj.omega, 0.0)
    total = en.kinetic_total + en.potential + 0.5 * 0.002 * traj.omega**2
    assert np.max(np.abs(total - e[0])) / e[0] < 1e-9


def test_steady_state_is_periodic_in_time(bench_machine, motor):
    ss = steady_state(bench_machine, motor, 0.04)
    assert ss.residual < 1e-10
    # integrate the time-domain equation from the steady state's start for one period: back to the start
    traj = simulate(bench_machine, motor, 0.04, duration=float(ss.period_time), omega0=float(ss.omega[0]),
                    samples=2)
    assert traj.phi[-1] == pytest.approx(2 * np.pi, rel=1e-9)
    assert traj.omega[-1] == pytest.approx(ss.omega[0], rel=1e-9)


def test_sized_flywheel_gives_the_target_delta_and_exact_beats_classic(bench_machine):
    mean, target = 10.0, 0.02
    sizing = size_flywheel(bench_machine, mean, target)
    drive = ConstantTorque(float(sizing.drive_torque[0]))
    exact = steady_state(bench_machine, drive, sizing.exact, mean_speed=mean)
    classic = steady_state(bench_machine, drive, sizing.classic, mean_speed=mean)
    err_exact = abs(exact.delta / target - 1)
    err_classic = abs(classic.delta / target - 1)
    assert err_exact < 1e-3        # the energy-mass method is exact up to the search grid
    assert err_exact < err_classic  # the classic method ignores the variation of J(phi)
    assert err_classic < 0.2


def test_sizing_for_a_constant_torque_is_conservative_for_an_induction_motor(bench_machine, motor):
    sizing = size_flywheel(bench_machine, 10.47, 0.02)
    ss = steady_state(bench_machine, motor, sizing.exact)
    # the motor's torque falls as the speed rises: it absorbs part of the fluctuation the flywheel was sized for
    assert ss.delta < 0.02
    soft = steady_state(bench_machine, ConstantTorque(0.0), sizing.exact, mean_speed=10.47)
    assert soft.delta == pytest.approx(0.02, rel=1e-3)


def test_huge_flywheel_drive_torque_tends_to_the_kinetostatic_torque(bench_mech, bench_machine, motor):
    errors = []
    for flywheel in (1.0, 100.0):
        ss = steady_state(bench_machine, motor, flywheel)
        shaft = ss.drive_torque - flywheel * ss.acceleration  # torque from the flywheel shaft into the linkage
        ref = kinetostatics(bench_mech, ss.phi, float(ss.time_mean_speed), 0.0).driving_torque
        errors.append(np.max(np.abs(shaft - ref)) / np.max(np.abs(ref)))
        # the motor torque itself flattens to the mean load
        assert np.ptp(ss.drive_torque) < 0.2 * np.ptp(ref) / np.sqrt(flywheel)
    assert errors[1] < 1e-3
    assert errors[1] < errors[0] / 10


def test_forces_at_real_speed_balance_the_crank_shaft(bench_mech, motor):
    loads = (RotaryDamper("bearing", "rocker", 0.01), LinearDamper("damper", "coupler.B", "ground.D", 2.0))
    eq = equivalent_machine(bench_mech, 360, speed_loads=loads)
    ss = steady_state(eq, motor, 0.01)
    rf = forces_at_speed(ss)
    expect = ss.drive_torque - 0.01 * ss.acceleration
    assert np.max(np.abs(rf.real.driving_torque - expect)) < 1e-8 * np.max(np.abs(expect))
    # the drive's work per cycle is what the dampers dissipate
    dissipated = np.sum(eq.damping(ss.phi) * ss.omega) * 2 * np.pi / ss.phi.size
    assert ss.energy_per_cycle == pytest.approx(dissipated, rel=1e-8)
    name, change = rf.largest_change()
    assert name in rf.joint_peaks and change > 0


def test_design_variants_in_one_call_match_single_runs(motor):
    cranks = [0.036, 0.04]
    stacked = equivalent_machine(stack_designs([four_bar(c, 0.12, 0.08, 0.1) for c in cranks]), 240)
    both = steady_state(stacked, motor, np.array([0.03, 0.05]))
    for i, (c, fw) in enumerate(zip(cranks, (0.03, 0.05), strict=True)):
        one = steady_state(equivalent_machine(four_bar(c, 0.12, 0.08, 0.1), 240), motor, fw)
        assert np.allclose(both.omega[i], one.omega, rtol=1e-9)
        assert both.delta[i] == pytest.approx(one.delta, rel=1e-7)


def test_start_up_reaches_the_steady_state(bench_machine, motor):
    run = start_up(bench_machine, motor, 0.04, tolerance=0.01)
    assert 0 < run.time_to_steady < run.trajectory.t[-1]
    assert run.trajectory.omega[0] == 0.0
    tail = run.trajectory.t > run.time_to_steady
    assert np.all(np.abs(run.trajectory.omega[tail] - run.steady.speed_curve()(run.trajectory.phi[tail]))
                  <= 0.01 * run.steady.mean_speed)


def test_table_motor_and_hydraulic_motor_reach_steady_states(bench_mech, motor):
    bench_machine = equivalent_machine(bench_mech, 240, speed_loads=(RotaryDamper("bearing", "crank", 0.02),))
    speeds = np.linspace(0.0, float(motor.synchronous_speed), 400)
    slip = 1 - speeds / motor.synchronous_speed
    from machdyn.dynamics import kloss_torque

    table = TorqueSpeedTable(tuple(speeds), tuple(kloss_torque(slip, motor.breakdown_ratio * motor.rated_torque,
                                                               motor.breakdown_slip)), ratio=motor.ratio)
    kloss = steady_state(bench_machine, motor, 0.04)
    tab = steady_state(bench_machine, table, 0.04)
    assert tab.mean_speed == pytest.approx(kloss.mean_speed, rel=1e-5)
    hyd = HydraulicMotor(displacement=20e-6, flow=20e-6 * 10.0 / (2 * np.pi) * 1.05, pressure_limit=200e5,
                         ratio=1.0)
    ss = steady_state(bench_machine, hyd, 0.04)
    assert 0.9 * hyd.no_load_speed < ss.mean_speed < hyd.no_load_speed


def test_constant_speed_drive_is_the_kinetostatic_case(bench_mech, bench_machine):
    ss = steady_state(bench_machine, ConstantSpeed(10.0))
    ref = kinetostatics(bench_mech, ss.phi, 10.0, 0.0).driving_torque
    assert np.allclose(ss.drive_torque, ref, rtol=1e-9, atol=1e-12)
    assert ss.delta == 0.0
