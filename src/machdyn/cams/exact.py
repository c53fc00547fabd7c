"""The extremes of a cam's pressure angle, radius of curvature and contact point over each segment, found on the
exact closed forms and independent of the angles the profile is sampled at.

A profile sampled at ``positions`` angles can step over a short segment (a 30 mm rise over 0.3 deg lies between
two of 720 samples) or over the few degrees where the pitch curve is sharpest; its sampled extremes then pass a
cam that fails. Here every segment is judged on its own interval, x = (theta - theta_0)/beta in [0, 1], through
the law's closed forms (:mod:`machdyn.cams.laws`): each smooth piece of the law (split where its acceleration
jumps: the parabolic law at 1/2, the modified trapezoid at 1/8, 3/8, 5/8, 7/8, the modified sine at 1/8, 7/8)
is sampled at :data:`GRID` points and the best sample refined by a bounded scalar search (Brent's method,
scipy's ``minimize_scalar(method="bounded")``) between its neighbours, to 1e-12 of the piece. The quantities are
those of :mod:`machdyn.cams.profile` (Norton, *Design of Machinery*, 5th ed., §8.6, eqs 8.31-8.33; Uicker,
Pennock & Shigley, *Theory of Machines and Mechanisms*, 4th ed., eqs 6.26-6.28):

* the pressure angle phi, tan phi = (G1 . u)/((J G1) . u) (0 for a flat face);
* the pitch curve's curvature kappa = -(G1 x G2)/|G1|^3 [1/m] (positive convex), whose largest convex value
  gives the smallest convex radius of curvature rho = 1/kappa (smooth where rho passes through infinity);
* a flat face's radius of curvature R_b + s + a and its contact point v = ds/dtheta.

Valid for every program of :mod:`machdyn.cams.program`; a search over a piece finds the piece's largest value
unless a narrower peak than 1/:data:`GRID` of the piece hides between two samples, which the laws' closed forms
(at most a few extremes per piece) do not have.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from .followers import Follower, follower_path
from .geometric import contour_phi
from .program import CONTOURS, Program

#: Samples per smooth piece of a segment before the bounded search refines the best.
GRID = 65
#: Where each law's acceleration jumps inside its interval [x].
BREAKS: dict[str, tuple[float, ...]] = {
    "parabolic": (0.5,),
    "modified_trapezoid": (0.125, 0.375, 0.625, 0.875),
    "modified_sine": (0.125, 0.875),
}
INSIDE = 1e-12  # a piece is evaluated just inside its ends, so that a jump's one-sided value is the piece's own


@dataclass(frozen=True)
class Extremes:
    """The exact extremes over the turn (SI): the largest |pressure angle| [rad] and its cam angle [rad]; the
    largest convex curvature of the pitch curve [1/m] (0 if none is convex) and its cam angle; a flat face's
    smallest radius R_b + s + a [m] and its angle; the contact point's range v_min, v_max [m]."""

    max_pressure_angle: float
    max_pressure_angle_at: float
    max_convex_curvature: float
    max_convex_curvature_at: float
    min_flat_radius: float
    min_flat_radius_at: float
    contact_min: float
    contact_max: float

    @property
    def min_convex_radius(self) -> float:
        """The smallest convex radius of curvature of the pitch curve [m] (inf where none is convex)."""
        return 1.0 / self.max_convex_curvature if self.max_convex_curvature > 0 else float("inf")


def smooth_pieces(prog: Program) -> list[tuple[int, float, float]]:
    """(segment, x0, x1) of every smooth piece of every segment."""
    out = []
    for k, seg in enumerate(prog.segments):
        cuts = (0.0, *BREAKS.get(seg.law, ()), 1.0) if seg.motion != "dwell" else (0.0, 1.0)
        if seg.motion != "dwell" and seg.law in CONTOURS:  # the contact passes from flank to nose
            x = contour_phi(seg.law, seg.contour[0], seg.contour[1], seg.lift, seg.contour[2]) / seg.duration
            cuts = (0.0, x if seg.motion == "rise" else 1.0 - x, 1.0)
        out += [(k, a, b) for a, b in zip(cuts[:-1], cuts[1:], strict=True)]
    return out


