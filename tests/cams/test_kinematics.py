"""Cam kinematics: the laws' derivatives against finite differences, the program's boundary checks, the profile's
pressure angle against the geometry of the computed cam surface, curvature, base circles and bad input."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from machdyn.cams.checks import check_cam, min_base_radius_curvature, min_base_radius_pressure
from machdyn.cams.followers import Follower
from machdyn.cams.laws import LAWS, normalised
from machdyn.cams.profile import cam_angles, profile
from machdyn.cams.program import Segment, program
from machdyn.errors import InputError

D = np.radians


def _feeder(law_rise: str = "cycloidal", law_return: str = "poly345"):
    return program([Segment("rise", D(100), 0.03, law_rise), Segment("dwell", D(80)),
                    Segment("return", D(120), 0.03, law_return), Segment("dwell", D(60))])


@pytest.mark.parametrize("name", list(LAWS))
def test_each_law_rises_by_one_and_its_derivatives_are_the_finite_differences_of_its_displacement(name):
    x = np.linspace(0.02, 0.98, 97)
    h = 1e-5
    y, y1, y2, y3 = normalised(name, x)
    assert normalised(name, 0.0)[0] == pytest.approx(0.0, abs=1e-15)
    assert normalised(name, 1.0)[0] == pytest.approx(1.0, abs=1e-12)
    for k, d in ((0, y1), (1, y2), (2, y3)):
        fd = (normalised(name, x + h)[k] - normalised(name, x - h)[k]) / (2 * h)
        # central differences are O(h^2); away from the parabolic law's switch at 1/2 and the pieces' edges
        keep = np.abs(x - 0.5) > 2 * h
        for edge in (0.125, 0.375, 0.625, 0.875):
            keep &= np.abs(x - edge) > 2 * h
        np.testing.assert_allclose(fd[keep], d[keep], atol=1e-5 * max(1.0, float(np.max(np.abs(d)))))


def test_the_peak_factors_are_the_books():
    """Peak acceleration factors Ca of each law (Norton, Design of Machinery, 5th ed., ch. 8; Rothbart, Cam
    Design Handbook, ch. 3), to the three decimals they print; 3-4-5 by its closed form 10/sqrt(3)."""
    x = np.linspace(0, 1, 200_001)
    peaks = {"harmonic": 4.935, "cycloidal": 6.283, "poly345": 10 / np.sqrt(3), "poly4567": 7.513,
             "modified_trapezoid": 4.888, "modified_sine": 5.528}
    for name, ca in peaks.items():
        assert float(np.max(normalised(name, x)[2])) == pytest.approx(ca, abs=1.5e-3), name


def test_program_svaj_are_the_finite_differences_of_s_over_the_whole_turn():
    prog = _feeder()
    th = cam_angles(720)
    m = prog.svaj(th)
    h = 1e-6
    # jerk jumps (finitely) where a cycloidal or 3-4-5 segment meets a dwell: the difference straddles it there
    edges = np.isin(np.round(np.degrees(th), 6), [0.0, 100.0, 180.0, 300.0])
    for got, k in ((m.v, "s"), (m.a, "v"), (m.j, "a")):
        fd = (getattr(prog.svaj(th + h), k) - getattr(prog.svaj(th - h), k)) / (2 * h)
        scale = float(np.max(np.abs(got)))
        keep = ~edges if k == "a" else np.ones_like(edges)
        np.testing.assert_allclose(fd[keep], got[keep], atol=2e-5 * scale)
    assert float(np.max(m.s)) == pytest.approx(0.03)
    assert prog.jumps == ()  # cycloidal and 3-4-5 into dwells: continuous velocity and acceleration


def test_harmonic_double_dwell_names_the_acceleration_jumps_and_uniform_the_velocity_jumps():
    prog = program([Segment("rise", D(90), 0.02, "harmonic"), Segment("dwell", D(90)),
                    Segment("return", D(90), 0.02, "uniform"), Segment("dwell", D(90))])
    kinds = {(j.quantity, round(float(np.degrees(j.angle)))) for j in prog.jumps}
    assert ("acceleration", 0) in kinds and ("acceleration", 90) in kinds
    assert ("velocity", 180) in kinds and ("velocity", 270) in kinds
    assert "180 deg" in str(next(j for j in prog.jumps if j.quantity == "velocity"))


@pytest.mark.parametrize("segments, words", [
    ([Segment("rise", D(180), 0.02), Segment("return", D(180), 0.02, start=D(170))], "overlaps"),
    ([Segment("rise", D(180), 0.02), Segment("return", D(170), 0.02, start=D(190))], "gap"),
    ([Segment("rise", D(180), 0.02), Segment("return", D(170), 0.02)], "360 deg"),
    ([Segment("rise", D(180), 0.02), Segment("return", D(180), 0.01)], "does not close"),
    ([Segment("rise", D(180), 0.02, "bezier"), Segment("return", D(180), 0.02)], "law"),
    ([Segment("rise", D(180), -0.02), Segment("return", D(180), 0.02)], "lift"),
])
def test_bad_programs_are_refused_naming_the_segment(segments, words):
    with pytest.raises(InputError, match=words) as err:
        program(segments)
    assert "cam.segments" in str(err.value)


def _surface_pressure_angle(prof, f: Follower):
    """The pressure angle measured on the computed cam surface alone: the surface's tangent by central
    differences of its points, rotated back to the fixed frame, against the follower's path direction."""
    th = prof.svaj.theta
    x, y = prof.surface
    n = th.size
    tx = np.roll(x, -1) - np.roll(x, 1)
    ty = np.roll(y, -1) - np.roll(y, 1)
    c, s = np.cos(th), np.sin(th)
    fx, fy = c * tx - s * ty, s * tx + c * ty  # R(+theta): back to the fixed frame
    nx, ny = fy, -fx  # a normal to the surface
    if f.motion == "translating":
        ux, uy = np.zeros(n), np.ones(n)
    else:
        from machdyn.cams.followers import follower_path
        p = follower_path(f, prof.svaj.s, prof.svaj.v, prof.svaj.a)
        ux, uy = p.u
    cosang = np.abs(nx * ux + ny * uy) / np.hypot(nx, ny)
    return np.arccos(np.clip(cosang, -1, 1))


