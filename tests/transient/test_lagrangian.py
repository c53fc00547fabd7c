"""The coupled equations against an independent derivation: a slider-crank on a frame on four sprung mounts,
driven from rest by an induction motor through a gear, written here from its Lagrangian in the generalised
coordinates s = (phi, x, y, beta) and integrated with scipy's solve_ivp.

The derivation shares nothing with :mod:`machdyn.transient` but the motor's torque-speed law and the mounts' data:
the slider-crank's positions are written by hand (crank pin r (cos phi, sin phi), rod angle
psi = asin(-r sin phi / l), slider on the x axis), every mass element's absolute position is (x, y) + R(beta) g(phi)
with the exact rotation R(beta), and Lagrange's equations for T = sum 1/2 m |r'|^2 + 1/2 I theta'^2 are taken in
their d'Alembert form (Lanczos, *The Variational Principles of Mechanics*, 4th ed., Dover 1970, ch. IV):

    sum_i m_i J_i^T (J_i s'' + J_i' s') + I_i k_i^T (k_i s'' + k_i' s') = Q,   J_i = dr_i/ds, k_i = dtheta_i/ds,

with J_i by the complex step (exact to round-off; Squire & Trapp, SIAM Review 40, 1998) and J_i' s' by a central
difference of J_i along s'. The mounts are linear springs and dampers along their lines (their definition in
:class:`machdyn.vibration.frame.Mount`), preloaded by the moving parts' mean weight over a turn (q = 0 the static
equilibrium, as machdyn measures it); the weight of the moving parts acts at their exact positions (run with and
without gravity); the motor's stator reacts on the frame (its torque does work on phi only).
machdyn's model keeps the kinetic energy to second order in the frame's small motion (q, q'); the exact rotation
here adds terms of third order, whose relative effect on the response is a fraction of the frame's largest rotation
beta_max (here 7e-3 rad, the mechanism's 73 kg shaking a 600 kg frame): the tolerances below are set from it. The
frame's centre of mass is put at its reference point, where the frame's own third-order terms vanish, so that what
is compared is the coupling of the mechanism with the frame. Without the second-order term of the momentum turning
with the frame (beta c_k in :mod:`machdyn.transient.model`) the vertical motion is off by 0.7 % and the rotation by
0.5 % (against 0.02 % and 0.09 % with it).
"""

import math

import numpy as np
import pytest

from machdyn.dynamics import InductionMotor
from machdyn.linkage import slider_crank
from machdyn.transient import Exciter, Scenario, coupled_model, run_scenario
from machdyn.vibration.frame import Frame, Mount

RPM = math.pi / 30.0
CRANK, ROD = 0.05, 0.3  # m
MASSES = (5.0, 8.0, 60.0)  # kg: crank, rod, slider
INERTIAS = (0.01, 0.06, 0.0)  # kg*m^2 about their centres (bars' centres at mid-length)
FLYWHEEL = 2.0  # kg*m^2 on the crank
FRAME_MASS, FRAME_INERTIA, FRAME_COM = 600.0, 150.0, (0.0, 0.0)  # centre at the reference point
MOUNTS = (("v1", (0.8, -0.4), 90.0, 4e5, 2e3), ("v2", (-0.4, -0.4), 90.0, 4e5, 2e3),
          ("h1", (0.8, -0.4), 0.0, 1.2e5, 1.5e3), ("h2", (-0.4, -0.4), 0.0, 1.2e5, 1.5e3))
MOTOR = InductionMotor(1500.0, 1440 * RPM, 1500 * RPM, 2.5, 5.0, 1.0, 0.01)  # 1.5 kW through 5:1, rotor 0.01 kg*m^2