def segment_motion(prog: Program, k: int, x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Cam angle [rad], s, v = ds/dtheta, a of segment k at x in its interval, from the law's closed form."""
    seg, t0, level = prog.segments[k], prog.starts[k], prog.levels[k]
    theta = t0 + seg.duration * x
    if seg.motion == "dwell":
        zero = np.zeros_like(x)
        return theta, zero + level, zero, zero
    y, y1, y2, _ = seg.normalised(x)  # the law's closed form (a spline for a table, the contour's for a shape)
    sign = 1.0 if seg.motion == "rise" else -1.0
    b, h = seg.duration, seg.lift
    return theta, level + sign * h * y, sign * h * y1 / b, sign * h * y2 / b**2


def _pitch(follower: Follower, s, v, a) -> tuple[np.ndarray, np.ndarray]:
    """|pressure angle| [rad] and convex curvature [1/m] of the pitch curve (:mod:`machdyn.cams.profile`)."""
    path = follower_path(follower, s, v, a)
    jf, jf1 = np.array([-path.f[1], path.f[0]]), np.array([-path.f1[1], path.f1[0]])
    g1 = path.f1 - jf
    g2 = path.f2 - 2.0 * jf1 - path.f
    jg = np.array([-g1[1], g1[0]])
    phi = np.arctan2(np.sum(g1 * path.u, axis=0), np.sum(jg * path.u, axis=0))
    cross = g1[0] * g2[1] - g1[1] * g2[0]
    return np.abs(phi), -cross / np.hypot(g1[0], g1[1]) ** 3


def _largest(fn: Callable[[np.ndarray], np.ndarray], x0: float, x1: float) -> tuple[float, float]:
    """The largest value of fn over [x0, x1] and where: a grid, then a bounded scalar search about its best."""
    from scipy.optimize import minimize_scalar

    span = x1 - x0
    xs = np.linspace(x0 + INSIDE * span, x1 - INSIDE * span, GRID)
    ys = fn(xs)
    i = int(np.argmax(ys))
    best_x, best = float(xs[i]), float(ys[i])
    lo, hi = float(xs[max(i - 1, 0)]), float(xs[min(i + 1, GRID - 1)])
    res = minimize_scalar(lambda x: -float(fn(np.array([x]))[0]), bounds=(lo, hi), method="bounded",
                          options={"xatol": 1e-12 * max(span, 1e-300)})
    if res.success and -float(res.fun) > best:
        best_x, best = float(res.x), -float(res.fun)
    return best, best_x


def extremes(prog: Program, follower: Follower) -> Extremes:
    """The exact extremes of the cam over every segment (module docstring)."""
    flat = follower.contact == "flat"
    phi = (0.0, 0.0)
    curv = (0.0, 0.0)
    rmin = (float("inf"), 0.0)
    vmin, vmax = float("inf"), -float("inf")

    def at(k: int, x: float) -> float:
        return float(segment_motion(prog, k, np.array([x]))[0][0])

    for k, x0, x1 in smooth_pieces(prog):
        if flat:
            def radius(x: np.ndarray, k: int = k) -> np.ndarray:
                _, s, _, a = segment_motion(prog, k, x)
                return -(follower.base_radius + s + a)

            def contact(x: np.ndarray, k: int = k) -> np.ndarray:
                return segment_motion(prog, k, x)[2]

            def contact_below(x: np.ndarray, k: int = k) -> np.ndarray:
                return -segment_motion(prog, k, x)[2]

            value, x = _largest(radius, x0, x1)
            if -value < rmin[0]:
                rmin = (-value, at(k, x))
            vmax = max(vmax, _largest(contact, x0, x1)[0])
            vmin = min(vmin, -_largest(contact_below, x0, x1)[0])
            continue

        def pressure(x: np.ndarray, k: int = k) -> np.ndarray:
            _, s, v, a = segment_motion(prog, k, x)
            return _pitch(follower, s, v, a)[0]

        def curvature(x: np.ndarray, k: int = k) -> np.ndarray:
            _, s, v, a = segment_motion(prog, k, x)
            return _pitch(follower, s, v, a)[1]

        value, x = _largest(pressure, x0, x1)
        if value > phi[0]:
            phi = (value, at(k, x))
        value, x = _largest(curvature, x0, x1)
        if value > curv[0]:
            curv = (value, at(k, x))
    if not flat:
        vmin = vmax = 0.0
    return Extremes(phi[0], phi[1], curv[0], curv[1], rmin[0], rmin[1], vmin, vmax)


def segment_angles(prog: Program, per_piece: int = GRID) -> np.ndarray:
    """Cam angles [rad] that sample every smooth piece of every segment at ``per_piece`` points, just inside its
    ends (for searches that need a grid that sees every segment, e.g. the smallest base circle)."""
    out = []
    for k, x0, x1 in smooth_pieces(prog):
        span = x1 - x0
        out.append(segment_motion(prog, k, np.linspace(x0 + INSIDE * span, x1 - INSIDE * span, per_piece))[0])
    return np.unique(np.concatenate(out))
