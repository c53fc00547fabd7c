"""Property tests of the linkage engine on random assemblable mechanisms.

Mechanism families: four-bars of every Grashof type (analysed only at the crank angles where they assemble),
offset slider-cranks, inverted slider-cranks and Stephenson six-bars, each with random masses, inertias, centres
of mass, a point mass, a spring, a point force and a body torque.

Finite-difference checks use the five-point central difference with step h = 1e-4 rad: its truncation error is
h^4/30 |d5x| ~ 3e-18 |d5x| (d5x the fifth derivative) and its round-off about 1.5 eps |x| / h ~ 3e-12 |x|.
Positions are kept at least 0.1 (normalised dyad determinant) away from dead positions and at least 1 deg inside
the ends of an assembly range, where derivatives grow like powers of 1/det (or of the distance to the limit,
det ~ sqrt(distance)), so |d5x| stays below ~1e9 times the link scale; the tolerance
1e-6 * (scale + |value|) covers both errors with margin while still catching any wrong term (a wrong term is of
the order of the value itself).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from machdyn.linkage import (
    PRP,
    RPR,
    RRP,
    RRR,
    BodyTorque,
    PointForce,
    PointMass,
    Spring,
    crank_angles,
    energy,
    four_bar,
    inverted_slider_crank,
    kinematics,
    kinetostatics,
    six_bar,
    slider_crank,
)
from machdyn.linkage.model import split_ref

SETTINGS = dict(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.filter_too_much,
                                                                       HealthCheck.too_slow])
H = 1e-4
DET_MIN = 0.1
length = st.floats(0.3, 3.0)


# ------------------------------------------------------------------------------------------ strategies


@st.composite
def base_mechanisms(draw, full_cycle=False, kinds=("four_bar", "slider_crank", "inverted", "six_bar")):
    """A random linkage of one of the four families (``full_cycle``: one whose crank turns fully)."""
    kind = draw(st.sampled_from(list(kinds)))
    branch = draw(st.sampled_from([1, -1]))
    if kind == "four_bar":
        if full_cycle:  # Grashof crank-rocker or double-crank: the crank (or ground) is the shortest link
            a = draw(st.floats(0.2, 0.6))
            b, c, d = draw(st.floats(1.0, 2.5)), draw(st.floats(1.0, 2.5)), draw(st.floats(1.0, 2.5))
            assume(a + max(b, c, d) <= sum((b, c, d)) - max(b, c, d) - 0.1)
            return four_bar(a, b, c, d, ground_angle=draw(st.floats(-1, 1)), branch=branch)
        return four_bar(draw(length), draw(length), draw(length), draw(length),
                        ground_angle=draw(st.floats(-1, 1)), branch=branch)
    if kind == "slider_crank":
        r = draw(st.floats(0.1, 1.0))
        e = draw(st.floats(-1.0, 1.0))
        rod = draw(st.floats(r + abs(e) + 0.2, 4.0)) if full_cycle else draw(st.floats(0.3, 4.0))
        return slider_crank(r, rod, e, slide_angle=draw(st.floats(-1.5, 1.5)), branch=branch)
    if kind == "inverted":
        r = draw(st.floats(0.1, 1.0))
        off = draw(st.floats(-0.3, 0.3))
        g = draw(st.floats(r + abs(off) + 0.2, 3.0))
        return inverted_slider_crank(r, g, offset=off, branch=branch)
    a = draw(st.floats(0.2, 0.5))
    b, c, d = draw(st.floats(1.0, 2.0)), draw(st.floats(1.0, 2.0)), draw(st.floats(1.0, 2.0))
    assume(a + max(b, c, d) <= sum((b, c, d)) - max(b, c, d) - 0.1)
    p = (draw(st.floats(0.0, 1.5)), draw(st.floats(-0.8, 0.8)))
    return six_bar(a, b, c, d, p, draw(st.floats(1.0, 3.0)), draw(st.floats(1.0, 3.0)),
                   (draw(st.floats(-1.0, 3.0)), draw(st.floats(-2.0, 2.0))), branch=branch,
                   branch2=draw(st.sampled_from([1, -1])))


@st.composite
def mechanisms(draw, full_cycle=False, loads=True, gravity=True, base=None):
    """A random linkage with random mass properties and (optionally) loads and gravity; ``base`` draws the
    bare linkage (default: :func:`base_mechanisms`)."""
    mech = draw(base if base is not None else base_mechanisms(full_cycle=full_cycle))
    bodies = tuple(
        replace(b, mass=draw(st.floats(0.1, 10.0)), inertia=draw(st.floats(0.0, 2.0)),
                com=(draw(st.floats(-0.5, 1.5)), draw(st.floats(-0.5, 0.5))))
        for b in mech.bodies
    )
    changes = {"bodies": bodies, "gravity": (draw(st.floats(-10, 10)), draw(st.floats(-10, 10)))
               if gravity else (0.0, 0.0)}
    if loads:
        moving = mech.moving_bodies
        last = moving[-1]
        point = list(mech.body(last).points)[-1]
        ground = dict(mech.ground, K=(draw(st.floats(-2, 2)), draw(st.floats(-2, 2))))
        changes.update(
            ground=ground,
            point_masses=(PointMass("pm", mech.crank.body, draw(st.floats(0.1, 5.0)),
                                    (draw(st.floats(-0.5, 0.5)), draw(st.floats(-0.5, 0.5))),
                                    draw(st.floats(0.0, 0.5))),),
            springs=(Spring("k", f"{last}.{point}", "ground.K", draw(st.floats(1.0, 500.0)),
                            draw(st.floats(0.0, 1.0))),),
            forces=(PointForce("f", f"{moving[1]}.{next(iter(mech.body(moving[1]).points))}",
                               draw(st.floats(-50, 50)), draw(st.floats(-50, 50))),),
            torques=(BodyTorque("t", moving[-1], draw(st.floats(-20, 20))),),
        )
    return replace(mech, **changes)


def good_angles(mech, n=720, full=False):
    """Crank angles (from a uniform grid) where the linkage assembles with every dyad at least DET_MIN from a
    dead position, also at +-h and +-2h (so that the finite differences stay on one assembly branch)."""
    phi = crank_angles(n)
    ok = np.ones(n, dtype=bool)
    for shift in (-2 * H, -H, 0.0, H, 2 * H):
        k = kinematics(mech, phi + shift, on_fail="mask")
        ok &= k.assembled
        for rep in k.dyad_reports:
            ok &= np.abs(np.nan_to_num(rep.det)) > DET_MIN
    # keep two grid steps (1 deg) away from the ends of an assembly range: near a limit the determinant grows
    # like the square root of the distance, so a det threshold alone does not bound the derivatives there
    for shift in (-2, -1, 1, 2):
        ok &= np.roll(ok, shift)
    if full:
        assume(ok.all())
        return phi
    assume(ok.sum() >= 4)
    return phi[ok][:: max(1, ok.sum() // 24)]


def derivative(f):
    """Five-point central difference of f(phi) -> tuple of arrays, as a function of phi."""
    def d(phi):
        vals = [f(phi + j * H) for j in (-2, -1, 1, 2)]
        return tuple((a - 8 * b + 8 * c - e) / (12 * H) for a, b, c, e in zip(*vals, strict=True))
    return d


def scale_of(mech):
    pts = [abs(v) for b in mech.bodies for xy in b.points.values() for v in xy]
    pts += [abs(v) for xy in mech.ground.values() for v in xy]
    return max(pts)


def all_points(mech):
    return [f"{b.name}.{p}" for b in mech.bodies for p in b.points]


# --------------------------------------------------------------------------------------------- kinematics


@settings(**SETTINGS)
@given(mech=mechanisms(loads=False, gravity=False), speed=st.floats(0.5, 20.0), accel=st.floats(-50, 50))
def test_velocities_and_accelerations_are_derivatives(mech, speed, accel):
    # With crank speed w and acceleration eps: v = x'(phi) w, a = x''(phi) w^2 + x'(phi) eps, with x' and x'' the
    # central differences of the positions (and of the unit-speed velocities) in phi.
    phi = good_angles(mech)
    L = scale_of(mech)
    k = kinematics(mech, phi, speed, accel)
    k1 = kinematics(mech, phi, 1.0)
    for ref in all_points(mech):
        p, p1 = k.point(ref), k1.point(ref)
        dx, dy = derivative(lambda q, ref=ref: (kinematics(mech, q).point(ref).x,
                                                kinematics(mech, q).point(ref).y))(phi)
        dvx, dvy = derivative(lambda q, ref=ref: (kinematics(mech, q).point(ref).vx,
                                                  kinematics(mech, q).point(ref).vy))(phi)
        for vel, acc, vel1, d1, d2 in ((p.vx, p.ax, p1.vx, dx, dvx), (p.vy, p.ay, p1.vy, dy, dvy)):
            assert np.allclose(vel1, d1, rtol=0, atol=1e-6 * (L + np.abs(vel1))), ref
            assert np.allclose(vel, d1 * speed, rtol=0, atol=1e-6 * (L + np.abs(vel)) * speed), ref
            assert np.allclose(acc, d2 * speed**2 + vel1 * accel, rtol=0,
                               atol=1e-6 * (L + np.abs(acc)) * (speed**2 + abs(accel))), ref
    for name in mech.moving_bodies:
        b, b1 = k.body(name), k1.body(name)

        def unwrapped(q, name=name, ref_angle=b1.angle):
            a = kinematics(mech, q).body(name).angle
            return (ref_angle + np.angle(np.exp(1j * (a - ref_angle))),)

        (dang,) = derivative(unwrapped)(phi)
        (dw,) = derivative(lambda q, name=name: (kinematics(mech, q).body(name).omega,))(phi)
        assert np.allclose(b1.omega, dang, rtol=0, atol=1e-6 * (1 + np.abs(b1.omega))), name
        assert np.allclose(b.omega, b1.omega * speed, rtol=1e-12, atol=1e-12), name
        assert np.allclose(b.alpha, dw * speed**2 + b1.omega * accel, rtol=0,
                           atol=1e-6 * (1 + np.abs(b.alpha)) * (speed**2 + abs(accel))), name


# ----------------------------------------------------------------------------------------------- dynamics


def _joint_locations(mech):
    """Where each joint's force acts: revolute joints at their common point; prismatic joints at the slider's
    joint point (RRP, PRP) or at the block's pin (RPR), as documented in machdyn.linkage.dyads."""
    where = {}
    for d in mech.dyads:
        if isinstance(d, RRP):
            where[f"{d.b}/{d.guide.body}"] = f"{d.b}.{d.inner}"
        elif isinstance(d, RPR):
            where[f"{d.a}/{d.b}"] = f"{d.a}.{split_ref(d.pin_a)[1]}"
        elif isinstance(d, PRP):
            where[f"{d.a}/{d.guide_a.body}"] = f"{d.a}.{d.inner}"
            where[f"{d.b}/{d.guide_b.body}"] = f"{d.b}.{d.inner}"
        else:
            assert isinstance(d, RRR)
    return where


