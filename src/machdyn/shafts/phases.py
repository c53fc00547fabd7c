"""Crank phase angles of a multi-cylinder machine chosen to minimise its primary or secondary forces or couples.

The two-term primary and secondary forces and couples of an engine follow from its direct and reverse crank
resultants in closed form (:func:`machdyn.shafts.reciprocating.direct_reverse`): the largest resultant of an order
over the turn is w^2 (|D| + |R|) (Khurmi & Gupta, *Theory of Machines*, 14th ed., sec. 22.10-22.11). That makes
every candidate cheap, so the free phases are searched exhaustively on a grid (every combination of multiples of
``step``), the chosen objective first and the sum of all four (each relative to its largest over the grid)
breaking ties; objective ``all`` minimises that sum itself. The grid holds (2 pi / step)^k candidates for k free
cranks; it is limited to half a million.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np

from ..errors import InputError
from .reciprocating import Cylinder

__all__ = ["OBJECTIVES", "PhaseSearch", "search_phases", "two_term_peaks"]

OBJECTIVES = ("primary_force", "secondary_force", "primary_couple", "secondary_couple", "all")
MAX_CANDIDATES = 500_000


def two_term_peaks(cylinders: Sequence[Cylinder], phases: np.ndarray, speed: float,
                   reference: float = 0.0) -> np.ndarray:
    """Largest primary force, secondary force, primary couple and secondary couple [N, N, N m, N m] over the turn
    for each row of ``phases`` (candidates x cylinders, [rad]): shape (candidates, 4)."""
    p = np.asarray(phases, dtype=float)
    m = np.array([c.reciprocating_mass * c.crank for c in cylinders])
    n = np.array([c.ratio for c in cylinders])
    ax = np.array([c.axis for c in cylinders])
    z = np.array([c.position - reference for c in cylinders])
    out = []
    for weight in (np.ones_like(z), z):
        d1 = (m * weight / 2 * np.exp(1j * p)).sum(axis=-1)
        r1 = (m * weight / 2 * np.exp(1j * (2 * ax - p))).sum(axis=-1)
        d2 = (m * weight / (2 * n) * np.exp(1j * (2 * p - ax))).sum(axis=-1)
        r2 = (m * weight / (2 * n) * np.exp(1j * (3 * ax - 2 * p))).sum(axis=-1)
        out += [np.abs(d1) + np.abs(r1), np.abs(d2) + np.abs(r2)]
    return speed**2 * np.stack([out[0], out[1], out[2], out[3]], axis=-1)


@dataclass(frozen=True)
class PhaseSearch:
    """The search: names of the free cylinders, the objective, its best phases [rad], the four two-term peaks
    before (as given) and after [N, N, N m, N m], and the number of candidates tried."""

    free: tuple[str, ...]
    objective: str
    phases: dict
    before: np.ndarray
    after: np.ndarray
    candidates: int

    def cylinders(self, cylinders: Sequence[Cylinder]) -> tuple[Cylinder, ...]:
        return tuple(replace(c, phase=self.phases[c.name]) if c.name in self.phases else c for c in cylinders)


def search_phases(cylinders: Sequence[Cylinder], free: Sequence[str], objective: str, step: float, speed: float,
                  reference: float = 0.0) -> PhaseSearch:
    """Exhaustive grid search of the phases of the ``free`` cylinders (multiples of ``step`` [rad]) minimising
    ``objective`` (one of :data:`OBJECTIVES`)."""
    if objective not in OBJECTIVES:
        raise InputError(f"The objective must be one of {', '.join(OBJECTIVES)}; got {objective!r}.")
    names = [c.name for c in cylinders]
    unknown = [f for f in free if f not in names]
    if unknown or not free or len(set(free)) != len(free):
        raise InputError(f"The free cylinders must be distinct names of {names}; got {list(free)}.")
    if not 0 < step <= np.pi:
        raise InputError(f"The phase step must lie in (0, 180] deg; got {np.degrees(step):g} deg.")
    levels = int(round(2 * np.pi / step))
    if abs(levels * step - 2 * np.pi) > 1e-9:
        raise InputError(f"The phase step must divide 360 deg; got {np.degrees(step):g} deg.")
    count = levels ** len(free)
    if count > MAX_CANDIDATES:
        raise InputError(f"{len(free)} free cranks in steps of {np.degrees(step):g} deg make {count} candidates; at "
                         f"most {MAX_CANDIDATES} are searched: free fewer cranks or take a larger step.")
    grid = np.stack(np.meshgrid(*([np.arange(levels) * step] * len(free)), indexing="ij"), axis=-1)
    grid = grid.reshape(-1, len(free))
    base = np.array([c.phase for c in cylinders])
    phases = np.broadcast_to(base, (grid.shape[0], base.size)).copy()
    index = [names.index(f) for f in free]
    phases[:, index] = grid
    peaks = two_term_peaks(cylinders, phases, speed, reference)
    scale = np.maximum(peaks.max(axis=0), 1e-300)
    rel = peaks / scale
    total = rel.sum(axis=1)
    goal = total if objective == "all" else rel[:, OBJECTIVES.index(objective)]
    # the objective first (to round-off), then the others
    best_goal = goal.min()
    tied = np.flatnonzero(goal <= best_goal + 1e-9)
    best = int(tied[np.argmin(total[tied])])
    before = two_term_peaks(cylinders, base[None, :], speed, reference)[0]
    return PhaseSearch(tuple(free), objective, {f: float(phases[best, i]) for f, i in zip(free, index, strict=True)},
                       before, peaks[best], int(count))
