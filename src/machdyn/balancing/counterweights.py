"""Crank counterweights of a slider-crank: full balance of the rotating masses, partial balance of the
reciprocating ones, and the trade-off between the force left along and across the stroke.

The connecting rod is split by static two-point substitution (:mod:`machdyn.balancing.substitution`) into a
rotating part at the crank pin and a reciprocating part at the slider. A counterweight opposite the crank pin
with first moment B b = (m_rot + c m_rec) r balances the rotating mass and the fraction c of the primary
reciprocating force; it moves the primary force (1 - c) m_rec r w^2 cos(theta) along the stroke into
c m_rec r w^2 sin(theta) across it (Khurmi & Gupta, *Theory of Machines*, 14th ed., ch. 22, sec. 22.2-22.3;
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed., sec. 16.8). The engine then evaluates
the exact balanced model (all harmonics, rod obliquity, rod inertia).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..errors import InputError, check_finite, check_positive
from ..linkage import RRP, Mechanism, PointMass, kinetostatics
from ..linkage.model import split_ref
from .frame import BalanceResult, compare, cycle, frame_loads
from .substitution import static_two_point

__all__ = [
    "balance_mass",
    "primary_unbalanced_force",
    "secondary_unbalanced_force",
    "SliderCrankMasses",
    "slider_crank_masses",
    "crank_counterweight",
    "TradeOff",
    "tradeoff_curve",
]


def balance_mass(rotating_mass, reciprocating_mass, crank_radius, fraction, balance_radius):
    """Balance mass B [kg] at radius b opposite the crank: B b = (m_1 + c m) r.

    Khurmi & Gupta, *Theory of Machines*, 14th ed., sec. 22.3 (all revolving and the fraction c of the
    reciprocating masses balanced).

    Parameters
    ----------
    rotating_mass : revolving mass m_1 at the crank radius [kg], >= 0
    reciprocating_mass : reciprocating mass m [kg], >= 0
    crank_radius : r [m], > 0
    fraction : c, the balanced fraction of the reciprocating mass [-], 0 ... 1
    balance_radius : b [m], > 0

    Examples
    --------
    Khurmi & Gupta, Example 22.1 (m = 50 kg, m_1 = 37 kg, r = 0.15 m, c = 2/3, b = 0.4 m):

    >>> round(balance_mass(37.0, 50.0, 0.15, 2 / 3, 0.4), 3)
    26.375
    """
    check_positive("rotating mass", rotating_mass, "kg", allow_zero=True)
    check_positive("reciprocating mass", reciprocating_mass, "kg", allow_zero=True)
    check_positive("crank radius", crank_radius, "m")
    check_positive("balance radius", balance_radius, "m")
    _check_fraction(fraction)
    return (rotating_mass + fraction * reciprocating_mass) * crank_radius / balance_radius


def _check_fraction(fraction) -> None:
    check_finite("balanced fraction", fraction)
    f = np.asarray(fraction, dtype=float)
    if np.any((f < 0) | (f > 1)):
        bad = f[(f < 0) | (f > 1)].ravel()[0] if f.ndim else float(f)
        raise InputError(f"The balanced fraction of the reciprocating mass must lie in 0 ... 1; got {bad:g}.")


def primary_unbalanced_force(crank_angle, reciprocating_mass, crank_radius, speed, fraction):
    """Primary force left after partial balance [N]: (along, across) the line of stroke.

    along = (1 - c) m w^2 r cos(theta), across = c m w^2 r sin(theta); resultant
    m w^2 r sqrt((1 - c)^2 cos^2 theta + c^2 sin^2 theta) (Khurmi & Gupta, 14th ed., sec. 22.3). theta is the
    crank angle from the inner (top) dead centre. Rod obliquity ignored (see :func:`secondary_unbalanced_force`).

    Parameters: crank_angle theta [rad]; reciprocating_mass m [kg] >= 0; crank_radius r [m] > 0; speed w
    [rad/s]; fraction c [-] in 0 ... 1.

    Examples
    --------
    >>> along, across = primary_unbalanced_force(np.pi / 2, 10.0, 0.1, 10.0, 0.6)
    >>> round(float(across), 6)
    60.0
    """
    check_finite("crank angle", crank_angle, "rad")
    check_positive("reciprocating mass", reciprocating_mass, "kg", allow_zero=True)
    check_positive("crank radius", crank_radius, "m")
    check_finite("speed", speed, "rad/s")
    _check_fraction(fraction)
    amplitude = reciprocating_mass * speed**2 * crank_radius
    theta = np.asarray(crank_angle, dtype=float)
    return (1.0 - fraction) * amplitude * np.cos(theta), fraction * amplitude * np.sin(theta)


def secondary_unbalanced_force(crank_angle, reciprocating_mass, crank_radius, speed, rod_ratio):
    """Secondary force along the stroke [N]: m w^2 r cos(2 theta) / n, n = rod length / crank radius
    (Khurmi & Gupta, 14th ed., sec. 22.5). A crank counterweight cannot balance it.

    Parameters: crank_angle [rad]; reciprocating_mass [kg] >= 0; crank_radius [m] > 0; speed [rad/s];
    rod_ratio n [-] > 1.

    Examples
    --------
    >>> round(float(secondary_unbalanced_force(0.0, 10.0, 0.1, 10.0, 4.0)), 6)
    25.0
    """
    check_finite("crank angle", crank_angle, "rad")
    check_positive("reciprocating mass", reciprocating_mass, "kg", allow_zero=True)
    check_positive("crank radius", crank_radius, "m")
    check_finite("speed", speed, "rad/s")
    check_positive("rod ratio n", rod_ratio)
    return reciprocating_mass * speed**2 * crank_radius * np.cos(2.0 * np.asarray(crank_angle, dtype=float)) / rod_ratio


@dataclass(frozen=True)
class SliderCrankMasses:
    """The masses of a slider-crank model split for balancing: rotating first moment about the crank pivot
    [kg*m] as a crank-frame vector, rotating mass at the pin [kg], reciprocating mass [kg], the crank pin
    (crank frame) and pivot [m], the stroke direction [rad] in global axes, and the names involved."""

    crank: str
    rod: str
    slider: str
    pin: tuple[float, float]
    pivot: tuple[float, float]
    rotating_moment: tuple[float, float]
    rotating_mass: float
    reciprocating_mass: float
    stroke_angle: float


def _first_moment(mech: Mechanism, body: str, about) -> tuple[float, np.ndarray]:
    """Mass [kg] and first moment [kg*m] about the body-frame point ``about`` of a body and its point masses."""
    b = mech.body(body)
    mass = float(b.mass)
    moment = float(b.mass) * (np.asarray(b.com, dtype=float) - about)
    for pm in mech.point_masses:
        if pm.body == body:
            mass += float(pm.mass)
            moment = moment + float(pm.mass) * (np.asarray(pm.position, dtype=float) - about)
    return mass, moment


def slider_crank_masses(mech: Mechanism) -> SliderCrankMasses:
    """Split a slider-crank model (crank + an RRP dyad on the crank pin with a guide fixed in the ground) into
    rotating and reciprocating masses, the rod by :func:`~machdyn.balancing.substitution.static_two_point`."""
    if mech.design_count is not None:
        raise InputError(f"Crank balancing takes a single design; mechanism '{mech.name}' has design arrays.")
    dyad = next((d for d in mech.dyads if isinstance(d, RRP) and split_ref(d.pin_a)[0] == mech.crank.body), None)
    if dyad is None or dyad.guide.body != "ground":
        raise InputError(
            f"Mechanism '{mech.name}' has no slider-crank: crank counterweights need an RRP dyad whose rod is "
            "pinned to the crank and whose slider runs on a guide fixed in the ground."
        )
    crank = mech.body(mech.crank.body)
    pivot = np.asarray(crank.points[split_ref(mech.crank.pivot)[1]], dtype=float)
    pin_name = split_ref(dyad.pin_a)[1]
    pin = np.asarray(crank.points[pin_name], dtype=float)
    rod = mech.body(dyad.a)
    rod_sub = static_two_point(rod, pin_name, dyad.inner, tolerance=1e-6)
    m_pin, m_slide = rod_sub.masses
    extra_rod = [pm for pm in mech.point_masses if pm.body == rod.name]
    if extra_rod:
        raise InputError(
            f"Point masses on the rod '{rod.name}' are not split; fold them into the rod's mass and centre."
        )
    _, crank_moment = _first_moment(mech, crank.name, pivot)
    slider_mass, _ = _first_moment(mech, dyad.b, np.zeros(2))
    rotating = crank_moment + m_pin * (pin - pivot)
    return SliderCrankMasses(
        crank=crank.name, rod=rod.name, slider=dyad.b, pin=tuple(pin), pivot=tuple(pivot),
        rotating_moment=(float(rotating[0]), float(rotating[1])), rotating_mass=float(m_pin),
        reciprocating_mass=float(m_slide + slider_mass), stroke_angle=float(np.asarray(dyad.guide.angle)),
    )


def _counterweight(masses: SliderCrankMasses, fraction, radius):
    """Counterweight mass [kg] and crank-frame position [m] for the balanced fraction(s) at ``radius``."""
    pin = np.asarray(masses.pin) - masses.pivot
    f = np.asarray(fraction, dtype=float)
    needed = -(np.asarray(masses.rotating_moment)[:, None] + masses.reciprocating_mass * pin[:, None] * f.ravel())
    size = np.hypot(needed[0], needed[1])
    direction = np.where(size > 0, needed / np.where(size > 0, size, 1.0), (-pin / np.hypot(*pin))[:, None])
    mass = size / radius
    position = np.asarray(masses.pivot)[:, None] + direction * radius
    return mass, position


def crank_counterweight(mech: Mechanism, fraction: float, radius: float, crank_angle=None,
                        speed: float = 1.0, name: str = "counterweight") -> BalanceResult:
    """Balance the rotating masses fully and ``fraction`` of the reciprocating mass with one counterweight on
    the crank at ``radius`` [m] from the pivot, opposite the rotating + reciprocating first moment.

    Parameters
    ----------
    mech : a slider-crank model (see :func:`slider_crank_masses`)
    fraction : balanced fraction c of the reciprocating mass [-], 0 ... 1 (commonly 1/2 ... 2/3)
    radius : counterweight radius b [m], > 0
    crank_angle : crank angles [rad] of the before/after evaluation (default one turn, 360 angles)
    speed : crank speed [rad/s] of the evaluation, > 0
    name : point-mass name of the counterweight

    Returns a :class:`~machdyn.balancing.frame.BalanceResult` whose model carries the point mass ``name``.
    """
    check_positive("counterweight radius", radius, "m")
    _check_fraction(fraction)
    masses = slider_crank_masses(mech)
    mass, position = _counterweight(masses, fraction, radius)
    cw = PointMass(name, masses.crank, float(mass[0]), (float(position[0, 0]), float(position[1, 0])))
    balanced = replace(mech, point_masses=tuple(mech.point_masses) + (cw,))
    phi = cycle() if crank_angle is None else crank_angle
    before, after = frame_loads(mech, phi, speed), frame_loads(balanced, phi, speed)
    note = (f"rotating mass at the pin {masses.rotating_mass:.6g} kg (rod share) and reciprocating mass "
            f"{masses.reciprocating_mass:.6g} kg; counterweight {cw.mass:.6g} kg at {radius:g} m")
    return BalanceResult(balanced, before, after, compare(before, after), (cw,), (note,))


@dataclass(frozen=True)
class TradeOff:
    """Peak and RMS shaking force [N] along and across the stroke, and the peak resultant, for each balanced
    fraction (exact engine values at the given speed), with the counterweight masses [kg]."""

    fraction: np.ndarray
    counterweight_mass: np.ndarray
    peak_along: np.ndarray
    peak_across: np.ndarray
    peak_total: np.ndarray
    rms_total: np.ndarray


def tradeoff_curve(mech: Mechanism, radius: float, fractions=None, crank_angle=None, speed: float = 1.0) -> TradeOff:
    """The partial-balance trade-off: for each fraction c the peak force left along the stroke falls like
    (1 - c) and the peak across it grows like c; evaluated for all fractions in one vectorised engine call.

    Parameters: mech a slider-crank model; radius [m] > 0; fractions [-] in 0 ... 1 (default 21 from 0 to 1);
    crank_angle [rad] (default one turn); speed [rad/s] > 0.
    """
    check_positive("counterweight radius", radius, "m")
    check_positive("crank speed", speed, "rad/s")
    f = np.linspace(0.0, 1.0, 21) if fractions is None else np.atleast_1d(np.asarray(fractions, dtype=float))
    _check_fraction(f)
    masses = slider_crank_masses(mech)
    mass, position = _counterweight(masses, f, radius)
    cw = PointMass("tradeoff_counterweight", masses.crank, mass, (position[0], position[1]))
    variants = replace(mech, point_masses=tuple(mech.point_masses) + (cw,), gravity=(0.0, 0.0))
    phi = cycle() if crank_angle is None else np.asarray(crank_angle, dtype=float)
    forces = kinetostatics(variants, phi, speed, 0.0)
    c, s = np.cos(masses.stroke_angle), np.sin(masses.stroke_angle)
    fx, fy = np.asarray(forces.frame_fx), np.asarray(forces.frame_fy)
    along, across = fx * c + fy * s, -fx * s + fy * c
    return TradeOff(
        fraction=f,
        counterweight_mass=np.asarray(mass, dtype=float),
        peak_along=np.max(np.abs(along), axis=-1),
        peak_across=np.max(np.abs(across), axis=-1),
        peak_total=np.max(np.hypot(fx, fy), axis=-1),
        rms_total=np.sqrt(np.mean(fx**2 + fy**2, axis=-1)),
    )
