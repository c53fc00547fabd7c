"""Dimensional synthesis against published inputs and against pylinkage's synthesis on the same tasks.

Where a source prints its inputs, machdyn is run on them and every result is checked by running the synthesised
linkage through the engine; where pylinkage (H. Farajallah, *pylinkage* 1.3, ``pylinkage.synthesis``, after
Sandor & Erdman and McCarthy) has a solution of the same task, the two are compared.
"""

from __future__ import annotations

import numpy as np
import pytest
from pylinkage.synthesis import Pose
from pylinkage.synthesis.burmester import compute_circle_point_curve
from pylinkage.synthesis.function_generation import (
    coefficients_to_link_lengths,
    solve_freudenstein_3_positions,
    solve_freudenstein_least_squares,
)
from pylinkage.synthesis.motion_generation import motion_generation

from machdyn.linkage import kinematics
from machdyn.synthesis import burmester
from machdyn.synthesis.candidate import Candidate, wrap
from machdyn.synthesis.dyads import solve
from machdyn.synthesis.function import chebyshev_spacing, coefficients, freudenstein, function_angles

# Waldron, Kinzel & Agrawal, *Kinematics, Dynamics, and Design of Machinery*, 3rd ed., three-position function
# synthesis as set in the Ohio State ME 3751 lecture 12 that follows the book: crank angles 35.02, 67.50,
# 100.0 deg, rocker angles 91.21, 101.79, 117.19 deg, ground 4.5 in.
THETA = np.radians([35.02, 67.50, 100.0])
PHI = np.radians([91.21, 101.79, 117.19])
GROUND = 4.5 * 0.0254


def test_three_point_function_synthesis_agrees_with_pylinkage_and_passes_its_points_in_the_engine():
    k = coefficients(THETA, PHI)
    r = solve_freudenstein_3_positions(list(zip(THETA, PHI, strict=True)))
    assert np.allclose(k, r, rtol=1e-12, atol=1e-12)
    c = freudenstein(THETA, PHI, GROUND)
    a, b, cc, d = coefficients_to_link_lengths(*r, ground_length=GROUND)
    assert (c.crank, c.coupler, c.rocker, c.ground) == pytest.approx((a, b, cc, d), rel=1e-12)
    rocker = kinematics(c.mechanism(), c.angles).body("rocker").angle + c.output_offset
    assert np.max(np.abs(wrap(rocker - PHI))) < 1e-9


def test_least_squares_function_synthesis_agrees_with_pylinkage():
    """y = log10(x) on [1, 2], crank 30..120 deg, rocker 240..330 deg, 12 points: the linear least-squares
    coefficients of Freudenstein's equation are pylinkage's to rounding."""
    x = np.linspace(1.0, 2.0, 12)
    t2, t4 = function_angles(np.log10, (1.0, 2.0), (np.radians(30), np.radians(120)),
                             (np.radians(240), np.radians(330)), x)
    k = coefficients(t2, t4)
    r1, r2, r3, _ = solve_freudenstein_least_squares(list(zip(t2, t4, strict=True)))
    assert np.allclose(k, (r1, r2, r3), rtol=1e-10, atol=1e-12)


def test_chebyshev_points_of_three_on_one_to_two():
    """Chebyshev spacing of three precision points on 1 <= x <= 2: 1.067, 1.5, 1.933 (the cosine rule of
    Uicker, Pennock & Shigley, ch. 10, to the 3 decimals such tables print)."""
    assert chebyshev_spacing(1.0, 2.0, 3) == pytest.approx([1.067, 1.5, 1.933], abs=5e-4)


def _poses():
    true = Candidate(kind="four_bar", origin=0j, crank=0.04, coupler=0.12, rocker=0.1, ground=0.13,
                     coupler_point=(0.06, 0.025), branch=1)
    phi = np.radians([10, 60, 110, 170, 240])
    return true.point(phi), true.coupler_angle(phi)


def _spread(circle_point: complex, centre: complex, p: np.ndarray, t: np.ndarray) -> float:
    """Relative spread of the circle point's distances from the centre over the poses (0: exactly a dyad)."""
    moving = p + (circle_point - p[0]) * np.exp(1j * (t - t[0]))
    r = np.abs(moving - centre)
    return float(np.ptp(r) / r.mean())


def test_five_position_burmester_points_against_pylinkage():
    """Five poses of a known four-bar. machdyn's Burmester points (roots of the two compatibility equations)
    are exact and include both dyads of that four-bar; pylinkage's (a grid search accepting 1 % spread) are
    dyads to within its 1 %: both solve the task, pylinkage approximately (the bench compares them)."""
    p, t = _poses()
    ours = burmester.points_five(p, t)
    assert min(abs(d.ground_pivot) for d in ours) < 1e-9 and min(abs(d.ground_pivot - 0.13) for d in ours) < 1e-9
    for d in ours:
        assert _spread(d.moving_pivot, d.ground_pivot, p, t) < 1e-9
    theirs = compute_circle_point_curve([Pose(float(q.real), float(q.imag), float(a)) for q, a in zip(p, t,
                                                                                                        strict=True)])
    assert len(theirs.center_curve) > 0
    for circle, centre in zip(theirs.circle_curve, theirs.center_curve, strict=True):
        assert _spread(complex(circle), complex(centre), p, t) < 0.02


def test_three_pose_motion_generation_pylinkage_solutions_are_in_the_standard_form_family():
    """Every four-bar pylinkage synthesises for three poses satisfies machdyn's standard-form dyad equations: with
    its crank's rotations as the free choices, machdyn's closed form gives back its ground pivot."""
    p, t = _poses()
    p, t = p[:3], t[:3]
    result = motion_generation([Pose(float(q.real), float(q.imag), float(a)) for q, a in zip(p, t, strict=True)],
                               max_solutions=10, require_grashof=False)
    assert result.raw_solutions
    for s in result.raw_solutions:
        a0 = complex(*s.ground_pivot_a)
        b1 = complex(*s.crank_pivot_b)
        z = p[0] - b1  # the coupler vector from the crank pin to the pose point
        moving = p - z * np.exp(1j * (t - t[0]))  # the crank pin in each pose
        assert np.ptp(np.abs(moving - a0)) < 1e-6 * max(1.0, abs(b1 - a0))
        betas = np.angle((moving[1:] - a0) / (moving[0] - a0))
        d = solve(p, t, betas)
        assert d is not None
        assert abs(d.ground_pivot - a0) < 1e-9 * max(1.0, abs(a0))