def _elements(s):
    """(positions (E, 2), absolute angles (E,), masses (E,), inertias (E,)) of the mass elements at s, complex-safe:
    the crank, the rod, the slider, the frame, the motor's rotor (its angle: the gear's ratio times phi)."""
    phi, x, y, beta = s
    c, sn = np.cos(beta), np.sin(beta)

    def absolute(gx, gy):
        return x + c * gx - sn * gy, y + sn * gx + c * gy

    pin = (CRANK * np.cos(phi), CRANK * np.sin(phi))
    psi = np.arcsin(-CRANK * np.sin(phi) / ROD)
    rod_centre = (pin[0] + 0.5 * ROD * np.cos(psi), pin[1] + 0.5 * ROD * np.sin(psi))
    slider = (pin[0] + ROD * np.cos(psi), 0.0 * phi)
    local = [(0.5 * pin[0], 0.5 * pin[1]), rod_centre, slider, FRAME_COM, (0.0 * phi, 0.0 * phi)]
    positions = [absolute(*g) for g in local]
    angles = [phi + beta, psi + beta, beta, beta, MOTOR.ratio * phi + beta]
    masses = [*MASSES, FRAME_MASS, 0.0]
    inertias = [INERTIAS[0] + FLYWHEEL, INERTIAS[1], INERTIAS[2], FRAME_INERTIA, MOTOR.rotor_inertia]
    return positions, angles, masses, inertias


def _jacobians(s):
    """(J (E, 2, 4), k (E, 4)) by the complex step."""
    h = 1e-30
    jac = np.zeros((5, 2, 4))
    rate = np.zeros((5, 4))
    for j in range(4):
        z = np.array(s, dtype=complex)
        z[j] += 1j * h
        positions, angles, _, _ = _elements(z)
        for e in range(5):
            jac[e, :, j] = np.imag(np.array(positions[e])) / h
            rate[e, j] = np.imag(angles[e]) / h
    return jac, rate


def _mount_matrices():
    """K, C over q = (x, y, beta) from the mounts' lines: deflection b.q, b = (cos d, sin d, p_x sin d - p_y cos d)."""
    k = np.zeros((3, 3))
    c = np.zeros((3, 3))
    for _, (px, py), degrees, rate, damping in MOUNTS:
        d = math.radians(degrees)
        b = np.array([math.cos(d), math.sin(d), px * math.sin(d) - py * math.cos(d)])
        k += rate * np.outer(b, b)
        c += damping * np.outer(b, b)
    return k, c


def _weight(s, gravity):
    """Generalised force (4,) of the moving parts' weight (the crank, the rod, the slider) at s."""
    jac, _ = _jacobians(s)
    _, _, masses, _ = _elements(np.zeros(4))
    return sum(masses[e] * jac[e].T @ np.array([0.0, -gravity]) for e in range(3))


def _reference(duration, t_eval, gravity=0.0):
    from scipy.integrate import solve_ivp

    _, _, masses, inertias = _elements(np.zeros(4))
    stiffness, damping = _mount_matrices()
    # the mounts' preload: the mean weight over a turn, so that q = 0 is the frame's static equilibrium
    turn = np.linspace(0.0, 2 * np.pi, 64, endpoint=False)
    preload = -np.mean([_weight(np.array([p, 0.0, 0.0, 0.0]), gravity)[1:] for p in turn], axis=0)

    def rhs(t, state):
        s, v = state[:4], state[4:]
        jac, rate = _jacobians(s)
        eps = 1e-6 / max(float(np.max(np.abs(v))), 1e-12)
        jac_p, rate_p = _jacobians(s + eps * v)
        jac_m, rate_m = _jacobians(s - eps * v)
        djac = (jac_p - jac_m) / (2 * eps)
        drate = (rate_p - rate_m) / (2 * eps)
        mass = np.zeros((4, 4))
        inertial = np.zeros(4)
        for e in range(5):
            mass += masses[e] * jac[e].T @ jac[e] + inertias[e] * np.outer(rate[e], rate[e])
            inertial += masses[e] * jac[e].T @ (djac[e] @ v) + inertias[e] * rate[e] * (drate[e] @ v)
        force = np.zeros(4)
        force[0] = float(MOTOR.torque_at(v[0]))
        force[1:] = -stiffness @ s[1:] - damping @ v[1:] + preload
        if gravity:
            force += _weight(s, gravity)
        return np.concatenate([v, np.linalg.solve(mass, force - inertial)])

    sol = solve_ivp(rhs, (0.0, duration), np.zeros(8), method="DOP853", rtol=1e-10, atol=1e-12, t_eval=t_eval)
    assert sol.success
    return sol.y


