"""Physics of the shaft line: balance closes both polygons at every angle, the exact engine agrees with the
linkage engine and with the planar balancing, influence coefficients recover a known unbalance, bearings obey
statics."""

from __future__ import annotations

import doctest
import importlib
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from machdyn.balancing.counterweights import balance_mass
from machdyn.balancing.frame import frame_loads
from machdyn.linkage.builders import slider_crank
from machdyn.shafts.balance import Plane, equivalent_in_planes, single_plane, two_plane
from machdyn.shafts.field import Reading, TrialRun, reading
from machdyn.shafts.field import single_plane as field_single
from machdyn.shafts.field import two_plane as field_two
from machdyn.shafts.reciprocating import (
    Cylinder,
    crank_phases_from_firing_order,
    engine_orders,
    piston_acceleration,
    reciprocating_loads,
)
from machdyn.shafts.rotating import Bearing, Mass, bearing_reactions, cycle, rotating_loads

ROOT_EXAMPLES = __import__("pathlib").Path(__file__).resolve().parents[2] / "examples"
MODULES = ["machdyn.shafts.rotating", "machdyn.shafts.balance", "machdyn.shafts.grades",
           "machdyn.shafts.reciprocating", "machdyn.shafts.field"]


@pytest.mark.parametrize("name", MODULES)
def test_doctests(name):
    result = doctest.testmod(importlib.import_module(name), optionflags=doctest.NORMALIZE_WHITESPACE)
    assert result.attempted > 0 and result.failed == 0


masses_st = st.lists(st.tuples(st.floats(0.01, 50.0), st.floats(0.01, 0.5), st.floats(0.0, 2 * math.pi),
                               st.floats(-1.0, 2.0)), min_size=1, max_size=6)


@settings(max_examples=40, deadline=None)
@given(masses_st, st.floats(-0.5, 0.4), st.floats(0.2, 1.5), st.floats(10.0, 400.0))
def test_two_plane_balance_leaves_no_force_and_no_couple_at_any_angle(data, z_l, gap, speed):
    masses = [Mass(f"m{i}", m, r, a, z) for i, (m, r, a, z) in enumerate(data)]
    result = two_plane(masses, Plane("L", z_l, 0.1), Plane("M", z_l + gap, 0.15), speed)
    scale_f = max(sum(m.mass * m.radius for m in masses) * speed**2, 1e-300)
    scale_m = scale_f * max(1.0, max(abs(m.position) for m in masses))
    assert np.max(result.after.force) <= 1e-9 * scale_f
    assert np.max(result.after.couple) <= 1e-9 * scale_m
    # the same about any other reference plane
    again = rotating_loads([*masses, *result.masses], speed, reference=0.77)
    assert np.max(again.couple) <= 1e-9 * scale_m * 2


def test_static_balance_leaves_the_couple_it_cannot_reach():
    masses = [Mass("a", 1.0, 0.1, 0.0, 0.0), Mass("b", 1.0, 0.1, math.pi, 1.0)]
    result = single_plane(masses, Plane("P", 0.5, 0.1), 10.0)
    assert result.corrections[0].mass == pytest.approx(0.0, abs=1e-15)
    assert np.max(result.after.couple) == pytest.approx(0.1 * 1.0 * 100.0, rel=1e-12)


def test_one_plane_shaft_line_equals_the_planar_counterweight():
    """A single cylinder with its crank counterweight in its own plane: the shaft line's static balance of the
    revolving mass plus the fraction c of the reciprocating mass equals machdyn.balancing's B b = (m_1 + c m) r."""
    m1, m, r, c, b = 37.0, 50.0, 0.15, 2 / 3, 0.4
    masses = [Mass("rot", m1, r, 0.0, 0.0), Mass("rec", c * m, r, 0.0, 0.0)]
    corr = single_plane(masses, Plane("cw", 0.0, b)).corrections[0]
    assert corr.mass == pytest.approx(balance_mass(m1, m, r, c, b), rel=1e-13)
    assert math.degrees(corr.angle) == pytest.approx(180.0, abs=1e-12)


