"""Rigid-body motion state and the transfer of motion to points of a body.

A body's state is the position, velocity and acceleration of its frame origin and its angle, angular
velocity and angular acceleration. For a point with body-frame coordinates c and r = R(theta) c:

    x = x0 + r,   v = v0 + omega k x r,   a = a0 + alpha k x r - omega^2 r

(rigid-body kinematics; Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed., ch. 3-4).
Arrays broadcast over designs x crank positions; scalars are allowed anywhere.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

#: A float or an array broadcasting over designs x positions.
Value = Any


@dataclass(slots=True)
class PointState:
    """Position [m], velocity [m/s] and acceleration [m/s^2] of a point, global axes."""

    x: Value
    y: Value
    vx: Value
    vy: Value
    ax: Value
    ay: Value

    @property
    def speed(self) -> np.ndarray:
        """|v| [m/s]."""
        return np.hypot(self.vx, self.vy)

    @property
    def accel(self) -> np.ndarray:
        """|a| [m/s^2]."""
        return np.hypot(self.ax, self.ay)


@dataclass(slots=True)
class BodyState:
    """Frame origin (x, y) [m] with its velocity and acceleration, angle [rad], omega [rad/s], alpha [rad/s^2];
    cos/sin of the angle are kept because every point transform needs them."""

    x: Value
    y: Value
    vx: Value
    vy: Value
    ax: Value
    ay: Value
    angle: Value
    omega: Value
    alpha: Value
    cos: Value
    sin: Value

    def offset(self, u, v) -> tuple[np.ndarray, np.ndarray]:
        """The body-frame vector (u, v) [m] rotated into global axes."""
        if isinstance(v, float) and v == 0.0:  # points on a link's axis: half the work
            return self.cos * u, self.sin * u
        return self.cos * u - self.sin * v, self.sin * u + self.cos * v

    def point(self, u, v) -> PointState:
        """Motion of the point with body-frame coordinates (u, v) [m]."""
        rx, ry = self.offset(u, v)
        w2 = self.omega * self.omega
        if np.ndim(self.alpha) == 0 and self.alpha == 0:  # steady crank: skip the zero tangential terms
            return PointState(
                self.x + rx, self.y + ry, self.vx - self.omega * ry, self.vy + self.omega * rx,
                self.ax - w2 * rx, self.ay - w2 * ry,
            )
        return PointState(
            self.x + rx,
            self.y + ry,
            self.vx - self.omega * ry,
            self.vy + self.omega * rx,
            self.ax - self.alpha * ry - w2 * rx,
            self.ay + self.alpha * rx - w2 * ry,
        )


def ground_state() -> BodyState:
    """The frame: at rest, unrotated."""
    z = np.float64(0.0)
    one = np.float64(1.0)
    return BodyState(z, z, z, z, z, z, z, z, z, one, z)


def body_from_point(p: PointState, local: tuple, angle, omega, alpha, cos=None, sin=None) -> BodyState:
    """The state of a body whose point with body-frame coordinates ``local`` [m] moves as ``p``."""
    c = np.cos(angle) if cos is None else cos
    s = np.sin(angle) if sin is None else sin
    if is_origin(local):
        return BodyState(p.x, p.y, p.vx, p.vy, p.ax, p.ay, angle, omega, alpha, c, s)
    u, v = local
    rx = c * u - s * v
    ry = s * u + c * v
    w2 = omega * omega
    return BodyState(
        p.x - rx,
        p.y - ry,
        p.vx + omega * ry,
        p.vy - omega * rx,
        p.ax + alpha * ry + w2 * rx,
        p.ay - alpha * rx + w2 * ry,
        angle,
        omega,
        alpha,
        c,
        s,
    )


def is_origin(local) -> bool:
    """True if the body-frame point ``local`` is the frame origin (0, 0) for every design."""
    u, v = local
    return isinstance(u, float | int) and isinstance(v, float | int) and u == 0 and v == 0
