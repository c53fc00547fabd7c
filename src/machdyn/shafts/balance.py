"""Static (one plane) and dynamic (two plane) balancing of masses rotating in several planes.

Dynamic balance asks that both the resultant force and the resultant couple of the rotating masses vanish:
sum(U) = 0 and sum(U z) = 0 with U = m r e^{i alpha} (Khurmi & Gupta, *Theory of Machines*, 14th ed., sec.
21.7-21.8; Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed., sec. 16.4). Two correction
masses in planes L and M at z_L != z_M satisfy both:

    U_M = (z_L S0 - S1) / (z_M - z_L),   U_L = -S0 - U_M,   S0 = sum(U), S1 = sum(U z),

which is the textbooks' couple polygon taken about plane L (its closing side gives m_M r_M l_M) followed by the
force polygon (its closing side gives m_L r_L). Static balance puts one correction -S0 in one plane: the force
vanishes, the couple generally does not.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ..errors import InputError, check_finite, check_positive
from .rotating import Mass, ShaftLoads, rotating_loads, unbalance

__all__ = ["Plane", "Correction", "BalanceResult", "two_plane", "single_plane", "polar"]


@dataclass(frozen=True)
class Plane:
    """A correction plane: ``name``, axial ``position`` [m] and the ``radius`` [m] > 0 of the correction mass."""

    name: str
    position: float
    radius: float

    def __post_init__(self) -> None:
        check_finite(f"axial position of plane '{self.name}'", self.position, "m")
        check_positive(f"correction radius of plane '{self.name}'", self.radius, "m")


@dataclass(frozen=True)
class Correction:
    """A correction mass: its plane, mass [kg], angle [rad] in 0 ... 2 pi from the reference mark and unbalance
    m r [kg*m]."""

    plane: Plane
    mass: float
    angle: float

    @property
    def unbalance(self) -> float:
        return self.mass * self.plane.radius

    def as_mass(self) -> Mass:
        return Mass(f"correction {self.plane.name}", self.mass, self.plane.radius, self.angle, self.plane.position)


def polar(u: complex) -> tuple[float, float]:
    """|u| and its angle in [0, 2 pi)."""
    angle = math.atan2(u.imag, u.real) % (2.0 * math.pi)
    if angle >= 2.0 * math.pi - 1e-12:  # -0.0 and round-off below a full turn read as 0
        angle = 0.0
    return abs(u), (0.0 if abs(u) == 0.0 else angle)


@dataclass(frozen=True)
class BalanceResult:
    """Corrections and the loads before and after them (at the given speed)."""

    corrections: tuple[Correction, ...]
    before: ShaftLoads
    after: ShaftLoads

    @property
    def masses(self) -> tuple[Mass, ...]:
        return tuple(c.as_mass() for c in self.corrections)


def _correction(plane: Plane, u: complex) -> Correction:
    size, angle = polar(u)
    return Correction(plane, size / plane.radius, angle)


def correction_unbalances(masses: Sequence[Mass], plane_l: Plane, plane_m: Plane) -> tuple[complex, complex]:
    """The correction unbalances U_L, U_M [kg*m] that balance ``masses`` dynamically (module docstring).

    Examples
    --------
    One mass of 1 kg*m midway between the planes: half of it opposite in each plane.

    >>> ul, um = correction_unbalances([Mass("a", 10.0, 0.1, 0.0, 0.5)], Plane("L", 0.0, 0.1), Plane("M", 1.0, 0.1))
    >>> round(ul.real, 12), round(um.real, 12)
    (-0.5, -0.5)
    """
    span = plane_m.position - plane_l.position
    if abs(span) <= 1e-9 * max(1.0, abs(plane_l.position), abs(plane_m.position)):
        raise InputError(
            f"The two correction planes '{plane_l.name}' and '{plane_m.name}' must stand at different axial "
            f"positions (a couple cannot be corrected in one plane); both are at {plane_l.position:g} m."
        )
    s0, s1 = unbalance(masses, plane_l.position)  # moments about plane L
    u_m = -s1 / span
    u_l = -s0 - u_m
    return complex(u_l), complex(u_m)


def two_plane(masses: Sequence[Mass], plane_l: Plane, plane_m: Plane, speed: float = 1.0,
              angle=None, reference: float = 0.0) -> BalanceResult:
    """Dynamic balance of ``masses`` by one correction mass in each of two planes (Khurmi & Gupta, 14th ed.,
    sec. 21.8). speed [rad/s] and angle [rad] only set where the before/after loads are evaluated."""
    u_l, u_m = correction_unbalances(masses, plane_l, plane_m)
    corrections = (_correction(plane_l, u_l), _correction(plane_m, u_m))
    before = rotating_loads(masses, speed, angle, reference)
    after = rotating_loads([*masses, *(c.as_mass() for c in corrections)], speed, before.angle, reference)
    return BalanceResult(corrections, before, after)


def single_plane(masses: Sequence[Mass], plane: Plane, speed: float = 1.0, angle=None,
                 reference: float = 0.0) -> BalanceResult:
    """Static balance by one correction mass, -sum(U) / r in ``plane`` (Khurmi & Gupta, 14th ed., sec. 21.4-21.5):
    the resultant force vanishes; the couple sum(U z) + U_c z_c generally remains."""
    s0, _ = unbalance(masses)
    corrections = (_correction(plane, -s0),)
    before = rotating_loads(masses, speed, angle, reference)
    after = rotating_loads([*masses, corrections[0].as_mass()], speed, before.angle, reference)
    return BalanceResult(corrections, before, after)


def equivalent_in_planes(masses: Sequence[Mass], z_a: float, z_b: float) -> tuple[complex, complex]:
    """The unbalances [kg*m] in the planes z_a and z_b that have the same force and couple as ``masses`` (the
    negatives of the two-plane corrections): used to carry a residual unbalance to the bearing planes."""
    if abs(z_b - z_a) <= 1e-9 * max(1.0, abs(z_a), abs(z_b)):
        raise InputError(f"The two planes must stand at different axial positions; both are at {z_a:g} m.")
    s0, s1 = unbalance(masses, z_a)
    u_b = s1 / (z_b - z_a)
    return complex(s0 - u_b), complex(u_b)


def peak_residual(result: BalanceResult) -> tuple[float, float]:
    """Largest |force| [N] and |couple| [N*m] left after the corrections, over the turn."""
    return float(np.max(result.after.force)), float(np.max(result.after.couple))


def forward_first_harmonic(loads: ShaftLoads) -> tuple[complex, complex]:
    """The forward-turning part of the first harmonic of the resultant force and of its first moment about the
    loads' reference plane: with F = F_x + i F_y = A e^{i theta} + B e^{-i theta} + (other orders), A [N]; likewise
    C [N m] for sum z F. Only A (and C) can be cancelled by masses turning with the shaft; B turns backwards
    (the reverse cranks of Khurmi & Gupta, 14th ed., sec. 22.10). Uniform angles over one turn."""
    theta = loads.angle
    turn = np.exp(-1j * theta)
    force = loads.fx + 1j * loads.fy
    moment = loads.first_moment_x() + 1j * loads.first_moment_y()
    return complex(np.mean(force * turn)), complex(np.mean(moment * turn))


def first_harmonic_corrections(loads: ShaftLoads, planes: Sequence[Plane]) -> tuple[Correction, ...]:
    """Corrections in one or two planes cancelling the forward first harmonic of ``loads`` (force, and couple
    with two planes): U = -A / w^2 in one plane; U_L + U_M = -A / w^2 and (z_L - z_ref) U_L + (z_M - z_ref) U_M =
    -C / w^2 in two. For rotating masses alone this is :func:`two_plane` (or :func:`single_plane`); for a
    cylinder it balances the direct crank, half the reciprocating mass."""
    a, c = forward_first_harmonic(loads)
    w2 = loads.speed**2
    if not w2 > 0:
        raise InputError(f"Balancing the first harmonic needs a shaft speed > 0; got {loads.speed:g} rad/s.")
    if len(planes) == 1:
        return (_correction(planes[0], -a / w2),)
    pl, pm = planes
    zl, zm = pl.position - loads.reference, pm.position - loads.reference
    if abs(zm - zl) <= 1e-9 * max(1.0, abs(pl.position), abs(pm.position)):
        raise InputError(f"The two correction planes '{pl.name}' and '{pm.name}' must stand at different axial "
                         f"positions; both are at {pl.position:g} m.")
    u_m = (-c / w2 + zl * a / w2) / (zm - zl)
    u_l = -a / w2 - u_m
    return (_correction(pl, u_l), _correction(pm, u_m))
