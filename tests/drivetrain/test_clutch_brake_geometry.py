"""Clutches and brakes from their geometry: each closed form against a second, independent method (the numerical
integral of the pressure distribution, the band's differential equation, block-by-block equilibrium, a stop-by-stop
heating simulation), limits that reduce to known cases, and bad geometry refused with a clear error."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp
from scipy.optimize import minimize_scalar

from machdyn.drivetrain import brakes, clutches
from machdyn.errors import InputError

RI, RO, PA, MU = 0.08, 0.125, 0.3e6, 0.3


@pytest.mark.parametrize("law", ["uniform_wear", "uniform_pressure"])
def test_plate_clutch_force_and_torque_are_the_integrals_of_the_face_pressure(law):
    """F = ∫ p 2πr dr and T = μ ∫ p r 2πr dr over the annulus, p = p_a r_i/r (wear) or p_a (pressure)."""
    def pressure(r):
        return PA * RI / r if law == "uniform_wear" else PA

    force = quad(lambda r: pressure(r) * 2 * math.pi * r, RI, RO)[0]
    torque = quad(lambda r: MU * pressure(r) * 2 * math.pi * r * r, RI, RO)[0]
    assert clutches.axial_force(PA, RI, RO, law) == pytest.approx(force, rel=1e-10)
    assert clutches.plate_clutch_torque(MU, force, RI, RO, 1, law) == pytest.approx(torque, rel=1e-10)
    assert clutches.max_pressure(force, RI, RO, law) == pytest.approx(PA, rel=1e-12)
    assert clutches.plate_clutch_torque(MU, force, RI, RO, 4, law) == pytest.approx(4 * torque, rel=1e-12)


@pytest.mark.parametrize("law", ["uniform_wear", "uniform_pressure"])
def test_cone_clutch_torque_is_the_integral_over_the_slant_face(law):
    """On the cone the face element is 2πr dr / sin α; its normal force's axial part is p 2πr dr (the axial force)
    and its friction's moment μ p r 2πr dr / sin α."""
    alpha = math.radians(12.5)

    def pressure(r):
        return PA * RI / r if law == "uniform_wear" else PA

    force = quad(lambda r: pressure(r) * 2 * math.pi * r / math.sin(alpha) * math.sin(alpha), RI, RO)[0]
    torque = quad(lambda r: MU * pressure(r) * r * 2 * math.pi * r / math.sin(alpha), RI, RO)[0]
    assert clutches.cone_axial_force(PA, RI, RO, law) == pytest.approx(force, rel=1e-10)
    assert clutches.cone_clutch_torque(MU, force, RI, RO, alpha, law) == pytest.approx(torque, rel=1e-10)
    # a 90° cone is a flat plate with one friction surface
    assert clutches.cone_clutch_torque(MU, force, RI, RO, math.pi / 2, law) == pytest.approx(
        clutches.plate_clutch_torque(MU, force, RI, RO, 1, law), rel=1e-12)


def test_uniform_wear_torque_for_a_given_outer_radius_and_pressure_is_largest_at_ri_over_ro_one_over_root_3():
    """Shigley's MED, 10th ed., §16-5: with p_a and r_o fixed, T ∝ r_i (r_o² − r_i²) peaks at r_i = r_o/√3."""
    best = minimize_scalar(lambda ri: -clutches.plate_clutch_torque(MU, clutches.axial_force(PA, ri, RO), ri, RO, 1),
                           bounds=(0.01 * RO, 0.99 * RO), method="bounded", options={"xatol": 1e-10})
    assert best.x == pytest.approx(RO / math.sqrt(3), rel=1e-5)


def test_uniform_wear_gives_less_torque_than_uniform_pressure_for_the_same_force():
    wear = clutches.plate_clutch_torque(MU, 1e3, RI, RO, 2, "uniform_wear")
    new = clutches.plate_clutch_torque(MU, 1e3, RI, RO, 2, "uniform_pressure")
    assert wear < new < wear * 1.02  # close for a narrow face