@pytest.mark.parametrize("gravity", [0.0, 9.81])
def test_the_coupled_equations_follow_from_the_lagrangian_of_a_slider_crank_on_a_sprung_frame(gravity):
    mech = slider_crank(CRANK, ROD, masses=MASSES, inertias=INERTIAS, gravity=(0.0, -gravity))
    frame = Frame(FRAME_MASS, FRAME_INERTIA, tuple(Mount(n, p, math.radians(d), k, c) for n, p, d, k, c in MOUNTS),
                  com=FRAME_COM)
    model = coupled_model([Exciter(mech, MOTOR, FLYWHEEL)], frame)
    run = run_scenario(model, Scenario(duration=1.0, rtol=1e-10))
    keep = slice(None, None, 8)
    t = run.t[keep]
    reference = _reference(1.0, t, gravity)
    beta_max = float(np.max(np.abs(reference[3])))
    assert run.omega[0, -1] > 20.0  # the crank has run up through the frame's modes (3-6 Hz)
    assert 1e-4 < beta_max < 1e-2
    speed_error = np.max(np.abs(run.omega[0, keep] - reference[4])) / np.max(reference[4])
    errors = [np.max(np.abs(run.q[i, keep] - reference[1 + i])) / np.max(np.abs(reference[1 + i])) for i in range(3)]
    # third-order terms of the exact rotation: relative effects of a fraction of beta_max (measured: 5e-4 and 0.13
    # of it)
    assert speed_error < 0.01 * beta_max
    assert max(errors) < 0.3 * beta_max


def test_the_general_and_the_scalar_right_hand_sides_agree_with_the_frame_turned_and_moving():
    """The general equations (:meth:`CoupledModel.matrices`, several cranks) and the scalar ones of
    :mod:`machdyn.transient.fast` (one crank) are the same equations: at a state with the frame displaced, turned
    and moving they give the same accelerations to round-off."""
    from machdyn.transient import fast

    mech = slider_crank(CRANK, ROD, masses=MASSES, inertias=INERTIAS, gravity=(0.0, 0.0))
    frame = Frame(FRAME_MASS, FRAME_INERTIA, tuple(Mount(n, p, math.radians(d), k, c) for n, p, d, k, c in MOUNTS),
                  com=(0.3, -0.2))
    model = coupled_model([Exciter(mech, MOTOR, FLYWHEEL, origin=(0.1, 0.2), angle=0.3)], frame)
    state = {"torques": [lambda w: float(MOTOR.torque_at(w))], "on": True, "brake": 0.0, "load": 0.0}
    scalar = fast.right_hand_side(model, state, lambda t: None, 1.0)
    phi, w = 0.7, 25.0
    q, dq = np.array([0.01, -0.004, 0.006]), np.array([0.2, -0.1, 0.08])
    got = scalar(0.0, np.concatenate([[phi, w], q, dq, np.zeros(4)]))
    mass, force, values, slopes = model.matrices(np.array([phi]), np.array([w]), q, dq)
    rhs = force.copy()
    rhs[0] += float(MOTOR.torque_at(w)) + model.parts[0].loads(phi, w, values[0]) - slopes[0][1]
    rhs[1:] += -model.stiffness @ q - model.damping @ dq
    expected = np.linalg.solve(mass, rhs)
    assert np.allclose([got[1], *got[5:8]], expected, rtol=1e-11, atol=1e-11 * np.max(np.abs(expected)))
