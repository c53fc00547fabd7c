"""Seed 003 (four-bar compactor with an "Archimedes lever"): the illustrative test geometry of
seed-reproduction.md section 003.2 (r = 0.03, l = R1 = 0.5, h = 0.25, R = 0.25 m, omega1 = 10 rad/s, sigma = -1;
not from the paper, which gives no dimensions) computed by the ENGINE, and the corrections of section 003.3.
"""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.linkage import diagnose, energy, kinetostatics
from machdyn.machines import compactor as cm

G = 9.80665
GEOM = dict(r=0.03, l=0.5, h=0.25, R=0.25)

# repro 003.2 table: phi [deg] -> x_B, y_B [m], theta2, theta3 [deg], omega2, omega3 [rad/s], eps2, eps3 [rad/s^2]
VECTORS = {
    0: (0.529996738, 0.001806133, 0.2069680, -83.1086505, -0.59974208, 0.00436439, -0.7669939, -12.8063529),
    90: (0.499099286, 0.000001623, -3.4396265, -90.2064289, 0.00216516, -1.19974798, 6.7303715, 0.8024108),
    200: (0.471668277, 0.001610561, 1.3604632, -96.5071321, 0.54202939, 0.38718040, -2.5870366, 10.8647345),
}
NAMES = ("x_B", "y_B", "theta2", "theta3", "omega2", "omega3", "eps2", "eps3")


def _close(got, expected):
    # repro 003.2: "tolerance: rel 1e-6 or abs 1e-8, whichever is larger"
    return abs(got - expected) <= max(1e-6 * abs(expected), 1e-8)


def _state(k):
    c, p = k.body("coupler"), k.point("coupler.B")
    r = k.body("rocker")
    return (p.x, p.y, np.degrees(c.angle), np.degrees(r.angle), c.omega, r.omega, c.alpha, r.alpha)


@pytest.mark.parametrize("phi", sorted(VECTORS))
def test_engine_test_vectors(phi):
    k = cm.Compactor().kinematics(np.radians([float(phi)]))
    for name, got, expected in zip(NAMES, _state(k), VECTORS[phi], strict=True):
        assert _close(float(got[0]), expected), (phi, name, float(got[0]), expected)
    # the pendulum end B computed from the rocker agrees with the plate's B (loop closure, round-off)
    rb = k.point("rocker.B")
    assert np.allclose(rb.x, k.point("coupler.B").x, atol=1e-14)
    assert np.allclose(rb.y, k.point("coupler.B").y, atol=1e-14)


@pytest.mark.parametrize("phi", sorted(VECTORS))
def test_closed_form_test_vectors(phi):
    d = cm.closed_form(np.radians(phi), omega1=10.0, branch=-1, **GEOM)
    got = (d["xB"], d["yB"], np.degrees(d["theta2"]), np.degrees(d["theta3"]), d["omega2"], d["omega3"],
           d["eps2"], d["eps3"])
    for name, g, expected in zip(NAMES, got, VECTORS[phi], strict=True):
        assert _close(float(g), expected), (phi, name)


def test_engine_equals_closed_form_over_a_cycle():
    # Both exact: agreement to round-off (1e-12 rad, 1e-12 rad/s, 1e-10 rad/s^2) at 3601 angles.
    phi = np.linspace(0, 2 * np.pi, 3601)
    k = cm.Compactor().kinematics(phi)
    d = cm.closed_form(phi, omega1=10.0, branch=-1, **GEOM)
    assert np.allclose(np.exp(1j * k.body("coupler").angle), np.exp(1j * d["theta2"]), atol=1e-12)
    assert np.allclose(np.exp(1j * k.body("rocker").angle), np.exp(1j * d["theta3"]), atol=1e-12)
    assert np.allclose(k.body("coupler").omega, d["omega2"], atol=1e-12)
    assert np.allclose(k.body("rocker").omega, d["omega3"], atol=1e-12)
    assert np.allclose(k.body("coupler").alpha, d["eps2"], atol=1e-10)
    assert np.allclose(k.body("rocker").alpha, d["eps3"], atol=1e-10)


