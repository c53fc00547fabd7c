"""Steady-state response of a frame: closed-form transmissibility, energy balance, a time-domain check, loads
from the linkage engine, and before/after comparisons."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from machdyn.errors import InputError
from machdyn.linkage import analyse, crank_angles, slider_crank
from machdyn.linkage.model import PointMass
from machdyn.vibration import (
    Frame,
    Mount,
    compare,
    critical_damping,
    harmonic_loads,
    modes,
    reduction_percent,
    shaking_loads,
    steady_state,
    transmissibility,
)

UP = np.pi / 2


def single_mount_frame(m, k, c):
    """A block whose vertical motion rests on one mount (k, c) at its centre of mass; two horizontal mounts
    above and below the centre hold x and the rotation without touching the vertical motion (damped, so that
    an excitation near their own modes is not refused as an undamped resonance)."""
    return Frame(m, m * 0.1, (Mount("iso", (0.0, 0.0), UP, k, c), Mount("top", (0.0, 0.5), 0.0, 1e6, 2e3),
                              Mount("bottom", (0.0, -0.5), 0.0, 1e6, 2e3)))


@settings(max_examples=60, deadline=None)
@given(r=st.floats(0.05, 8.0), zeta=st.floats(0.01, 0.8), m=st.floats(1.0, 5000.0), k=st.floats(1e3, 1e8))
def test_single_mount_matches_closed_form_transmissibility(r, zeta, m, k):
    # Rao, Mechanical Vibrations, 5th ed., eq. (9.94): F_T / F_0 = sqrt(1 + (2 zeta r)^2) / sqrt((1 - r^2)^2 +
    # (2 zeta r)^2); and X = (F0/k) / sqrt((1 - r^2)^2 + (2 zeta r)^2) (eq. 3.30). Both exact: rel 1e-9.
    c = zeta * critical_damping(k, m)
    w = r * np.sqrt(k / m)
    f0 = 250.0
    resp = steady_state(single_mount_frame(m, k, c), harmonic_loads(w, force_y=f0))
    assert abs(resp.mount_force("iso")[0]) / f0 == pytest.approx(float(transmissibility(r, zeta)), rel=1e-9)
    x = abs(resp.displacement((0.0, 0.0))[0, 1])
    assert x == pytest.approx(f0 / k / np.sqrt((1 - r**2) ** 2 + (2 * zeta * r) ** 2), rel=1e-9)
    # RMS of a single harmonic is amplitude / sqrt 2; velocity amplitude is w X.
    assert resp.rms_velocity((0.0, 0.0), direction=UP) == pytest.approx(w * x / np.sqrt(2), rel=1e-12)
    assert resp.transmitted_force_rms("iso") == pytest.approx(abs(resp.mount_force("iso")[0]) / np.sqrt(2))


def random_frame(draw_k, draw_c, com=(0.1, -0.05)):
    mounts = (
        Mount("a", (-0.9, -0.3), UP, draw_k[0], draw_c[0]),
        Mount("b", (0.8, -0.3), np.radians(80), draw_k[1], draw_c[1]),
        Mount("c", (0.1, 0.4), 0.0, draw_k[2], draw_c[2]),
        Mount("d", (-0.2, -0.3), np.radians(20), draw_k[3], draw_c[3]),
    )
    return Frame(800.0, 150.0, mounts, com=com)


@settings(max_examples=40, deadline=None)
@given(k=st.lists(st.floats(1e4, 1e7), min_size=4, max_size=4),
       c=st.lists(st.floats(10.0, 2e4), min_size=4, max_size=4),
       w=st.floats(1.0, 400.0),
       q=st.lists(st.complex_numbers(max_magnitude=1e4, allow_nan=False, allow_infinity=False), min_size=3,
                  max_size=3))
def test_energy_input_per_cycle_equals_damping_dissipation(k, c, w, q):
    # Steady state: over a cycle the loads' work equals what the dampers dissipate (kinetic and elastic
    # energy return to their start). Independent formulas: pi Re(i Q^H q) vs sum pi w c |delta|^2. Rel 1e-8.
    frame = random_frame(k, c)
    resp = steady_state(frame, harmonic_loads(w, *q))
    w_in = resp.input_energy_per_cycle()[0]
    w_d = resp.dissipated_energy_per_cycle()[0]
    assert w_in == pytest.approx(w_d, rel=1e-8, abs=1e-12 * max(1.0, abs(w_d)))
    assert w_d >= 0


def test_steady_state_matches_time_integration():
    # Integrate M q'' + C q' + K q = Re(Q e^{i w t}) from rest with solve_ivp until transients have died
    # (modal damping >= 0.2, 60 periods of the slowest mode) and compare the last period with the frequency-domain
    # answer. Tolerance 1e-5 of the amplitude: the integrator's rtol 1e-9 plus e^{-zeta w_n t} < 1e-10 leftovers.
    from scipy.integrate import solve_ivp

    frame = random_frame([2e5, 3e5, 1e5, 2e5], [6e3, 8e3, 4e3, 5e3])
    md = modes(frame)
    assert np.min(md.damping_ratios) > 0.15
    w = 1.3 * md.angular_frequencies[1]
    loads = harmonic_loads(w, 300.0, 200.0 - 100.0j, 50.0j)
    resp = steady_state(frame, loads)
    m, k, c = frame.mass_matrix(), frame.stiffness_matrix(), frame.damping_matrix()
    minv = np.linalg.inv(m)
    q0 = loads.vector()[0]

    def rhs(t, s):
        x, v = s[:3], s[3:]
        return np.concatenate([v, minv @ ((q0 * np.exp(1j * w * t)).real - c @ v - k @ x)])

    t_end = 60 * 2 * np.pi / md.angular_frequencies[0]
    period = 2 * np.pi / w
    t_eval = t_end - period + np.linspace(0, period, 50)
    sol = solve_ivp(rhs, (0, t_end), np.zeros(6), t_eval=t_eval, rtol=1e-9, atol=1e-13, method="DOP853")
    expected = (np.exp(1j * w * t_eval)[:, None] * resp.coordinates[0]).real
    scale = np.max(np.abs(resp.coordinates[0]))
    np.testing.assert_allclose(sol.y[:3].T, expected, atol=1e-5 * scale)


def test_time_history_rms_equals_parseval_sum():
    frame = random_frame([2e5, 3e5, 1e5, 2e5], [600.0, 800.0, 400.0, 500.0])
    mech = slider_crank(0.05, 0.2, masses=(1.0, 1.2, 1.5))
    loads = shaking_loads(analyse(mech, crank_angles(360), speed=90.0), orders=8)
    resp = steady_state(frame, loads)
    t, ax, ay = resp.time_history((0.5, 0.3), "acceleration", samples=720)
    # Trapezoid-free mean over one whole period of a trigonometric polynomial of degree 8 < 360: exact.
    assert np.sqrt(np.mean(ax**2 + ay**2)) == pytest.approx(resp.rms_acceleration((0.5, 0.3)), rel=1e-12)
    assert np.sqrt(np.mean(ay**2)) == pytest.approx(resp.rms_acceleration((0.5, 0.3), direction=UP), rel=1e-12)
    # Peak of a periodic force: at least its RMS, at most the sum of its harmonic amplitudes.
    peak = resp.transmitted_force_peak("a")
    assert resp.transmitted_force_rms("a") <= peak <= np.sum(np.abs(resp.mount_force("a"))) * (1 + 1e-12)


def test_shaking_loads_rebuild_the_engines_frame_force_and_moment():
    # The harmonics of a slider-crank's shaking force are a finite sum in practice; with 12 orders the rebuilt
    # force differs from the engine's by less than 1e-6 of its peak (the next orders of a lambda = 0.25 crank are
    # ~lambda^12 smaller). The moment about the frame's reference point includes the origin shift.
    mech = slider_crank(0.05, 0.2, masses=(1.0, 1.2, 1.5))
    phi = crank_angles(360)
    an = analyse(mech, phi, speed=100.0)
    origin = (0.4, -0.25)
    loads = shaking_loads(an, orders=12, origin=origin)
    e = np.exp(1j * np.outer(phi, loads.orders))
    fx, fy = an.forces.frame_force
    mean = lambda v: np.mean(v)  # noqa: E731
    np.testing.assert_allclose((e @ loads.force_x).real + mean(fx), fx, atol=1e-6 * np.max(np.abs(fx)))
    np.testing.assert_allclose((e @ loads.force_y).real + mean(fy), fy, atol=1e-6 * np.max(np.abs(fy)))
    m_ref = an.forces.shaking_moment((-origin[0], -origin[1]))
    np.testing.assert_allclose((e @ loads.moment).real + mean(m_ref), m_ref, atol=1e-6 * np.max(np.abs(m_ref)))
    assert loads.frequencies[0] == pytest.approx(100.0 / (2 * np.pi))


def test_balanced_mechanism_shakes_the_frame_less():
    # A counterweight opposite the crank pin (mass x radius = rotating + half the reciprocating mass at the pin)
    # cuts the first-order shaking force, so the frame's RMS acceleration falls at every point.
    base = slider_crank(0.05, 0.2, masses=(0.0, 1.2, 1.5), slide_angle=UP)
    cw = PointMass("cw", "crank", 0.6 + 0.75, (-0.05, 0.0))
    balanced = replace(base, point_masses=(*base.point_masses, cw))
    frame = Frame(300.0, 40.0, (Mount("l", (-0.5, -0.3), UP, 3e5, 800.0), Mount("r", (0.5, -0.3), UP, 3e5, 800.0),
                                Mount("s", (0.0, -0.3), 0.0, 2e5, 500.0)))
    phi = crank_angles(360)
    before = steady_state(frame, shaking_loads(analyse(base, phi, speed=150.0)))
    after = steady_state(frame, shaking_loads(analyse(balanced, phi, speed=150.0)))
    cmp = compare(before, after, {"left": (-0.5, 0.0), "top": (0.0, 0.4)}, "acceleration")
    assert np.all(cmp.reduction > 0)
    # Half the reciprocating force is moved from the slide direction (vertical) to the horizontal: the vertical
    # mounts carry less, the horizontal one more (the classic trade-off of partial balance).
    assert cmp.mounts == ("l", "r", "s")
    assert np.all(cmp.force_after[:2] < cmp.force_before[:2]) and cmp.force_after[2] > cmp.force_before[2]
    assert cmp.mean_reduction == pytest.approx(float(reduction_percent(np.mean(cmp.before), np.mean(cmp.after))))


def test_reduction_percent_of_seed_002():
    # seed-reproduction.md 002.1 item 13: (0.5129 - 0.3546) / 0.5129 = 30.8637 % (paper prints 30.89 %).
    assert float(reduction_percent(0.5129, 0.3546)) == pytest.approx(30.8637, abs=5e-5)


def test_response_errors():
    frame = single_mount_frame(100.0, 1e5, 0.0)
    with pytest.raises(InputError, match="unbounded"):
        steady_state(frame, harmonic_loads(np.sqrt(1e5 / 100.0), force_y=1.0))
    with pytest.raises(InputError, match="crank speed of shaking loads must be > 0"):
        harmonic_loads(0.0, force_y=1.0)
    with pytest.raises(InputError, match="quantity must be one of"):
        steady_state(single_mount_frame(100.0, 1e5, 10.0), harmonic_loads(5.0, force_y=1.0)).rms((0, 0), "jerk")
    with pytest.raises(InputError, match="at least one named point"):
        r = steady_state(single_mount_frame(100.0, 1e5, 10.0), harmonic_loads(5.0, force_y=1.0))
        compare(r, r, {})
    with pytest.raises(InputError, match="level before must be > 0"):
        reduction_percent(0.0, 1.0)
    with pytest.raises(InputError, match="undamped isolator at resonance"):
        transmissibility(1.0, 0.0)
    mech = slider_crank(0.05, 0.2)
    with pytest.raises(InputError, match="crank acceleration"):
        shaking_loads(analyse(mech, crank_angles(36), speed=10.0, acceleration=1.0))


def test_engine_driven_frame_matches_time_integration_of_the_engines_loads():
    # Second method for the whole chain (engine -> harmonics -> frame response -> mount forces): integrate
    # M q'' + C q' + K q = load(t) with solve_ivp, the load being the engine's own frame force and shaking moment
    # time series (periodic cubic spline over crank angle, its mean removed: the static sag is not vibration),
    # rotated into the frame's axes and carried to the frame's reference point by statics alone (the moment about
    # the reference point, taken in mechanism coordinates). Mount forces are then k delta + c delta' along each
    # line, delta = n . u of the mount point. Tolerance 1e-4 of the largest amplitude: 12 orders of a
    # lambda = 0.25 crank leave ~lambda^12 ~ 1e-7, the spline on 1-degree steps ~1e-8, transients after 40
    # periods of the slowest mode with zeta >= 0.15 below e^{-37}, the integrator's rtol 1e-9.
    from scipy.integrate import solve_ivp
    from scipy.interpolate import CubicSpline

    frame = random_frame([2e5, 3e5, 1e5, 2e5], [6e3, 8e3, 4e3, 5e3])
    md = modes(frame)
    assert np.min(md.damping_ratios) > 0.15
    mech = slider_crank(0.05, 0.2, masses=(1.0, 1.2, 1.5))
    phi = crank_angles(360)
    speed = 90.0
    an = analyse(mech, phi, speed=speed)
    origin, angle = (0.4, -0.25), 0.3
    resp = steady_state(frame, shaking_loads(an, orders=12, origin=origin, angle=angle))

    fx, fy = (np.asarray(v, dtype=float) for v in an.forces.frame_force)
    rot = np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]])
    gx, gy = rot @ np.vstack([fx, fy])
    reference_in_mechanism = rot.T @ (-np.asarray(origin))
    mz = np.asarray(an.forces.shaking_moment(tuple(reference_in_mechanism)), dtype=float)
    series = np.vstack([gx, gy, mz])
    series = series - series.mean(axis=1, keepdims=True)
    closed = np.hstack([series, series[:, :1]])
    spline = CubicSpline(np.append(phi, phi[0] + 2 * np.pi), closed, axis=1, bc_type="periodic",
                         extrapolate="periodic")
    assert phi[0] == 0.0  # the harmonics' phases refer to crank angle 0 at t = 0

    m, k, c = frame.mass_matrix(), frame.stiffness_matrix(), frame.damping_matrix()
    minv = np.linalg.inv(m)

    def rhs(t, s):
        x, v = s[:3], s[3:]
        load = spline(speed * t)
        return np.concatenate([v, minv @ (load - c @ v - k @ x)])

    period = 2 * np.pi / speed
    t_end = np.ceil(40 * 2 * np.pi / md.angular_frequencies[0] / period) * period
    t_eval = t_end - period + np.arange(72) * period / 72
    sol = solve_ivp(rhs, (0, t_end), np.zeros(6), t_eval=t_eval, rtol=1e-9, atol=1e-13, method="DOP853")
    assert sol.success
    e = np.exp(1j * np.outer(t_eval, resp.angular_frequencies))
    expected_q = (e @ resp.coordinates).real
    scale = np.max(np.abs(sol.y[:3]), axis=1)
    np.testing.assert_allclose(sol.y[:3].T, expected_q, atol=1e-4 * np.max(scale))
    for mount in frame.mounts:
        b = mount.influence
        direct = mount.stiffness * (b @ sol.y[:3]) + mount.damping * (b @ sol.y[3:])
        harmonic = (e @ resp.mount_force(mount.name)).real
        np.testing.assert_allclose(direct, harmonic, atol=1e-4 * np.max(np.abs(direct)))