@pytest.mark.parametrize("follower", [
    Follower("translating", "roller", 0.05, 0.012, 0.0),
    Follower("translating", "roller", 0.05, 0.012, 0.015),
    Follower("translating", "knife", 0.05, 0.0, -0.01),
    Follower("oscillating", "roller", 0.04, 0.01, 0.0, 0.12, 0.09),
])
def test_the_profile_normal_makes_the_stated_pressure_angle_with_the_follower_path(follower):
    prog = _feeder() if follower.motion == "translating" else program(
        [Segment("rise", D(100), D(15), "cycloidal"), Segment("dwell", D(80)),
         Segment("return", D(120), D(15), "poly345"), Segment("dwell", D(60))])
    prof = profile(prog, follower, cam_angles(7200))
    measured = _surface_pressure_angle(prof, follower)
    np.testing.assert_allclose(measured, np.abs(prof.pressure_angle), atol=2e-4)
    # the surface is the pitch curve moved r_r inwards along its normal
    gap = np.hypot(*(prof.pitch - prof.surface))
    np.testing.assert_allclose(gap, follower.roller_radius, atol=1e-12)


def test_radius_of_curvature_matches_the_circle_through_three_points_and_the_polar_formula():
    prog = _feeder()
    f = Follower("translating", "roller", 0.05, 0.01, 0.0)
    th = cam_angles(20000)
    prof = profile(prog, f, th)
    x, y = prof.pitch
    a = np.array([np.roll(x, 1), np.roll(y, 1)])
    b = np.array([x, y])
    c = np.array([np.roll(x, -1), np.roll(y, -1)])
    ab, bc, ca = (np.hypot(*(b - a)), np.hypot(*(c - b)), np.hypot(*(a - c)))
    area2 = np.abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
    keep = area2 > 1e-16
    circ = ab * bc * ca / (2.0 * area2)  # circumradius abc/(4 K), K = area2/2
    rho = np.abs(prof.pitch_curvature_radius)
    sel = keep & (rho < 1.0)
    np.testing.assert_allclose(circ[sel], rho[sel], rtol=2e-3)
    # Norton eq 8.33 for a radial follower: rho = (r^2 + v^2)^1.5 / (r^2 + 2 v^2 - r a)
    m = prof.svaj
    r = f.prime_radius + m.s
    polar = (r**2 + m.v**2) ** 1.5 / (r**2 + 2 * m.v**2 - r * m.a)
    np.testing.assert_allclose(prof.pitch_curvature_radius, polar, rtol=1e-10)


