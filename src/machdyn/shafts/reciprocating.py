"""Reciprocating machines in several planes: in-line, V, opposed and radial engines and compressors.

Each cylinder has its crank at angle ``phase`` on the shaft and its line of stroke at angle ``axis`` in the
transverse plane (x, y), at axial position z. With the shaft at theta the crank stands at phi = theta + phase -
axis from the cylinder's inner dead centre. For a zero-offset slider-crank of crank r and rod l the piston's
distance from the shaft is x = r cos phi + S, S = sqrt(l^2 - r^2 sin^2 phi), and at constant speed w

    x'' = -w^2 (r cos phi + r^2 cos 2phi / S + r^4 sin^2 phi cos^2 phi / S^3)     (exact),

so the reciprocating mass m puts the force -m x'' on the frame along the line of stroke. The textbooks keep the
first two terms of its series, the primary m w^2 r cos phi and the secondary m w^2 r cos(2 phi) / n, n = l / r
(Khurmi & Gupta, *Theory of Machines*, 14th ed., sec. 22.4-22.5 and 22.8-22.9; Uicker, Pennock & Shigley, 5th
ed., sec. 16.6-16.9). The exact force holds every even harmonic; its orders are found by the discrete Fourier
transform of the exact values (:func:`machdyn.linkage.harmonics.harmonics`). A rotating mass at the crank pin
(crank web plus the rod's rotating share) adds m_rot r w^2 along the crank.

The direct-and-reverse-crank method (Khurmi & Gupta, 14th ed., sec. 22.10-22.11) writes each primary force as
two half-masses on cranks turning +w and -w: the resultants sum(m r / 2 e^{i phase}) and
sum(m r / 2 e^{i (2 axis - phase)}); the secondary ones sum(m r / 2n e^{i (2 phase - axis)}) and
sum(m r / 2n e^{i (3 axis - 2 phase)}) on cranks of 2w. The largest resultant force of an order is w^2 (|D| + |R|).
Valid for zero-offset cylinders, rod longer than crank, rigid shaft at constant speed.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ..errors import InputError, check_finite, check_positive
from .rotating import Mass, ShaftLoads, cycle, rotating_loads

__all__ = ["Cylinder", "piston_acceleration", "reciprocating_loads", "two_term_loads", "direct_reverse",
           "crank_phases_from_firing_order", "EngineOrders", "engine_orders"]


@dataclass(frozen=True)
class Cylinder:
    """One cylinder: ``name``; axial ``position`` [m]; crank ``phase`` [rad] on the shaft; line of stroke
    ``axis`` [rad] in the transverse plane (from x towards y); ``crank`` radius r [m] > 0; ``rod`` length l [m] >
    r; ``reciprocating_mass`` [kg] >= 0; ``rotating_mass`` [kg] >= 0 at the crank pin."""

    name: str
    position: float
    phase: float
    axis: float
    crank: float
    rod: float
    reciprocating_mass: float
    rotating_mass: float = 0.0

    def __post_init__(self) -> None:
        check_finite(f"axial position of cylinder '{self.name}'", self.position, "m")
        check_finite(f"crank phase of cylinder '{self.name}'", self.phase, "rad")
        check_finite(f"axis of cylinder '{self.name}'", self.axis, "rad")
        check_positive(f"crank radius of cylinder '{self.name}'", self.crank, "m")
        check_positive(f"rod length of cylinder '{self.name}'", self.rod, "m")
        check_positive(f"reciprocating mass of cylinder '{self.name}'", self.reciprocating_mass, "kg", allow_zero=True)
        check_positive(f"rotating mass of cylinder '{self.name}'", self.rotating_mass, "kg", allow_zero=True)
        if not self.rod > self.crank:
            raise InputError(f"The rod of cylinder '{self.name}' must be longer than its crank ({self.crank:g} m); "
                             f"got {self.rod:g} m.")

    @property
    def ratio(self) -> float:
        """n = l / r [-]."""
        return self.rod / self.crank

    def crank_mass(self) -> Mass:
        """The rotating mass at the crank pin as a :class:`~machdyn.shafts.rotating.Mass`."""
        return Mass(f"{self.name} crank", self.rotating_mass, self.crank, self.phase, self.position)


def piston_acceleration(phi, crank: float, rod: float, speed: float):
    """Exact piston acceleration [m/s^2] along the line of stroke (away from the shaft positive) of a zero-offset
    slider-crank at crank angle phi [rad] from inner dead centre, crank r [m], rod l [m] > r, constant speed w
    [rad/s] (module docstring; Uicker, Pennock & Shigley, 5th ed., sec. 16.6, eq. before the series).

    Examples
    --------
    At inner dead centre: -w^2 r (1 + r / l).

    >>> round(float(piston_acceleration(0.0, 0.1, 0.4, 10.0)), 12)
    -12.5
    """
    p = np.asarray(phi, dtype=float)
    s = np.sqrt(rod**2 - (crank * np.sin(p)) ** 2)
    return -(speed**2) * (crank * np.cos(p) + crank**2 * np.cos(2 * p) / s
                          + crank**4 * np.sin(p) ** 2 * np.cos(p) ** 2 / s**3)


def _zero(theta, speed, reference) -> ShaftLoads:
    z = np.zeros_like(theta)
    return ShaftLoads(theta, float(speed), z, z, z, z, float(reference))


def _line_loads(cyl: Cylinder, along, theta, speed, reference) -> ShaftLoads:
    d = np.exp(1j * cyl.axis) * along
    z = cyl.position - reference
    return ShaftLoads(theta, float(speed), d.real, d.imag, -z * d.imag, z * d.real, float(reference))


def reciprocating_loads(cylinders: Sequence[Cylinder], speed: float, angle=None, reference: float = 0.0,
                        include_rotating: bool = True) -> ShaftLoads:
    """Exact frame loads of the cylinders' reciprocating masses (and their rotating masses if asked): the force
    -m x'' along each line of stroke and its couples about the plane ``reference`` [m]."""
    check_finite("shaft speed", speed, "rad/s")
    theta = cycle() if angle is None else np.asarray(angle, dtype=float)
    total = _zero(theta, speed, reference)
    for c in cylinders:
        phi = theta + c.phase - c.axis
        total = total + _line_loads(c, -c.reciprocating_mass * piston_acceleration(phi, c.crank, c.rod, speed),
                                    theta, speed, reference)
    if include_rotating:
        total = total + rotating_loads([c.crank_mass() for c in cylinders], speed, theta, reference)
    return total


def two_term_loads(cylinders: Sequence[Cylinder], speed: float, order: int, angle=None,
                   reference: float = 0.0) -> ShaftLoads:
    """The textbooks' primary (``order`` 1: m w^2 r cos phi) or secondary (``order`` 2: m w^2 r cos 2phi / n)
    loads of the reciprocating masses (Khurmi & Gupta, 14th ed., sec. 22.4-22.5)."""
    if order not in (1, 2):
        raise InputError(f"The two-term series has orders 1 (primary) and 2 (secondary); got {order!r}.")
    theta = cycle() if angle is None else np.asarray(angle, dtype=float)
    total = _zero(theta, speed, reference)
    for c in cylinders:
        phi = theta + c.phase - c.axis
        amp = c.reciprocating_mass * speed**2 * c.crank
        along = amp * np.cos(phi) if order == 1 else amp * np.cos(2 * phi) / c.ratio
        total = total + _line_loads(c, along, theta, speed, reference)
    return total


def direct_reverse(cylinders: Sequence[Cylinder], order: int, reference: float = 0.0,
                   couple: bool = False) -> tuple[complex, complex]:
    """The direct and reverse crank resultants of the primary (order 1) or secondary (order 2) reciprocating
    effects [kg*m] (or their moments about ``reference`` [kg*m^2] if ``couple``): module docstring (Khurmi &
    Gupta, 14th ed., sec. 22.10-22.11)."""
    d = r = 0j
    for c in cylinders:
        w = c.reciprocating_mass * c.crank * ((c.position - reference) if couple else 1.0)
        if order == 1:
            d += w / 2 * np.exp(1j * c.phase)
            r += w / 2 * np.exp(1j * (2 * c.axis - c.phase))
        elif order == 2:
            d += w / (2 * c.ratio) * np.exp(1j * (2 * c.phase - c.axis))
            r += w / (2 * c.ratio) * np.exp(1j * (3 * c.axis - 2 * c.phase))
        else:
            raise InputError(f"Direct and reverse cranks are built for orders 1 and 2; got {order!r}.")
    return complex(d), complex(r)


def crank_phases_from_firing_order(order: Sequence[int], strokes: int = 4) -> dict[int, float]:
    """Crank phases [rad] of cylinders (numbered 1..N) firing in ``order``, evenly spaced by 720/N deg for a
    four-stroke or 360/N deg for a two-stroke cycle: the k-th cylinder to fire reaches its firing dead centre
    k * interval after the first, so its crank trails by that angle (Khurmi & Gupta, 14th ed., sec. 22.12).

    Examples
    --------
    >>> {k: round(float(np.degrees(v))) for k, v in crank_phases_from_firing_order([1, 3, 4, 2]).items()}
    {1: 0, 3: 180, 4: 0, 2: 180}
    """
    n = len(order)
    if strokes not in (2, 4):
        raise InputError(f"An engine cycle has 2 or 4 strokes; got {strokes!r}.")
    if sorted(order) != list(range(1, n + 1)):
        raise InputError(f"A firing order must name each cylinder 1..{n} once; got {list(order)}.")
    interval = (4 * np.pi if strokes == 4 else 2 * np.pi) / n
    return {int(c): float((-k * interval) % (2 * np.pi)) for k, c in enumerate(order)}


@dataclass(frozen=True)
class EngineOrders:
    """Largest resultant force [N] and couple [N*m] over the turn: exact total, exact harmonic orders 1..k, and
    the textbooks' primary and secondary values; with the direct/reverse resultants of both orders [kg*m]."""

    exact: ShaftLoads
    orders: np.ndarray
    force_order: np.ndarray
    couple_order: np.ndarray
    primary_force: float
    secondary_force: float
    primary_couple: float
    secondary_couple: float
    primary_dr: tuple[complex, complex]
    secondary_dr: tuple[complex, complex]


