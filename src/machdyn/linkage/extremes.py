"""Locating the extreme of a function of the crank angle to full precision, using the engine's vectorisation:
sample, then re-sample ever finer around the best sample.

The engine is closed form: a series (the driving torque, a joint's force) can be evaluated at any crank angle,
not only at the sampled ones. The largest value of a sampled series misses the true peak by up to the series'
change over half a step, and by more where a load table has a breakpoint or an active window an edge between
two samples (a punch force that starts between samples). :func:`refine` takes the sampled extremes of many
series at once, adds the loads' breakpoints (:func:`breakpoints`), and closes in on each between the neighbours
of its best candidates; :func:`refine_extreme` does it for one smooth function. Source of the method: a
uniform-grid (zooming) search, Press, Teukolsky, Vetterling & Flannery, *Numerical Recipes*, 3rd ed., §10.1
(bracketing) and §10.2 (golden-section search, of which the zooming grid is the many-point form), valid for a
function continuous between the breakpoints given; at a step (a window's edge) the edge itself is a candidate.

Each level evaluates ``points`` angles spanning two steps of the previous level around its best sample, so
the bracket shrinks by (points - 1)/2 per level; four levels of 41 points take a 3600-sample grid to an angle
resolution below 1e-9 rad, where the value of a smooth extreme is exact to rounding (its error is second
order in the angle error). One vectorised call per level: cheaper than a scalar optimiser's many calls.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence

import numpy as np

from .model import Mechanism


def refine_extreme(
    func: Callable[[np.ndarray], np.ndarray],
    grid: np.ndarray,
    values: np.ndarray,
    pick: str = "max",
    *,
    levels: int = 4,
    points: int = 41,
) -> tuple[float, float]:
    """The maximum (``pick='max'``) or minimum of ``func`` near its best sample, to full precision.

    Each level evaluates ``points`` angles spanning two steps of the previous level around its best sample, so the
    bracket shrinks by (points − 1)/2 per level. Valid for a smooth function whose extreme lies within one grid step
    of the best sample.

    Parameters
    ----------
    func : callable
        Maps an array of crank angles [rad] to values [any unit].
    grid : numpy.ndarray
        A uniform first sampling of crank angles [rad].
    values : numpy.ndarray
        ``func(grid)`` [any unit].
    pick : str
        'max' or 'min'.
    levels : int
        Refinement levels [-].
    points : int
        Angles per level [-].

    Returns
    -------
    tuple of float
        (angle [rad], value [unit of func]).

    Examples
    --------
    >>> import numpy as np
    >>> grid = np.linspace(0.0, 2.0 * np.pi, 36, endpoint=False)
    >>> [round(v, 9) for v in refine_extreme(lambda x: np.sin(x - 0.3), grid, np.sin(grid - 0.3))]
    [1.870796609, 1.0]
    """
    if pick not in ("max", "min"):
        raise ValueError(f"pick must be 'max' or 'min'; got {pick!r}")
    best = np.argmax if pick == "max" else np.argmin
    i = int(best(values))
    x, v = float(grid[i]), float(values[i])
    step = float(grid[1] - grid[0])
    for _ in range(levels):
        local = x + np.linspace(-step, step, points)
        local_values = np.asarray(func(local), dtype=float)
        j = int(best(local_values))
        candidate = float(local_values[j])
        if (candidate > v) if pick == "max" else (candidate < v):
            x, v = float(local[j]), candidate
        step = 2.0 * step / (points - 1)
    return x, v


#: Width [rad] of the crank-angle bracket at which the search stops: the value of a smooth extreme is then exact
#: to rounding (its error is of the order of the square of the angle's), and a kink's is a candidate itself.
ANGLE_TOL = 1e-8
#: Points per bracket in each pass (the bracket shrinks by (POINTS - 1) / 2 per pass).
POINTS = 17
#: Most passes (from a bracket of two steps of 360 positions, 8 passes reach ANGLE_TOL).
MAX_PASSES = 14
#: Sampled local extremes refined per series: the best few, for a second peak that the sampling undercut.
CANDIDATES = 3

#: How an extreme is told from a series: the value maximised.
_SENSE: dict[str, Callable[[np.ndarray], np.ndarray]] = {
    "max": lambda v: v,
    "min": lambda v: -v,
    "max_abs": np.abs,
}


def breakpoints(mech: Mechanism) -> np.ndarray:
    """The crank angles where a load of ``mech`` has a kink or a step.

    The edges of each active window and the angles of each tabulated load (any callable load value with an
    ``angles`` attribute, such as the force-stroke table's :class:`~machdyn.linkage.stroke_loads.PeriodicTable`).

    Parameters
    ----------
    mech : Mechanism
        The mechanism whose forces and torques are read.

    Returns
    -------
    numpy.ndarray
        The breakpoints [rad] in [0, 2 pi), sorted, each once.

    Examples
    --------
    >>> from machdyn.linkage import PointForce, slider_crank
    >>> import dataclasses, math
    >>> press = dataclasses.replace(slider_crank(0.04, 0.25), forces=(
    ...     PointForce("punch", "slider.B", 0.0, 6e4, (math.radians(250), math.radians(270))),))
    >>> [round(math.degrees(a), 6) for a in breakpoints(press)]
    [250.0, 270.0]
    """
    out: list[float] = []
    for load in (*mech.forces, *mech.torques):
        active = getattr(load, "active", None)
        if active is not None and active[1] - active[0] < 2 * math.pi:
            out += [float(active[0]), float(active[1])]
        for value in (getattr(load, "fx", None), getattr(load, "fy", None), getattr(load, "torque", None)):
            angles = getattr(value, "angles", None)
            if angles is not None:
                out += [float(a) for a in angles]
    return np.unique(np.mod(np.asarray(out, dtype=float), 2 * math.pi))


def refine(evaluate: Callable[[np.ndarray], Mapping[str, np.ndarray]], phi: np.ndarray,
           sampled: Mapping[str, tuple[np.ndarray, str]], kinks: Sequence[float] | np.ndarray = (), *,
           periodic: bool = True) -> dict[str, float]:
    """The exact extreme of each of several sampled series, between the samples and at the loads' breakpoints.

    For each series the best :data:`CANDIDATES` local extremes among the samples and the breakpoints are
    bracketed by their neighbours; each pass evaluates :data:`POINTS` angles across every bracket (all series
    in one call of ``evaluate``) and keeps the best point and its neighbours, until the bracket is narrower than
    :data:`ANGLE_TOL`. The value kept is the most extreme ever evaluated, so it is never less extreme than the
    samples.

    Parameters
    ----------
    evaluate : callable
        Maps crank angles [rad] to ``{name: values}`` [any unit], every series of ``sampled`` at those angles.
    phi : numpy.ndarray
        The sampled crank angles [rad], increasing.
    sampled : mapping
        ``name -> (values at phi, extreme)``, extreme "max", "min" or "max_abs".
    kinks : sequence of float
        The loads' breakpoints [rad] (:func:`breakpoints`).
    periodic : bool
        Whether ``phi`` covers one turn (else the search stays within [phi[0], phi[-1]]).

    Returns
    -------
    dict
        ``name -> extreme`` [unit of the series]: the largest value, the smallest or the largest magnitude; a
        series with no finite sample is left out.

    Examples
    --------
    >>> import numpy as np
    >>> phi = np.linspace(0.0, 2 * np.pi, 12, endpoint=False)
    >>> got = refine(lambda x: {"s": np.sin(x - 0.3)}, phi, {"s": (np.sin(phi - 0.3), "max")})
    >>> round(got["s"], 12)
    1.0
    """
    phi = np.asarray(phi, dtype=float)
    lo, hi = float(phi.min()), float(phi.max())
    if periodic:
        extra = np.asarray(kinks, dtype=float)
        extra = lo + np.mod(extra - lo, 2 * math.pi)
    else:
        extra = np.asarray([k for k in np.asarray(kinks, dtype=float)
                            for k in (lo + np.mod(k - lo, 2 * math.pi),) if k <= hi])
    grid = np.unique(np.concatenate([phi, extra]))
    at_kinks = evaluate(extra) if extra.size else {}
    best: dict[str, float] = {}
    brackets: dict[str, list[tuple[float, float]]] = {}
    for name, (values, how) in sampled.items():
        sense = _SENSE[how]
        score = np.full(grid.shape, -np.inf)
        score[np.searchsorted(grid, phi)] = np.where(np.isfinite(values), sense(np.asarray(values, float)), -np.inf)
        if extra.size:
            score[np.searchsorted(grid, extra)] = np.where(np.isfinite(at_kinks[name]), sense(at_kinks[name]),
                                                           -np.inf)
        if not np.isfinite(score).any():
            continue
        best[name] = float(np.max(score))
        brackets[name] = [_bracket(grid, i, periodic) for i in _peaks(score, periodic)]
    for _ in range(MAX_PASSES):
        live = {n: b for n, b in brackets.items() if b}
        if not live:
            break
        layout = [(n, a, z) for n, bs in live.items() for a, z in bs]
        points = np.concatenate([np.linspace(a, z, POINTS) for _, a, z in layout])
        found = evaluate(points)
        for n in live:
            brackets[n] = []
        for k, (name, a, z) in enumerate(layout):
            score = _SENSE[sampled[name][1]](np.asarray(found[name][k * POINTS:(k + 1) * POINTS], dtype=float))
            score = np.where(np.isfinite(score), score, -np.inf)
            i = int(np.argmax(score))
            if not np.isfinite(score[i]):
                continue
            best[name] = max(best[name], float(score[i]))
            step = (z - a) / (POINTS - 1)
            if 2 * step > ANGLE_TOL:
                brackets[name].append((max(a, a + (i - 1) * step), min(z, a + (i + 1) * step)))
    return {name: (-v if sampled[name][1] == "min" else v) for name, v in best.items()}


def _peaks(score: np.ndarray, periodic: bool) -> list[int]:
    """The indices of the best :data:`CANDIDATES` local maxima of a sampled score that may hold the extreme: a
    local maximum whose value and larger step to a neighbour (what a smooth curve can rise above it between
    them) reach the best sample's value."""
    left = np.roll(score, 1)
    right = np.roll(score, -1)
    if not periodic:
        left[0], right[-1] = -np.inf, -np.inf
    local = np.flatnonzero((score >= left) & (score >= right) & np.isfinite(score))
    if not local.size:
        local = np.array([int(np.argmax(score))])
    with np.errstate(invalid="ignore"):
        rise = np.fmax(np.nan_to_num(score[local] - left[local], posinf=0.0),
                       np.nan_to_num(score[local] - right[local], posinf=0.0))
    best = float(np.max(score))
    hopeful = local[score[local] + rise >= best]
    return [int(i) for i in hopeful[np.argsort(score[hopeful])[::-1][:CANDIDATES]]]


def _bracket(grid: np.ndarray, i: int, periodic: bool) -> tuple[float, float]:
    """The crank angles of the neighbours of candidate ``i`` (through the end of the turn when periodic)."""
    n = grid.size
    if periodic:
        below = grid[i - 1] if i > 0 else grid[-1] - 2 * math.pi
        above = grid[i + 1] if i < n - 1 else grid[0] + 2 * math.pi
    else:
        below, above = grid[max(i - 1, 0)], grid[min(i + 1, n - 1)]
    return float(below), float(above)
