"""Motion generation: four-bars that carry a coupler through two to five given positions.

Each position is a point of the coupler P_j [m] and the coupler's angle theta_j [rad]. Dyads through the
positions come from the standard form (:mod:`machdyn.synthesis.dyads`: two and three positions, with their free
choices either given or sampled) or from Burmester theory (:mod:`machdyn.synthesis.burmester`: four positions,
the curves sampled; five, the Burmester points); two dyads make a four-bar, the first driven as the crank
(Norton, *Design of Machinery*, 5th ed., ch. 5; Erdman, Sandor & Kota, *Mechanism Design*, ch. 8).

Free choices are sampled from a seeded generator, so a task always gives the same candidates. Candidates whose
links are longer than ``max_length`` or shorter than ``min_length`` [m] are left out.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import InputError
from .burmester import curves, points_five
from .candidate import Candidate, four_bar_from_points
from .dyads import Dyad, solve, two_positions, with_ground_pivot


def four_bar_from_dyads(crank: Dyad, rocker: Dyad, angles: Any, *, method: str, free: dict | None = None
                        ) -> Candidate:
    """The four-bar of a crank dyad and a rocker dyad built for the same positions (coupler ``angles`` [rad])."""
    a1, b1 = crank.moving_pivot, rocker.moving_pivot
    phi = np.angle(crank.w) + crank.beta
    first = float(np.mod(crank.beta[1], 2 * np.pi)) if crank.beta.size > 1 else 0.0
    direction = 1 if first < np.pi else -1
    offset = float(np.asarray(angles, dtype=float)[0] - np.angle(b1 - a1))
    return four_bar_from_points(crank.ground_pivot, a1, b1, rocker.ground_pivot, crank.p1, phi, direction=direction,
                                coupler_offset=offset, free=dict(free or {}), method=method)


def _crank_turns(crank: Dyad, rocker: Dyad) -> bool:
    """True if the four-bar of the two dyads is Grashof with the crank shortest (its crank turns fully)."""
    links = np.array([abs(crank.w), abs(rocker.moving_pivot - crank.moving_pivot), abs(rocker.w),
                      abs(rocker.ground_pivot - crank.ground_pivot)])
    s, l_ = links.min(), links.max()
    return bool(links[0] <= s and s + l_ <= links.sum() - s - l_)


def _scale(points: np.ndarray) -> float:
    span = float(np.max(np.abs(points - points.mean()))) if points.size > 1 else 0.0
    return span if span > 0 else 1.0


def sampled_dyads(points: Any, angles: Any, count: int, rng: np.random.Generator,
                  betas: tuple[float, ...] | None = None, role: str = "crank") -> list[Dyad]:
    """Dyads through the positions: ``count`` samples of the free choices (two or three positions; the given
    ``betas`` instead, when not None), the sampled Burmester curves (four) or the Burmester points (five).

    For two and three positions a ``role`` "crank" dyad turns one way by 10 to 160 deg between positions, a
    "rocker" dyad swings by at most 70 deg either way (what a crank-rocker's links do)."""
    p = np.asarray(points, dtype=complex)
    t = np.asarray(angles, dtype=float)
    n = p.size
    if n == 2:
        scale = _scale(p)
        out = []
        for _ in range(count):
            z = scale * rng.uniform(0.3, 1.5) * np.exp(1j * rng.uniform(-np.pi, np.pi))
            b2 = betas[0] if betas else rng.choice([-1, 1]) * rng.uniform(np.radians(15), np.radians(150))
            out.append(two_positions(p, t, z, b2))
        return out
    if n == 3:
        if betas is not None:
            d = solve(p, t, betas)
            return [] if d is None else [d]
        out = []
        tries = 0
        while len(out) < count and tries < 50 * count:  # a degenerate task gives no dyad for any choice
            tries += 1
            sign = rng.choice([-1, 1])
            if role == "crank":
                b2 = sign * rng.uniform(np.radians(10), np.radians(160))
                b3 = b2 + sign * rng.uniform(np.radians(10), np.radians(160))
            else:
                b2, b3 = rng.uniform(-np.radians(70), np.radians(70), 2)
            d = solve(p, t, [b2, b3])
            if d is not None:
                out.append(d)
        return out
    if n == 4:
        return curves(p, t, samples=max(8, count)).dyads(p)
    if n == 5:
        return points_five(p, t)
    raise InputError(f"Motion generation takes 2 to 5 positions; got {n}.")


def motion_candidates(points: Any, angles: Any, *, count: int = 200, seed: int = 0,
                      crank_betas: tuple[float, ...] | None = None, rocker_betas: tuple[float, ...] | None = None,
                      max_length: float | None = None, min_length: float | None = None,
                      method: str | None = None, crank_pivot: complex | None = None,
                      rocker_pivot: complex | None = None) -> list[Candidate]:
    """Up to ``count`` four-bars through the positions (points [m] complex, coupler angles [rad]).

    ``crank_betas`` / ``rocker_betas`` fix the free rotations of the crank's / rocker's dyad (three positions);
    ``crank_pivot`` / ``rocker_pivot`` [m] fix its ground pivot instead (three positions,
    :func:`~machdyn.synthesis.dyads.with_ground_pivot`); otherwise the free choices are sampled. Links outside
    [min_length, max_length] [m] (default 2 % and 5 times the size of the task) are refused."""
    p = np.asarray(points, dtype=complex)
    t = np.asarray(angles, dtype=float)
    rng = np.random.default_rng(seed)
    scale = _scale(p)
    hi = 5.0 * scale if max_length is None else float(max_length)
    lo = 0.02 * scale if min_length is None else float(min_length)
    pool = max(8, int(np.sqrt(count)) * 4)
    if (crank_pivot is not None or rocker_pivot is not None) and p.size != 3:
        raise InputError(f"Ground pivots can be prescribed for three positions; got {p.size} positions.")
    cranks = sampled_dyads(p, t, pool, rng, crank_betas, role="crank")
    rockers = cranks if (rocker_betas is None and p.size >= 4) else sampled_dyads(p, t, pool, rng, rocker_betas,
                                                                                  role="rocker")
    for pivot, side in ((crank_pivot, "crank"), (rocker_pivot, "rocker")):
        if pivot is not None:
            fixed = with_ground_pivot(p, t, complex(pivot))
            if fixed is None:
                raise InputError(f"No dyad through the three positions has its ground pivot at the {side} pivot "
                                 f"({complex(pivot).real:.6g}, {complex(pivot).imag:.6g}) m (a pole of the "
                                 "positions); move it.")
            if side == "crank":
                cranks = [fixed]
            else:
                rockers = [fixed]
    name = method or {2: "two positions", 3: "three positions", 4: "Burmester, four positions",
                      5: "Burmester, five positions"}[p.size]
    if crank_pivot is not None or rocker_pivot is not None:
        name += ", given ground pivots"
    pairs = [(i, j) for i in range(len(cranks)) for j in range(len(rockers)) if cranks[i] is not rockers[j]]
    order = rng.permutation(len(pairs))
    # Pairs whose crank can turn fully (Grashof, crank shortest) first: the cheap part of the defect check.
    turns = np.array([_crank_turns(cranks[i], rockers[j]) for i, j in pairs], dtype=bool)
    order = np.concatenate([order[turns[order]], order[~turns[order]]])
    out: list[Candidate] = []
    for k in order:
        i, j = pairs[k]
        c, r = cranks[i], rockers[j]
        if abs(c.ground_pivot - r.ground_pivot) < 1e-9 * scale:
            continue
        cand = four_bar_from_dyads(c, r, t, method=name,
                                   free={"crank_beta": tuple(float(b) for b in c.beta[1:]),
                                         "rocker_beta": tuple(float(b) for b in r.beta[1:])})
        lengths = np.array(list(cand.lengths().values()))
        if lengths.max() > hi or lengths.min() < lo:
            continue
        out.append(cand)
        if len(out) >= count:
            break
    return out
