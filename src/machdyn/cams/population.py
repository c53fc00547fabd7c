"""A population of translating roller (or knife-edge) cams analysed at once: NumPy arrays over designs, no loop
over designs, with the same exact extremes as the single-design checks (:mod:`machdyn.cams.exact`).

The designs share the shape of one motion program and differ in base radius R_b, roller radius r_r, offset e and
lift scale (each an array of N values, or one value for all): s = lift_scale * s_0(theta). With d = sqrt(R_p^2 - e^2),
R_p = R_b + r_r, the closed forms of :mod:`machdyn.cams.profile` become, per design and angle,

  tan phi = (v - e)/(d + s)          (Norton, *Design of Machinery*, 5th ed., eq 8.31)
  kappa = -(G1 x G2)/|G1|^3          (the curvature of the pitch curve, positive where convex; rho = 1/kappa)

with G1 = (d + s, v - e), G2 = (2 v - e, a - d - s) (:mod:`machdyn.cams.profile`; Uicker, Pennock & Shigley,
*Theory of Machines and Mechanisms*, 4th ed., eqs 6.26-6.28).

The largest |phi| and the largest convex kappa are found as :func:`machdyn.cams.exact.extremes` finds them for one
design, on each smooth piece of each segment (x in [0, 1] of the segment, split where the law's acceleration
jumps): the piece is sampled at the same :data:`~machdyn.cams.exact.GRID` points, and for every design at once
the best sample's bracket (its two neighbours) is shrunk by a golden-section search of :data:`GOLDEN_STEPS`
steps on the law's closed form (Press et al., *Numerical Recipes*, 3rd ed., §10.2): the bracket, 2/64 of the
piece, ends 0.618^36 x 2/64 ~ 1e-9 of the piece wide, where a smooth maximum's value differs from the exact one by
(1/2)|f''| dx^2 < 1e-12 |f| for any |f''/f| below 1e6 (per piece^2; the laws' pressure angle and curvature have a
few broad extremes per piece). A maximum at a piece's end is its end sample's own value, as in the single search.
The largest |phi| is searched as the largest |tan phi| (the same place: d + s > 0), without an arctangent per
step. The result equals the single-design check (:func:`machdyn.cams.checks.check_cam`) to about 1e-15.

The smallest base circle meeting a pressure-angle limit, R_b = sqrt(d_min^2 + e^2) - r_r with
d_min = max(|v - e|/tan phi_max - s) (direct, :func:`machdyn.cams.checks.min_base_radius_pressure`), is taken over
the same angles as the single check, every piece's grid (:func:`machdyn.cams.exact.segment_angles`).

A design the single-design run refuses (a base radius not > 0, a negative roller radius, a lift scale not > 0, a
value not finite, or an offset |e| >= R_p: the follower does not assemble) is reported with ``valid`` False and
NaN results, so that a study counts it infeasible and goes on with the others. The extremes are computed in chunks
of :data:`CHUNK_DESIGNS` designs (bounded memory); the per-angle pressure angles are (N, K) for the K angles given
(none: ``theta=[]``). Valid for translating followers
with a roller (r_r > 0) or a knife edge (r_r = 0) and every program of :mod:`machdyn.cams.program` but the contour
laws (circular arc, tangent), whose motion follows from one cam's own base circle and roller (refused).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .exact import GRID, INSIDE, segment_motion, smooth_pieces
from .program import CONTOURS, Program

#: Golden-section steps that shrink a piece's best bracket (2/64 of the piece) to ~1e-9 of the piece.
GOLDEN_STEPS = 36
_INV_GOLD = (np.sqrt(5.0) - 1.0) / 2.0
#: Designs evaluated together: the temporaries (designs x GRID per piece) stay bounded for any population.
CHUNK_DESIGNS = 16384


@dataclass(frozen=True)
class PopulationCams:
    """Per design (N): largest |pressure angle| [rad], smallest convex radius of curvature of the pitch curve
    [m] (inf if none), the smallest base radius meeting the limit [m]; the (N, K) pressure angles [rad] at the
    given cam angles; and the flags: ``valid`` (the design assembles; else NaN results), ``pressure_failed``
    (|phi| above the limit), ``undercut`` (a roller larger than the smallest convex radius), ``curvature_failed``
    (that radius not above ``curvature_factor`` x the roller's), the failures of
    :func:`machdyn.cams.checks.check_cam`."""

    max_pressure_angle: np.ndarray
    min_pitch_curvature_radius: np.ndarray
    min_base_radius_pressure: np.ndarray
    pressure_angle: np.ndarray
    valid: np.ndarray
    pressure_failed: np.ndarray
    undercut: np.ndarray
    curvature_failed: np.ndarray


def _slope(s, v, e, d) -> np.ndarray:
    """|tan phi| = |v - e|/(d + s) of a translating follower (module docstring): the largest |phi| is the largest
    |tan phi| (d + s > 0), searched without an arctangent per step."""
    return np.abs(v - e) / (d + s)


def _curvature(s, v, a, e, d) -> np.ndarray:
    """Convex curvature [1/m] of a translating follower's pitch curve (module docstring; the expressions of
    :func:`machdyn.cams.exact._pitch` for a translating path)."""
    g1x, g1y = d + s, v - e
    cross = g1x * (a - d - s) - g1y * (2.0 * v - e)
    speed2 = g1x * g1x + g1y * g1y
    return -cross / (speed2 * np.sqrt(speed2))


def _golden_max(fn: Callable[[np.ndarray], np.ndarray], lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """The largest value of fn met by a golden-section search for a maximum in [lo, hi], per design (N,): the
    better interior point is always kept, so the largest of the last two is the largest met."""
    c = hi - _INV_GOLD * (hi - lo)
    d = lo + _INV_GOLD * (hi - lo)
    fc, fd = fn(c), fn(d)
    for _ in range(GOLDEN_STEPS):
        left = fc >= fd  # the maximum lies in [lo, d]: d becomes the upper end, c the new d
        hi = np.where(left, d, hi)
        lo = np.where(left, lo, c)
        new = np.where(left, hi - _INV_GOLD * (hi - lo), lo + _INV_GOLD * (hi - lo))
        fnew = fn(new)
        c, d = np.where(left, new, d), np.where(left, c, new)
        fc, fd = np.where(left, fnew, fd), np.where(left, fc, fnew)
    return np.maximum(fc, fd)


def _piece_max(fn: Callable[[np.ndarray], np.ndarray], xs: np.ndarray, values: np.ndarray) -> np.ndarray:
    """The largest of fn over a piece sampled at xs (K,) with values (N, K): the best sample, refined between
    its neighbours (as :func:`machdyn.cams.exact._largest` does for one design)."""
    i = np.argmax(values, axis=1)
    best = values[np.arange(values.shape[0]), i]
    lo, hi = xs[np.maximum(i - 1, 0)], xs[np.minimum(i + 1, xs.size - 1)]
    return np.maximum(best, _golden_max(fn, lo, hi))


def _arrays(*values):
    """The designs' (N,) arrays, broadcast to one length."""
    arrays = [np.atleast_1d(np.asarray(x, dtype=float)) for x in values]
    if any(x.ndim != 1 for x in arrays):
        raise InputError("cams.population: base_radius, roller_radius, offset and lift_scale must each be one "
                         "value or a 1-D array of one value per design.")
    try:
        n = np.broadcast_shapes(*(x.shape for x in arrays))[0]
    except ValueError as exc:
        raise InputError(f"cams.population: the designs' arrays differ in length "
                         f"({', '.join(str(x.size) for x in arrays)}).") from exc
    return [np.broadcast_to(x, (n,)).copy() for x in arrays]