@settings(**SETTINGS)
@given(mech=mechanisms(), speed=st.floats(0.5, 20.0), accel=st.floats(-50, 50))
def test_every_body_is_in_equilibrium(mech, speed, accel):
    # Rebuild sum F = m a_G and sum M_O = I alpha + r_G x m a_G on every moving body from the reported joint
    # reactions, the driving torque, gravity, point masses, springs, external forces and torques. Residual below
    # 1e-9 of the largest force (moment: of the largest force times the link scale) -- round-off level.
    phi = good_angles(mech)
    f = kinetostatics(mech, phi, speed, accel)
    k = f.kinematics
    gx, gy = mech.gravity
    where = _joint_locations(mech)
    L = scale_of(mech)
    acc = {b: [0.0, 0.0, 0.0] for b in mech.moving_bodies}  # residual Fx, Fy, M_O (applied - inertial)
    scale = [1e-300]

    def add(body, x, y, fx, fy, m=0.0):
        if body == "ground":
            return
        acc[body][0] = acc[body][0] + fx
        acc[body][1] = acc[body][1] + fy
        acc[body][2] = acc[body][2] + x * fy - y * fx + m
        scale[0] = max(scale[0], float(np.max(np.hypot(fx, fy))))

    for name in mech.moving_bodies:
        b, g = mech.body(name), k.com(name)
        add(name, g.x, g.y, b.mass * (gx - g.ax), b.mass * (gy - g.ay), -b.inertia * k.body(name).alpha)
    for pm in mech.point_masses:
        g = k.local_point(pm.body, pm.position)
        add(pm.body, g.x, g.y, pm.mass * (gx - g.ax), pm.mass * (gy - g.ay), -pm.inertia * k.body(pm.body).alpha)
    for fo in mech.forces:
        p = k.point(fo.point)
        add(split_ref(fo.point)[0], p.x, p.y, fo.fx + 0 * p.x, fo.fy + 0 * p.x)
    for t in mech.torques:
        add(t.body, 0.0, 0.0, 0.0, 0.0, t.torque)
    for s in mech.springs:
        p1, p2 = k.point(s.point_1), k.point(s.point_2)
        dx, dy = p2.x - p1.x, p2.y - p1.y
        ln = np.hypot(dx, dy)
        assume(np.min(ln) > 1e-3)  # a spring of zero length has no direction
        tension = s.stiffness * (ln - s.free_length)
        add(split_ref(s.point_1)[0], p1.x, p1.y, tension * dx / ln, tension * dy / ln)
        add(split_ref(s.point_2)[0], p2.x, p2.y, -tension * dx / ln, -tension * dy / ln)
    add(mech.crank.body, 0.0, 0.0, 0.0, 0.0, f.driving_torque)
    for j in f.joints:
        r = f.joint(j.name)
        ref = where[j.name] if j.kind == "P" else f"{j.body_2}.{j.name.split(':')[0]}"
        p = k.point(ref)
        couple = 0.0 if r.couple is None else r.couple
        add(j.body_2, p.x, p.y, r.fx, r.fy, couple)
        add(j.body_1, p.x, p.y, -r.fx, -r.fy, -couple)
    for name, (rx, ry, rm) in acc.items():
        assert np.max(np.abs(rx)) < 1e-9 * scale[0], name
        assert np.max(np.abs(ry)) < 1e-9 * scale[0], name
        assert np.max(np.abs(rm)) < 1e-9 * scale[0] * L, name