def _order_peak(a, b, theta, orders) -> np.ndarray:
    """max over the turn of |(a_k, b_k)|, a_k the order-k part of a."""
    fa, fb = np.fft.rfft(a), np.fft.rfft(b)
    n = theta.size
    out = []
    for k in orders:
        ak = 2.0 / n * np.abs(fa[k]) * np.cos(k * theta + np.angle(fa[k]))
        bk = 2.0 / n * np.abs(fb[k]) * np.cos(k * theta + np.angle(fb[k]))
        out.append(float(np.max(np.hypot(ak, bk))))
    return np.array(out)


def engine_orders(cylinders: Sequence[Cylinder], speed: float, samples: int = 360, harmonics: int = 6,
                  reference: float = 0.0, include_rotating: bool = False) -> EngineOrders:
    """The engine's shaking force and couple: exact, by harmonic order, and the two-term primary and secondary
    values beside them. Uniform angles over one turn (``samples`` >= 4 * harmonics)."""
    if not 1 <= harmonics < samples // 2:
        raise InputError(f"The highest harmonic must lie in 1 ... {samples // 2 - 1}; got {harmonics!r}.")
    theta = cycle(samples)
    exact = reciprocating_loads(cylinders, speed, theta, reference, include_rotating)
    orders = np.arange(1, harmonics + 1)
    p, s = (two_term_loads(cylinders, speed, k, theta, reference) for k in (1, 2))
    return EngineOrders(
        exact=exact, orders=orders,
        force_order=_order_peak(exact.fx, exact.fy, theta, orders),
        couple_order=_order_peak(exact.mx, exact.my, theta, orders),
        primary_force=p.peak_force, secondary_force=s.peak_force,
        primary_couple=p.peak_couple, secondary_couple=s.peak_couple,
        primary_dr=direct_reverse(cylinders, 1, reference), secondary_dr=direct_reverse(cylinders, 2, reference),
    )
