"""Rotating masses on one shaft: the force and the couples they put on the frame, over the crank angle.

A mass m at radius r, at angle alpha from the shaft's reference mark and at axial position z, is carried round by
the shaft at angle theta and speed w. Its inertia (centrifugal) force on the bearings is m r w^2 in the direction
theta + alpha; written as a complex number in the transverse plane (x + i y),

    F = w^2 U exp(i theta),   U = m r exp(i alpha)   (the mass's unbalance [kg*m]),

and its moment about the transverse axes through the reference plane z = 0 is z x F = (-z F_y, z F_x) (Khurmi &
Gupta, *Theory of Machines*, 14th ed., ch. 21, sec. 21.7-21.8: the force polygon of m r and the couple polygon
of m r l; Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed., sec. 16.4). The shaft is rigid,
the speed constant; axes: z along the shaft, x and y across it, theta from x towards y.

Bearings: the shaft is a rigid body on two or more bearings of given radial stiffness (equal when not given);
with two bearings the reactions follow from statics alone, with more they share the load in proportion to the
bearings' deflections u + t z_i (a rigid shaft on elastic supports, Den Hartog, *Mechanical Vibrations*, 4th ed.,
sec. 2.2's statics of a rigid bar on springs).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ..errors import InputError, check_finite, check_positive

__all__ = ["Mass", "Bearing", "ShaftLoads", "unbalance", "rotating_loads", "bearing_reactions", "cycle"]


@dataclass(frozen=True)
class Mass:
    """A mass on the shaft: ``mass`` [kg] >= 0 at ``radius`` [m] >= 0, at ``angle`` [rad] from the reference mark
    (in the sense of rotation), in the plane at axial ``position`` [m]."""

    name: str
    mass: float
    radius: float
    angle: float
    position: float

    def __post_init__(self) -> None:
        check_positive(f"mass of '{self.name}'", self.mass, "kg", allow_zero=True)
        check_positive(f"radius of '{self.name}'", self.radius, "m", allow_zero=True)
        check_finite(f"angle of '{self.name}'", self.angle, "rad")
        check_finite(f"axial position of '{self.name}'", self.position, "m")

    @property
    def unbalance(self) -> complex:
        """m r exp(i alpha) [kg*m]."""
        return complex(self.mass * self.radius * np.exp(1j * self.angle))


@dataclass(frozen=True)
class Bearing:
    """A bearing at axial ``position`` [m] with radial ``stiffness`` [N/m] (> 0; only ratios matter)."""

    name: str
    position: float
    stiffness: float = 1.0

    def __post_init__(self) -> None:
        check_finite(f"axial position of bearing '{self.name}'", self.position, "m")
        check_positive(f"stiffness of bearing '{self.name}'", self.stiffness, "N/m")


def cycle(samples: int = 360) -> np.ndarray:
    """``samples`` shaft angles [rad] over one turn, end excluded (means over them are cycle means)."""
    if int(samples) != samples or samples < 8:
        raise InputError(f"The number of shaft angles per turn must be an integer >= 8; got {samples!r}.")
    return np.linspace(0.0, 2.0 * np.pi, int(samples), endpoint=False)


def unbalance(masses: Sequence[Mass], reference: float = 0.0) -> tuple[complex, complex]:
    """The resultant unbalance sum(m r e^{i alpha}) [kg*m] and its first moment about the plane ``reference``,
    sum(m r (z - z_ref) e^{i alpha}) [kg*m^2]: the closing sides of the force and couple polygons (Khurmi & Gupta,
    14th ed., sec. 21.8).

    Examples
    --------
    Two equal masses opposite each other 0.2 m apart: no force, a couple of 1 kg*m * 0.2 m.

    >>> ms = [Mass("a", 10.0, 0.1, 0.0, 0.0), Mass("b", 10.0, 0.1, np.pi, 0.2)]
    >>> s0, s1 = unbalance(ms)
    >>> round(abs(s0), 12), round(abs(s1), 12)
    (0.0, 0.2)
    """
    s0 = sum((m.unbalance for m in masses), 0j)
    s1 = sum((m.unbalance * (m.position - reference) for m in masses), 0j)
    return complex(s0), complex(s1)


@dataclass(frozen=True)
class ShaftLoads:
    """Frame loads over one turn (SI): shaft angle [rad], speed [rad/s], the resultant force fx, fy [N] and the
    couples mx, my [N*m] about the x and y axes through the reference plane at axial position ``reference`` [m]."""

    angle: np.ndarray
    speed: float
    fx: np.ndarray
    fy: np.ndarray
    mx: np.ndarray
    my: np.ndarray
    reference: float = 0.0

    @property
    def force(self) -> np.ndarray:
        return np.hypot(self.fx, self.fy)

    @property
    def couple(self) -> np.ndarray:
        return np.hypot(self.mx, self.my)

    @property
    def peak_force(self) -> float:
        return float(np.max(self.force))

    @property
    def peak_couple(self) -> float:
        return float(np.max(self.couple))

    def __add__(self, other: ShaftLoads) -> ShaftLoads:
        if other.reference != self.reference or other.angle.shape != self.angle.shape:
            raise InputError("Shaft loads add only over the same angles and about the same reference plane.")
        return ShaftLoads(self.angle, self.speed, self.fx + other.fx, self.fy + other.fy, self.mx + other.mx,
                          self.my + other.my, self.reference)

    def first_moment_x(self) -> np.ndarray:
        """sum(z F_x) [N*m] about the reference plane (= my)."""
        return self.my

    def first_moment_y(self) -> np.ndarray:
        """sum(z F_y) [N*m] about the reference plane (= -mx)."""
        return -self.mx


def rotating_loads(masses: Sequence[Mass], speed: float, angle=None, reference: float = 0.0) -> ShaftLoads:
    """The force and couples of rotating masses on the frame at each shaft angle.

    F = w^2 sum(U) e^{i theta}; about the plane z_ref, (M_x, M_y) = (-sum(z F_y), sum(z F_x)) (Khurmi & Gupta,
    14th ed., sec. 21.7-21.8). Parameters: masses; speed w [rad/s]; angle theta [rad] (default one turn of 360);
    reference z_ref [m]. Valid for a rigid shaft at constant speed.

    Examples
    --------
    >>> loads = rotating_loads([Mass("a", 2.0, 0.05, 0.0, 0.3)], 10.0, [0.0])
    >>> float(loads.fx[0]), float(loads.my[0])
    (10.0, 3.0)
    """
    check_finite("shaft speed", speed, "rad/s")
    theta = cycle() if angle is None else np.asarray(angle, dtype=float)
    check_finite("shaft angle", theta, "rad")
    check_finite("reference plane", reference, "m")
    s0, s1 = unbalance(masses, reference)
    turn = np.exp(1j * theta)
    f = speed**2 * s0 * turn
    first = speed**2 * s1 * turn  # sum z F as a complex number
    return ShaftLoads(theta, float(speed), f.real, f.imag, -first.imag, first.real, float(reference))


@dataclass(frozen=True)
class Reactions:
    """The force [N] each bearing takes from the shaft over the turn: ``fx``, ``fy`` shaped (bearings, angles)."""

    names: tuple[str, ...]
    positions: np.ndarray
    fx: np.ndarray
    fy: np.ndarray

    @property
    def peak(self) -> np.ndarray:
        """Largest |force| per bearing [N]."""
        return np.max(np.hypot(self.fx, self.fy), axis=-1)


def bearing_reactions(loads: ShaftLoads, bearings: Sequence[Bearing]) -> Reactions:
    """Forces the bearings take from a rigid shaft carrying ``loads``.

    The bearing forces P_i = k_i (u + t z_i) (a rigid shaft on elastic supports) balance the resultant force and
    its first moment: sum P_i = F, sum P_i z_i = sum z F. With two bearings this is the statics of a beam on two
    supports (independent of the stiffnesses). Needs at least two bearings at distinct positions.
    """
    if len(bearings) < 2:
        raise InputError(f"Bearing reactions need at least two bearings; got {len(bearings)}.")
    z = np.array([b.position for b in bearings], dtype=float)
    k = np.array([b.stiffness for b in bearings], dtype=float)
    if np.ptp(z) <= 1e-12 * max(1.0, float(np.max(np.abs(z)))):
        raise InputError(f"The bearings must stand at distinct axial positions; all are at {z[0]:g} m.")
    names = tuple(b.name for b in bearings)
    if len(set(names)) != len(names):
        raise InputError(f"Bearing names must be unique; got {list(names)}.")
    z_ref = loads.reference
    zr = z - z_ref
    a = np.array([[k.sum(), (k * zr).sum()], [(k * zr).sum(), (k * zr * zr).sum()]])
    out = []
    for force, moment in ((loads.fx, loads.first_moment_x()), (loads.fy, loads.first_moment_y())):
        ut = np.linalg.solve(a, np.vstack([force, moment]))
        out.append(k[:, None] * (ut[0][None, :] + zr[:, None] * ut[1][None, :]))
    return Reactions(names, z, out[0], out[1])
