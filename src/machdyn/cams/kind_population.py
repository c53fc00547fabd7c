"""The population form of the ``[cam]`` kind (:attr:`machdyn.pipeline.ProblemKind.population`): the checks a run
of each design reports — the largest pressure angle, the smallest convex radius of curvature of the pitch curve
and of the cam surface, the smallest base circle meeting the pressure-angle limit — for N translating roller or
knife-edge cams at once, the designs differing in base radius, roller radius and offset.

The results are those of :func:`.population.analyse_population` (Norton, *Design of Machinery*, 5th ed.,
eq 8.31; the pitch curve's curvature of :mod:`.profile`), which finds the largest pressure angle and the smallest
radius of curvature exactly between samples on each segment's own closed form, as the single-design run's
:mod:`.exact` does, and the smallest base circle on the same grid: they agree with the run to rounding.

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
    pop = analyse_population(model.program, [], rb, rr, e, 1.0, limit)  # exact extremes; no per-angle table
    rho = pop.min_pitch_curvature_radius
    near = np.flatnonzero(valid & (rho <= rr))  # only these may undercut the drawn profile (exact <= drawn)
    if f.contact == "roller" and near.size:  # the run's build refuses a roller that undercuts the drawn profile
        drawn = analyse_population(model.program, cam_angles(problem.cam.positions), rb[near], rr[near], e[near],
                                   1.0, limit)
        valid[near] &= ~(drawn.min_pitch_curvature_radius <= rr[near])
    found = {"cam.max_pressure_angle": pop.max_pressure_angle,
             "cam.min_pitch_curvature_radius": rho,
             "cam.min_surface_curvature_radius": np.where(np.isfinite(rho), rho - rr, rho),
             "cam.min_base_radius_pressure": pop.min_base_radius_pressure, "cam.base_radius": rb,
             "cam.pressure_angle_limit": np.full(n, limit)}
    return {k: np.where(valid, found[k], np.nan) for k in wanted}


