"""Point references and design-parameter shapes shared by the engine's modules.

A known point is written ``"body.point"``; ground points are ``"ground.NAME"``. Design parameters are floats
or arrays of N design variants; as columns (N, 1) they broadcast against M crank angles to (N, M).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any, Protocol

import numpy as np

from ..errors import InputError

GROUND = "ground"

Array = np.ndarray
Number = float | Array
Vec = tuple[Number, Number]


class Points(Protocol):
    """What a point lookup reads of a mechanism (a :class:`~machdyn.linkage.model.Mechanism` is one): its ground
    points and its bodies, each with its named points."""

    @property
    def ground(self) -> Mapping[str, Vec]: ...

    def body(self, name: str) -> Any: ...


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


def local_point(mech: Points, body: str, point: str):
    """Body-frame coordinates [m] of ``point`` of ``body`` (or of a ground point), as columns."""
    if body == GROUND:
        x, y = mech.ground[point]
    else:
        x, y = mech.body(body).points[point]
    return column(x), column(y)


#: Read-only broadcast views of single values, shared (a view of 0.0 over (N, M) serves every body at rest).
_VIEWS: dict = {}


def full(value, shape):
    """``value`` broadcast to ``shape``: the array itself when it has that shape already, else a read-only
    broadcast view (no copy either way)."""
    if isinstance(value, np.ndarray):
        if value.shape == shape:
            return value
        if value.ndim:
            return np.broadcast_to(value, shape)
    if isinstance(value, float | int | np.ndarray) and not isinstance(value, bool):
        number = float(value)
        key = (number, math.copysign(1.0, number), shape)  # 0.0 and -0.0 kept apart
        view = _VIEWS.get(key)
        if view is None:
            if len(_VIEWS) >= 512:
                _VIEWS.clear()
            view = _VIEWS[key] = np.broadcast_to(number, shape)
        return view
    return np.broadcast_to(value, shape)