def test_gamma_rule_and_transmission_angle():
    # repro 003.2: gamma_max = 3.440 deg (at phi ~ 270 deg; printed 3 decimals -> 5e-4 deg), meeting gamma < 20 deg;
    # transmission angle |theta2 - theta3| within 82.5 ... 97.9 deg (1 decimal -> 0.05 deg).
    res = cm.Compactor().gamma_check()
    assert np.degrees(res["gamma_max"]) == pytest.approx(3.440, abs=5e-4)
    assert np.degrees(res["at"]) == pytest.approx(270.0, abs=1.0)
    assert res["ok"] is True
    assert np.degrees(res["transmission_min"]) == pytest.approx(82.5, abs=0.05)
    assert np.degrees(res["transmission_max"]) == pytest.approx(97.9, abs=0.05)
    # the engine's own diagnostics agree (grid of 3600, so to the grid's resolution ~1e-5 rad)
    d = diagnose(cm.Compactor().mechanism())
    assert d.grashof == "crank-rocker"
    assert d.transmission_angle_min == pytest.approx(res["transmission_min"], abs=1e-5)
    assert d.transmission_angle_max == pytest.approx(res["transmission_max"], abs=1e-5)
    # a steeper design breaks the rule: a long crank tilts the plate by about asin(r / l)
    steep = cm.Compactor(r=0.2, l=0.5, h=0.25, R=0.35).gamma_check()
    assert steep["ok"] is False and np.degrees(steep["gamma_max"]) > 20


def test_corrected_eqs_8_10_against_printed_form():
    # repro 003.3: at phi = 60 deg the printed eq 8 gives 5.56 deg against the correct 62.93 deg (2 decimals).
    comp = cm.Compactor()
    phi = np.radians(60.0)
    k = comp.kinematics(np.array([phi]))
    a_pt, b_pt = k.point("crank.A"), k.point("coupler.B")
    m_crank = a_pt.y[0] / a_pt.x[0]
    m_plate = (b_pt.y[0] - a_pt.y[0]) / (b_pt.x[0] - a_pt.x[0])
    assert np.degrees(cm.line_angle_printed(m_crank, m_plate)) == pytest.approx(5.56, abs=0.005)
    assert np.degrees(cm.line_angle(m_crank, m_plate)) == pytest.approx(62.93, abs=0.005)
    alpha, beta, gamma = comp.angles(np.array([phi]))
    assert abs(np.degrees(alpha[0])) == pytest.approx(np.degrees(cm.line_angle(m_crank, m_plate)), abs=1e-9)
    # atan2 forms at phi = 90 deg, where eq 8 divides by zero: alpha = theta2 - 90 deg, gamma = theta2
    alpha, beta, gamma = comp.angles(np.radians([90.0]))
    assert np.degrees(alpha[0]) == pytest.approx(-3.4396265 - 90.0, abs=1e-6)
    assert np.degrees(gamma[0]) == pytest.approx(-3.4396265, abs=1e-6)
    assert np.degrees(beta[0]) == pytest.approx(-90.2064289 + 3.4396265, abs=1e-6)


PHI_TEST = np.radians(np.arange(5.0, 360.0, 10.0))


def _normal(th2):
    return -np.sin(th2), np.cos(th2)


