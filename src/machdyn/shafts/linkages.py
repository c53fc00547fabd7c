"""Planar linkages placed on the shaft line: any machdyn mechanism at an axial position, turned about the shaft.

A linkage whose crank pivot lies on the shaft axis, in the transverse plane at axial position z, its own x axis
turned by ``axis`` about the shaft from the shaft's x axis, its crank at ``phase`` when the shaft stands at 0
(crank angle phi = theta + phase), puts on the frame the shaking force the planar engine computes,
-sum(m a_G) of its moving masses (:func:`machdyn.balancing.frame.frame_loads`, Uicker, Pennock & Shigley, 5th
ed., sec. 16.3), turned into shaft axes, and its moment z x F about the reference plane; the planar shaking moment
about the crank pivot (the drive's reaction included) is a torque about the shaft axis, reported beside them.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..balancing.frame import frame_loads
from ..errors import InputError
from .rotating import ShaftLoads

__all__ = ["LinkagePlane", "linkage_loads"]


@dataclass(frozen=True)
class LinkagePlane:
    """A planar linkage (the engine's :class:`~machdyn.linkage.model.Mechanism`) at axial ``position`` [m], its
    crank at ``phase`` [rad] for shaft angle 0, its x axis at ``axis`` [rad] about the shaft."""

    name: str
    mechanism: Any
    position: float
    phase: float = 0.0
    axis: float = 0.0

    def __post_init__(self) -> None:
        pivot = self.mechanism.ground[self.mechanism.crank.pivot.split(".")[1]]
        if max(abs(float(pivot[0])), abs(float(pivot[1]))) > 1e-12:
            raise InputError(f"The crank pivot of linkage '{self.name}' must lie on the shaft axis, at the linkage's "
                             f"origin; it is at ({float(pivot[0]):g}, {float(pivot[1]):g}) m.")


def linkage_loads(planes: tuple[LinkagePlane, ...], speed: float, angle: np.ndarray,
                  reference: float = 0.0) -> tuple[ShaftLoads, np.ndarray]:
    """The frame loads of the linkages in shaft axes over the shaft ``angle`` [rad], and the shaking moment of each
    about its crank pivot [N m], a torque about the shaft axis (shape linkages x angles)."""
    theta = np.asarray(angle, dtype=float)
    z0 = np.zeros_like(theta)
    total = ShaftLoads(theta, float(speed), z0, z0, z0, z0, float(reference))
    torque = []
    for p in planes:
        fl = frame_loads(p.mechanism, theta + p.phase, speed)
        f = np.exp(1j * p.axis) * (np.asarray(fl.fx) + 1j * np.asarray(fl.fy))
        z = p.position - reference
        total = total + ShaftLoads(theta, float(speed), f.real, f.imag, -z * f.imag, z * f.real, float(reference))
        torque.append(np.asarray(fl.moment, dtype=float))
    return total, np.array(torque).reshape(len(planes), theta.size)