def test_single_cylinder_equals_the_linkage_engine_frame_loads():
    """One plane, one cylinder: the exact shaft-line force equals the planar engine's shaking force of the same
    slider-crank (massless rod, crank mass at the pin, slider mass), at every crank angle."""
    r, l, m_rec, m_rot, w = 0.08, 0.3, 3.0, 1.5, 157.0
    mech = slider_crank(r, l, masses=(m_rot, 0.0, m_rec), inertias=(0.0, 0.0, 0.0),
                        coms=((r, 0.0), (l / 2, 0.0), (0.0, 0.0)), gravity=(0.0, 0.0))
    phi = cycle(360)
    planar = frame_loads(mech, phi, w)
    line = reciprocating_loads([Cylinder("1", 0.0, 0.0, 0.0, r, l, m_rec, m_rot)], w, phi)
    scale = (m_rec + m_rot) * r * w**2
    assert np.max(np.abs(line.fx - planar.fx)) <= 1e-9 * scale
    assert np.max(np.abs(line.fy - planar.fy)) <= 1e-9 * scale


def test_exact_piston_acceleration_is_the_second_derivative_of_the_position():
    r, l, w = 0.05, 0.17, 30.0
    phi = np.linspace(0.0, 2 * np.pi, 50)
    h = 1e-4
    x = lambda p: r * np.cos(p) + np.sqrt(l**2 - (r * np.sin(p)) ** 2)  # noqa: E731
    fd = (x(phi + h) - 2 * x(phi) + x(phi - h)) / h**2 * w**2
    assert np.allclose(piston_acceleration(phi, r, l, w), fd, rtol=0, atol=1e-5 * r * w**2)


def test_exact_first_order_equals_the_primary_and_second_order_approaches_the_secondary():
    """Zero offset: the exact force's order 1 is exactly the primary m w^2 r; order 2 is m w^2 r (lambda +
    lambda^3/4 + 15 lambda^5/128 + 35 lambda^7/512 + ...) (the Fourier series of the piston acceleration, Uicker
    et al., 5th ed., sec. 16.6), slightly above the two-term 1/n."""
    cyl = [Cylinder("1", 0.0, 0.0, 0.0, 0.05, 0.2, 2.0)]
    e = engine_orders(cyl, 100.0, 720, 6)
    lam = 0.25
    assert e.force_order[0] == pytest.approx(e.primary_force, rel=1e-12)
    assert e.force_order[1] == pytest.approx(2.0 * 100.0**2 * 0.05 * (lam + lam**3 / 4 + 15 * lam**5 / 128
                                                                    + 35 * lam**7 / 512), rel=2e-6)
    assert e.force_order[1] > e.secondary_force


def test_exact_orders_tend_to_the_two_term_values_as_the_crank_to_rod_ratio_vanishes():
    """lambda = r / l -> 0: the exact force's order 1 stays the primary m w^2 r, order 2 tends to the two-term
    secondary m w^2 r lambda with a relative excess lambda^2 / 4 + O(lambda^4) (the Fourier series of the
    piston acceleration, Uicker et al., 5th ed., sec. 16.6), and orders 3 and above vanish (order 4 as
    lambda^3 / 4); so the two-term textbook model is the limit of the exact one."""
    r, m, w = 0.05, 2.0, 100.0
    excess, fourth = [], []
    for n in (4.0, 8.0, 16.0, 32.0, 64.0):
        lam = 1.0 / n
        e = engine_orders([Cylinder("1", 0.0, 0.0, 0.0, r, r * n, m)], w, 720, 6)
        mrw2 = m * w**2 * r
        assert e.force_order[0] == pytest.approx(e.primary_force, rel=1e-12)
        assert e.secondary_force == pytest.approx(mrw2 * lam, rel=1e-12)
        excess.append(e.force_order[1] / e.secondary_force - 1.0)
        assert excess[-1] == pytest.approx(lam**2 / 4, rel=0.6 * lam**2 + 1e-9)
        fourth.append(e.force_order[3] / mrw2)
        assert fourth[-1] == pytest.approx(lam**3 / 4, rel=lam**2 + 1e-6)
        assert e.force_order[2] <= 1e-9 * mrw2 and e.force_order[4] <= 1e-9 * mrw2  # odd orders: none at all
    assert all(b < a for a, b in zip(excess, excess[1:], strict=False))
    assert excess[-1] < 1e-4 and fourth[-1] < 1e-6


def test_four_stroke_inline_four_is_free_of_primary_forces_and_couples():
    phases = crank_phases_from_firing_order([1, 3, 4, 2])
    cyl = [Cylinder(str(k), 0.1 * k, phases[k], 0.0, 0.04, 0.14, 0.5) for k in (1, 2, 3, 4)]
    e = engine_orders(cyl, 600.0, reference=0.25)
    assert e.force_order[0] <= 1e-9 * e.force_order[1]
    assert e.couple_order[0] <= 1e-9 * e.force_order[1]
    assert e.secondary_force == pytest.approx(4 * 0.5 * 600.0**2 * 0.04 / 3.5, rel=1e-12)


