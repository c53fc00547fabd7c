"""Path generation: four-bars whose coupler point passes through given points, with or without prescribed
timing (the crank's rotation between the points).

Three points: closed form. The coupler's rotations alpha_2, alpha_3 become free choices and each dyad follows
from the standard form (:mod:`machdyn.synthesis.dyads`): with prescribed timing the crank dyad's rotations
beta_j are the given ones and the rocker dyad's gamma_j are free (Norton, *Design of Machinery*, 5th ed., ch. 5,
"path generation with prescribed timing"; Erdman, Sandor & Kota, *Mechanism Design*, ch. 8); without timing
the beta_j are free too.

More points: the residuals P(phi_j) - target_j over the linkage's nine dimensions and the crank angles (one per
point without timing; one start angle with timing) are driven to zero by :func:`scipy.optimize.least_squares`,
started from closed-form three-point solutions through the first, middle and last targets (each seed's crank
angles at the other targets from the nearest point of its coupler curve). A four-bar's coupler curve can pass
through up to nine points (Alt, Burmester); a solution with residual below 1e-12 of the task's size is exact to
rounding, others carry their error.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import numpy as np

from ..errors import InputError
from .candidate import Candidate
from .dyads import solve
from .motion import _scale, four_bar_from_dyads


def three_points(points: Any, *, timing: tuple[float, float] | None = None, count: int = 200, seed: int = 0,
                 max_length: float | None = None, min_length: float | None = None) -> list[Candidate]:
    """Up to ``count`` four-bars whose coupler point passes the three ``points`` [m] (complex); ``timing`` =
    (beta_2, beta_3) [rad], the crank's rotations from the first point, or None."""
    p = np.asarray(points, dtype=complex)
    if p.size != 3:
        raise InputError(f"Closed-form path generation takes 3 points; got {p.size}.")
    rng = np.random.default_rng(seed)
    scale = _scale(p)
    hi = 5.0 * scale if max_length is None else float(max_length)
    lo = 0.02 * scale if min_length is None else float(min_length)
    out: list[Candidate] = []
    tries = 0
    while len(out) < count and tries < 50 * count:
        tries += 1
        alpha = np.cumsum(rng.uniform(-np.radians(60), np.radians(60), 2))
        angles = np.concatenate([[0.0], alpha])
        if timing is not None:
            betas = np.asarray(timing, dtype=float)
        else:
            sign = rng.choice([-1, 1])
            b2 = sign * rng.uniform(np.radians(20), np.radians(150))
            betas = np.array([b2, b2 + sign * rng.uniform(np.radians(20), np.radians(150))])
        sign = rng.choice([-1, 1])
        g2 = sign * rng.uniform(np.radians(5), np.radians(120))
        gammas = np.array([g2, g2 + sign * rng.uniform(np.radians(5), np.radians(120))])
        crank, rocker = solve(p, angles, betas), solve(p, angles, gammas)
        if crank is None or rocker is None:
            continue
        cand = four_bar_from_dyads(crank, rocker, angles, method="path, three points" + (
            " with timing" if timing is not None else ""), free={"alpha": tuple(float(a) for a in alpha),
                                                                 "crank_beta": tuple(float(b) for b in betas),
                                                                 "rocker_beta": tuple(float(g) for g in gammas)})
        lengths = np.array(list(cand.lengths().values()))
        if lengths.max() > hi or lengths.min() < lo:
            continue
        out.append(cand)
    return out


def _params(c: Candidate) -> np.ndarray:
    return np.array([c.origin.real, c.origin.imag, c.crank, c.coupler, c.rocker, c.ground, c.ground_angle,
                     c.coupler_point[0], c.coupler_point[1]])


def _from_params(x: np.ndarray, like: Candidate) -> Candidate:
    return replace(like, origin=complex(x[0], x[1]), crank=float(x[2]), coupler=float(x[3]), rocker=float(x[4]),
                   ground=float(x[5]), ground_angle=float(x[6]), coupler_point=(float(x[7]), float(x[8])))


