"""A shaft line on its six-degree-of-freedom frame in time, against the analyses that answer its limits.

(a) At a prescribed constant shaft speed the frame settles into the periodic steady state that
    :func:`machdyn.shafts.frame6.steady_response` computes order by order (Rao, *Mechanical Vibrations*, 5th ed.,
    sec. 6.15).
(b) A free decay of the frame (the shaft held) vibrates at the natural frequencies of
    :func:`machdyn.shafts.frame6.modes6` (the eigenvalues of K - w^2 M), read from its spectrum.
(c) The energy balance of a run-up and braked stop: motor work = change of energy + dissipation, to 1e-6 of the
    motor work; without motor and dampers the energy is conserved (a check of every derivative in the equations).
(d) With one soft translational mode the frame is the one-degree-of-freedom oscillator driven through its
    resonance at a constant angular acceleration: its direct integration, and Lewis's closed-form envelope
    (F. M. Lewis, Trans. ASME 54 (1932) 253-261; :mod:`machdyn.transient.closed_forms`) with the tolerance its
    own test justifies (tests/validation/test_transient_resonance.py).
"""

from dataclasses import replace

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from machdyn.dynamics import InductionMotor
from machdyn.shafts.frame6 import Frame6, Mount6, modes6, steady_response
from machdyn.shafts.model import ShaftLine
from machdyn.shafts.reciprocating import Cylinder
from machdyn.shafts.rotating import Mass, rotating_loads
from machdyn.transient.closed_forms import passage_envelope
from machdyn.transient.run import Scenario
from machdyn.transient.shaft_model import shaft_frame_model
from machdyn.transient.shaft_run import run_shaft_scenario

RPM = np.pi / 30.0


def line(masses=(), cylinders=()):
    """A shaft line of ``masses`` and ``cylinders`` (the analysis's own objects)."""
    return ShaftLine(100.0, 360, 6, 0.0, tuple(masses), tuple(cylinders), (), (), (), None, (), ())


def block(damping=600.0):
    """A 120 kg frame on seven mounts (four vertical, two lateral, one axial): six modes of 4.9-24 Hz."""
    spec = [((0.3, -0.2, 0.0), (0, 1, 0), 2e5), ((-0.3, -0.2, 0.0), (0, 1, 0), 2e5),
            ((0.3, -0.2, 0.4), (0, 1, 0), 2e5), ((-0.3, -0.2, 0.4), (0, 1, 0), 2e5),
            ((0.0, -0.2, 0.0), (1, 0, 0), 1.5e5), ((0.0, -0.2, 0.4), (1, 0, 0), 1.5e5),
            ((0.0, -0.2, 0.2), (0, 0, 1), 1.5e5)]
    mounts = tuple(Mount6(f"m{i}", p, d, k, damping) for i, (p, d, k) in enumerate(spec))
    return Frame6(120.0, (5.0, 6.0, 4.0), mounts, (0.02, 0.05, 0.2))


#: two light unbalances in two planes, the shaft off the frame's origin: every degree of freedom is driven
LIGHT = (Mass("front", 0.02, 0.1, 0.3, 0.0), Mass("rear", 0.015, 0.1, 2.0, 0.4))
SHAFT = (0.05, 0.1)


def test_a_prescribed_constant_speed_settles_to_the_frames_steady_response():
    speed = 60.0  # between the third and fourth modes
    frame = block(damping=1500.0)
    model = shaft_frame_model(line(LIGHT), frame, SHAFT)
    run = run_shaft_scenario(model, Scenario(duration=2.0, prescribed=(speed, 0.0), method="DOP853", rtol=1e-10))
    theta = np.linspace(0.0, 2 * np.pi, 360, endpoint=False)
    response = steady_response(frame, rotating_loads(LIGHT, speed, theta, 0.0), SHAFT, orders=3)
    last = run.t >= run.t[-1] - 2 * np.pi / speed
    t = run.t[last]
    expected = (np.exp(1j * np.outer(t, response.orders * speed)) @ response.q).real.T  # (6, samples)
    got = run.q[:, last]
    # the slowest mode's free vibration has decayed to below 1e-6 of its start; what remains is the model's second
    # order: the moving masses' departure from their mean (m / M ~ 3e-4) and the shaking force turning with the
    # frame (by its rotation, ~1e-6 rad)
    for k in range(6):
        scale = np.max(np.abs(expected[k]))
        assert np.max(np.abs(got[k] - expected[k])) <= 1e-3 * scale, k
    # the drive holds the speed against the frame's pull: the mean power it gives is what the mounts dissipate
    assert run.energy_error < 1e-6


def test_a_free_decay_vibrates_at_the_frames_natural_frequencies():
    frame = block(damping=0.0)
    model = shaft_frame_model(line(LIGHT), frame, SHAFT)
    run = run_shaft_scenario(model, Scenario(duration=1.5, prescribed=(0.0, 0.0), method="DOP853", rtol=1e-9,
                                             samples_per_period=16),
                             frame_start=np.full(6, 1e-3))
    hz, shapes = modes6(frame)
    modal = shapes.T @ frame.mass_matrix() @ run.q  # each row one mode's coordinate
    dt = run.t[1] - run.t[0]
    assert np.allclose(np.diff(run.t), dt)
    pad = 64 * run.t.size
    freq = np.fft.rfftfreq(pad, dt)
    window = np.hanning(run.t.size)
    for j in range(6):
        spectrum = np.abs(np.fft.rfft(modal[j] * window, pad))
        i = int(np.argmax(spectrum))
        # the peak between its neighbours: a parabola through the log-magnitudes (Gaussian interpolation; the
        # Hann window's main lobe is close to a Gaussian), good to 1e-4 of a bin of the padded spectrum
        a, b, c = np.log(spectrum[i - 1:i + 2])
        peak = freq[i] + 0.5 * (a - c) / (a - 2 * b + c) * (freq[1] - freq[0])
        assert peak == pytest.approx(hz[j], rel=1e-3), j
    assert np.max(np.abs(run.energy - run.energy[0])) <= 1e-7 * run.energy[0]


