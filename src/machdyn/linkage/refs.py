"""Point references and design-parameter shapes shared by the engine's modules.

A known point is written ``"body.point"``; ground points are ``"ground.NAME"``. Design parameters are floats
or arrays of N design variants; as columns (N, 1) they broadcast against M crank angles to (N, M).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ..errors import InputError

if TYPE_CHECKING:
    from .model import Mechanism

GROUND = "ground"

Array = np.ndarray
Number = float | Array
Vec = tuple[Number, Number]


def split_ref(ref: str) -> tuple[str, str]:
    """Split ``"body.point"`` into its two names."""
    if not isinstance(ref, str) or ref.count(".") != 1:
        raise InputError(f"A point reference must be written 'body.point'; got {ref!r}.")
    body, point = ref.split(".")
    return body, point


def column(value):
    """A design parameter as a column (N, 1) so that it broadcasts against crank angles (M,); a float as is."""
    arr = np.asarray(value, dtype=float)
    if arr.ndim == 0:
        return float(arr)
    return arr[:, None] if arr.ndim == 1 else arr


def local_point(mech: Mechanism, body: str, point: str):
    """Body-frame coordinates [m] of ``point`` of ``body`` (or of a ground point), as columns."""
    if body == GROUND:
        x, y = mech.ground[point]
    else:
        x, y = mech.body(body).points[point]
    return column(x), column(y)


def full(value, shape):
    """``value`` broadcast to ``shape``: the array itself when it has that shape already, else a read-only
    broadcast view (no copy either way)."""
    if isinstance(value, np.ndarray) and value.shape == shape:
        return value
    return np.broadcast_to(value, shape)