def test_two_bearings_obey_statics_and_more_share_the_same_totals():
    masses = [Mass("a", 2.0, 0.1, 0.3, 0.2), Mass("b", 1.0, 0.2, 2.0, 0.9)]
    loads = rotating_loads(masses, 50.0, reference=0.1)
    two = bearing_reactions(loads, [Bearing("A", 0.0), Bearing("B", 1.0)])
    for k in range(2):
        f = (loads.fx, loads.fy)[k]
        rf = (two.fx, two.fy)[k]
        assert np.allclose(rf.sum(axis=0), f, atol=1e-9 * np.max(np.abs(f)))
    # moment about bearing A: R_B * 1.0 = sum z F (z from A)
    u = sum(m.mass * m.radius * m.position * np.exp(1j * (m.angle + loads.angle)) for m in masses) * 50.0**2
    assert np.allclose(two.fx[1], u.real, atol=1e-9 * np.max(np.abs(u)))
    three = bearing_reactions(loads, [Bearing("A", 0.0, 2e8), Bearing("M", 0.5), Bearing("B", 1.0)])
    assert np.allclose(three.fy.sum(axis=0), loads.fy, atol=1e-9 * np.max(np.abs(loads.fy)))
    assert np.allclose((three.fy * (three.positions[:, None] - 0.1)).sum(axis=0), -loads.mx,
                       atol=1e-9 * np.max(np.abs(loads.mx)))


def _rigid_rotor(unbalances, planes, sensors, speed):
    """Steady 1x response of a rigid rotor (mass 30 kg, transverse inertia 2 kg m^2 about z = 0.5 m) on two
    isotropic spring-damper bearings: (K + i w C - w^2 M) q = w^2 F, q = (u, tilt); sensor reading = u + tilt
    (z - 0.5). A linear rotor model for the influence-coefficient test."""
    k = np.diag([4e6, 3e6])
    c = np.diag([900.0, 500.0])
    zb = np.array([0.0, 1.0]) - 0.5
    kk = np.array([[k.sum(), (np.diag(k) * zb).sum()], [(np.diag(k) * zb).sum(), (np.diag(k) * zb**2).sum()]])
    cc = np.array([[c.sum(), (np.diag(c) * zb).sum()], [(np.diag(c) * zb).sum(), (np.diag(c) * zb**2).sum()]])
    mm = np.diag([30.0, 2.0])
    f = np.array([sum(unbalances), sum(u * (z - 0.5) for u, z in zip(unbalances, planes, strict=True))])
    q = np.linalg.solve(kk + 1j * speed * cc - speed**2 * mm, speed**2 * f)
    return [q[0] + q[1] * (z - 0.5) for z in sensors]


def test_influence_coefficients_recover_a_known_unbalance_exactly():
    speed, planes, sensors, radius = 180.0, (0.1, 0.9), (0.0, 1.0), 0.2
    true = [0.012 * np.exp(1j * 0.7), 0.02 * np.exp(1j * 3.9)]  # kg at the radius
    def run(extra):
        u = [(t + e) * radius for t, e in zip(true, extra, strict=True)]
        return [reading(v) for v in _rigid_rotor(u, planes, sensors, speed)]
    original = run([0, 0])
    trials = [TrialRun(0, 0.01, 0.0, tuple(run([0.01, 0]))),
              TrialRun(1, 0.015, 1.0, tuple(run([0, 0.015 * np.exp(1j)])))]
    fb = field_two(original, trials)
    corr = fb.correction()
    assert np.allclose(corr, [-t for t in true], rtol=1e-9, atol=1e-15)
    after = run(list(corr))
    assert max(r.amplitude for r in after) <= 1e-9 * max(r.amplitude for r in original)
    one = field_single(original[0], 0.01, 0.0, run([0.01, 0])[0])
    assert one.correction_mass[0] > 0


def test_a_trial_mass_left_on_is_counted_in_the_correction():
    base = Reading(2.0, 0.3)
    with_trial = reading(complex(base.vector("o")) + 100.0 * 0.01 * np.exp(1j * 1.2))
    removed = field_single(base, 0.01, 1.2, with_trial)
    kept = field_single(base, 0.01, 1.2, with_trial, removed=False)
    assert np.allclose(kept.correction(), removed.correction() - 0.01 * np.exp(1.2j), atol=1e-15)


