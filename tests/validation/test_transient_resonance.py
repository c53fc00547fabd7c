"""The machine in time against the published theory of passage through resonance and of capture.

Sources
-------
* F. M. Lewis, "Vibration during acceleration through a critical speed", Trans. ASME 54 (1932) 253-261: an
  oscillator driven through its resonance at a constant angular acceleration; his Fresnel-integral solution of
  the undamped passage (the Cornu spiral: the largest amplitude 1.1707 times the amplitude left after the
  passage, reached at u = 1.217 past the resonance), which :mod:`machdyn.transient.closed_forms` evaluates, with
  the damped envelope by the Faddeeva function (Abramowitz & Stegun, *Handbook of Mathematical Functions*, 7.1.3,
  7.3). Checked here three ways: the closed forms against a direct integration of the one-degree-of-freedom
  equation, and the coupled model (an unbalanced rotor on a frame, its crank turned at a constant angular
  acceleration) against a direct integration of the unbalanced oscillator's own equation.
* V. O. Kononenko, *Vibrating Systems with a Limited Power Supply*, Iliffe 1969, ch. 2: an unbalanced rotor on an
  elastic base driven by a motor of limited power; its stationary speeds are where the motor's torque equals the
  vibration torque c Omega X^2 / 2 (the power the base's damper takes over the speed). A weak motor is captured
  below the resonance at that stationary speed; a strong one passes it. Checked by the speed of the stationary
  motion and by the energy balance of the run.

* I. I. Blekhman, *Synchronization in Science and Technology*, ASME Press 1988 (the self-synchronisation of
  unbalanced vibration exciters): two identical exciters turning in opposite directions on a body on soft
  springs (above its resonances) synchronise by themselves into the phase that leaves the body without rocking,
  its vibration rectilinear, perpendicular to the line joining the shafts (the principle of two-exciter
  screens and feeders). Checked by the phase the run settles in, the direction of the vibration, and its
  amplitude 2 m e / M (1 - w_n^2 / Omega^2)^-1.

The maximum-amplitude estimates of R. Markert & M. Seidler (Int. J. Solids Struct. 38 (2001) 1975-1992) are
not used: the closed forms above are exact for the model they solve, and are what the tests check against.
"""

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from machdyn.dynamics import TorqueSpeedTable
from machdyn.transient import Exciter, Scenario, coupled_model, run_scenario
from machdyn.transient.closed_forms import passage_envelope, undamped_passage_peak, vibration_torque
from machdyn.transient.passage import capture
from machdyn.vibration.frame import Frame, Mount
from transient.machines import rotor, sprung_block


def _oscillator_peak(w, alpha, zeta, t_resonance=8.0, f=1.0):
    """Largest |x| of x'' + 2 zeta w x' + w^2 x = f cos(Omega_0 t + alpha t^2 / 2), from rest, the exciting
    frequency reaching w at t_resonance, integrated to 2 t_resonance."""
    om0 = w - alpha * t_resonance

    def rhs(t, y):
        return [y[1], f * np.cos(om0 * t + 0.5 * alpha * t * t) - 2 * zeta * w * y[1] - w * w * y[0]]

    t = np.linspace(0.0, 2 * t_resonance, 40001)
    sol = solve_ivp(rhs, (0.0, 2 * t_resonance), [0.0, 0.0], method="DOP853", rtol=1e-10, atol=1e-13, t_eval=t)
    return float(np.max(np.abs(sol.y[0]))), t, sol.y[0]


