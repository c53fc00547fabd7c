"""Second, independent methods for the machine dynamics: the reduced inertia from the engine's kinetic energy,
the steady state against Newton-Euler kinetostatics and a long plain integration, the energy-mass flywheel
against a bisection on the simulated delta, the Kloss curve, the hydraulic motor and the flywheel parts."""

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq, minimize_scalar

from machdyn.dynamics import (
    ConstantTorque,
    HydraulicMotor,
    InductionMotor,
    disc_flywheel,
    kloss_breakdown_slip,
    kloss_torque,
    rim_flywheel,
    size_flywheel,
    steady_state,
)
from machdyn.linkage import energy, kinetostatics

RPM = np.pi / 30.0


def test_reduced_inertia_is_twice_the_kinetic_energy_at_unit_speed(bench_mech, bench_machine):
    phi = np.linspace(0.1, 6.2, 41)
    kinetic = energy(bench_mech, phi, 1.0, 0.0).kinetic_total
    np.testing.assert_allclose(bench_machine.inertia(phi), 2.0 * kinetic, rtol=1e-10)
    # central differences of the engine's kinetic energy, step 1e-4 rad: truncation ~h^2 J''' ~ 1e-9 relative
    h = 1e-4
    fd = (energy(bench_mech, phi + h, 1.0, 0.0).kinetic_total
          - energy(bench_mech, phi - h, 1.0, 0.0).kinetic_total) / h
    scale = float(np.max(np.abs(fd)))
    assert np.max(np.abs(bench_machine.inertia.derivative(phi) - fd)) < 1e-6 * scale


def test_steady_state_satisfies_newton_euler_of_the_full_linkage(bench_mech, bench_machine, motor):
    """The engine's kinetostatics at the simulated omega(phi), epsilon(phi) must ask of the crank exactly the drive
    torque less what accelerates the flywheel."""
    flywheel = 0.01
    ss = steady_state(bench_machine, motor, flywheel)
    ks = kinetostatics(bench_mech, ss.phi, ss.omega, ss.acceleration).driving_torque
    expected = ss.drive_torque - flywheel * ss.acceleration
    # 360 Hermite nodes of J: interpolation error O(h^4) ~ 1e-8 of the peak torque
    assert np.max(np.abs(ks - expected)) < 1e-6 * np.max(np.abs(ss.drive_torque))


def test_steady_state_matches_a_long_plain_integration(bench_machine, motor):
    """Integrate phi, omega in time from rest until the motion settles, with no shooting."""
    flywheel = 0.01
    ss = steady_state(bench_machine, motor, flywheel)
    jm = bench_machine.inertia

    def rhs(t, y):
        phi, w = y
        j = float(jm(np.array([phi]))[0]) + flywheel
        dj = float(jm.derivative(np.array([phi]))[0])
        m = float(motor.torque_at(w)) + float(bench_machine.moment_at(np.array([phi]), np.array([w]))[0])
        return [w, (m - 0.5 * dj * w * w) / j]

    cycles = np.arange(1, 200) * 2.0 * np.pi
    crossings = []

    def event(t, y):
        return np.sin(0.5 * y[0])  # zero at every multiple of 2 pi

    sol = solve_ivp(rhs, (0.0, 40.0), [1e-3, 0.0], method="LSODA", rtol=1e-11, atol=1e-12, events=event)
    crossings = sol.y_events[0][:, 1]
    del cycles
    assert crossings.size > 20
    # the last two cycle starts agree (settled) and equal the shooting's omega(0)
    assert abs(crossings[-1] - crossings[-2]) < 1e-8 * crossings[-1]
    assert abs(crossings[-1] - ss.omega[0]) < 1e-7 * ss.omega[0]


def test_energy_mass_flywheel_equals_a_bisection_on_the_simulated_delta(bench_machine):
    """The Wittenbauer flywheel assumes the drive gives the mean torque; with that drive the simulated delta at
    the sized flywheel is the target, and a bisection on the flywheel inertia finds the same inertia."""
    w, delta = 10.0, 0.05
    sizing = size_flywheel(bench_machine, w, delta)
    drive = ConstantTorque(float(sizing.drive_torque[0]))

    def excess(jf):
        return float(steady_state(bench_machine, drive, jf, mean_speed=w).delta) - delta

    j_bisect = brentq(excess, 2e-3, 1.0, xtol=1e-12, rtol=1e-10)
    assert j_bisect == pytest.approx(float(sizing.exact[0]), rel=1e-6)