def test_equivalent_unbalances_in_two_planes_carry_force_and_couple():
    masses = [Mass("a", 3.0, 0.1, 1.0, 0.3), Mass("b", 2.0, 0.05, 4.0, 0.8)]
    ua, ub = equivalent_in_planes(masses, 0.0, 1.0)
    eq = [Mass("A", abs(ua), 1.0, float(np.angle(ua)), 0.0), Mass("B", abs(ub), 1.0, float(np.angle(ub)), 1.0)]
    a, b = rotating_loads(masses, 10.0), rotating_loads(eq, 10.0)
    assert np.allclose(a.fx, b.fx) and np.allclose(a.my, b.my) and np.allclose(a.mx, b.mx)


def test_the_six_dof_frame_reduces_to_the_planar_frame_for_planar_loads():
    """Mounts in the plane z = 0 acting in it (plus vertical z springs that hold the out-of-plane motions), a
    centre of mass in the plane: the in-plane natural frequencies and the steady response to in-plane loads are
    those of machdyn.vibration's planar Frame."""
    from machdyn.shafts.frame6 import Frame6, Mount6, modes6, steady_response
    from machdyn.vibration.frame import Frame, Mount
    from machdyn.vibration.modes import modes
    from machdyn.vibration.response import harmonic_loads, steady_state

    planar_mounts = [Mount("a", (-0.5, -0.3), math.pi / 2, 2e5, 300.0),
                     Mount("b", (0.6, -0.3), math.pi / 2, 3e5, 200.0), Mount("c", (0.0, -0.3), 0.0, 1.5e5, 100.0)]
    planar = Frame(120.0, 9.0, tuple(planar_mounts), com=(0.05, 0.1))
    mounts6 = [Mount6(m.name, (*m.position, 0.0), (*m.unit_vector, 0.0), m.stiffness, m.damping)
               for m in planar_mounts]
    mounts6 += [Mount6(f"z{i}", p, (0.0, 0.0, 1.0), 4e5) for i, p in enumerate(((-0.5, -0.3, 0.0),
                                                                                (0.6, -0.3, 0.0), (0.0, 0.5, 0.0)))]
    frame = Frame6(120.0, (4.0, 5.0, 9.0), tuple(mounts6), com=(0.05, 0.1, 0.0))
    f6, _ = modes6(frame)
    f3 = modes(planar).frequencies
    in_plane = [f for f in f6 if np.min(np.abs(f - f3)) <= 1e-9 * f]
    assert len(in_plane) >= 3
    # a rotating force in the plane through the origin: compare the response of the in-plane coordinates
    loads = rotating_loads([Mass("u", 1.0, 0.01, 0.3, 0.0)], 80.0, cycle(64))
    resp = steady_response(frame, loads, orders=2)
    fx, fy = np.fft.rfft(loads.fx)[1] * 2 / 64, np.fft.rfft(loads.fy)[1] * 2 / 64
    planar_resp = steady_state(planar, harmonic_loads(80.0, fx, fy, 0.0))
    q3 = planar_resp.coordinates[0]
    assert np.allclose(resp.q[0][[0, 1, 5]], q3, rtol=1e-9, atol=1e-15)
    assert np.allclose(resp.q[0][[2, 3, 4]], 0.0, atol=1e-15)