@pytest.mark.parametrize("zeta", [0.0, 0.01, 0.03])
def test_lewis_passage_envelope_against_direct_integration(zeta):
    w, alpha = 50.0, 2.0
    peak, t, _ = _oscillator_peak(w, alpha, zeta)
    predicted = float(np.max(passage_envelope(t - 8.0, w, alpha, zeta))) / (2 * w)
    # the envelope leaves out the non-resonant part of Duhamel's integral, of relative size ~ sqrt(alpha) / w
    # (2.8 % here); the integration itself is good to 1e-9
    assert peak == pytest.approx(predicted, rel=np.sqrt(alpha) / w)
    if zeta == 0.0:
        fresnel, _, after = undamped_passage_peak(w, alpha)
        assert predicted == pytest.approx(fresnel / (2 * w), rel=1e-6)  # the Faddeeva form is the Fresnel one
        assert fresnel / after == pytest.approx(1.1707, abs=1e-4)  # the Cornu spiral's farthest point
    else:  # slower than steady: the passage never reaches the steady resonant amplitude f / (2 zeta w^2)
        assert peak < 1.0 / (2 * zeta * w * w)


def test_coupled_rotor_through_resonance_at_constant_acceleration():
    """The frame's x mode passed by an unbalance m e whose crank is turned at a constant angular acceleration:
    the coupled model against the oscillator (M + m) x'' + c x' + k x = m e (phi'^2 cos phi + phi'' sin phi)."""
    me, frame = 0.1, sprung_block(damping=300.0)
    model = coupled_model([Exciter(rotor(1.0, 0.1), None)], frame)
    alpha, duration = 10.0, 6.5  # through 49.75 rad/s at 5 s, the peak about 0.7 s later
    run = run_scenario(model, Scenario(duration=duration, prescribed=(0.0, alpha), method="DOP853", rtol=1e-9))
    m_total = frame.mass + 1.0

    def rhs(t, y):
        phi, w = 0.5 * alpha * t * t, alpha * t
        return [y[1], (me * (w * w * np.cos(phi) + alpha * np.sin(phi)) - 300.0 * y[1] - 2.5e5 * y[0]) / m_total]

    sol = solve_ivp(rhs, (0.0, duration), [0.0, 0.0], method="DOP853", rtol=1e-11, atol=1e-14, t_eval=run.t)
    x = run.q[0]
    # the stiff vertical springs and the rotor's offset couple x to y and the rotation by m e / M ~ 1e-3 of it
    assert np.max(np.abs(x - sol.y[0])) <= 5e-3 * np.max(np.abs(sol.y[0]))
    wn = np.sqrt(2.5e5 / m_total)
    zeta = 300.0 / (2 * np.sqrt(2.5e5 * m_total))
    t = run.t - wn / alpha
    predicted = me * wn * wn / m_total / (2 * wn) * float(np.max(passage_envelope(t, wn, alpha, zeta)))
    # the closed form takes the unbalance force m e w^2 at the resonance; it grows by 2 alpha t_peak / w over the
    # time to the peak (about 6 %), and the envelope's own error is ~ sqrt(alpha) / w
    assert np.max(np.abs(x)) == pytest.approx(predicted, rel=0.1)
    assert run.energy_error < 1e-6


def _sommerfeld(torque_at_rest, duration):
    """The rotor (1 kg at 0.1 m, 0.5 kg*m^2 of its own) started at 40 rad/s, below the base's x mode."""
    frame = sprung_block()  # k = 2.5e5 N/m, c = 200 N*s/m, M = 100 kg: w_n = 49.75 rad/s with the unbalance
    motor = TorqueSpeedTable((0.0, 100.0), (torque_at_rest, 0.0))  # Kononenko's linear characteristic L(Omega)
    model = coupled_model([Exciter(rotor(1.0, 0.1, inertia=0.5), motor)], frame)
    return run_scenario(model, Scenario(duration=duration, speed=40.0, method="DOP853", rtol=1e-9))


def _stationary_speeds(torque_at_rest):
    """Kononenko's stationary speeds: L(Omega) = S(Omega), in increasing order."""
    def surplus(w):
        return torque_at_rest * (1 - w / 100.0) - vibration_torque(w, 0.1, 101.0, 2.5e5, 200.0)

    grid = np.linspace(1.0, 100.0, 2000)
    values = surplus(grid)
    return [brentq(surplus, grid[i], grid[i + 1]) for i in np.flatnonzero(np.sign(values[:-1]) != np.sign(values[1:]))]


