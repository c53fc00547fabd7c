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
refined likewise, by a golden-section search for the largest convex curvature -(G1 x G2)/|G1|^3 between the
neighbours of its largest sample (the run's :func:`.exact.extremes` does the same search design by design). The
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
    if f.contact == "roller":  # the run's build refuses a roller that undercuts the drawn profile
        drawn = analyse_population(model.program, cam_angles(problem.cam.positions), rb, rr, e, 1.0, limit)
        valid &= ~(drawn.min_pitch_curvature_radius <= rr)
    grid = segment_angles(model.program)
    pop = analyse_population(model.program, grid, rb, rr, e, 1.0, limit)
    rho = pop.min_pitch_curvature_radius
    largest = _refined(model.program, grid, pop.pressure_angle, rb + rr, e)
    sharpest = _sharpest(model.program, grid, rb + rr, e)
    rho = np.where(sharpest > 0, 1.0 / np.where(sharpest > 0, sharpest, 1.0), np.inf)
    rho = np.minimum(pop.min_pitch_curvature_radius, rho)
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


#: golden-section steps: the bracket of two sample spacings shrinks to 0.618^60 ~ 3e-13 of itself
GOLDEN_STEPS = 60


def _curvature(prog: Any, theta: np.ndarray, prime: np.ndarray, e: np.ndarray) -> np.ndarray:
    """The pitch curve's convex curvature -(G1 x G2)/|G1|^3 [1/m] at ``theta`` (broadcast with the designs)."""
    m = prog.svaj(theta)
    d = np.sqrt(prime**2 - e**2)
    g1x, g1y = d + m.s, m.v - e
    g2x, g2y = 2.0 * m.v - e, m.a - d - m.s
    return -(g1x * g2y - g1y * g2x) / np.hypot(g1x, g1y) ** 3


def _sharpest(prog: Any, grid: np.ndarray, prime: np.ndarray, e: np.ndarray) -> np.ndarray:
    """The largest convex curvature [1/m] of each design's pitch curve: its largest sample on ``grid``, refined by
    a golden-section search between the sample's neighbours (module docstring)."""
    sampled = _curvature(prog, grid[None, :], prime[:, None], e[:, None])
    lo, _, hi = _peaks(sampled, grid)
    prime, e = prime[:, None], e[:, None]
    ratio = (np.sqrt(5.0) - 1.0) / 2.0
    x1, x2 = hi - ratio * (hi - lo), lo + ratio * (hi - lo)
    f1, f2 = _curvature(prog, x1, prime, e), _curvature(prog, x2, prime, e)
    for _ in range(GOLDEN_STEPS):
        left = f1 >= f2  # the largest lies in [lo, x2]
        lo, hi = np.where(left, lo, x1), np.where(left, x2, hi)
        x1, x2, f1, f2 = (np.where(left, hi - ratio * (hi - lo), x2), np.where(left, x1, lo + ratio * (hi - lo)),
                          np.where(left, np.nan, f2), np.where(left, f1, np.nan))
        fresh = _curvature(prog, np.where(left, x1, x2), prime, e)
        f1, f2 = np.where(left, fresh, f1), np.where(left, f2, fresh)
    return np.maximum(np.max(sampled, axis=1), np.max(np.maximum(f1, f2), axis=1))


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