def test_flat_face_curvature_and_face_width():
    prog = _feeder()
    f = Follower("translating", "flat", 0.04)
    prof = profile(prog, f, cam_angles(3600))
    m = prof.svaj
    np.testing.assert_allclose(prof.surface_curvature_radius, 0.04 + m.s + m.a, rtol=1e-12)
    chk = check_cam(prof, prog, face_margin=0.002, face_width=0.01)
    assert chk.face_width == pytest.approx(float(np.max(m.v) - np.min(m.v)) + 0.004)
    assert any("too narrow" in s for s in chk.failed)
    # the cam surface is the envelope of the face: the face line touches it (surface . normal = R_b + s)
    nrm = prof.normal
    np.testing.assert_allclose(np.sum(prof.surface * nrm, axis=0), 0.04 + m.s, atol=1e-14)


def test_smallest_base_circles_are_exactly_at_their_limits():
    prog = _feeder()
    th = cam_angles(1440)
    for f in (Follower("translating", "roller", 0.05, 0.01, 0.0), Follower("translating", "roller", 0.05, 0.01, 0.008)):
        rb = min_base_radius_pressure(prog, f, D(30), th)
        worst = float(np.max(np.abs(profile(prog, replace(f, base_radius=rb), th).pressure_angle)))
        assert np.degrees(worst) == pytest.approx(30.0, abs=1e-9)
        worse = float(np.max(np.abs(profile(prog, replace(f, base_radius=0.97 * rb), th).pressure_angle)))
        assert np.degrees(worse) > 30.0
    flat = Follower("translating", "flat", 0.05)
    rb = min_base_radius_curvature(prog, flat, th)
    rho = profile(prog, replace(flat, base_radius=rb), th).surface_curvature_radius
    assert float(np.min(rho)) == pytest.approx(0.0, abs=1e-12)
    osc = Follower("oscillating", "roller", 0.04, 0.01, 0.0, 0.12, 0.09)
    prog_o = program([Segment("rise", D(90), D(15), "cycloidal"), Segment("dwell", D(90)),
                      Segment("return", D(90), D(15), "cycloidal"), Segment("dwell", D(90))])
    rb = min_base_radius_pressure(prog_o, osc, D(35), th)
    worst = float(np.max(np.abs(profile(prog_o, replace(osc, base_radius=rb), th).pressure_angle)))
    assert np.degrees(worst) == pytest.approx(35.0, abs=1e-6)
    # an oscillating follower's pressure angle is not monotone in R_b: smaller circles than the one found fail
    for smaller in np.linspace(0.0201, 0.999 * rb, 7):  # from the smallest assembling circle, |d - l| - r_r
        if smaller > 0.0:
            f = replace(osc, base_radius=smaller)
            assert float(np.max(np.abs(profile(prog_o, f, th).pressure_angle))) > D(35) - 1e-9