def test_centrifugal_clutch_engages_at_its_spring_speed_and_grows_with_the_square_of_the_speed():
    args = (0.25, 4, 2.0, 0.12, 0.15, 500.0)
    c = clutches.centrifugal_clutch(*args, 100.0)
    assert clutches.centrifugal_clutch(*args, 0.999 * c.engagement_speed).torque == 0.0
    assert clutches.centrifugal_clutch(*args, c.engagement_speed).torque == pytest.approx(0.0, abs=1e-9)
    # T(ω) = n μ R (m r ω² − P_s): a straight line in ω²
    w = np.array([120.0, 150.0, 200.0])
    t = np.array([clutches.centrifugal_clutch(*args, x).torque for x in w])
    slope = np.polyfit(w**2, t, 1)[0]
    assert slope == pytest.approx(4 * 0.25 * 0.15 * 2.0 * 0.12, rel=1e-10)


@pytest.mark.parametrize("call, words", [
    (lambda: clutches.plate_clutch_torque(0.3, 1e3, 0.125, 0.125), "inner radius"),
    (lambda: clutches.plate_clutch_torque(0.3, 1e3, 0.2, 0.1), "smaller than its outer radius"),
    (lambda: clutches.axial_force(1e5, 0.0, 0.1), "inner radius > 0"),
    (lambda: clutches.plate_clutch_torque(float("nan"), 1e3, 0.1, 0.2), "coefficient of friction"),
    (lambda: clutches.cone_clutch_torque(0.3, 1e3, 0.1, 0.2, 0.0), "semi-cone angle"),
    (lambda: clutches.centrifugal_clutch(0.3, 4, 1.0, 0.2, 0.15, 0.0, 10.0), "drum's inner radius"),
    (lambda: clutches.plate_clutch_torque(0.3, 1e3, 0.1, 0.2, 0), "friction surfaces"),
])
def test_bad_clutch_geometry_is_refused_with_a_clear_error(call, words):
    with pytest.raises(InputError, match=words):
        call()


def test_internal_shoe_moments_are_the_vector_moments_of_the_lining_forces_about_the_hinge():
    """Second method: the drum's centre at the origin, the hinge at (a, 0); the lining element at angle θ carries
    the normal force p b r dθ along the radius and the friction f p b r dθ along the tangent; their moments about
    the hinge are cross products, integrated with quad (Shigley's MED, 10th ed., §16-2, Fig. 16-6)."""
    f, r, b, a, t1, t2 = 0.32, 0.15, 0.032, 0.123, math.radians(10), math.radians(126)
    m = brakes.shoe_moments(f, r, b, t1, t2, a)
    peak = 1.0  # θ_a = 90° inside the lining

    def pressure(t):
        return math.sin(t) / peak

    def cross(px, py, fx, fy):
        return px * fy - py * fx

    def normal_moment(t):
        px, py = r * math.cos(t) - a, r * math.sin(t)
        n = pressure(t) * b * r
        return cross(px, py, n * math.cos(t), n * math.sin(t))

    def friction_moment(t):
        px, py = r * math.cos(t) - a, r * math.sin(t)
        q = f * pressure(t) * b * r
        return cross(px, py, -q * math.sin(t), q * math.cos(t))

    assert abs(quad(normal_moment, t1, t2)[0]) == pytest.approx(m.normal, rel=1e-10)
    assert abs(quad(friction_moment, t1, t2)[0]) == pytest.approx(m.friction, rel=1e-10)
    torque = quad(lambda t: f * pressure(t) * b * r * r, t1, t2)[0]
    assert m.torque == pytest.approx(torque, rel=1e-10)


def test_a_shoe_hinged_too_close_to_the_centre_locks_itself_and_is_refused():
    with pytest.raises(InputError, match="locks itself"):
        brakes.internal_shoe_brake(0.6, 1e3, 0.15, 0.03, 0.0, math.radians(150), 0.05, 0.1)


def test_band_tension_ratio_is_the_solution_of_the_band_equation():
    """dT/dθ = μ T along the band (Euler–Eytelwein), integrated numerically over the wrap."""
    mu, wrap = 0.3, math.radians(270)
    sol = solve_ivp(lambda _t, y: mu * y, (0.0, wrap), [1.0], rtol=1e-11, atol=1e-12)
    assert brakes.band_ratio(mu, wrap) == pytest.approx(sol.y[0, -1], rel=1e-8)


