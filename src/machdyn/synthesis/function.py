"""Function generation: a four-bar whose rocker angle follows a prescribed function of its crank angle.

Freudenstein's equation (F. Freudenstein, "Approximate synthesis of four-bar linkages", *Trans. ASME* 77 (1955)
853-861; Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 4th ed., ch. 10, "Freudenstein's
equation"), with the crank pivot O2 at the origin and the rocker pivot O4 at (d, 0):

    K1 cos(theta4) - K2 cos(theta2) + K3 = cos(theta2 - theta4),
    K1 = d / a,   K2 = d / c,   K3 = (a^2 - b^2 + c^2 + d^2) / (2 a c),

with a, b, c, d the crank, coupler, rocker and ground lengths [m] and theta2, theta4 the absolute crank and rocker
angles [rad]. It is linear in K1..K3: three precision points give them exactly, more points in the least-squares
sense (Freudenstein's structural-error minimum); :func:`freudenstein_least_squares` can then refine the true
output-angle error with :func:`scipy.optimize.least_squares`. A negative a or c is a link pointing the other way:
its length is taken positive and its angle turned by pi.

Precision points are spaced over the input range with Chebyshev spacing (Uicker, Pennock & Shigley, ch. 10,
"Chebychev spacing": x_j = (x0 + x1)/2 - (x1 - x0)/2 cos((2j - 1) pi / (2n)), j = 1..n), which nearly minimises
the largest structural error between the points.

Valid for any angle pairs whose system is not singular and whose coupler length squared comes out positive; the
result may still have defects (branch, order, Grashof), which :mod:`machdyn.synthesis.defects` reports.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from typing import Any

import numpy as np

from ..errors import InputError
from .candidate import Candidate, four_bar_from_points, wrap

#: The functions a function-generation task may name: y = f(x).
FUNCTIONS: dict[str, Callable[[Any], Any]] = {
    "log10": np.log10, "ln": np.log, "exp": np.exp, "sqrt": np.sqrt, "square": np.square,
    "cube": lambda x: np.asarray(x) ** 3, "reciprocal": lambda x: 1.0 / np.asarray(x), "sin": np.sin,
    "cos": np.cos, "tan": np.tan,
}
#: Points at which a function is evaluated over its range to find where it overflows.
DOMAIN_SAMPLES = 1001


def undefined_in(name: str, x0: float, x1: float) -> str | None:
    """Where the function ``name`` is undefined or not finite over [x0, x1] (a message), None if it is finite
    there: a non-finite end, log10/ln/sqrt at x <= 0, the poles of 1/x (x = 0) and tan (x = pi/2 + k pi), and an
    overflow found by evaluating the function at :data:`DOMAIN_SAMPLES` points of the range."""
    if not (np.isfinite(x0) and np.isfinite(x1)):
        return f"the range must be finite numbers; got [{x0:g}, {x1:g}]"
    lo, hi = min(x0, x1), max(x0, x1)
    if name in ("log10", "ln", "sqrt") and lo <= 0:
        return f"{name}(x) is undefined at x <= 0 (the range must be > 0); got [{x0:g}, {x1:g}]"
    if name == "reciprocal" and lo <= 0 <= hi:
        return f"reciprocal(x) = 1/x is undefined at x = 0, inside the range [{x0:g}, {x1:g}]"
    if name == "tan":
        pole = np.pi / 2 + np.ceil((lo - np.pi / 2) / np.pi) * np.pi
        if pole <= hi:
            return f"tan(x) is undefined at x = {pole:.6g} (pi/2 + k pi), inside the range [{x0:g}, {x1:g}]"
    with np.errstate(all="ignore"):
        x = np.linspace(lo, hi, DOMAIN_SAMPLES)
        y = np.asarray(FUNCTIONS[name](x), dtype=float)
    bad = np.flatnonzero(~np.isfinite(y))
    if bad.size:
        return f"{name}(x) is not finite at x = {x[bad[0]]:.6g} ({y[bad[0]]:g}), inside the range [{x0:g}, {x1:g}]"
    return None


def chebyshev_spacing(start: float, stop: float, count: int) -> np.ndarray:
    """``count`` Chebyshev precision points over [start, stop] (any unit):
    x_j = (start + stop)/2 - (stop - start)/2 cos((2j - 1) pi / (2 count)), j = 1..count.

    >>> np.round(chebyshev_spacing(0.0, 1.0, 3), 4)
    array([0.067, 0.5  , 0.933])
    """
    if int(count) != count or count < 1:
        raise InputError(f"The number of precision points must be an integer >= 1; got {count!r}.")
    j = np.arange(1, int(count) + 1)
    return 0.5 * (start + stop) - 0.5 * (stop - start) * np.cos((2 * j - 1) * np.pi / (2 * int(count)))


def function_angles(func: Callable[[np.ndarray], np.ndarray], x_range: tuple[float, float],
                    input_range: tuple[float, float], output_range: tuple[float, float], x: Any) -> tuple[Any, Any]:
    """(theta2, theta4) [rad] of the function y = ``func``(x) at ``x``, mapped linearly: x_range -> crank
    angles ``input_range`` (start, stop) [rad], y(x_range) -> rocker angles ``output_range`` (start, stop) [rad]."""
    x0, x1 = x_range
    y0, y1 = float(func(np.asarray(x0))), float(func(np.asarray(x1)))
    if x1 == x0 or y1 == y0:
        raise InputError(f"The function must change over its range; got y({x0:g}) = {y0:g}, y({x1:g}) = {y1:g}.")
    xx = np.asarray(x, dtype=float)
    t2 = input_range[0] + (xx - x0) / (x1 - x0) * (input_range[1] - input_range[0])
    t4 = output_range[0] + (np.asarray(func(xx), dtype=float) - y0) / (y1 - y0) * (output_range[1] - output_range[0])
    return t2, t4


def coefficients(theta2: Any, theta4: Any) -> np.ndarray:
    """K1, K2, K3 of Freudenstein's equation through the angle pairs [rad]: exact for three, least squares
    (of the equation's residual) for more."""
    t2 = np.asarray(theta2, dtype=float)
    t4 = np.asarray(theta4, dtype=float)
    if t2.shape != t4.shape or t2.ndim != 1 or t2.size < 3:
        raise InputError(f"Function generation needs at least 3 pairs of input and output angles of one length; "
                         f"got {t2.size} and {t4.size}.")
    rows = np.stack([np.cos(t4), -np.cos(t2), np.ones_like(t2)], axis=1)
    rhs = np.cos(t2 - t4)
    if t2.size == 3:
        if abs(np.linalg.det(rows)) < 1e-12:
            raise InputError("The three precision points give a singular Freudenstein system (two input or two "
                             "output angles with equal cosines); move a precision point.")
        return np.linalg.solve(rows, rhs)
    k, *_ = np.linalg.lstsq(rows, rhs, rcond=None)
    return k


def from_coefficients(k: Any, theta2: Any, ground: float = 1.0, *, method: str = "freudenstein") -> Candidate:
    """The four-bar [m] of Freudenstein coefficients ``k`` with ground length ``ground`` [m] (the free scale),
    its crank angles at ``theta2`` [rad]. Raises :class:`InputError` when no real linkage has them."""
    k1, k2, k3 = (float(v) for v in k)
    if not (np.isfinite([k1, k2, k3]).all() and k1 != 0.0 and k2 != 0.0):
        raise InputError(f"No four-bar has the Freudenstein coefficients K1 = {k1:.6g}, K2 = {k2:.6g}, K3 = {k3:.6g}"
                         " (a zero K1 or K2 would need an infinite link).")
    d = float(ground)
    a, c = d / k1, d / k2
    b2 = a * a + c * c + d * d - 2.0 * a * c * k3
    if not b2 > 0.0:
        raise InputError(f"No four-bar has the Freudenstein coefficients K1 = {k1:.6g}, K2 = {k2:.6g}, "
                         f"K3 = {k3:.6g}: the coupler length squared is {b2:.6g} (must be > 0).")
    t2 = np.asarray(theta2, dtype=float)
    flip4 = np.pi if c < 0 else 0.0
    angles = t2 + (np.pi if a < 0 else 0.0)
    # The branch (which of the two closures) is set from the wanted output angle by the callers.
    return Candidate(kind="four_bar", origin=0j, crank=abs(a), coupler=float(np.sqrt(b2)), rocker=abs(c), ground=d,
                     ground_angle=0.0, coupler_point=(float(np.sqrt(b2)), 0.0), angles=angles,
                     direction=1 if t2[-1] >= t2[0] else -1, output_offset=-flip4, method=method,
                     free={"ground": d, "K1": k1, "K2": k2, "K3": k3, "input_offset": np.pi if a < 0 else 0.0})


def _branch_at(a1: complex, d: float, c: float, rocker_angle: float) -> int:
    b1 = d + c * np.exp(1j * rocker_angle)
    return four_bar_from_points(0j, a1, b1, d + 0j, b1, [0.0]).branch


def freudenstein(theta2: Any, theta4: Any, ground: float = 1.0) -> Candidate:
    """The four-bar whose rocker is at ``theta4`` [rad] when its crank is at ``theta2`` [rad] (three or more
    pairs; exact for three), with ground length ``ground`` [m]. See the module for the equation and sources."""
    t2 = np.asarray(theta2, dtype=float)
    t4 = np.asarray(theta4, dtype=float)
    k = coefficients(t2, t4)
    cand = from_coefficients(k, t2, ground, method="freudenstein" if t2.size == 3 else "freudenstein least squares")
    return _with_branch(cand, t4)


def _with_branch(cand: Candidate, theta4: np.ndarray) -> Candidate:
    a1 = cand.crank * np.exp(1j * cand.angles[0])
    branch = _branch_at(a1, cand.ground, cand.rocker, float(theta4[0]) - cand.output_offset)
    return replace(cand, branch=branch)


def output_error(cand: Candidate, theta2: Any, theta4: Any) -> np.ndarray:
    """The candidate's rocker angle minus the wanted ``theta4`` [rad] at the crank angles ``theta2`` [rad] of the
    task (NaN where it cannot assemble)."""
    # the crank's angle is the task's input angle, turned by pi where Freudenstein's crank length came out < 0
    phi = np.asarray(theta2, dtype=float) + float(cand.free.get("input_offset", 0.0))
    return wrap(cand.output_angle(phi) + cand.output_offset - np.asarray(theta4, dtype=float))


def freudenstein_least_squares(theta2: Any, theta4: Any, ground: float = 1.0, *, refine: bool = True) -> Candidate:
    """The four-bar through many (theta2, theta4) pairs [rad]: Freudenstein's linear least squares, then (with
    ``refine``) the output-angle error itself minimised over K1..K3 by :func:`scipy.optimize.least_squares`
    started from it (the refined result is kept only if its worst angle error is smaller)."""
    t2 = np.asarray(theta2, dtype=float)
    t4 = np.asarray(theta4, dtype=float)
    k0 = coefficients(t2, t4)
    best = _with_branch(from_coefficients(k0, t2, ground, method="freudenstein least squares"), t4)
    if not refine or t2.size <= 3:
        return best
    from scipy.optimize import least_squares

    def residual(k):
        try:
            c = _with_branch(from_coefficients(k, t2, ground), t4)
        except InputError:
            return np.full(t2.size, 10.0)
        e = output_error(c, t2, t4)
        return np.where(np.isfinite(e), e, 10.0)

    sol = least_squares(residual, k0, xtol=1e-14, ftol=1e-14, gtol=1e-14, max_nfev=400)
    try:
        refined = _with_branch(from_coefficients(sol.x, t2, ground, method="freudenstein least squares, refined"),
                               t4)
    except InputError:
        return best
    old = np.nanmax(np.abs(output_error(best, t2, t4)))
    new = np.abs(output_error(refined, t2, t4))
    return refined if np.isfinite(new).all() and new.max() < old else best