@settings(**SETTINGS)
@given(mech=mechanisms(loads=False, gravity=False), speed=st.floats(0.5, 20.0), accel=st.floats(-50, 50))
def test_frame_force_is_minus_sum_of_inertia(mech, speed, accel):
    # Gravity off, no loads: the force on the frame equals -sum(m a_G) (point masses included), to 1e-9 of the
    # largest inertia force.
    phi = good_angles(mech)
    f = kinetostatics(mech, phi, speed, accel)
    k = f.kinematics
    sx = sum(mech.body(b).mass * k.com(b).ax for b in mech.moving_bodies)
    sy = sum(mech.body(b).mass * k.com(b).ay for b in mech.moving_bodies)
    scale = max(max(float(np.max(np.hypot(k.com(b).ax, k.com(b).ay))) * mech.body(b).mass
                    for b in mech.moving_bodies), 1e-300)
    fx, fy = f.frame_force
    assert np.allclose(fx, -sx, rtol=0, atol=1e-9 * scale)
    assert np.allclose(fy, -sy, rtol=0, atol=1e-9 * scale)


@settings(**SETTINGS)
@given(mech=mechanisms(), speed=st.floats(0.5, 20.0), accel=st.floats(-50, 50))
def test_input_power_is_rate_of_energy(mech, speed, accel):
    # T w + P_loads = dE/dt with E = 1/2 I_red(phi) w^2 + V(phi): dE/dt = w dE/dphi (at fixed w) + I_red w eps,
    # dE/dphi by the five-point difference (module docstring). Loads: the external force and
    # torque (their power is computed here from the velocities). Tolerance 1e-6 of the power scale.
    phi = good_angles(mech)
    e = energy(mech, phi, speed, accel)
    (de,) = derivative(lambda q: (energy(mech, q, speed).total,))(phi)
    k = e.kinematics
    rate = speed * de + e.reduced_inertia * speed * accel
    load = 0.0
    for fo in mech.forces:
        p = k.point(fo.point)
        load = load + fo.fx * p.vx + fo.fy * p.vy
    for t in mech.torques:
        load = load + t.torque * k.body(t.body).omega
    power = e.forces.input_power + load
    scale = float(np.max(np.abs(rate))) + float(np.max(np.abs(power)))
    # floor: round-off of the difference, 1.5 eps |E| w / h ~ 3e-12 |E| w, with a margin of 3000
    floor = 1e-8 * speed * float(np.max(np.abs(e.total)))
    assert np.allclose(power, rate, rtol=0, atol=1e-6 * scale + floor)