def test_band_and_block_ratio_is_block_by_block_equilibrium():
    """Each block of 2θ: radial (T_in + T_out) sin θ = N, tangential (T_in − T_out) cos θ = μ N, solved as a
    linear system block after block."""
    mu, n, half = 0.3, 10, math.radians(7.5)
    tension = 1.0
    for _ in range(n):
        # unknowns T_in, N: [sin θ, -1; cos θ, -μ] [T_in, N] = [-T_out sin θ, T_out cos θ]
        a = np.array([[math.sin(half), -1.0], [math.cos(half), -mu]])
        rhs = np.array([-tension * math.sin(half), tension * math.cos(half)])
        tension = float(np.linalg.solve(a, rhs)[0])
    assert brakes.band_ratio(mu, 0.0, n, 2 * half) == pytest.approx(tension, rel=1e-12)


def test_band_brakes_limits_and_self_locking():
    mu, wrap, r = 0.3, math.radians(270), 0.25
    ratio = math.exp(mu * wrap)
    simple = brakes.band_brake(mu, 100.0, r, 0.5, 0.1, wrap)
    assert simple.torque == pytest.approx(100.0 * 0.5 / 0.1 * (ratio - 1) * r)
    # a differential brake with its tight end on the pivot is a simple band brake
    diff = brakes.differential_band_brake(mu, 100.0, r, 0.5, 0.1, 0.0, wrap)
    assert diff.torque == pytest.approx(simple.torque, rel=1e-12)
    # the lever force falls to zero as b2 → b1 e^{μθ}; at it the brake locks itself
    b1 = 0.02
    near = brakes.differential_band_brake(mu, 100.0, r, 0.5, b1 * ratio * 1.001, b1, wrap)
    assert near.torque > 100 * simple.torque
    with pytest.raises(InputError, match="locks itself"):
        brakes.differential_band_brake(mu, 100.0, r, 0.5, b1 * ratio, b1, wrap)


def test_block_brake_moment_balance_and_self_locking():
    mu, f, r, l, x, a = 0.3, 200.0, 0.2, 0.9, 0.3, 0.05
    b = brakes.block_brake(mu, f, r, l, x, a)
    n = b.torque / (mu * r)
    assert f * l + mu * n * a - n * x == pytest.approx(0.0, abs=1e-9)  # moments about the pivot
    assert b.torque > brakes.block_brake(mu, f, r, l, x, 0.0).torque > b.torque_reverse
    assert brakes.block_brake(mu, f, r, l, x, 0.0).torque == pytest.approx(mu * f * l / x * r)
    with pytest.raises(InputError, match="locks itself"):
        brakes.block_brake(mu, f, r, l, mu * 0.5, 0.5)
    double = brakes.double_block_brake(mu, f, r, l, x, a)
    assert double.torque == pytest.approx(b.torque + b.torque_reverse)


def test_long_shoe_equivalent_friction_is_the_ratio_of_the_integrated_friction_to_the_normal_resultant():
    """p = p0 cos φ over ±θ: μ' = μ ∫ p dφ / ∫ p cos φ dφ (the resultant normal force through the shoe's centre)."""
    mu, theta = 0.3, math.radians(50)
    friction = quad(lambda p: mu * math.cos(p), -theta, theta)[0]
    normal = quad(lambda p: math.cos(p) ** 2, -theta, theta)[0]
    assert brakes.equivalent_friction(mu, 2 * theta) == pytest.approx(friction / normal, rel=1e-10)
    assert brakes.equivalent_friction(mu, 0.0) == mu


def test_repeated_stops_heat_the_drum_to_the_geometric_series_limit():
    """Stop after stop: add ΔT, cool by e^{−β t1}; after many stops the peak is ΔT/(1 − e^{−β t1})."""
    h = brakes.temperature_rise(50e3, 15.0, 460.0, cooling=25.0, interval=45.0)
    level = 0.0
    for _ in range(3000):
        level = level + h.rise_per_stop
        peak = level
        level *= math.exp(-h.decay_rate * h.interval)
    assert h.steady_peak_rise == pytest.approx(peak, rel=1e-9)
    assert h.steady_base_rise == pytest.approx(level, rel=1e-9)
    t, rise = h.history(5)
    assert max(rise) < h.steady_peak_rise and rise[0] == pytest.approx(h.rise_per_stop)
    assert brakes.temperature_rise(50e3, 15.0, 460.0).steady_peak_rise == pytest.approx(50e3 / (15 * 460))
    with pytest.raises(InputError, match="without bound"):
        brakes.temperature_rise(50e3, 15.0, 460.0, interval=45.0)