def test_kloss_curve_through_the_rated_point_with_its_breakdown_torque():
    rated_slip, ratio = 0.04, 2.5
    sb = float(kloss_breakdown_slip(rated_slip, ratio))
    tb = 100.0
    assert float(kloss_torque(rated_slip, tb, sb)) == pytest.approx(tb / ratio, rel=1e-12)
    best = minimize_scalar(lambda s: -float(kloss_torque(s, tb, sb)), bounds=(1e-4, 1.0), method="bounded",
                           options={"xatol": 1e-10})
    assert best.x == pytest.approx(sb, rel=1e-5) and -best.fun == pytest.approx(tb, rel=1e-10)
    motor = InductionMotor(rated_power=4000.0, rated_speed=1440 * RPM, synchronous_speed=1500 * RPM,
                           breakdown_ratio=ratio, ratio=5.0, efficiency=0.95)
    crank_speed = 1440 * RPM / 5.0
    assert float(motor.torque_at(crank_speed)) == pytest.approx(4000.0 / (1440 * RPM) * 5.0 * 0.95, rel=1e-12)
    # the slope against central differences
    h = 1e-6 * crank_speed
    fd = (motor.torque_at(crank_speed + h) - motor.torque_at(crank_speed - h)) / (2 * h)
    assert float(motor.slope(crank_speed)) == pytest.approx(float(fd), rel=1e-6)
    assert float(motor.torque_slope(crank_speed)[1]) == pytest.approx(float(fd), rel=1e-6)


def test_hydraulic_motor_torque_and_speed_from_displacement_pressure_and_flow():
    """T = eta_m V p / 2 pi at the relief pressure; speed = eta_v Q / V (rev/s) where the pressure reaches it."""
    vd, q, p, ev, em = 50e-6, 1e-3, 20e6, 0.92, 0.88
    hm = HydraulicMotor(vd, q, p, ev, em, ratio=2.0)
    assert float(hm.starting_torque) == pytest.approx(2.0 * em * vd * p / (2 * np.pi), rel=1e-12)
    speed_at_limit = ev * q / vd * 2 * np.pi / 2.0  # crank rad/s
    assert float(hm.pressure(speed_at_limit)) == pytest.approx(p, rel=1e-9)
    assert float(hm.pressure(speed_at_limit * 1.01)) < p
    assert float(hm.no_load_speed) == pytest.approx(q / vd * 2 * np.pi / 2.0, rel=1e-12)


def test_flywheel_parts_obey_the_rim_and_disc_formulas():
    rim = rim_flywheel(50.0, 20.0, 21.0, rim_speed=25.0, width_to_thickness=3.0)
    r = rim.diameter / 2
    assert rim.mass * r**2 == pytest.approx(50.0, rel=1e-12)
    assert rim.mass == pytest.approx(7850.0 * 2 * np.pi * r * rim.width * rim.thickness, rel=1e-12)
    assert rim.rim_speed == pytest.approx(21.0 * r, rel=1e-12)
    disc = disc_flywheel(10.0, 100.0)
    assert 0.5 * disc.mass * (disc.diameter / 2) ** 2 == pytest.approx(10.0, rel=1e-12)


@pytest.mark.parametrize("flywheel", [0.01, 0.002])
def test_fourier_collocation_agrees_with_shooting(bench_machine, motor, flywheel):
    """The same machine with J as Hermite pieces (exact nodes and slopes, O(h^4) between) takes the shooting path;
    the collocation's steady state must agree to the Hermite interpolation error."""
    from dataclasses import replace

    from machdyn.dynamics import PeriodicCurve

    x = bench_machine.inertia.x
    hermite = PeriodicCurve.hermite(x, bench_machine.inertia(x), bench_machine.inertia.derivative(x), 2 * np.pi)
    shooting = steady_state(replace(bench_machine, inertia=hermite), motor, flywheel)
    collocation = steady_state(bench_machine, motor, flywheel)
    assert shooting.iterations > 0 and collocation.iterations == 0
    assert collocation.residual < 1e-10
    # the Hermite J's own error, O(h^4): measured 3.3e-9 of omega at 360 nodes and 2.2e-10 at 720 for the
    # lighter flywheel (the 16-fold drop of the interpolation error, not of the collocation)
    np.testing.assert_allclose(collocation.omega, shooting.omega, rtol=1e-8)
    np.testing.assert_allclose(collocation.time, shooting.time, rtol=1e-8, atol=1e-12)
    assert collocation.period_time == pytest.approx(float(shooting.period_time), rel=1e-8)