@settings(**SETTINGS)
@given(mech=mechanisms(full_cycle=True), speed=st.floats(0.5, 20.0))
def test_work_energy_balance_over_a_cycle(mech, speed):
    # Over a full revolution at constant speed: input work + load work = 0 (E returns to its start), to 1e-9
    # relative to the work that flows (periodic trapezoidal rule, exponentially accurate; 720 positions).
    phi = crank_angles(720)
    good_angles(mech, full=True)
    e = energy(mech, phi, speed)
    wb = e.work_balance()
    assert wb.full_cycle
    step = 2 * np.pi / phi.size
    flow = step * (np.sum(np.abs(e.forces.driving_torque)) + np.sum(np.abs(e.load_power)) / speed)
    # round-off floor for designs where almost no work flows: eps-level sums of the energy terms
    floor = 1e-12 * float(np.max(np.abs(e.total)))
    assert abs(float(wb.residual)) <= 1e-9 * flow + floor
    if flow > 1e-6 * float(np.max(np.abs(e.total))):
        assert float(wb.relative) < 1e-9


@settings(max_examples=10, deadline=None)
@given(n=st.integers(2, 5), data=st.data())
def test_n_designs_equal_n_single_calls(n, data):
    # A mechanism with array parameters (N design variants) gives the same results as N scalar mechanisms, to
    # round-off (rel 1e-12), for kinematics, forces and energy; unassembled positions are NaN in both.
    a = np.array(data.draw(st.lists(st.floats(0.2, 0.6), min_size=n, max_size=n)))
    b = np.array(data.draw(st.lists(st.floats(0.8, 2.5), min_size=n, max_size=n)))
    c = np.array(data.draw(st.lists(st.floats(0.8, 2.5), min_size=n, max_size=n)))
    d = np.array(data.draw(st.lists(st.floats(0.8, 2.5), min_size=n, max_size=n)))
    e = np.array(data.draw(st.lists(st.floats(-0.3, 0.3), min_size=n, max_size=n)))
    phi = crank_angles(72)
    for build in (
        lambda i: four_bar(a[i], b[i], c[i], d[i], ground_angle=0.2),
        lambda i: slider_crank(a[i], b[i] + 0.5, e[i], slide_angle=0.3),
    ):
        many = build(slice(None))
        assert many.design_count == n
        km = kinematics(many, phi, 3.0, on_fail="mask")
        fm = kinetostatics(many, phi, 3.0)  if km.assembled.all() else None
        for i in range(n):
            one = build(i)
            k1 = kinematics(one, phi, 3.0, on_fail="mask")
            for name in many.moving_bodies:
                np.testing.assert_allclose(km.body(name).angle[i], k1.body(name).angle, rtol=1e-12, atol=1e-12)
                np.testing.assert_allclose(km.body(name).alpha[i], k1.body(name).alpha, rtol=1e-12, atol=1e-12)
            np.testing.assert_array_equal(km.assembled[i], k1.assembled)
            if fm is not None:
                f1 = kinetostatics(one, phi, 3.0)
                np.testing.assert_allclose(fm.driving_torque[i], f1.driving_torque, rtol=1e-12, atol=1e-12)
                np.testing.assert_allclose(fm.frame_force[0][i], f1.frame_force[0], rtol=1e-12, atol=1e-12)
                np.testing.assert_allclose(energy(many, phi, 3.0).total[i], energy(one, phi, 3.0).total,
                                           rtol=1e-12, atol=1e-12)
