"""A follower motion given as a table: a quintic spline through the designer's points of one rise.

The designer gives interior points (x_i, y_i) of a rise, x the fraction of the segment's cam angle and y the
fraction of its lift, both in (0, 1) for x; the law adds the ends (0, 0) and (1, 1) and passes the interpolating
B-spline of degree 5 through all of them with y' = y'' = 0 at both ends (:func:`scipy.interpolate.make_interp_spline`
with ``bc_type`` giving the first and second derivatives; C. de Boor, *A Practical Guide to Splines*, rev. ed.,
Springer 2001, ch. IX and XIII). A spline of degree 5 has continuous derivatives up to the fourth, so the
displacement, velocity, acceleration and jerk are continuous inside the segment, and with the zero end
velocity and acceleration it joins dwells without a jump (Norton, *Design of Machinery*, 5th ed., ch. 8, the
fundamental law of cam design). A return uses the same y, falling.

Validity: at least one interior point, x strictly increasing in (0, 1); y is not forced to stay in [0, 1] or to
rise monotonically (a designer's overshoot shows in the program's plots and checks).
"""

from __future__ import annotations

from collections.abc import Callable
from functools import cache

import numpy as np

from ..errors import InputError

Values = tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]


def check_points(points, field: str) -> None:
    """Raise :class:`InputError` naming ``field`` unless the points make a table law (module docstring)."""
    pts = np.asarray(points, dtype=float)
    if pts.ndim != 2 or pts.shape[0] < 1 or pts.shape[1] != 2:
        raise InputError(f"{field} must give at least one interior point [x, y] (fractions of the segment's angle "
                         f"and lift) for the 'table' law; got {len(points)}.")
    if not np.isfinite(pts).all():
        raise InputError(f"{field} must be finite numbers; got {pts.tolist()}.")
    x = pts[:, 0]
    if not (np.all(x > 0.0) and np.all(x < 1.0) and np.all(np.diff(x) > 0.0)):
        raise InputError(f"{field}: the x of the points (fractions of the segment's angle) must increase strictly "
                         f"inside (0, 1); got {x.tolist()}.")


@cache
def table_law(points: tuple[tuple[float, float], ...]) -> Callable[[np.ndarray], Values]:
    """The normalised law (y, y', y'', y''') of the interior ``points`` [-] (module docstring).

    >>> f = table_law(((0.5, 0.5),))
    >>> [round(float(v), 9) for v in f(np.array([0.0, 0.5, 1.0]))[0]]
    [0.0, 0.5, 1.0]
    """
    check_points(points, "points")
    from scipy.interpolate import make_interp_spline

    pts = np.asarray(points, dtype=float)
    x = np.concatenate([[0.0], pts[:, 0], [1.0]])
    y = np.concatenate([[0.0], pts[:, 1], [1.0]])
    ends = [(1, 0.0), (2, 0.0)]
    if x.size < 3:  # pragma: no cover - check_points needs one interior point
        raise InputError("A table law needs at least one interior point.")
    spline = make_interp_spline(x, y, k=5, bc_type=(ends, ends))
    d1, d2, d3 = spline.derivative(1), spline.derivative(2), spline.derivative(3)

    def law(t: np.ndarray) -> Values:
        return spline(t), d1(t), d2(t), d3(t)

    return law
