"""Spur gear teeth: the bending stress at the root by Lewis's equation with Barth's velocity factor, and the surface
(Hertz) contact stress of the mating flanks.

All functions take and return SI floats: m, N, Pa, m/s.

Sources
-------
- R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., McGraw-Hill 2015, §14-1
  "The Lewis bending equation": σ = K_v W_t / (F m Y) (eq. 14-8, SI), the Lewis form factor Y of 20° full-depth
  teeth (Table 14-2) and Barth's velocity factors (eqs. 14-4a–d, SI: cast iron cast profile (3.05 + V)/3.05, cut
  or milled (6.1 + V)/6.1, hobbed or shaped (3.56 + √V)/3.56, shaved or ground (5.56 + √V)/5.56, V in m/s);
  §14-5 "Surface durability": σ_c = −C_p [K_v W_t/(F cos φ) (1/r1 + 1/r2)]^{1/2} (eq. 14-14) with the elastic
  coefficient C_p = [π ((1 − ν1²)/E1 + (1 − ν2²)/E2)]^{−1/2} (eq. 14-13) and r = d sin φ / 2.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError

#: Shigley's MED, 10th ed., Table 14-2: the Lewis form factor Y of 20° full-depth teeth by the number of teeth.
LEWIS_TEETH = (12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 24, 26, 28, 30, 34, 38, 43, 50, 60, 75, 100, 150, 300,
               400)
LEWIS_Y = (0.245, 0.261, 0.277, 0.290, 0.296, 0.303, 0.309, 0.314, 0.322, 0.328, 0.331, 0.337, 0.346, 0.353,
           0.359, 0.371, 0.384, 0.397, 0.409, 0.422, 0.435, 0.447, 0.460, 0.472, 0.480)
RACK_Y = 0.485

#: Barth's velocity factors (Shigley's MED, 10th ed., eq. 14-4, V in m/s): K_v = (c + V^e)/c.
MANUFACTURE = {"cast": (3.05, 1.0), "cut": (6.1, 1.0), "hobbed": (3.56, 0.5), "ground": (5.56, 0.5)}


def lewis_form_factor(teeth: float) -> float:
    """Y of a 20° full-depth tooth (Shigley's MED, 10th ed., Table 14-2), linear between the tabulated numbers of
    teeth, the rack's 0.485 beyond 400 teeth.

    Parameters
    ----------
    teeth : N >= 12.

    Returns
    -------
    float
        Y [-].

    Examples
    --------
    >>> lewis_form_factor(16), lewis_form_factor(23)
    (0.296, 0.334)
    """
    if not (math.isfinite(teeth) and teeth >= 12):
        raise InputError(f"Table 14-2 of the Lewis form factor starts at 12 teeth; got {teeth!r}.")
    if teeth > 400:
        return RACK_Y
    return float(np.interp(teeth, LEWIS_TEETH, LEWIS_Y))


def velocity_factor(pitch_speed: float, manufacture: str = "hobbed") -> float:
    """Barth's dynamic (velocity) factor K_v (Shigley's MED, 10th ed., §14-1, eqs. 14-4a–d, SI form).

    Parameters
    ----------
    pitch_speed : V [m/s] >= 0, the pitch-line speed.
    manufacture : "cast" (cast iron, cast profile), "cut" (cut or milled), "hobbed" (or shaped) or "ground"
        (or shaved).

    Returns
    -------
    float
        K_v [-] >= 1.

    Examples
    --------
    >>> round(velocity_factor(3.192, "cut"), 4)
    1.5233
    """
    if manufacture not in MANUFACTURE:
        raise InputError(f"The teeth are {', '.join(MANUFACTURE)}; got {manufacture!r}.")
    if not (math.isfinite(pitch_speed) and pitch_speed >= 0):
        raise InputError(f"A pitch-line speed is >= 0; got {pitch_speed!r}.")
    c, e = MANUFACTURE[manufacture]
    return (c + pitch_speed**e) / c


def lewis_bending_stress(tangential_load: float, face_width: float, module: float, teeth: float,
                         pitch_speed: float, manufacture: str = "hobbed") -> float:
    """The bending stress at a tooth's root by Lewis's equation, σ = K_v W_t / (F m Y) (Shigley's MED, 10th ed.,
    eq. 14-8). Valid for spur gears whose load acts at the tip of one tooth, with the velocity factor as the only
    allowance for dynamics (no AGMA/ISO 6336 factors).

    Parameters
    ----------
    tangential_load : W_t [N] >= 0 at the pitch circle.
    face_width : F [m] > 0.
    module : m [m] > 0.
    teeth : N of the gear checked (>= 12).
    pitch_speed : V [m/s].
    manufacture : see :func:`velocity_factor`.

    Returns
    -------
    float
        σ [Pa].

    Examples
    --------
    >>> round(lewis_bending_stress(1000.0, 0.03, 0.003, 20, 5.0) / 1e6, 2)
    56.18
    """
    for name, value in (("face width", face_width), ("module", module)):
        if not (math.isfinite(value) and value > 0):
            raise InputError(f"A gear's {name} must be > 0; got {value!r}.")
    if not (math.isfinite(tangential_load) and tangential_load >= 0):
        raise InputError(f"A tangential load is >= 0; got {tangential_load!r}.")
    kv = velocity_factor(pitch_speed, manufacture)
    return kv * tangential_load / (face_width * module * lewis_form_factor(teeth))


def elastic_coefficient(modulus_1: float, poisson_1: float, modulus_2: float, poisson_2: float) -> float:
    """C_p = [π ((1 − ν1²)/E1 + (1 − ν2²)/E2)]^{−1/2} (Shigley's MED, 10th ed., eq. 14-13).

    Parameters
    ----------
    modulus_1, modulus_2 : E [Pa] > 0; poisson_1, poisson_2 : ν [-], 0 <= ν < 0.5.

    Returns
    -------
    float
        C_p [√Pa].

    Examples
    --------
    Steel on steel (207 GPa, 0.3): C_p = 190.3 √MPa (Table 14-8 prints 191, from 2300 √psi rounded):

    >>> round(elastic_coefficient(207e9, 0.3, 207e9, 0.3) / 1e3, 1)
    190.3
    """
    for e, nu in ((modulus_1, poisson_1), (modulus_2, poisson_2)):
        if not (math.isfinite(e) and e > 0 and 0.0 <= nu < 0.5):
            raise InputError(f"A gear material needs E > 0 and 0 <= ν < 0.5; got E = {e!r}, ν = {nu!r}.")
    return 1.0 / math.sqrt(math.pi * ((1 - poisson_1**2) / modulus_1 + (1 - poisson_2**2) / modulus_2))


def contact_stress(tangential_load: float, face_width: float, pinion_diameter: float, gear_diameter: float,
                   pitch_speed: float, *, pressure_angle: float = math.radians(20.0), manufacture: str = "hobbed",
                   elastic: float | None = None) -> float:
    """The Hertz contact stress of two spur gears' flanks at the pitch point, reported as a magnitude (Shigley's
    MED, 10th ed., eq. 14-14, which writes it negative, a compression):

    σ_c = C_p [K_v W_t / (F cos φ) (1/r1 + 1/r2)]^{1/2},  r_i = d_i sin φ / 2

    Parameters
    ----------
    tangential_load : W_t [N] >= 0; face_width : F [m] > 0;
    pinion_diameter, gear_diameter : d [m] > 0 of the pitch circles (external gears);
    pitch_speed : V [m/s]; pressure_angle : φ [rad], 0 < φ < 45°; manufacture : see :func:`velocity_factor`;
    elastic : C_p [√Pa] (:func:`elastic_coefficient`; None: steel on steel, 207 GPa and 0.3, 190 √MPa).

    Returns
    -------
    float
        |σ_c| [Pa].

    Examples
    --------
    >>> round(contact_stress(1000.0, 0.03, 0.06, 0.18, 5.0) / 1e6, 1)
    521.2
    """
    if not (0.0 < pressure_angle < math.radians(45.0)):
        raise InputError(f"A pressure angle is between 0 and 45°; got {math.degrees(pressure_angle):g}°.")
    for name, value in (("face width", face_width), ("pinion diameter", pinion_diameter),
                        ("gear diameter", gear_diameter)):
        if not (math.isfinite(value) and value > 0):
            raise InputError(f"A gear's {name} must be > 0; got {value!r}.")
    if elastic is None:
        elastic = elastic_coefficient(207e9, 0.3, 207e9, 0.3)
    kv = velocity_factor(pitch_speed, manufacture)
    r1 = pinion_diameter * math.sin(pressure_angle) / 2.0
    r2 = gear_diameter * math.sin(pressure_angle) / 2.0
    return elastic * math.sqrt(kv * tangential_load / (face_width * math.cos(pressure_angle)) * (1 / r1 + 1 / r2))
