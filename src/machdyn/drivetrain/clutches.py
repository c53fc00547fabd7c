"""Friction clutches from their geometry: the torque a plate, multi-plate, cone or centrifugal clutch passes while
it slips, from the coefficient of friction, the axial force (or the largest pressure), the radii, the cone angle,
the shoes' mass, the spring force and the speed.

Two pressure laws bound a flat or conical friction face. A new face, rigid plates: the pressure is uniform,
p = const. A worn face: the wear rate, proportional to p·r, is the same everywhere, so p·r = const and the largest
pressure acts at the inner radius. Uniform wear gives the smaller torque for the same force and is the law
designers use (Shigley's §16-5).

All functions take and return SI floats: m, N, Pa, kg, rad, rad/s, N·m.

Sources
-------
- R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., McGraw-Hill 2015, §16-5
  "Frictional-contact axial clutches" (uniform wear: F = π p_a d (D − d)/2, T = F f (D + d)/4; uniform pressure:
  F = π p_a (D² − d²)/4, T = F f (D³ − d³)/(3 (D² − d²))) and §16-6 "Disk brakes"/"Cone clutches and brakes"
  (the same with the torque divided by sin α).
- R. S. Khurmi, J. K. Gupta, *Theory of Machines*, 14th ed., S. Chand/Eurasia 2005, ch. 10 "Friction",
  §§ "Single disc or plate clutch", "Multiple disc clutch", "Cone clutch" and "Centrifugal clutch"
  (T = n μ (P_c − P_s) R, P_c = m ω² r).
- Each closed form is checked in the tests against the numerical integral of its pressure distribution
  (:func:`scipy.integrate.quad`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

from ..errors import InputError

Law = Literal["uniform_wear", "uniform_pressure"]
LAWS: tuple[str, ...] = ("uniform_wear", "uniform_pressure")


def _finite_positive(name: str, value: float, *, allow_zero: bool = False) -> None:
    ok = math.isfinite(value) and (value >= 0 if allow_zero else value > 0)
    if not ok:
        raise InputError(f"The clutch's {name} must be {'>= 0' if allow_zero else '> 0'}; got {value!r}.")


def _check_radii(inner: float, outer: float) -> None:
    _finite_positive("outer radius", outer)
    _finite_positive("inner radius", inner, allow_zero=True)
    if not inner < outer:
        raise InputError(f"The friction face's inner radius {inner:g} m must be smaller than its outer radius "
                         f"{outer:g} m.")


def _check_law(law: str) -> None:
    if law not in LAWS:
        raise InputError(f"The pressure law must be one of {', '.join(LAWS)}; got {law!r}.")


def friction_radius(inner: float, outer: float, law: Law = "uniform_wear") -> float:
    """The mean friction radius R_f of an annular face, T = μ F R_f per face (Shigley's MED, 10th ed., §16-5).

    uniform wear:     R_f = (r_o + r_i)/2
    uniform pressure: R_f = 2 (r_o³ − r_i³) / (3 (r_o² − r_i²))

    Parameters
    ----------
    inner : r_i [m], 0 <= r_i < r_o.
    outer : r_o [m] > 0.
    law : "uniform_wear" (a worn face, p·r = const) or "uniform_pressure" (a new face).

    Returns
    -------
    float
        R_f [m], between r_i and r_o.

    Examples
    --------
    >>> friction_radius(0.1, 0.15), round(friction_radius(0.1, 0.15, "uniform_pressure"), 5)
    (0.125, 0.12667)
    """
    _check_radii(inner, outer)
    _check_law(law)
    if law == "uniform_wear":
        return 0.5 * (outer + inner)
    return 2.0 * (outer**3 - inner**3) / (3.0 * (outer**2 - inner**2))


def axial_force(max_pressure: float, inner: float, outer: float, law: Law = "uniform_wear") -> float:
    """The axial force that presses an annular face to the largest pressure p_a (Shigley's MED, 10th ed., §16-5).

    uniform wear:     F = 2π p_a r_i (r_o − r_i)   (p_a at the inner radius; needs r_i > 0)
    uniform pressure: F = π p_a (r_o² − r_i²)

    Parameters
    ----------
    max_pressure : p_a [Pa] > 0, the largest pressure the lining admits.
    inner, outer : r_i, r_o [m], 0 <= r_i < r_o (r_i > 0 for uniform wear: p·r = const is unbounded at r = 0).
    law : "uniform_wear" or "uniform_pressure".

    Returns
    -------
    float
        F [N].

    Examples
    --------
    A face of 200 and 300 mm diameters at 0.1 MPa (uniform wear): F = 2π·0.1e6·0.1·0.05 = 3142 N:

    >>> round(axial_force(0.1e6, 0.1, 0.15))
    3142
    """
    _check_radii(inner, outer)
    _check_law(law)
    _finite_positive("largest pressure", max_pressure)
    if law == "uniform_wear":
        if inner <= 0:
            raise InputError("Uniform wear needs an inner radius > 0: the pressure p = p_a r_i / r is unbounded "
                             "at the centre.")
        return 2.0 * math.pi * max_pressure * inner * (outer - inner)
    return math.pi * max_pressure * (outer**2 - inner**2)


def max_pressure(force: float, inner: float, outer: float, law: Law = "uniform_wear") -> float:
    """The largest pressure on an annular face pressed by the axial force F: the inverse of :func:`axial_force`.

    Parameters
    ----------
    force : F [N] > 0; inner, outer : r_i, r_o [m]; law : as :func:`axial_force`.

    Returns
    -------
    float
        p_a [Pa].

    Examples
    --------
    >>> round(max_pressure(3141.5927, 0.1, 0.15) / 1e6, 4)
    0.1
    """
    _finite_positive("axial force", force)
    return force / axial_force(1.0, inner, outer, law)


def plate_clutch_torque(friction: float, force: float, inner: float, outer: float, surfaces: int = 2,
                        law: Law = "uniform_wear") -> float:
    """The slip torque of a single- or multi-plate clutch (or an annular disc brake), T = n μ F R_f
    (Shigley's MED, 10th ed., §16-5; Khurmi & Gupta, *Theory of Machines*, ch. 10, "Multiple disc clutch").

    Parameters
    ----------
    friction : μ [-] > 0, the coefficient of friction of the lining.
    force : F [N] >= 0, the axial (spring) force pressing the plates together.
    inner, outer : r_i, r_o [m] of the friction faces, 0 <= r_i < r_o.
    surfaces : n, the number of pairs of friction faces in contact (a single plate gripped on both sides: 2;
        a multi-plate clutch with n1 driving and n2 driven plates: n1 + n2 − 1).
    law : "uniform_wear" (design value) or "uniform_pressure".

    Returns
    -------
    float
        T [N·m]. Valid for flat annular faces with a constant coefficient of friction.

    Examples
    --------
    A single plate, both sides effective, 300/200 mm diameters, μ = 0.3, pressed to 0.1 MPa (uniform wear):
    T = 2·0.3·3142·0.125 = 235.6 N·m:

    >>> round(plate_clutch_torque(0.3, axial_force(0.1e6, 0.1, 0.15), 0.1, 0.15), 1)
    235.6
    """
    _finite_positive("coefficient of friction", friction)
    _finite_positive("axial force", force, allow_zero=True)
    if int(surfaces) != surfaces or surfaces < 1:
        raise InputError(f"A plate clutch has a whole number >= 1 of friction surfaces; got {surfaces!r}.")
    return surfaces * friction * force * friction_radius(inner, outer, law)


def cone_clutch_torque(friction: float, force: float, inner: float, outer: float, half_angle: float,
                       law: Law = "uniform_wear") -> float:
    """The slip torque of a cone clutch, T = μ F R_f / sin α (Shigley's MED, 10th ed., §16-6 "Cone clutches and
    brakes"; Khurmi & Gupta, *Theory of Machines*, ch. 10, "Cone clutch").

    The axial force F presses the cone; the normal force on the face is F / sin α.

    Parameters
    ----------
    friction : μ [-] > 0.
    force : F [N] >= 0, the axial force.
    inner, outer : r_i, r_o [m], the radii of the ends of the conical face, 0 <= r_i < r_o.
    half_angle : α [rad], the semi-cone angle (between the face and the axis), 0 < α <= π/2 (π/2: a flat plate).
        Cones below about 8° (tan α < μ) tend to grab and need a force to come apart.
    law : "uniform_wear" or "uniform_pressure".

    Returns
    -------
    float
        T [N·m].

    Examples
    --------
    >>> round(cone_clutch_torque(0.3, 1000.0, 0.1, 0.15, math.radians(12.5)), 2)
    173.26
    """
    if not (math.isfinite(half_angle) and 0.0 < half_angle <= 0.5 * math.pi):
        raise InputError(f"A cone clutch's semi-cone angle must be > 0 and <= 90°; got "
                         f"{math.degrees(half_angle):g}°.")
    return plate_clutch_torque(friction, force, inner, outer, 1, law) / math.sin(half_angle)


def cone_axial_force(max_pressure: float, inner: float, outer: float, law: Law = "uniform_wear") -> float:
    """The axial force of a cone clutch at the largest face pressure p_a: the same as a flat face of the same end
    radii, since the face's normal force F/sin α acts on an area 1/sin α times larger (Shigley's MED, 10th ed.,
    §16-6). See :func:`axial_force`.

    Examples
    --------
    >>> cone_axial_force(1e5, 0.1, 0.15) == axial_force(1e5, 0.1, 0.15)
    True
    """
    return axial_force(max_pressure, inner, outer, law)


@dataclass(frozen=True)
class Centrifugal:
    """A centrifugal clutch at one speed: the centrifugal force of one shoe [N], the net force pressing it on the
    drum [N], the torque [N·m] and the speed at which the shoes touch the drum [rad/s]."""

    centrifugal_force: float
    contact_force: float
    torque: float
    engagement_speed: float


def centrifugal_clutch(friction: float, shoes: int, shoe_mass: float, shoe_radius: float, drum_radius: float,
                       spring_force: float, speed: float) -> Centrifugal:
    """The torque of a centrifugal clutch of n shoes held back by springs (Khurmi & Gupta, *Theory of Machines*,
    14th ed., ch. 10, "Centrifugal clutch").

    P_c = m ω² r,   T = n μ (P_c − P_s) R  for P_c > P_s, else 0;   engagement at ω_e = √(P_s / (m r)).

    Parameters
    ----------
    friction : μ [-] > 0 between shoe and drum.
    shoes : n >= 1.
    shoe_mass : m [kg] > 0 of one shoe.
    shoe_radius : r [m] > 0, the radius of the shoes' centre of mass when they touch the drum.
    drum_radius : R [m] >= r, the inner radius of the drum.
    spring_force : P_s [N] >= 0, the spring's force on one shoe when it touches the drum (the spring's pull on the
        shoe, inwards).
    speed : ω [rad/s] >= 0 of the driving (shoe) side.

    Returns
    -------
    Centrifugal

    Examples
    --------
    Four shoes of 2 kg at 120 mm, drum 150 mm, springs 500 N, μ = 0.25, at 1000 rpm: P_c = 2·104.72²·0.12 =
    2632 N, T = 4·0.25·2132·0.15 = 319.8 N·m:

    >>> c = centrifugal_clutch(0.25, 4, 2.0, 0.12, 0.15, 500.0, 1000 * math.pi / 30)
    >>> round(c.centrifugal_force), round(c.torque, 1), round(c.engagement_speed * 30 / math.pi)
    (2632, 319.8, 436)
    """
    _finite_positive("coefficient of friction", friction)
    _finite_positive("shoe mass", shoe_mass)
    _finite_positive("shoe radius", shoe_radius)
    _finite_positive("spring force", spring_force, allow_zero=True)
    _finite_positive("speed", speed, allow_zero=True)
    if int(shoes) != shoes or shoes < 1:
        raise InputError(f"A centrifugal clutch has a whole number >= 1 of shoes; got {shoes!r}.")
    if not (math.isfinite(drum_radius) and drum_radius >= shoe_radius):
        raise InputError(f"The drum's inner radius {drum_radius!r} m must be at least the radius of the shoes' "
                         f"centre of mass {shoe_radius:g} m.")
    pc = shoe_mass * speed**2 * shoe_radius
    contact = max(pc - spring_force, 0.0)
    return Centrifugal(pc, contact, shoes * friction * contact * drum_radius,
                       math.sqrt(spring_force / (shoe_mass * shoe_radius)))
