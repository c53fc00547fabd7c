"""The population form of the ``[cam]`` kind (:attr:`machdyn.pipeline.ProblemKind.population`): the checks a run
of each design reports — the largest pressure angle, the smallest convex radius of curvature of the pitch curve
and of the cam surface, the smallest base circle meeting the pressure-angle limit — for N translating roller or
knife-edge cams at once, the designs differing in base radius, roller radius and offset.

The closed forms are those of :func:`.population.analyse_population` (Norton, *Design of Machinery*, 5th ed.,
eq 8.31; the pitch curve's curvature of :mod:`.profile`), evaluated on the angles that sample every smooth piece
of every segment (:func:`.exact.segment_angles`, the grid the single-design smallest base circle is searched on).
The single-design run judges the largest pressure angle and the smallest radius exactly between samples
(:mod:`.exact`). The largest pressure angle is refined here the same way: from each design's largest sample, a
few Newton steps on d phi/d theta = 0, i.e. N = a (d + s) - v (v - e) = 0 with N' = j (d + s) - a (v - e)
(the derivative of tan phi = (v - e)/(d + s)), kept between the sample's neighbours, so that it agrees with the
run to rounding where the largest angle lies inside a smooth piece. The smallest convex radius of curvature is
refined likewise: the largest convex curvature -(G1 x G2)/|G1|^3 where its slope vanishes between the
neighbours of its largest samples (the run's :func:`.exact.extremes` searches for the same maximum design by
design). The
smallest base circle agrees to rounding (both are direct on the same grid).

A design the run refuses is NaN here too: a base radius <= 0, a roller <= 0 (a roller follower), an offset not
smaller than the prime radius (it does not assemble), a size over :data:`.followers.MAX_CAM_SIZE`, a roller not
smaller than the smallest convex radius of curvature of the pitch curve at the drawn angles (``cam.positions``;
the cam would be undercut). An oscillating or flat-faced follower, another varied field or another key: None,
each design is run whole.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

import numpy as np

from .checks import default_pressure_limit
from .exact import segment_angles
from .followers import MAX_CAM_SIZE
from .population import analyse_population
from .profile import cam_angles
from .stage import build

#: the paths a design may set: the field of :func:`analyse_population` each is
PATHS = {"cam.base_radius": "base_radius", "cam.follower.roller_radius": "roller_radius",
         "cam.follower.offset": "offset"}

KEYS = ("cam.max_pressure_angle", "cam.min_pitch_curvature_radius", "cam.min_surface_curvature_radius",
        "cam.min_base_radius_pressure", "cam.base_radius", "cam.pressure_angle_limit")


def population(problem: Any, values: Mapping[str, Any], keys: Iterable[str]) -> dict[str, np.ndarray] | None:
    """The ``keys`` of N cam designs, (N,) arrays (module docstring); None where this form cannot stand in for the
    runs."""
    wanted = list(keys)
    if any(k not in KEYS for k in wanted) or any(p not in PATHS for p in values):
        return None
    model, problems = build(problem)
    if problems or model is None:
        return None
    f = model.follower
    if f.motion != "translating" or f.contact == "flat":
        return None
    n = len(next(iter(values.values()))) if values else 1
    given = {"base_radius": f.base_radius, "roller_radius": f.roller_radius, "offset": f.offset}
    x = {name: np.full(n, float(value)) for name, value in given.items()}
    for path, arr in values.items():
        x[PATHS[path]] = np.broadcast_to(np.asarray(arr, dtype=float), (n,)).copy()
    rb, rr, e = x["base_radius"], x["roller_radius"], x["offset"]
    sizes = np.stack([rb, rr, e])
    valid = np.all(np.isfinite(sizes) & (np.abs(sizes) <= MAX_CAM_SIZE), axis=0) & (rb > 0)
    valid &= (rr > 0) if f.contact == "roller" else (rr == 0)
    valid &= np.abs(e) < rb + rr
    out = {k: np.full(n, np.nan) for k in wanted}
    if not valid.any():
        return out
    good = int(np.flatnonzero(valid)[0])
    rb, rr, e = (np.where(valid, a, a[good]) for a in (rb, rr, e))  # designs that fail stand in as a good one
    limit = problem.cam.checks.pressure_angle_limit
    limit = default_pressure_limit(f) if limit is None else float(limit)
    grid = segment_angles(model.program)
    pop = analyse_population(model.program, grid, rb, rr, e, 1.0, limit)
    rho = pop.min_pitch_curvature_radius
    largest = _refined(model.program, grid, pop.pressure_angle, rb + rr, e)
    sharpest = _sharpest(model.program, grid, rb + rr, e)
    rho = np.where(sharpest > 0, 1.0 / np.where(sharpest > 0, sharpest, 1.0), np.inf)
    rho = np.minimum(pop.min_pitch_curvature_radius, rho)
    near = np.flatnonzero(valid & (rho <= rr))  # only these may undercut the drawn profile (exact <= drawn)
    if f.contact == "roller" and near.size:  # the run's build refuses a roller that undercuts the drawn profile
        drawn = analyse_population(model.program, cam_angles(problem.cam.positions), rb[near], rr[near], e[near],
                                   1.0, limit)
        valid[near] &= ~(drawn.min_pitch_curvature_radius <= rr[near])
    found = {"cam.max_pressure_angle": np.maximum(pop.max_pressure_angle, largest),
             "cam.min_pitch_curvature_radius": rho,
             "cam.min_surface_curvature_radius": np.where(np.isfinite(rho), rho - rr, rho),
             "cam.min_base_radius_pressure": pop.min_base_radius_pressure, "cam.base_radius": rb,
             "cam.pressure_angle_limit": np.full(n, limit)}
    return {k: np.where(valid, found[k], np.nan) for k in wanted}


#: Newton steps from the largest sample: quadratic convergence from a sample spacing of about 1/64 of a piece
NEWTON_STEPS = 6


def _refined(prog: Any, grid: np.ndarray, phi: np.ndarray, prime: np.ndarray, e: np.ndarray) -> np.ndarray:
    """The largest |pressure angle| [rad] of each design (N), refined from its largest sample of ``phi`` (N, K) by
    Newton's method on d phi/d theta = 0 between the sample's neighbours (module docstring)."""
    lo, theta, hi = _peaks(np.abs(phi), grid)
    prime, e = prime[:, None], e[:, None]
    d = np.sqrt(prime**2 - e**2)
    for _ in range(NEWTON_STEPS):
        m = prog.svaj(theta)
        slope = m.a * (d + m.s) - m.v * (m.v - e)
        bend = m.j * (d + m.s) - m.a * (m.v - e)
        with np.errstate(divide="ignore", invalid="ignore"):
            step = np.where(bend != 0.0, slope / np.where(bend != 0.0, bend, 1.0), 0.0)
        theta = np.clip(theta - step, lo, hi)
    m = prog.svaj(theta)
    return np.max(np.abs(np.arctan2(m.v - e, d + m.s)), axis=1)


#: Illinois (regula falsi) steps on the curvature's slope: superlinear from a bracket of two sample spacings
SECANT_STEPS = 30


def _curvature(prog: Any, theta: np.ndarray, prime: np.ndarray, e: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The pitch curve's convex curvature k = -(G1 x G2)/|G1|^3 [1/m] at ``theta`` (broadcast with the designs)
    and its slope dk/dtheta, from G1' = (v, a), G2' = (2 a, j - v) (the derivatives of the module's G1, G2)."""
    m = prog.svaj(theta)
    d = np.sqrt(prime**2 - e**2)
    g1x, g1y = d + m.s, m.v - e
    g2x, g2y = 2.0 * m.v - e, m.a - d - m.s
    cross = g1x * g2y - g1y * g2x
    cross1 = m.v * g2y + g1x * (m.j - m.v) - m.a * g2x - g1y * 2.0 * m.a
    size2 = g1x * g1x + g1y * g1y
    size3 = size2 * np.sqrt(size2)
    return -cross / size3, -cross1 / size3 + 3.0 * cross * (g1x * m.v + g1y * m.a) / (size3 * size2)


