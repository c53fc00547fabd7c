"""Evaluation of the loads on a linkage at each position: inertia, gravity, external forces and torques,
springs. Shared by kinetostatics (forces) and energy (powers and potentials)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .model import LoadValue
from .motion import Kinematics
from .refs import GROUND, column, split_ref
from .state import PointState


def window(phi, active: tuple[float, float] | None):
    """1 where the crank angle phi [rad] lies in ``active`` = (start, end) [rad] (wrapping through 2*pi
    when start > end), else 0; 1 everywhere without a window or for a window of a full turn or more."""
    if active is None or active[1] - active[0] >= 2.0 * np.pi:
        return 1.0
    start, end = (a % (2.0 * np.pi) for a in active)
    p = np.mod(phi, 2.0 * np.pi)
    inside = (p >= start) & (p <= end) if start <= end else (p >= start) | (p <= end)
    return inside.astype(float)


def evaluate(value: LoadValue, phi):
    """A load value at crank angles phi: a constant, a design array, or a function of phi."""
    if callable(value):
        return np.asarray(value(phi), dtype=float)
    return column(value)


@dataclass(slots=True)
class Mass:
    """A mass element moving with a body: the body itself or a point mass attached to it."""

    name: str
    body: str
    mass: Any
    inertia: Any
    motion: PointState


def mass_elements(kin: Kinematics) -> list[Mass]:
    """Every mass of the mechanism with the motion of its centre."""
    mech = kin.mechanism
    out = []
    for name in mech.moving_bodies:
        b = mech.body(name)
        out.append(Mass(name, name, column(b.mass), column(b.inertia), kin.com(name)))
    for pm in mech.point_masses:
        out.append(Mass(pm.name, pm.body, column(pm.mass), column(pm.inertia), kin.local_point(pm.body, pm.position)))
    return out


@dataclass(slots=True)
class AppliedForce:
    name: str
    body: str
    motion: PointState
    fx: np.ndarray
    fy: np.ndarray


@dataclass(slots=True)
class AppliedTorque:
    name: str
    body: str
    torque: np.ndarray


def applied_forces(kin: Kinematics) -> list[AppliedForce]:
    """External point forces [N] at each position (windows applied)."""
    out = []
    for f in kin.mechanism.forces:
        on = window(kin.crank_angle, f.active)
        body = split_ref(f.point)[0]
        out.append(
            AppliedForce(f.name, body, kin.point(f.point), evaluate(f.fx, kin.crank_angle) * on,
                         evaluate(f.fy, kin.crank_angle) * on)
        )
    return out


def applied_torques(kin: Kinematics) -> list[AppliedTorque]:
    """External torques [N*m] on bodies at each position (windows applied)."""
    return [
        AppliedTorque(t.name, t.body, evaluate(t.torque, kin.crank_angle) * window(kin.crank_angle, t.active))
        for t in kin.mechanism.torques
    ]


@dataclass(slots=True)
class SpringState:
    """A spring at each position: length [m], its rate [m/s], tension [N] (positive when stretched) and the
    unit vector from point 1 to point 2."""

    name: str
    body_1: str
    body_2: str
    p1: PointState
    p2: PointState
    length: np.ndarray
    rate: np.ndarray
    tension: np.ndarray
    ex: np.ndarray
    ey: np.ndarray
    energy: np.ndarray


def spring_states(kin: Kinematics) -> list[SpringState]:
    """Linear springs: tension = k (l - l0), stored energy k (l - l0)^2 / 2 (Hooke's law)."""
    out = []
    for s in kin.mechanism.springs:
        p1, p2 = kin.point(s.point_1), kin.point(s.point_2)
        dx, dy = p2.x - p1.x, p2.y - p1.y
        length = np.hypot(dx, dy)
        with np.errstate(invalid="ignore", divide="ignore"):
            ex, ey = dx / length, dy / length
        ex = np.where(length > 0, ex, 0.0)
        ey = np.where(length > 0, ey, 0.0)
        rate = ex * (p2.vx - p1.vx) + ey * (p2.vy - p1.vy)
        stretch = length - column(s.free_length)
        k = column(s.stiffness)
        out.append(
            SpringState(s.name, split_ref(s.point_1)[0], split_ref(s.point_2)[0], p1, p2, length, rate,
                        k * stretch, ex, ey, 0.5 * k * stretch * stretch)
        )
    return out


def is_ground(body: str) -> bool:
    return body == GROUND