def test_half_the_reciprocating_masses_balances_the_primary_force_of_a_90_deg_v_twin():
    """A 90 deg V-twin on one crank pin: its primary forces add up to one direct crank m r w^2 turning with the
    shaft and no reverse crank (Khurmi & Gupta, 14th ed., sec. 22.11), so correcting c = 1/2 of each reciprocating
    mass as if it revolved at the pin removes the whole primary force; the secondary remains."""
    from machdyn.reading import load_problem
    from machdyn.shafts.model import analyse, build

    text = """
[shaft_line]
speed = "3000 rpm"
[[cylinders]]
name = "front"
position = "0 mm"
axis = "45 deg"
crank = "40 mm"
rod = "140 mm"
reciprocating_mass = "0.5 kg"
[[cylinders]]
name = "rear"
position = "0 mm"
axis = "-45 deg"
crank = "40 mm"
rod = "140 mm"
reciprocating_mass = "0.5 kg"
[balance]
reciprocating_fraction = 0.5
planes = [ { name = "web", position = "0 mm", radius = "40 mm" } ]
"""
    problem = load_problem(text)
    line, problems = build(problem)
    assert problems == []
    result = analyse(problem, line)
    d, r = result.engine.primary_dr
    assert abs(r) <= 1e-15 and abs(d) == pytest.approx(0.5 * 0.04, rel=1e-12)  # one direct crank of m r
    assert result.balance.corrections[0].mass == pytest.approx(0.5, rel=1e-12)
    after = result.balance.after
    n = after.angle.size
    first = np.abs(np.fft.rfft(after.fx)[1]) * 2 / n + np.abs(np.fft.rfft(after.fy)[1]) * 2 / n
    assert first <= 1e-9 * result.engine.primary_force
    second = np.hypot(np.abs(np.fft.rfft(after.fx)[2]), np.abs(np.fft.rfft(after.fy)[2])) * 2 / n
    # the secondary of a 90 deg V stays, across the V's centre line: sqrt(2) m w^2 r / n (Khurmi & Gupta, 22.11)
    assert result.engine.secondary_force == pytest.approx(math.sqrt(2) * 0.5 * 0.04 * (3000 * math.pi / 30) ** 2
                                                          / 3.5, rel=1e-12)
    assert second > 0.9 * result.engine.secondary_force


SLIDER_CRANK = """
[linkages.mechanism]
type = "slider_crank"
crank = { length = "50 mm", mass = "2.5 kg", inertia = "0.004 kg*m^2", com = ["15 mm", "0 mm"] }
rod = { length = "200 mm", mass = "1.2 kg", inertia = "0.0055 kg*m^2", com = ["60 mm", "0 mm"] }
slider = { mass = "1.5 kg" }
"""

LINKAGE_LINE = """
[shaft_line]
speed = "1500 rpm"
reference = "0 mm"

[[linkages]]
name = "front"
position = "{z1}"
phase = "0 deg"
""" + SLIDER_CRANK + """
[[linkages]]
name = "rear"
position = "{z2}"
phase = "180 deg"
axis = "90 deg"
""" + SLIDER_CRANK


def test_linkages_on_the_shaft_carry_the_planar_engine_shaking_force_into_space():
    """Two slider-cranks of examples/slider_crank.toml (rod with its own inertia) in two planes, the second turned
    90 deg about the shaft and half a turn behind: the shaft line's force is the planar engine's shaking force of
    each, turned into shaft axes, and its couple z x F; in one plane at z = 0 the couple vanishes."""
    from machdyn.reading import load_problem, read_problem
    from machdyn.shafts.model import analyse, build

    problem = load_problem(LINKAGE_LINE.replace("{z1}", "-100 mm").replace("{z2}", "150 mm"))
    line, problems = build(problem)
    assert problems == []
    result = analyse(problem, line)
    w = 1500 * math.pi / 30
    mech = read_problem(ROOT_EXAMPLES / "slider_crank.toml").model
    from dataclasses import replace

    quiet = replace(mech, forces=(), torques=(), springs=(), point_masses=())
    theta = result.loads.angle
    a, b = frame_loads(quiet, theta, w), frame_loads(quiet, theta + math.pi, w)
    fx = a.fx - b.fy  # the rear one turned by 90 deg: (x, y) -> (-y, x)
    fy = a.fy + b.fx
    assert np.allclose(result.loads.fx, fx, atol=1e-9 * np.max(np.abs(fx)))
    assert np.allclose(result.loads.fy, fy, atol=1e-9 * np.max(np.abs(fy)))
    assert np.allclose(result.loads.my, -0.1 * a.fx + 0.15 * (-b.fy), atol=1e-9 * np.max(np.abs(fx)))
    assert np.allclose(result.linkage_torque.sum(axis=0), a.moment + b.moment, atol=1e-9 * np.max(np.abs(a.moment)))
    one = load_problem(LINKAGE_LINE.replace("{z1}", "0 mm").replace("{z2}", "0 mm"))
    r1 = analyse(one, build(one)[0])
    assert np.max(r1.loads.couple) <= 1e-12 * np.max(r1.loads.force)


def test_a_linkage_whose_crank_pivot_is_off_the_shaft_is_refused():
    from dataclasses import replace

    from machdyn.errors import InputError
    from machdyn.shafts.linkages import LinkagePlane

    mech = slider_crank(0.05, 0.2)
    LinkagePlane("ok", mech, 0.0)
    moved = replace(mech, ground={**mech.ground, "O": (0.1, 0.0)})
    with pytest.raises(InputError, match="must lie on the shaft axis"):
        LinkagePlane("off", moved, 0.0)