def test_k1_is_the_normal_force_on_the_plate_at_a():
    # repro 003.3: a crank force P tangential at A balances a force P / cos(alpha) normal to the plate at A (virtual
    # work). Engine: massless links, gravity off, a resisting force of magnitude F_n normal to the plate at A; the
    # driving torque M must give F_n = (M / r) k1 exactly (rel 1e-9, round-off). F_n = 1000 N.
    fn = 1000.0
    comp = cm.Compactor(gravity=(0.0, 0.0))

    def th2(phi):
        return cm.closed_form(phi, branch=-1, **GEOM)["theta2"]

    from dataclasses import replace

    from machdyn.linkage import PointForce

    load = PointForce("press", "coupler.A", lambda p: -fn * _normal(th2(p))[0], lambda p: -fn * _normal(th2(p))[1])
    mech = replace(comp.mechanism(), forces=(load,))
    f = kinetostatics(mech, PHI_TEST, speed=10.0)
    alpha, _, _ = comp.angles(PHI_TEST)
    assert np.allclose(cm.plate_normal_force(f.driving_torque, comp.r, alpha), fn, rtol=1e-9, atol=0)
    assert np.allclose(cm.force_gain_crank(alpha), fn * comp.r / f.driving_torque, rtol=1e-9)


def test_k2_is_a_lever_about_b():
    # k2 = l/a with the fulcrum at B (repro 003.3): on the massless plate, a load Q normal to the plate at a
    # distance a from B is balanced by a normal force Q a / l at A (moment balance about B). The engine's reaction
    # at joint A (crank on plate) must have that normal component (rel 1e-9). a = 0.1 m, Q = 2000 N.
    from dataclasses import replace

    from machdyn.linkage import PointForce

    q, a = 2000.0, 0.1
    comp = cm.Compactor(gravity=(0.0, 0.0), q_from_b=a)

    def n(phi):
        return _normal(cm.closed_form(phi, branch=-1, **GEOM)["theta2"])

    load = PointForce("Q", "coupler.P", lambda p: q * n(p)[0], lambda p: q * n(p)[1])
    mech = replace(comp.mechanism(), forces=(load,))
    f = kinetostatics(mech, PHI_TEST, speed=1e-3)
    ra = f.joint("A")
    nx, ny = n(PHI_TEST)
    normal_at_a = ra.fx * nx + ra.fy * ny  # force on the plate from the crank, along the plate normal
    assert np.allclose(-normal_at_a * cm.force_gain_lever(comp.l, a), q, rtol=1e-9)


# ------------------------------------------------------------------------------------ eqs 18-19

# Assumed data of the eq 19 example (repro 003.3: "Q = 2000 N vertical at 0.10 m from B"; its masses are not
# printed). They are recoverable from the two printed results: at phi = 0 the Q terms are 12.0209 N m (correct)
# and 30.0131 N m (printed form), so both 6.02 and 24.01 need a weight term of -6.00 N m, i.e. a plate weight
# G2 = 400 N (399.86 N < G2 <= 400.4 N fits both roundings), the crank's centroid at O (G1 does no work) and a
# pendulum weight that does not show at 2 decimals (V3y = 6.5e-5 m/s at phi = 0). Q acts upwards on the plate
# (the material resists the plate).
EXAMPLE = dict(m1=50.0 / G, m2=400.0 / G, m3=100.0 / G, I1=0.002, I2=0.8, I3=0.05, q_force=(0.0, 2000.0),
               q_from_b=0.10)


def test_eq19_example():
    # repro 003.3: eq 19 as printed gives 24.01 N m at phi = 0 against the correct 6.02 N m (2 decimals: 0.005).
    comp = cm.Compactor(**EXAMPLE)
    phi = np.array([0.0])
    m_engine = comp.reduced_moment(phi)
    assert m_engine[0] == pytest.approx(6.02, abs=0.005)
    k = comp.kinematics(phi)
    v2, v3 = k.com("coupler"), k.com("rocker")
    g2, g3 = (0.0, -comp.m2 * G), (0.0, -comp.m3 * G)
    printed = cm.reduced_moment_eq19_printed(comp.omega1, g2, (v2.vx, v2.vy), comp.q_force, g3, (v3.vx, v3.vy))
    assert printed[0] == pytest.approx(24.01, abs=0.005)