WN = np.sqrt(2.5e5 / 101.0)


def test_sommerfeld_capture_of_a_weak_motor():
    run = _sommerfeld(2.0, 6.0)
    roots = _stationary_speeds(2.0)
    captured, final = capture(run, [WN], free_speed=100.0)
    assert captured
    # the captured speed is Kononenko's lowest stationary speed, below the resonance (the speed still swings
    # slowly about it, by under 1 %)
    assert roots[0] < WN
    assert final == pytest.approx(roots[0], rel=0.02)
    # the motor's power goes into shaking the base: over the last second its damper takes more than 3/4 of it (82 %
    # here; the rest still speeds the rotor and its vibration up, slowly)
    last = run.t >= run.t[-1] - 1.0
    power_in = np.gradient(run.works[0], run.t)[last].mean()
    power_out = np.gradient(run.works[2], run.t)[last].mean()
    assert 0.75 * power_in < power_out < power_in
    assert run.energy_error < 1e-6


def test_a_stronger_motor_passes_the_resonance():
    run = _sommerfeld(30.0, 3.0)
    roots = _stationary_speeds(30.0)
    captured, final = capture(run, [WN], free_speed=100.0)
    assert not captured
    assert len(roots) == 1 and roots[0] > WN  # one stationary speed, above the resonance
    assert 1.3 * WN < final < roots[0]  # through the resonance, on its way to the stationary speed
    # the jump: far smaller vibration once through (over the last 0.2 s against the largest)
    x = np.abs(run.q[0])
    last = run.t >= run.t[-1] - 0.2
    assert x[last].max() < 0.3 * x.max()  # 0.21 here
    # and the base's damper now takes a small share of the motor's power
    assert np.gradient(run.works[2], run.t)[last].mean() < 0.1 * np.gradient(run.works[0], run.t)[last].mean()
    assert run.energy_error < 1e-6


def test_blekhman_two_counter_rotating_exciters_synchronise_into_rectilinear_vibration():
    k, c = 1e4, 100.0
    body = Frame(50.0, 5.0, (Mount("v1", (0.4, 0.0), np.pi / 2, k, c), Mount("v2", (-0.4, 0.0), np.pi / 2, k, c),
                             Mount("h", (0.0, 0.0), 0.0, k, c)))  # modes 14-20 rad/s, the exciters at 110 rad/s
    motor = TorqueSpeedTable((0.0, 110.0), (10.0, 0.0))
    exciters = [Exciter(rotor(0.5, 0.1, inertia=0.01, name="a"), motor, origin=(0.3, 0.0), name="a"),
                Exciter(rotor(0.5, 0.1, inertia=0.01, name="b"), motor, origin=(-0.3, 0.0), mirror=True, name="b")]
    model = coupled_model(exciters, body)
    # started 115 degrees apart: the body's motion pulls them together
    run = run_scenario(model, Scenario(duration=2.0, speed=100.0, angle=(0.0, 2.0), method="DOP853"))
    # the second exciter is mirrored: equal own angles put the unbalances symmetric about the y axis, their
    # horizontal forces cancelling and their vertical forces adding
    difference = np.degrees(np.angle(np.exp(1j * (run.phi[0] - run.phi[1]))))
    assert abs(difference[0]) > 100
    assert np.max(np.abs(difference[run.t > 1.5])) < 2.0
    last = run.t >= run.t[-1] - 0.2
    vertical, horizontal = np.ptp(run.q[1][last]), np.ptp(run.q[0][last])
    speed = run.omega[0, -1]
    mass = 51.0
    bounce = 2 * k / mass
    expected = 2 * (2 * 0.05 / mass) / (1 - bounce / speed**2)  # peak to peak of the rectilinear vibration
    assert vertical == pytest.approx(expected, rel=0.05)  # the rest: free vibration from the start, decaying
    assert horizontal < 0.3 * vertical
    assert run.energy_error < 1e-6