def test_first_harmonic_target_cancels_the_forward_first_harmonic_of_linkages_in_two_planes():
    """The tamper line of two double tampers: corrections aimed at the forward-turning first harmonic leave
    none of it in the force or the couple (to 1e-9); the backward part and the higher orders stay. For rotating
    masses alone the same target gives the classical two-plane corrections."""
    from machdyn.reading import load_problem
    from machdyn.shafts.balance import forward_first_harmonic
    from machdyn.shafts.model import analyse, build

    text = (ROOT_EXAMPLES / "shaft_tamper_line.toml").read_text()  # [balance] target = "first_harmonic"
    assert 'target = "first_harmonic"' in text
    problem = load_problem(text)
    result = analyse(problem, build(problem)[0])
    a0, c0 = forward_first_harmonic(result.loads)
    a1, c1 = forward_first_harmonic(result.balance.after)
    assert abs(c0) > 0 and abs(a1) <= 1e-9 * (abs(a0) + abs(c0)) and abs(c1) <= 1e-9 * abs(c0)
    assert result.balance.after.peak_couple < result.loads.peak_couple
    masses = [Mass("a", 2.0, 0.1, 0.4, 0.2), Mass("b", 1.0, 0.2, 2.5, 0.9)]
    from machdyn.shafts.balance import first_harmonic_corrections

    planes = (Plane("L", 0.0, 0.1), Plane("M", 1.0, 0.1))
    fh = first_harmonic_corrections(rotating_loads(masses, 50.0, reference=0.3), planes)
    classic = two_plane(masses, *planes).corrections
    for x, y in zip(fh, classic, strict=True):
        assert x.mass == pytest.approx(y.mass, rel=1e-12) and x.angle == pytest.approx(y.angle, abs=1e-12)


def test_opposed_flat_twin_cancels_primary_and_secondary_forces_but_leaves_a_primary_couple():
    """A flat twin (boxer): cylinders on opposite sides (axes 0 and 180 deg), cranks 180 deg apart, offset along
    the shaft by a: the pistons move in opposition, so both forces cancel; the primary couple m w^2 r a and the
    secondary couple m w^2 r a / n remain (Uicker, Pennock & Shigley, 5th ed., sec. 16.9, opposed engines)."""
    m, r, l, a, w = 0.4, 0.035, 0.12, 0.08, 600.0
    cyl = [Cylinder("L", 0.0, 0.0, 0.0, r, l, m), Cylinder("R", a, math.pi, math.pi, r, l, m)]
    e = engine_orders(cyl, w, 720, 4, reference=a / 2)
    assert e.primary_force <= 1e-12 * m * r * w**2 and e.force_order[0] <= 1e-9 * m * r * w**2
    assert e.secondary_force <= 1e-12 * m * r * w**2 and e.force_order[1] <= 1e-9 * m * r * w**2
    assert e.primary_couple == pytest.approx(m * w**2 * r * a, rel=1e-12)
    assert e.secondary_couple == pytest.approx(m * w**2 * r * a / (l / r), rel=1e-12)


def test_trial_masses_left_on_in_sequence_still_recover_the_unbalance():
    """Two-plane runs where the first trial mass stays on during the second trial run: the second influence
    coefficient is measured from the first trial run's readings, and the corrections to add are the true ones less
    the masses left on."""
    speed, planes, sensors, radius = 150.0, (0.1, 0.9), (0.0, 1.0), 0.2
    true = [0.01 * np.exp(2.0j), 0.02 * np.exp(-0.5j)]

    def run(extra):
        u = [(t + e) * radius for t, e in zip(true, extra, strict=True)]
        return tuple(reading(v) for v in _rigid_rotor(u, planes, sensors, speed))

    w1, w2 = 0.008, 0.02 * np.exp(1j)  # meets the 30 % / 30 deg trial-mass rule
    trials = [TrialRun(0, 0.008, 0.0, run([w1, 0]), removed=False),
              TrialRun(1, 0.02, 1.0, run([w1, w2]), removed=True)]
    fb = field_two(run([0, 0]), trials)
    assert np.allclose(fb.correction(), [-true[0] - w1, -true[1]], rtol=1e-9, atol=1e-15)