@pytest.fixture(scope="module")
def motor():
    """A 3 kW four-pole motor directly on the shaft."""
    return InductionMotor(3000.0, 1440 * RPM, 1500 * RPM, 2.5, 1.0, 1.0, 0.01)


def single_cylinder():
    """A vertical cylinder with a counterweight for its rotating mass and half its reciprocating mass."""
    return line([Mass("counterweight", 1.1, 0.04, np.pi, 0.1)],
                [Cylinder("c1", 0.1, 0.0, np.pi / 2, 0.04, 0.14, 1.0, 0.6)])


def test_a_run_up_and_braked_stop_close_their_energy_balance(motor):
    model = shaft_frame_model(single_cylinder(), block(), (0.0, 0.0), motor, 0.1)
    run = run_shaft_scenario(model, Scenario(duration=2.0, switch_off=1.0, brake_time=1.0, brake_torque=25.0))
    assert run.ended == "stopped"
    assert np.max(run.omega) > 140.0  # it ran up through every mode (the highest at 152 rad/s)
    w = run.works[:, -1]
    residual = w[0] - w[2] - w[3] - (run.energy[-1] - run.energy[0])
    assert abs(residual) <= 1e-6 * w[0]
    assert w[2] > 0 and w[3] > 0


def test_without_drive_and_dampers_the_shaft_line_and_frame_conserve_their_energy():
    """Lagrange's equations of the model conserve T + V when nothing drives or dissipates: a check of every
    derivative in them (J', p', h', the moving masses' block, the coupling turning with the frame, the gyroscopic
    term of the drive line's spin)."""
    model = shaft_frame_model(single_cylinder(), block(damping=0.0), (0.03, -0.02), None, 0.2)
    run = run_shaft_scenario(model, Scenario(duration=0.6, speed=90.0, method="DOP853", rtol=1e-11))
    assert np.max(np.abs(run.q[3:])) > 1e-4  # the frame rocks
    assert np.max(np.abs(run.energy - run.energy[0])) <= 1e-8 * run.energy[0]


def test_one_soft_translational_mode_is_the_oscillator_driven_through_resonance():
    """The frame's x mode alone is soft (its mount at the centre of mass, nothing else acting along x); the
    unbalance m e turns at a constant angular acceleration through it."""
    mass, k, c = 100.0, 2.5e5, 300.0
    stiff = 4e5
    mounts = (Mount6("x", (0.0, 0.0, 0.0), (1, 0, 0), k, c),
              *(Mount6(f"y{i}", (sx * 0.5, 0.0, sz * 0.5), (0, 1, 0), stiff, 2e3)
                for i, (sx, sz) in enumerate(((1, 1), (1, -1), (-1, 1), (-1, -1)))),
              Mount6("z1", (0.5, 0.0, 0.0), (0, 0, 1), stiff, 2e3),
              Mount6("z2", (-0.5, 0.0, 0.0), (0, 0, 1), stiff, 2e3))
    frame = Frame6(mass, (20.0, 20.0, 20.0), mounts)
    me = 0.1
    model = shaft_frame_model(line([Mass("unbalance", 1.0, me, 0.0, 0.0)]), frame)
    speed0, alpha, duration = 35.0, 10.0, 2.9  # through 50 rad/s at 1.5 s, the peak some 0.7 s later
    run = run_shaft_scenario(model, Scenario(duration=duration, prescribed=(speed0, alpha), method="DOP853",
                                             rtol=1e-8))

    def rhs(t, y):
        phi, w = speed0 * t + 0.5 * alpha * t * t, speed0 + alpha * t
        return [y[1], (me * (w * w * np.cos(phi) + alpha * np.sin(phi)) - c * y[1] - k * y[0]) / mass]

    sol = solve_ivp(rhs, (0.0, duration), [0.0, 0.0], method="DOP853", rtol=1e-11, atol=1e-14, t_eval=run.t)
    x = run.q[0]
    # the unbalance's departure from its mean couples x to the stiff rotation about z by m e / M ~ 1e-3
    assert np.max(np.abs(x - sol.y[0])) <= 5e-3 * np.max(np.abs(sol.y[0]))
    wn, zeta = np.sqrt(k / mass), c / (2 * np.sqrt(k * mass))
    t = run.t - (wn - speed0) / alpha
    predicted = me * wn * wn / mass / (2 * wn) * float(np.max(passage_envelope(t, wn, alpha, zeta)))
    # the closed form's own tolerance (tests/validation/test_transient_resonance.py): the envelope leaves out the
    # non-resonant part (~ sqrt(alpha) / w) and takes the force m e w^2 at the resonance
    assert np.max(np.abs(x)) == pytest.approx(predicted, rel=0.1)
    assert run.energy_error < 1e-6


def test_a_frame_lighter_than_its_moving_parts_is_refused():
    frame = replace(block(), mass=1.0, inertia=(0.01, 0.01, 0.01))
    with pytest.raises(Exception, match="whole machine"):
        shaft_frame_model(single_cylinder(), frame)