def _extremes(prog: Program, e: np.ndarray, d: np.ndarray, k: np.ndarray,
              tan_limit: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per design: the exact largest |tan phi|, the largest convex curvature [1/m] (0 if none) and d_min [m] over
    the pieces' grids (module docstring), for offsets e, d = sqrt(R_p^2 - e^2) and lift scales k (N,)."""
    ec, dc, kc = e[:, None], d[:, None], k[:, None]
    slope_max = np.zeros_like(e)
    kappa_max = np.zeros_like(e)
    dmin = np.full_like(e, -np.inf)
    for seg, x0, x1 in smooth_pieces(prog):
        span = x1 - x0
        dwell = prog.segments[seg].motion == "dwell"
        xs = np.linspace(x0 + INSIDE * span, x1 - INSIDE * span, 1 if dwell else GRID)
        _, s0, v0, a0 = segment_motion(prog, seg, xs)
        s, v, a = kc * s0, kc * v0, kc * a0
        slope, kappa = _slope(s, v, ec, dc), _curvature(s, v, a, ec, dc)
        dmin = np.maximum(dmin, np.max(np.abs(v - ec) / tan_limit - s, axis=1))
        if dwell:  # constant over the dwell: its one sample is its value
            slope_max = np.maximum(slope_max, slope[:, 0])
            kappa_max = np.maximum(kappa_max, kappa[:, 0])
            continue

        def pressure(x: np.ndarray, seg: int = seg) -> np.ndarray:
            _, s1, v1, _ = segment_motion(prog, seg, x)
            return _slope(k * s1, k * v1, e, d)

        def curvature(x: np.ndarray, seg: int = seg) -> np.ndarray:
            _, s1, v1, a1 = segment_motion(prog, seg, x)
            return _curvature(k * s1, k * v1, k * a1, e, d)

        slope_max = np.maximum(slope_max, _piece_max(pressure, xs, slope))
        kappa_max = np.maximum(kappa_max, _piece_max(curvature, xs, kappa))
    return slope_max, kappa_max, dmin


def analyse_population(prog: Program, theta, base_radius, roller_radius=0.0, offset=0.0, lift_scale=1.0,
                       pressure_limit: float = np.radians(30.0), curvature_factor: float = 1.0) -> PopulationCams:
    """The exact largest pressure angle, smallest convex radius of curvature, smallest base circle and the
    checks' flags of N translating cams (module docstring); ``theta`` [rad] the cam angles of the (N, K)
    pressure angles, ``pressure_limit`` [rad] in (0, 90 deg), ``curvature_factor`` [-] the required
    rho_min / r_r (1: no undercut)."""
    if not 0 < pressure_limit < np.pi / 2:
        raise InputError(f"cams.population: pressure_limit must lie between 0 and 90 deg; got "
                         f"{np.degrees(pressure_limit):g} deg.")
    contour = [seg.law for seg in prog.segments if seg.motion != "dwell" and seg.law in CONTOURS]
    if contour:
        raise InputError(f"cams.population: the {contour[0]} law follows from one cam's own base circle, nose and "
                         "roller, not a shape the designs share; analyse such cams one by one.")
    rb, rr, e, k = _arrays(base_radius, roller_radius, offset, lift_scale)
    rp = rb + rr
    with np.errstate(invalid="ignore"):
        valid = (np.isfinite(rb) & np.isfinite(rr) & np.isfinite(e) & np.isfinite(k) & (rb > 0) & (rr >= 0)
                 & (k > 0) & (np.abs(e) < rp))
    # a refused design is computed on a harmless stand-in and reported as NaN
    rb, rr, e, k = (np.where(valid, x, y) for x, y in ((rb, 1.0), (rr, 0.0), (e, 0.0), (k, 1.0)))
    rp = rb + rr
    d = np.sqrt(rp**2 - e**2)
    tan_limit = np.tan(pressure_limit)
    slope_max, kappa_max, dmin = np.empty_like(rb), np.empty_like(rb), np.empty_like(rb)
    for lo in range(0, rb.size, CHUNK_DESIGNS):  # bounded temporaries (designs x GRID) for any population
        part = slice(lo, lo + CHUNK_DESIGNS)
        slope_max[part], kappa_max[part], dmin[part] = _extremes(prog, e[part], d[part], k[part], tan_limit)
    ec, dc, kc = e[:, None], d[:, None], k[:, None]
    phi_max = np.arctan(slope_max)
    with np.errstate(divide="ignore"):
        rho = np.where(kappa_max > 0, 1.0 / np.where(kappa_max > 0, kappa_max, 1.0), np.inf)
    rbmin = np.maximum(np.hypot(np.maximum(dmin, 0.0), e) - rr, 0.0)
    roller = rr > 0  # a knife edge has no roller to undercut (as in check_cam)
    nan = np.where(valid, 1.0, np.nan)
    th = np.asarray(theta, dtype=float)
    m = prog.svaj(th)
    pressure_angle = np.arctan2(kc * m.v - ec, dc + kc * m.s) * nan[:, None]
    return PopulationCams(
        max_pressure_angle=phi_max * nan, min_pitch_curvature_radius=rho * nan,
        min_base_radius_pressure=rbmin * nan, pressure_angle=pressure_angle, valid=valid,
        pressure_failed=valid & (phi_max > pressure_limit),
        undercut=valid & roller & (rho <= rr),
        curvature_failed=valid & roller & (rho <= rr * curvature_factor))