@pytest.mark.parametrize("kwargs, words", [
    ({"base_radius": 0.005, "roller_radius": 0.004, "offset": 0.01}, "too small to assemble"),
    ({"base_radius": -0.01, "roller_radius": 0.004}, "base_radius must be > 0"),
    ({"contact": "roller", "roller_radius": 0.0}, "roller_radius"),
    ({"motion": "oscillating", "pivot_distance": 0.3, "arm_length": 0.1, "roller_radius": 0.01}, "does not assemble"),
    ({"motion": "oscillating", "contact": "flat"}, "flat face"),
])
def test_bad_followers_are_refused_naming_the_field(kwargs, words):
    base = {"motion": "translating", "contact": "roller", "base_radius": 0.05, "roller_radius": 0.01}
    with pytest.raises(InputError, match=words):
        Follower(**(base | kwargs))


def test_an_undercut_cam_fails_its_check_with_the_angle():
    prog = program([Segment("rise", D(40), 0.03, "cycloidal"), Segment("return", D(40), 0.03, "cycloidal"),
                    Segment("dwell", D(280))])
    f = Follower("translating", "roller", 0.02, 0.015)
    chk = check_cam(profile(prog, f, cam_angles(1440)), prog)
    assert any("undercut" in s and "cam angle" in s for s in chk.failed)


@settings(max_examples=30, deadline=None)
@given(rise=st.floats(20, 170), lift=st.floats(0.002, 0.05), rb=st.floats(0.02, 0.1),
       law=st.sampled_from(sorted(LAWS)))
def test_pressure_angle_formula_holds_for_any_radial_cam(rise, lift, rb, law):
    prog = program([Segment("rise", D(rise), lift, law), Segment("return", D(360 - rise), lift, "cycloidal")])
    f = Follower("translating", "roller", rb, 0.005)
    th = cam_angles(360)
    prof = profile(prog, f, th)
    m = prof.svaj
    np.testing.assert_allclose(np.tan(prof.pressure_angle), m.v / (f.prime_radius + m.s), rtol=1e-9, atol=1e-12)


def test_a_population_analysed_at_once_matches_each_design_analysed_alone():
    from machdyn.cams.exact import segment_angles
    from machdyn.cams.population import analyse_population

    prog = _feeder()
    th = segment_angles(prog)  # the angles the checks' base-circle searches use: every segment sampled alike
    rng = np.random.default_rng(3)
    n = 12
    rb, rr, e, k = rng.uniform(0.03, 0.08, n), rng.uniform(0.005, 0.015, n), rng.uniform(-0.01, 0.01, n), \
        rng.uniform(0.5, 1.5, n)
    pop = analyse_population(prog, th, rb, rr, e, k, D(30))
    for i in range(n):
        scaled = program([Segment("rise", D(100), 0.03 * k[i], "cycloidal"), Segment("dwell", D(80)),
                          Segment("return", D(120), 0.03 * k[i], "poly345"), Segment("dwell", D(60))])
        f = Follower("translating", "roller", rb[i], rr[i], e[i])
        alone = profile(scaled, f, th)
        np.testing.assert_allclose(pop.pressure_angle[i], alone.pressure_angle, atol=1e-12)
        chk = check_cam(alone, scaled, pressure_limit=D(30))
        # both find the exact extremes between samples, on each segment's closed form
        assert pop.max_pressure_angle[i] == pytest.approx(chk.max_pressure_angle, rel=1e-12)
        assert pop.min_pitch_curvature_radius[i] == pytest.approx(chk.min_pitch_radius, rel=1e-12)
        assert pop.min_base_radius_pressure[i] == pytest.approx(chk.min_base_radius_pressure, rel=1e-12)
    one_varying = analyse_population(prog, th, np.linspace(0.03, 0.08, 5), 0.01)
    assert one_varying.min_base_radius_pressure.shape == (5,)
    not_assembling = analyse_population(prog, th, [0.05, 0.01], 0.0, [0.0, 0.02])
    assert not_assembling.valid.tolist() == [True, False]
    assert np.isnan(not_assembling.max_pressure_angle[1])
