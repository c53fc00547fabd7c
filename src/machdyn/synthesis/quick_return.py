"""Crank-rocker for a rocker swing and a time ratio, slider-crank for a stroke and a time ratio: closed form.

At the two limit positions of the output the crank and coupler are in line: stretched out (|O2 B1| = b + a) and
folded (|O2 B2| = b - a). Between them the crank turns 180 deg + delta one way and 180 deg - delta the other, so
the time ratio (slow stroke over fast stroke at constant crank speed) is

    Q = (180 deg + delta) / (180 deg - delta),     delta = 180 deg (Q - 1) / (Q + 1),

and the crank pivot O2 sees the chord B1 B2 under the angle delta: it lies on the circle through B1 and B2 on
which that chord subtends the inscribed angle delta (a straight line through B1 B2 when Q = 1). Any point of
the arc gives a linkage; its position along the arc is the designer's free choice (Norton, *Design of
Machinery*, 5th ed., ch. 3, the crank-rocker for a rocker swing and the quick-return fourbar; A. S. Hall,
*Kinematics and Linkage Design*, 1961, the same construction). With O2 on the arc,

    a = (|O2 B1| - |O2 B2|) / 2,     b = (|O2 B1| + |O2 B2|) / 2.

For the slider-crank the chord is the stroke on the slide line and the offset is O2's distance from that line
(Norton, ch. 3, quick-return mechanisms, for the offset slider-crank's time ratio).

Validity: 0 < swing < 180 deg, Q >= 1 (Q < 3 is usual: delta < 90 deg). Points of the arc near B2 give a
tiny crank and near its middle a crank as long as the coupler; the defects module reports Grashof and
transmission-angle defects of whatever the free choice gives.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from .candidate import Candidate, four_bar_from_points


def construction_angle(time_ratio: float) -> float:
    """delta [rad] of a time ratio Q >= 1: delta = pi (Q - 1) / (Q + 1) (Norton, ch. 3, time ratio).

    >>> round(float(np.degrees(construction_angle(1.25))), 4)
    20.0
    """
    if not (np.isfinite(time_ratio) and time_ratio >= 1.0):
        raise InputError(f"The time ratio must be a finite number >= 1 (slow stroke over fast stroke); got "
                         f"{time_ratio!r}.")
    return float(np.pi * (time_ratio - 1.0) / (time_ratio + 1.0))


def _pivot_on_arc(b1: complex, b2: complex, delta: float, position: float, side: int) -> complex:
    """O2 on the arc through B1 (stretched) and B2 (folded) that sees B1 B2 under ``delta`` [rad]; ``position``
    in (0, 1) runs from B2 to the far middle of the arc (where a would be 0); ``side`` +1 / -1: the arc to the
    left / right of B1 -> B2. For delta = 0: on the line beyond B2 at ``position / (1 - position)`` chord
    lengths."""
    if not 0.0 < position < 1.0:
        raise InputError(f"The position of the crank pivot on the construction arc must be in (0, 1); got "
                         f"{position!r}.")
    chord = b2 - b1
    s = abs(chord)
    unit = chord / s
    if delta < 1e-12:
        return b2 + unit * s * position / (1.0 - position)
    mid = 0.5 * (b1 + b2)
    normal = 1j * unit * side
    radius = s / (2.0 * np.sin(delta))
    centre = mid + normal * radius * np.cos(delta)
    t_b2 = np.angle(b2 - centre)
    t_far = np.angle(normal)  # the middle of the arc on the centre's side (delta < 90 deg: the major arc)
    if delta >= np.pi / 2:
        t_far = np.angle(-normal)
    sweep = np.angle(np.exp(1j * (t_far - t_b2)))
    return complex(centre + radius * np.exp(1j * (t_b2 + position * sweep)))


def _stroke_direction(theta_out: float, theta_in: float, slow: float) -> int:
    """+1 (counter-clockwise) if the crank turning counter-clockwise from ``theta_out`` to ``theta_in`` covers
    ``slow`` [rad], else -1."""
    ccw = np.mod(theta_in - theta_out, 2 * np.pi)
    return 1 if abs(ccw - slow) <= abs((2 * np.pi - ccw) - slow) else -1


def crank_rocker(swing: float, time_ratio: float = 1.0, rocker: float = 1.0, *, position: float = 0.5,
                 side: int = 1, start: float | None = None, slow_stroke: str = "out") -> Candidate:
    """The crank-rocker whose rocker of length ``rocker`` [m] swings through ``swing`` [rad] with the time
    ratio ``time_ratio`` (slow stroke / fast stroke >= 1).

    The rocker pivot O4 is the task's origin; the rocker starts the swing at ``start`` [rad] (default: the swing
    symmetric about the upward vertical) and turns counter-clockwise by ``swing`` in the "out" stroke. Free
    choices: ``position`` in (0, 1) and ``side`` (+1 / -1) of the crank pivot on the construction arc (see
    :func:`_pivot_on_arc`); ``slow_stroke`` "out" or "back" says which stroke takes the longer time.
    The candidate's ``angles`` are the crank angles [rad] at the two limit positions (start, end of the swing).
    """
    if not (np.isfinite(swing) and 0.0 < swing < np.pi):
        raise InputError(f"The rocker swing must be between 0 and 180 deg; got {np.degrees(swing):.6g} deg.")
    if not (np.isfinite(rocker) and rocker > 0.0):
        raise InputError(f"The rocker length must be > 0 m; got {rocker!r} m.")
    if slow_stroke not in ("out", "back"):
        raise InputError(f"slow_stroke must be 'out' or 'back'; got {slow_stroke!r}.")
    delta = construction_angle(time_ratio)
    psi1 = np.pi / 2 - swing / 2 if start is None else float(start)
    p1, p2 = rocker * np.exp(1j * psi1), rocker * np.exp(1j * (psi1 + swing))
    # The stretched-out position at the start of the stroke that should be slow: the crank turns 180 + delta
    # from stretched to folded in the direction it runs.
    b_str, b_fold = (p1, p2) if slow_stroke == "out" else (p2, p1)
    o2 = _pivot_on_arc(b_str, b_fold, delta, position, side)
    r_str, r_fold = abs(b_str - o2), abs(b_fold - o2)
    a = 0.5 * (r_str - r_fold)  # and the coupler (r_str + r_fold) / 2, read back from the points
    th_str, th_fold = float(np.angle(b_str - o2)), float(np.angle(b_fold - o2) + np.pi)
    direction = _stroke_direction(th_str, th_fold, np.pi + delta)
    # Positions in the task's order: start of the swing, end of the swing.
    # (the crank keeps turning the same way: with the back stroke slow, the out stroke covers 180 - delta)
    th1, th2 = (th_str, th_fold) if slow_stroke == "out" else (th_fold, th_str)
    a1 = o2 + a * np.exp(1j * th1)
    cand = four_bar_from_points(o2, a1, p1, 0j, p1, [th1, th2], direction=direction,
                                free={"position": position, "side": side, "rocker": rocker},
                                method="quick return (Hall)" if delta > 0 else "crank-rocker (Q = 1)")
    return cand


def slider_crank(stroke: float, time_ratio: float = 1.0, *, position: float = 0.5, side: int = 1,
                 slow_stroke: str = "out") -> Candidate:
    """The offset slider-crank whose slider travels ``stroke`` [m] along the task's x axis, from x = 0 (inner
    dead centre) to x = ``stroke`` (outer dead centre) in the "out" stroke, with the time ratio ``time_ratio``.

    Free choices as :func:`crank_rocker`: ``position`` and ``side`` of the crank pivot on the construction arc
    (for Q = 1 on the slide line behind the inner dead centre, ``position`` setting the rod length).
    The candidate's ``angles`` are the crank angles [rad] at the inner and outer dead centres.
    """
    if not (np.isfinite(stroke) and stroke > 0.0):
        raise InputError(f"The stroke must be > 0 m; got {stroke!r} m.")
    if slow_stroke not in ("out", "back"):
        raise InputError(f"slow_stroke must be 'out' or 'back'; got {slow_stroke!r}.")
    delta = construction_angle(time_ratio)
    x_in, x_out = 0j, complex(stroke)
    # The folded position is the inner dead centre, the stretched one the outer: stretched -> folded is the
    # in (back) stroke; with the out stroke slow the crank turns 180 - delta from stretched to folded.
    o2 = _pivot_on_arc(x_out, x_in, delta, position, -side)
    r_str, r_fold = abs(x_out - o2), abs(x_in - o2)
    a, b = 0.5 * (r_str - r_fold), 0.5 * (r_str + r_fold)
    th_out, th_in = float(np.angle(x_out - o2)), float(np.angle(x_in - o2) + np.pi)
    back_arc = np.pi - delta if slow_stroke == "out" else np.pi + delta  # crank turn of the back stroke
    direction = _stroke_direction(th_out, th_in, back_arc)
    a_in = o2 + a * np.exp(1j * th_in)
    branch = 1 if (x_in - a_in).real >= 0.0 else -1
    return Candidate(kind="slider_crank", origin=o2, crank=float(a), coupler=float(b), offset=float(-o2.imag),
                     slide_angle=0.0, branch=branch, angles=np.array([th_in, th_out]), direction=direction,
                     free={"position": position, "side": side, "stroke": stroke},
                     method="quick return (Hall)" if delta > 0 else "in-line slider-crank (Q = 1)")