def _sharpest(prog: Any, grid: np.ndarray, prime: np.ndarray, e: np.ndarray) -> np.ndarray:
    """The largest convex curvature [1/m] of each design's pitch curve: its largest samples on ``grid``, each
    refined where its slope changes sign between the sample's neighbours by the Illinois method on dk/dtheta = 0
    (module docstring)."""
    sampled = _curvature(prog, grid[None, :], prime[:, None], e[:, None])[0]
    lo, _, hi = _peaks(sampled, grid)
    prime, e = prime[:, None], e[:, None]
    f_lo, f_hi = _curvature(prog, lo, prime, e)[1], _curvature(prog, hi, prime, e)[1]
    bracketed = (f_lo > 0) & (f_hi < 0)
    for _ in range(SECANT_STEPS):
        with np.errstate(divide="ignore", invalid="ignore"):
            x = np.where(bracketed, (lo * f_hi - hi * f_lo) / (f_hi - f_lo), lo)
        x = np.where(np.isfinite(x), np.clip(x, lo, hi), lo)
        f = _curvature(prog, x, prime, e)[1]
        left = f < 0  # the root lies in [lo, x]
        lo, f_lo, hi, f_hi = (np.where(left, lo, x), np.where(left, f_lo * 0.5, f), np.where(left, x, hi),
                              np.where(left, f, f_hi * 0.5))
    refined = np.where(bracketed, _curvature(prog, x, prime, e)[0], -np.inf)
    return np.maximum(np.max(sampled, axis=1), np.max(refined, axis=1))


#: the local maxima refined per design: the largest of a cam's lies in one of its few rises and returns, and two
#: of them may come within a sample's error of each other (a rise and a return of equal lift)
CANDIDATES = 4


def _peaks(values: np.ndarray, grid: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(N, CANDIDATES) angles [rad] of each design's largest local maxima of ``values`` (N, K) on ``grid``, with
    their neighbours below and above (the bracket a search refines them in)."""
    k_all = np.arange(grid.size)
    before, after = values[:, np.maximum(k_all - 1, 0)], values[:, np.minimum(k_all + 1, grid.size - 1)]
    local = np.where((values >= before) & (values >= after), values, -np.inf)
    count = min(CANDIDATES, grid.size)
    k = np.argpartition(-local, count - 1, axis=1)[:, :count]
    return grid[np.maximum(k - 1, 0)], grid[k], grid[np.minimum(k + 1, grid.size - 1)]
