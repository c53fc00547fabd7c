"""Every synthesised linkage, built as the engine's model and run by the engine, does what its task asked: it
passes its precision points or positions to 1e-9 and has the requested swing or stroke and time ratio. The
Burmester curves are checked by construction: every circle point's positions lie on a circle about its centre
point, for random pole configurations."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from machdyn.linkage import kinematics
from machdyn.synthesis import burmester
from machdyn.synthesis.candidate import Candidate, wrap
from machdyn.synthesis.defects import Targets, check, full_turn
from machdyn.synthesis.function import (
    chebyshev_spacing,
    freudenstein,
    freudenstein_least_squares,
    function_angles,
    output_error,
)
from machdyn.synthesis.motion import motion_candidates
from machdyn.synthesis.path import path_candidates, three_points
from machdyn.synthesis.quick_return import construction_angle, crank_rocker, slider_crank

SETTINGS = settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def engine(c: Candidate, phi):
    """The engine's kinematics of the candidate's model at crank angles ``phi``."""
    return kinematics(c.mechanism(), np.asarray(phi, dtype=float), 1.0)


def engine_point(c: Candidate, phi):
    k = engine(c, phi)
    p = k.point("coupler.P")
    return c.place(p.x, p.y)


def engine_coupler_angle(c: Candidate, phi):
    return engine(c, phi).body("coupler").angle + c.coupler_offset


# ------------------------------------------------------------------------------------ function generation


@SETTINGS
@given(start2=st.floats(0.0, 2.0), span2=st.floats(0.6, 1.6), start4=st.floats(-3.0, 3.0),
       span4=st.floats(0.4, 1.2), f=st.sampled_from([np.log10, np.sqrt, np.exp]))
def test_freudenstein_three_points_pass_through_the_engine(start2, span2, start4, span4, f):
    x = chebyshev_spacing(1.0, 2.0, 3)
    t2, t4 = function_angles(f, (1.0, 2.0), (start2, start2 + span2), (start4, start4 + span4), x)
    try:
        c = freudenstein(t2, t4, 0.1)
    except ValueError:
        assume(False)
    rocker = engine(c, c.angles).body("rocker").angle + c.output_offset
    assert np.all(np.isfinite(rocker))
    # the closure reaches the precision points on the candidate's branch, or the defect check says it does not
    report = check(c, Targets(outputs=t4, scale=0.1), need_full_turn=False, transmission_limit=0.0)
    if not any(d.startswith("branch") for d in report.defects):
        assert np.max(np.abs(wrap(rocker - t4))) < 1e-9


def test_freudenstein_least_squares_recovers_a_linkage_that_generates_its_own_function():
    """Angle pairs taken from a real four-bar (many of them): the least-squares fit is exact and gives that
    four-bar back (Freudenstein's coefficients are unique up to the ground length)."""
    true = Candidate(kind="four_bar", origin=0j, crank=0.03, coupler=0.11, rocker=0.08, ground=0.1, branch=1,
                     coupler_point=(0.11, 0.0))
    phi = np.linspace(0.2, 1.8, 25)
    t4 = true.output_angle(phi)
    c = freudenstein_least_squares(phi, t4, 0.1)
    assert c.crank == pytest.approx(0.03, rel=1e-9)
    assert c.coupler == pytest.approx(0.11, rel=1e-9)
    assert c.rocker == pytest.approx(0.08, rel=1e-9)
    assert np.max(np.abs(output_error(c, phi, t4))) < 1e-9


def test_chebyshev_spacing_is_the_cosine_rule():
    x = chebyshev_spacing(0.0, 2.0, 4)
    j = np.arange(1, 5)
    assert np.allclose(x, 1.0 - np.cos((2 * j - 1) * np.pi / 8), atol=1e-15)


# ------------------------------------------------------------------------------------------- quick return


@SETTINGS
@given(swing=st.floats(np.radians(15), np.radians(100)), q=st.floats(1.0, 1.8), pos=st.floats(0.05, 0.95),
       side=st.sampled_from([1, -1]), slow=st.sampled_from(["out", "back"]))
def test_crank_rocker_has_the_swing_and_the_time_ratio_in_the_engine(swing, q, pos, side, slow):
    c = crank_rocker(swing, q, 0.2, position=pos, side=side, slow_stroke=slow)
    assume(full_turn(c))
    phi1, phi2 = c.angles
    psi1 = np.pi / 2 - swing / 2
    k = engine(c, np.array([phi1, phi2]))
    rocker = k.body("rocker")
    miss = np.max(np.abs(wrap(rocker.angle - [psi1, psi1 + swing])))
    report = check(c, Targets(outputs=np.array([psi1, psi1 + swing]), scale=0.2), transmission_limit=0.0)
    # where the rocker pivot lies between the two crank lines, the limit positions are on different circuits:
    # the defect check says so exactly when the engine misses the second limit
    assert (miss < 1e-9) == (not any(d.startswith("branch") for d in report.defects))
    assume(miss < 1e-9)
    assert np.max(np.abs(rocker.omega)) < 1e-9  # the limit positions: the rocker stands still

    # the extremes found from the engine alone: the rocker's angular velocity changes sign there
    def omega(phi):
        return float(engine(c, np.array([phi])).body("rocker").omega[0])

    found = [brentq(omega, p - 0.05, p + 0.05, xtol=1e-14) for p in (phi1, phi2)]
    out = np.mod(c.direction * (found[1] - found[0]), 2 * np.pi)  # crank turn of the out stroke
    ratio = out / (2 * np.pi - out) if slow == "out" else (2 * np.pi - out) / out
    assert ratio == pytest.approx(q, rel=1e-9, abs=1e-9)
    # the whole turn stays inside the swing
    turn = engine(c, np.linspace(0, 2 * np.pi, 721)).body("rocker").angle
    assert np.max(np.abs(wrap(turn - (psi1 + swing / 2)))) <= swing / 2 + 1e-9


@SETTINGS
@given(stroke=st.floats(0.02, 0.5), q=st.floats(1.0, 1.6), pos=st.floats(0.05, 0.95), side=st.sampled_from([1, -1]))
def test_slider_crank_has_the_stroke_and_the_time_ratio_in_the_engine(stroke, q, pos, side):
    c = slider_crank(stroke, q, position=pos, side=side)
    outputs = c.output_angle(c.angles)[0] + np.array([0.0, stroke])
    assume(not check(c, Targets(outputs=outputs, scale=stroke), transmission_limit=np.radians(5)).defects)
    k = engine(c, c.angles)
    s = k.slide("slider")
    assert abs(abs(s.s[1] - s.s[0]) - stroke) < 1e-9 * max(stroke, 1.0)
    assert np.max(np.abs(s.v)) < 1e-9
    out = np.mod(c.direction * (c.angles[1] - c.angles[0]), 2 * np.pi)
    assert out / (2 * np.pi - out) == pytest.approx(q, rel=1e-9)
    travel = engine(c, np.linspace(0, 2 * np.pi, 721)).slide("slider").s
    assert travel.max() - travel.min() <= stroke * (1 + 1e-9)


def test_construction_angle_of_a_time_ratio():
    """delta = 180 (Q - 1)/(Q + 1) deg: Q = 1.25 gives 20 deg, Q = 1 gives 0."""
    assert np.degrees(construction_angle(1.25)) == pytest.approx(20.0, abs=1e-12)
    assert construction_angle(1.0) == 0.0
    with pytest.raises(ValueError, match="time ratio"):
        construction_angle(0.8)


# -------------------------------------------------------------------------------------- motion and path


def _poses(draw_seed: int, n: int):
    rng = np.random.default_rng(draw_seed)
    p = np.concatenate([[0j], np.cumsum(rng.uniform(0.02, 0.08, n - 1) * np.exp(1j * rng.uniform(-0.8, 0.8, n - 1)))])
    t = np.concatenate([[0.0], np.cumsum(rng.uniform(-0.6, 0.6, n - 1))])
    return p, t


@pytest.mark.parametrize("seed", range(4))
def test_three_position_candidates_free_of_branch_defects_pass_their_positions_in_the_engine(seed):
    p, t = _poses(seed, 3)
    cands = motion_candidates(p, t, count=60, seed=seed)
    reports = [check(c, Targets(points=p, coupler_angles=t, scale=0.05), need_full_turn=False) for c in cands]
    good = [c for c, r in zip(cands, reports, strict=True) if not any(d.startswith(("branch", "assembly"))
                                                                     for d in r.defects)]
    assert good, "some candidates reach all three positions on one branch"
    for c in good[:10]:
        assert np.max(np.abs(engine_point(c, c.angles) - p)) < 1e-9
        assert np.max(np.abs(wrap(engine_coupler_angle(c, c.angles) - t))) < 1e-9


@SETTINGS
@given(seed=st.integers(0, 10_000))
def test_burmester_circle_points_stay_on_circles_about_their_centre_points(seed):
    """By construction: moving the coupler through its four positions carries each circle point along a circle
    whose centre is the matching centre point (the poles of the positions drawn at random)."""
    p, t = _poses(seed, 4)
    cur = burmester.curves(p, t, samples=90)
    dyads = cur.dyads(p)
    assume(len(dyads) > 4)
    for d in dyads:
        moving = p - d.z * np.exp(1j * (t - t[0]))  # the circle point in each position
        r = np.abs(moving - d.ground_pivot)
        assert np.ptp(r) < 1e-9 * max(1.0, r.max())


def test_five_position_burmester_points_contain_the_linkage_the_positions_came_from():
    true = Candidate(kind="four_bar", origin=0j, crank=0.04, coupler=0.12, rocker=0.1, ground=0.13,
                     coupler_point=(0.06, 0.025), branch=1)
    phi = np.radians([10, 60, 110, 170, 240])
    p, t = true.point(phi), true.coupler_angle(phi)
    dyads = burmester.points_five(p, t)
    centres = [d.ground_pivot for d in dyads]
    assert min(abs(z - 0j) for z in centres) < 1e-9
    assert min(abs(z - 0.13) for z in centres) < 1e-9
    for d in dyads:  # every Burmester pair passes the five positions
        moving = p - d.z * np.exp(1j * (t - t[0]))
        assert np.ptp(np.abs(moving - d.ground_pivot)) < 1e-9


def test_path_through_three_points_with_prescribed_timing():
    p = np.array([0j, 0.05 + 0.03j, 0.1 + 0.02j])
    timing = (np.radians(40), np.radians(90))
    cands = three_points(p, timing=timing, count=40, seed=3)
    assert cands
    for c in cands:
        steps = wrap(c.angles - c.angles[0])[1:]
        assert np.allclose(steps, wrap(np.array(timing)), atol=1e-12)
    good = [c for c in cands if not check(c, Targets(points=p, scale=0.05), need_full_turn=False).defects
            or np.max(np.abs(c.point(c.angles) - p)) < 1e-12]
    assert good
    for c in good[:5]:
        assert np.max(np.abs(engine_point(c, c.angles) - p)) < 1e-9


def test_path_through_five_points_by_least_squares_passes_them_in_the_engine():
    p = np.array([0j, 0.03 + 0.04j, 0.08 + 0.06j, 0.13 + 0.05j, 0.16 + 0.02j])
    cands = path_candidates(p, count=2, seeds=12, max_length=0.4, transmission_limit=np.radians(32))
    assert cands
    for c in cands:
        assert np.max(np.abs(engine_point(c, c.angles) - p)) < 1e-9


def test_structural_error_vanishes_at_the_precision_points_of_the_function():
    """Three Chebyshev points for log10 on [1, 2], the error measured through the function's own mapping of x to
    the input angle: zero at the three points (to rounding), not zero between them."""
    ranges = ((np.radians(30), np.radians(120)), (np.radians(60), np.radians(150)))
    x = chebyshev_spacing(1.0, 2.0, 3)
    c = freudenstein(*function_angles(np.log10, (1.0, 2.0), *ranges, x), 0.1)
    at_points = output_error(c, *function_angles(np.log10, (1.0, 2.0), *ranges, x))
    assert np.max(np.abs(at_points)) < 1e-12
    between = output_error(c, *function_angles(np.log10, (1.0, 2.0), *ranges, np.array([1.0, 1.25, 2.0])))
    assert np.all(np.abs(between) > 1e-6)


@SETTINGS
@given(seed=st.integers(0, 10_000), gx=st.floats(-0.2, 0.2), gy=st.floats(-0.2, 0.2))
def test_a_dyad_with_a_given_ground_pivot_keeps_its_circle_point_on_a_circle_about_it(seed, gx, gy):
    """Norton §5.9 by construction: the circle point found for a chosen ground pivot takes its three positions
    at one distance from that pivot, and its rotations solve the standard form (the non-trivial root)."""
    from machdyn.synthesis.dyads import solve as solve_dyad
    from machdyn.synthesis.dyads import with_ground_pivot

    p, t = _poses(seed, 3)
    d = with_ground_pivot(p, t, complex(gx, gy))
    assume(d is not None and abs(d.w) > 1e-3)
    moving = p - d.z * np.exp(1j * (t - t[0]))
    r = np.abs(moving - complex(gx, gy))
    assert np.ptp(r) < 1e-9 * max(1.0, r.max())
    again = solve_dyad(p, t, d.beta[1:])
    assume(again is not None)
    assert abs(again.ground_pivot - complex(gx, gy)) < 1e-9


def test_motion_with_both_ground_pivots_given_runs_through_the_positions_in_the_engine():
    p = np.array([0j, 0.08 + 0.06j, 0.18 + 0.04j])
    t = np.radians([0.0, -30.0, -90.0])
    found = []
    grid = [complex(x, y) for x in np.linspace(-0.1, 0.3, 5) for y in (-0.15, -0.05)]
    for o2, o4 in ((a, b) for a in grid for b in grid if abs(a - b) > 0.05):
        (c,) = motion_candidates(p, t, crank_pivot=o2, rocker_pivot=o4, max_length=2.0, min_length=1e-6)
        assert abs(c.origin - o2) < 1e-12 and abs(c.rocker_pivot - o4) < 1e-12
        report = check(c, Targets(points=p, coupler_angles=t, scale=0.1), need_full_turn=False)
        if not any(d.startswith(("branch", "assembly")) for d in report.defects):
            found.append(c)
    assert found
    for c in found[:5]:
        assert np.max(np.abs(engine_point(c, c.angles) - p)) < 1e-9
        assert np.max(np.abs(wrap(engine_coupler_angle(c, c.angles) - t))) < 1e-9
