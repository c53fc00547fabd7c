"""Inverse position: the crank angles at which an output (a slider's travel or a link's angle) takes a value.

The forward position of every dyad is closed form, so the output is a smooth function of the crank angle f(phi)
wherever the linkage assembles. Its inverse is found by sampling one crank range, refining the extrema of the
samples (scipy.optimize.minimize_scalar) so that no pair of roots near a turning point is lost, and solving
f(phi) = target with Brent's method (scipy.optimize.brentq) on every bracketed sign change. A target outside
the reachable range raises :class:`~machdyn.errors.InputError` with that range, never a silent NaN.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..errors import InputError, check_finite
from .kinematics import kinematics
from .model import Mechanism

_TWO_PI = 2.0 * np.pi


@dataclass(frozen=True)
class InversePosition:
    """Every crank angle [rad] in the crank range at which ``output`` equals each target.

    ``angles`` is shaped designs + targets + (solutions,), ascending along the last axis; a target with fewer
    solutions than the most has NaN after its ``count`` solutions (``count`` is shaped designs + targets).
    ``reachable`` = (lowest, highest) value of the output over the crank range [m or rad], one per design.
    """

    output: str
    target: np.ndarray
    angles: np.ndarray
    count: np.ndarray
    reachable: tuple[np.ndarray, np.ndarray]
    crank_range: tuple[float, float]


def inverse_position(
    mech: Mechanism,
    target,
    *,
    slider: str | None = None,
    body: str | None = None,
    crank_range: tuple[float, float] = (0.0, _TWO_PI),
    samples: int = 720,
) -> InversePosition:
    """The crank angles phi [rad] where a slider's travel s(phi) [m] or a body's angle theta(phi) [rad] equals
    ``target``: all solutions in ``crank_range``, for every target and every design variant.

    The forward position is the closed form of the dyads (:func:`~machdyn.linkage.kinematics.kinematics`);
    roots are bracketed by the sign changes of ``samples`` evenly spaced positions, with the extrema between
    samples refined first, and solved to ~1e-13 rad by Brent's method (Brent, *Algorithms for Minimization
    without Derivatives*, 1973, ch. 4, as scipy.optimize.brentq). Angles of a body are compared modulo 2 pi.

    Parameters
    ----------
    mech : Mechanism
        The linkage; its parameters may be arrays of N design variants.
    target : array_like
        The wanted slider travel [m] along its guide (as ``kinematics(...).slide(slider).s``) or body angle
        [rad] (as ``kinematics(...).body(body).angle``); any shape.
    slider, body : str
        Exactly one: the slider or block whose travel is given, or the body whose angle is given.
    crank_range : (start, end) [rad]
        The crank angles searched, at most one turn; a whole turn (the default) is treated as periodic and
        returns angles in [start, end).
    samples : int
        Sampled positions over the range (>= 16): at most one extremum of the output between two samples.

    Returns
    -------
    InversePosition

    Raises
    ------
    InputError
        A target out of reach (naming the reachable range and the design), neither or both of slider/body, an
        unknown name, a bad crank range or sample count.

    Examples
    --------
    The crank angles at which the piston of a slider-crank (crank 0.1 m, rod 0.3 m) is 0.3 m from the crank
    shaft, in degrees:

    >>> import numpy as np
    >>> from machdyn.linkage import slider_crank
    >>> sol = inverse_position(slider_crank(0.1, 0.3), 0.3, slider="slider")
    >>> np.round(np.degrees(sol.angles), 4).tolist(), int(sol.count)
    ([80.4059, 279.5941], 2)
    """
    if not isinstance(mech, Mechanism):
        raise InputError(f"inverse_position needs a Mechanism as its first argument; got {type(mech).__name__}.")
    if (slider is None) == (body is None):
        raise InputError("inverse_position needs exactly one of slider=... (a travel) or body=... (an angle).")
    targets = np.asarray(target, dtype=float)
    check_finite("target of inverse_position", targets)
    if int(samples) != samples or samples < 16:
        raise InputError(f"The number of samples of inverse_position must be an integer >= 16; got {samples!r}.")
    start, end = _crank_range(crank_range)
    periodic = end - start >= _TWO_PI - 1e-12
    n = int(samples)
    h = (end - start) / n
    # A whole turn is sampled one step beyond each end, so that an extremum or root at the seam is inside.
    grid = np.linspace(start - h, end + h, n + 3) if periodic else np.linspace(start, end, n + 1)
    is_angle = body is not None
    name = str(body if is_angle else slider)
    output = f"{name}.angle" if is_angle else f"{name}.s"

    def values(m: Mechanism, phi):
        kin = kinematics(m, phi, on_fail="mask")
        y = kin.body(name).angle if is_angle else kin.slide(name).s
        return np.where(kin.assembled, y, np.nan)

    sampled = np.atleast_2d(values(mech, grid))
    designs = mech.design_count
    flat = targets.ravel()
    per_design = []
    lows, highs = [], []
    for i in range(sampled.shape[0]):
        single = mech.take_designs(i) if designs is not None else mech

        def f(phi, single=single):
            return float(values(single, np.float64(phi)))

        roots, low, high = _solve_design(f, grid, sampled[i], flat, is_angle)
        for k, found in enumerate(roots):
            if not found:
                _out_of_reach(output, flat[k], low, high, is_angle, i if designs is not None else None, start, end)
        per_design.append([_fold(r, start, end, periodic) for r in roots])
        lows.append(low)
        highs.append(high)
    width = max((len(r) for d in per_design for r in d), default=0)
    angles = np.full((len(per_design), flat.size, width), np.nan)
    count = np.zeros((len(per_design), flat.size), dtype=int)
    for i, d in enumerate(per_design):
        for k, r in enumerate(d):
            angles[i, k, : len(r)] = r
            count[i, k] = len(r)
    lead = (designs,) if designs is not None else ()
    return InversePosition(
        output,
        targets,
        angles.reshape(lead + targets.shape + (width,)),
        count.reshape(lead + targets.shape),
        (np.asarray(lows).reshape(lead), np.asarray(highs).reshape(lead)),
        (start, end),
    )


def _crank_range(crank_range) -> tuple[float, float]:
    try:
        start, end = (float(v) for v in crank_range)
    except (TypeError, ValueError):
        raise InputError(f"The crank_range must be (start, end) in rad; got {crank_range!r}.") from None
    if not (np.isfinite(start) and np.isfinite(end)) or end <= start or end - start > _TWO_PI + 1e-9:
        raise InputError(
            f"The crank_range must be finite with start < end and span at most one turn (2 pi rad); got "
            f"({start!r}, {end!r})."
        )
    return start, min(end, start + _TWO_PI)


def _solve_design(f: Callable[[float], float], grid, y, targets, is_angle: bool):
    """Roots of f(phi) = each target for one design, and the reachable (low, high) of the output."""
    from scipy.optimize import brentq, minimize_scalar

    valid = np.isfinite(y)
    level = np.unwrap(np.where(valid, y, 0.0)) if is_angle else y  # angles continuous through +-pi
    phis, ys = list(grid), list(np.where(valid, level, np.nan))
    # Refine each interior extremum of the samples; the refined point joins the grid between its neighbours.
    extra_phi, extra_y = [], []
    for j in range(1, len(grid) - 1):
        if not (valid[j - 1] and valid[j] and valid[j + 1]):
            continue
        left, right = level[j] - level[j - 1], level[j + 1] - level[j]
        if not left * right < 0:
            continue
        sign = 1.0 if left > 0 else -1.0  # a maximum when rising then falling

        def objective(phi, sign=sign, ref=level[j]):
            value = f(phi)
            if is_angle:  # the same branch of the unwrapped angle as the sample
                value = ref + np.angle(np.exp(1j * (value - ref)))
            return -sign * value

        best = minimize_scalar(objective, bounds=(grid[j - 1], grid[j + 1]), method="bounded",
                               options={"xatol": 1e-12})
        if np.isfinite(best.fun):
            extra_phi.append(float(best.x))
            extra_y.append(-sign * float(best.fun))
    order = np.argsort(np.concatenate([phis, extra_phi]), kind="stable")
    phi_all = np.concatenate([phis, extra_phi])[order]
    y_all = np.concatenate([ys, extra_y])[order]
    ok = np.isfinite(y_all)
    if not np.any(ok):
        return [[] for _ in targets], np.nan, np.nan
    low, high = float(np.min(y_all[ok])), float(np.max(y_all[ok]))
    scale = max(high - low, abs(high), abs(low), 1e-300)
    tol = 1e-10 * scale
    results = []
    for t in targets:
        g = y_all - t
        if is_angle:
            g = np.angle(np.exp(1j * g))  # wrapped to (-pi, pi]: zero where the angle equals t modulo 2 pi
        found = [float(p) for p, gv, good in zip(phi_all, g, ok, strict=True) if good and abs(gv) <= tol]
        for j in range(len(phi_all) - 1):
            a, b = g[j], g[j + 1]
            if not (ok[j] and ok[j + 1]) or abs(a) <= tol or abs(b) <= tol or a * b >= 0:
                continue
            if is_angle and abs(a - b) > np.pi:  # the wrap of the difference, not a crossing
                continue

            def residual(phi, t=t):
                r = f(phi) - t
                return float(np.angle(np.exp(1j * r))) if is_angle else r

            found.append(float(brentq(residual, phi_all[j], phi_all[j + 1], xtol=1e-13)))
        results.append(found)
    span = float(np.max(level[valid]) - np.min(level[valid])) if is_angle else high - low
    if is_angle and span >= _TWO_PI:
        low, high = -np.pi, np.pi
    return results, low, high


def _fold(roots: list[float], start: float, end: float, periodic: bool) -> np.ndarray:
    """Roots mapped into [start, end) for a whole turn (into [start, end] otherwise), sorted, duplicates
    (the same root found from both sides of a sample) merged."""
    r = np.asarray(roots, dtype=float)
    if periodic:
        r = start + np.mod(r - start, _TWO_PI)
        r = np.where(r >= end - 1e-12, r - _TWO_PI, r)
        r = np.where(r < start, start, r)
    else:
        r = r[(r >= start - 1e-12) & (r <= end + 1e-12)]
    r = np.sort(r)
    if r.size:
        keep = np.concatenate([[True], np.diff(r) > 1e-9])
        r = r[keep]
        if periodic and r.size > 1 and r[-1] - r[0] > _TWO_PI - 1e-9:
            r = r[:-1]
    return r


def _out_of_reach(output, value, low, high, is_angle, design, start, end) -> None:
    where = f" of design {design}" if design is not None else ""
    crank = f"crank angles {np.degrees(start):.1f}°–{np.degrees(end):.1f}°"
    if not np.isfinite(low):
        raise InputError(f"The linkage{where} does not assemble anywhere in the {crank}; no {output} is reachable.")
    if is_angle:
        raise InputError(
            f"The target {output} {value:g} rad ({np.degrees(value):.4g}°) is out of reach{where}: over the "
            f"{crank} it spans {low:.6g} rad to {high:.6g} rad ({np.degrees(low):.4g}° to {np.degrees(high):.4g}°)."
        )
    raise InputError(
        f"The target {output} {value:g} m is out of reach{where}: over the {crank} it spans {low:.6g} m to "
        f"{high:.6g} m."
    )