def refine(seed: Candidate, points: Any, *, timing: Any = None, tol: float = 1e-13, max_nfev: int = 250,
           transmission_limit: float = 0.0, full_turn: bool = False) -> tuple[Candidate, float]:
    """The seed's dimensions and crank angles adjusted by least squares until its coupler point passes the
    ``points`` [m] (complex); ``timing`` = crank rotations from the first point [rad] (N - 1 values) or None.

    With ``transmission_limit`` [rad] > 0 the residuals also hold the shortfall of the transmission angle below
    the limit at 8 crank angles between consecutive points (or over a full turn with ``full_turn``): where the
    points leave freedom (fewer than nine), the fit moves along it to a linkage that transmits well. Returns the
    candidate and its largest distance from a target [m]."""
    from scipy.optimize import least_squares

    p = np.asarray(points, dtype=complex)
    scale = _scale(p)
    curve_phi = np.linspace(0.0, 2 * np.pi, 720, endpoint=False)
    curve = seed.point(curve_phi)
    ok = np.isfinite(curve)
    if not ok.any():
        return seed, np.inf
    near = np.array([curve_phi[ok][np.argmin(np.abs(curve[ok] - q))] for q in p])
    near = near[0] + seed.direction * np.mod(seed.direction * (near - near[0]), 2 * np.pi)  # in the seed's order
    t = None if timing is None else np.concatenate([[0.0], np.asarray(timing, dtype=float)])
    if t is not None and t.size != p.size:
        raise InputError(f"The timing needs one crank rotation per point after the first: {p.size - 1}; got "
                         f"{t.size - 1}.")
    x0 = np.concatenate([_params(seed), near if t is None else near[:1]])

    def phis(x):
        return x[9:] if t is None else x[9] + t

    branch = seed.branch
    between = np.linspace(0.0, 1.0, 8, endpoint=False)[1:]
    turn = np.linspace(0.0, 2 * np.pi, 36, endpoint=False)

    def shortfall(x, phi):
        if full_turn:
            q = phi[0] + turn
        else:
            q = (phi[:-1, None] + np.diff(phi)[:, None] * between[None, :]).ravel()
        o2 = x[0] + 1j * x[1]
        length = np.abs(o2 + x[5] * np.exp(1j * x[6]) - o2 - x[2] * np.exp(1j * q))
        cos_mu = (x[3] ** 2 + x[4] ** 2 - length**2) / (2.0 * x[3] * x[4])
        mu = np.arccos(np.clip(np.abs(cos_mu), 0.0, 1.0)) - np.maximum(np.abs(cos_mu) - 1.0, 0.0)
        return np.maximum(transmission_limit - mu, 0.0)

    def residual(x):  # the closure of Candidate.joints, written out for speed
        phi = phis(x)
        o2 = x[0] + 1j * x[1]
        a = o2 + x[2] * np.exp(1j * phi)
        r = o2 + x[5] * np.exp(1j * x[6]) - a
        L = np.abs(r)
        cos_g = (x[3] ** 2 + L**2 - x[4] ** 2) / (2.0 * x[3] * L)
        ab = np.exp(1j * (np.angle(r) + branch * np.arccos(np.clip(cos_g, -1.0, 1.0))))
        e = a + (x[7] + 1j * x[8]) * ab - p
        e = np.where(np.abs(cos_g) <= 1.0, e, e + 10.0 * scale * (np.abs(cos_g) - 1.0))
        rows = [e.real / scale, e.imag / scale]
        if transmission_limit > 0.0:
            rows.append(0.1 * shortfall(x, phi))
        return np.concatenate(rows)

    sol = least_squares(residual, x0, method="trf", xtol=tol, ftol=tol, gtol=tol, max_nfev=max_nfev)
    x = sol.x
    if min(x[2], x[3], x[4], x[5]) <= 0:
        return seed, np.inf
    out = _from_params(x, seed)
    phi = phis(x)
    steps = np.diff(phi)
    direction = 1 if np.sum(np.mod(steps, 2 * np.pi) < np.pi) >= steps.size / 2 else -1
    out = replace(out, angles=np.asarray(phi, dtype=float), direction=direction,
                  method=seed.method.replace("three points", f"{p.size} points, least squares"))
    err = float(np.max(np.abs(out.point(phi) - p)))
    return out, err if np.isfinite(err) else np.inf


def path_candidates(points: Any, *, timing: Any = None, count: int = 60, seed: int = 0, seeds: int | None = None,
                    max_length: float | None = None, min_length: float | None = None,
                    transmission_limit: float = 0.0, full_turn: bool = False) -> list[Candidate]:
    """Four-bars whose coupler point passes the ``points`` [m] (complex; 3 or more), with ``timing`` (crank
    rotations from the first point [rad]) or without. Three points: :func:`three_points`; more: ``seeds``
    (default ``count``) closed-form seeds through the first, middle and last point refined by :func:`refine`,
    the exact ones (error < 1e-9 of the task's size) kept, or when there is none the closest ones (each
    candidate's error is reported by :mod:`.defects`); ``transmission_limit`` and ``full_turn`` as
    :func:`refine`."""
    p = np.asarray(points, dtype=complex)
    if p.size < 3:
        raise InputError(f"Path generation needs at least 3 points; got {p.size}.")
    if p.size == 3:
        return three_points(p, timing=None if timing is None else tuple(timing), count=count, seed=seed,
                            max_length=max_length, min_length=min_length)
    mid = p.size // 2
    t = None if timing is None else np.asarray(timing, dtype=float)
    pick = [0, mid, p.size - 1]
    seed_timing = None if t is None else (float(t[mid - 1]), float(t[-1]))
    starts = three_points(p[pick], timing=seed_timing, count=seeds or count, seed=seed, max_length=max_length,
                          min_length=min_length)
    scale = _scale(p)
    hi = 5.0 * scale if max_length is None else float(max_length)
    lo = 0.02 * scale if min_length is None else float(min_length)
    out: list[Candidate] = []
    near: list[tuple[float, Candidate]] = []
    for s in starts:
        cand, err = refine(s, p, timing=t, transmission_limit=transmission_limit, full_turn=full_turn)
        lengths = np.array(list(cand.lengths().values()))
        if not (np.isfinite(err) and lengths.max() <= hi and lengths.min() >= lo):
            continue
        if err < 1e-9 * scale:
            out.append(cand)
        else:
            near.append((err, cand))
        if len(out) >= count:
            break
    if not out:  # no exact linkage (more points than the fit can pass, or timing too strict): the closest ones
        out = [c for _, c in sorted(near, key=lambda e: e[0])[:count]]
    return out