def test_corrected_eq19_equals_engine_reduced_moment():
    # The corrected formula (Q at its own point, G1 included) built from the engine's velocities equals the
    # engine's reduced moment at every angle (rel 1e-12). The crank centroid is off O here so that G1 matters.
    comp = cm.Compactor(**{**EXAMPLE, "crank_com": 0.01})
    phi = np.linspace(0, 2 * np.pi, 361)
    k = comp.kinematics(phi)
    loads = [((0.0, -m * G), (k.com(b).vx, k.com(b).vy))
             for b, m in (("crank", comp.m1), ("coupler", comp.m2), ("rocker", comp.m3))]
    qp = k.point("coupler.P")
    loads.append((comp.q_force, (qp.vx, qp.vy)))
    m_formula = cm.reduced_moment(comp.omega1, loads)
    m_engine = comp.reduced_moment(phi)
    assert np.allclose(m_formula, m_engine, rtol=1e-12, atol=1e-12 * np.max(np.abs(m_engine)))
    # and the printed form (Q at V2, no G1) is not the same
    assert np.max(np.abs(m_formula - m_engine)) < 1e-9 < np.max(np.abs(
        cm.reduced_moment_eq19_printed(comp.omega1, loads[1][0], loads[1][1], comp.q_force, loads[2][0],
                                       loads[2][1]) - m_engine))


def test_reduced_moment_by_virtual_work():
    # Independent of eq 19: at constant speed d(KE)/dt = (M_drive + M_red) w1, i.e. M_drive = w1^2/2 dI_red/dphi -
    # M_red. The engine's kinetostatic driving torque (joint-by-joint equilibrium) must satisfy it; dI_red/dphi by a
    # central difference with h = 1e-5 rad (truncation ~ h^2 I''' / 6 ~ 1e-11 kg m^2/rad, round-off ~ 1e-16 /
    # 1e-5 ~ 1e-11), so the check is to 1e-7 of the torque scale.
    comp = cm.Compactor(**{**EXAMPLE, "crank_com": 0.01})
    phi = np.linspace(0, 2 * np.pi, 73)
    h = 1e-5
    di = (comp.reduced_inertia(phi + h) - comp.reduced_inertia(phi - h)) / (2 * h)
    torque = kinetostatics(comp.mechanism(), phi, speed=comp.omega1).driving_torque
    expected = 0.5 * comp.omega1**2 * di - comp.reduced_moment(phi)
    assert np.allclose(torque, expected, rtol=0, atol=1e-7 * np.max(np.abs(torque)))
    # massless links: the drive simply balances the loads, M_drive = -M_red
    light = cm.Compactor(q_force=(0.0, 2000.0), q_from_b=0.1)
    t0 = kinetostatics(light.mechanism(), phi, speed=light.omega1).driving_torque
    assert np.allclose(t0, -light.reduced_moment(phi), rtol=1e-12, atol=1e-9)


def test_eq18_reduced_inertia():
    # Eq 18 with centroidal I2, I3, centroid speeds and I1 about O equals the engine's 2 KE / w1^2 (rel 1e-12).
    comp = cm.Compactor(**{**EXAMPLE, "crank_com": 0.01})
    phi = np.linspace(0, 2 * np.pi, 361)
    k = comp.kinematics(phi)
    v2, v3 = k.com("coupler"), k.com("rocker")
    i_red = cm.reduced_inertia_eq18(comp.omega1, comp.I1 + comp.m1 * comp.crank_com**2, comp.m2, v2.speed,
                                    comp.I2, k.body("coupler").omega, comp.m3, v3.speed, comp.I3,
                                    k.body("rocker").omega)
    assert np.allclose(i_red, comp.reduced_inertia(phi), rtol=1e-12, atol=0)
    e = energy(comp.mechanism(), phi, speed=comp.omega1)
    assert np.allclose(i_red, 2 * e.kinetic_total / comp.omega1**2, rtol=1e-12)
