"""Grashof's rule for four-bar linkages: which link can turn fully (Norton, *Design of Machinery*, 5th ed.,
§2.12: s + l vs p + q, and which link is the shortest)."""

from __future__ import annotations

import numpy as np

from .dyad_types import RRR
from .model import Mechanism
from .refs import GROUND, split_ref


def _four_bar_lengths(mech: Mechanism):
    """Crank, coupler, rocker and ground lengths [m] if ``mech`` is a four-bar (one RRR from the crank to the
    ground), else None."""
    if len(mech.dyads) != 1 or not isinstance(mech.dyads[0], RRR):
        return None
    d = mech.dyads[0]
    body_a, pin_a = split_ref(d.pin_a)
    body_b, pin_b = split_ref(d.pin_b)
    if body_a != mech.crank.body or body_b != GROUND:
        return None
    pivot = split_ref(mech.crank.pivot)[1]

    def dist(p, q):
        return np.hypot(np.asarray(p[0]) - q[0], np.asarray(p[1]) - q[1])

    crank = mech.body(mech.crank.body).points
    a, b = mech.body(d.a).points, mech.body(d.b).points
    return (
        dist(crank[pin_a], crank[pivot]),
        dist(a[pin_a], a[d.inner]),
        dist(b[pin_b], b[d.inner]),
        dist(mech.ground[pin_b], mech.ground[pivot]),
    )


def grashof_type(mech: Mechanism):
    """Grashof type of a four-bar (Norton, *Design of Machinery*, 5th ed., §2.12).

    With s the shortest, l the longest and p, q the other links: s + l < p + q is a Grashof linkage whose type
    follows from which link is shortest (crank: crank-rocker; ground: double-crank; coupler: Grashof
    double-rocker; rocker: rocker-crank), s + l = p + q a change-point linkage, s + l > p + q a non-Grashof
    triple-rocker.

    Parameters
    ----------
    mech : Mechanism
        A mechanism [link lengths in m]; only a four-bar (one RRR group from the crank to the ground) is classed.

    Returns
    -------
    str or numpy.ndarray or None
        'crank-rocker', 'double-crank', 'rocker-crank', 'Grashof double-rocker', 'change-point' or
        'non-Grashof triple-rocker'; an array of names for design variants; None if ``mech`` is not a four-bar.

    Examples
    --------
    >>> from machdyn.linkage import four_bar
    >>> grashof_type(four_bar(0.02, 0.08, 0.07, 0.09))
    'crank-rocker'
    >>> grashof_type(four_bar(0.05, 0.05, 0.05, 0.05))
    'change-point'
    """
    lengths = _four_bar_lengths(mech)
    if lengths is None:
        return None
    links = np.broadcast_arrays(*[np.asarray(v, dtype=float) for v in lengths])
    stack = np.stack(links, axis=-1)
    s, l_ = stack.min(axis=-1), stack.max(axis=-1)
    total = stack.sum(axis=-1)
    pq = total - s - l_
    shortest = stack.argmin(axis=-1)
    names = np.array(["crank-rocker", "rocker-crank", "Grashof double-rocker", "double-crank"])
    # shortest index: 0 crank, 1 coupler, 2 rocker, 3 ground
    grashof = names[np.choose(shortest, [0, 2, 1, 3])]
    tol = 1e-12 * total
    kind = np.where(np.abs(s + l_ - pq) <= tol, "change-point",
                    np.where(s + l_ < pq, grashof, "non-Grashof triple-rocker"))
    return str(kind) if kind.ndim == 0 else kind


def grashof_margin(mech: Mechanism):
    """The Grashof margin s + l - (p + q) of a four-bar (Norton, *Design of Machinery*, 5th ed., §2.12).

    With s the shortest, l the longest and p, q the other links: negative for a Grashof linkage (its shortest
    link turns fully), zero for a change-point linkage, positive for a non-Grashof triple-rocker.

    Parameters
    ----------
    mech : Mechanism
        A mechanism [link lengths in m]; only a four-bar (one RRR group from the crank to the ground) has one.

    Returns
    -------
    float or numpy.ndarray or None
        s + l - (p + q) [m]; an array for design variants; None if ``mech`` is not a four-bar.

    Examples
    --------
    >>> from machdyn.linkage import four_bar
    >>> round(float(grashof_margin(four_bar(0.02, 0.08, 0.07, 0.09))), 12)
    -0.04
    """
    lengths = _four_bar_lengths(mech)
    if lengths is None:
        return None
    stack = np.stack(np.broadcast_arrays(*[np.asarray(v, dtype=float) for v in lengths]), axis=-1)
    s, l_ = stack.min(axis=-1), stack.max(axis=-1)
    margin = s + l_ - (stack.sum(axis=-1) - s - l_)
    return float(margin) if margin.ndim == 0 else margin
