"""The Marin factors that turn a steel specimen's rotating-beam endurance limit into a part's, and the notch
sensitivity that turns a stress-concentration factor K_t into the fatigue notch factor K_f.

SI floats in and out (Pa, m, K); the empirical fits are in the units they were fitted in (MPa, kpsi, inches, °F),
converted at each function's boundary.

Sources
-------
- R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., McGraw-Hill 2015, ch. 6:
  §6-8 S_e' = 0.5 S_ut (S_ut <= 1400 MPa), else 700 MPa; §6-9 the Marin factors (Table 6-2 surface factor
  k_a = a S_ut^b, eq. 6-20 size factor k_b, eq. 6-26 load factor k_c, eq. 6-27 temperature factor k_d, eq. 6-28
  and Table 6-5 reliability factor k_e = 1 − 0.08 z_a); §6-10 notch sensitivity, K_f = 1 + q (K_t − 1) and
  Neuber's equation with √a of eq. 6-35.
- W. D. Pilkey, D. F. Pilkey, *Peterson's Stress Concentration Factors*, 3rd ed., Wiley 2008, §1.9 "Notch
  sensitivity": q = 1/(1 + a/r) with a = 0.0254 (2070/S_u)^1.8 mm for steels (S_u in MPa, >= 550 MPa).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from statistics import NormalDist

from ..errors import InputError

MPA = 1e6
KPSI = 6.894757293168361e6
INCH = 0.0254


def _positive(name: str, value: float) -> None:
    if not (math.isfinite(value) and value > 0):
        raise InputError(f"The {name} must be > 0; got {value!r}.")


#: Table 6-2 of Shigley's MED, 10th ed.: k_a = a S_ut^b with S_ut in MPa.
SURFACE_FACTORS: dict[str, tuple[float, float]] = {
    "ground": (1.58, -0.085),
    "machined": (4.51, -0.265),   # or cold-drawn
    "cold_drawn": (4.51, -0.265),
    "hot_rolled": (57.7, -0.718),
    "as_forged": (272.0, -0.995),
}
#: Eq. 6-26 of Shigley's MED, 10th ed.: k_c for the kind of load.
LOAD_FACTORS: dict[str, float] = {"bending": 1.0, "axial": 0.85, "torsion": 0.59}


def specimen_endurance_limit(ultimate: float) -> float:
    """The rotating-beam endurance limit of a steel specimen, S_e' = 0.5 S_ut for S_ut <= 1400 MPa, else 700 MPa
    (Shigley's MED, 10th ed., §6-8, eq. 6-8).

    Parameters
    ----------
    ultimate : S_ut [Pa] > 0, of a steel.

    Returns
    -------
    float
        S_e' [Pa].

    Examples
    --------
    >>> specimen_endurance_limit(600e6) / 1e6, specimen_endurance_limit(1600e6) / 1e6
    (300.0, 700.0)
    """
    _positive("ultimate strength", ultimate)
    return min(0.5 * ultimate, 700.0 * MPA)


def surface_factor(ultimate: float, finish: str) -> float:
    """The Marin surface factor k_a = a S_ut^b (Shigley's MED, 10th ed., §6-9, eq. 6-19 and Table 6-2; S_ut in
    MPa inside).

    Parameters
    ----------
    ultimate : S_ut [Pa] > 0.
    finish : "ground", "machined" (or "cold_drawn"), "hot_rolled" or "as_forged".

    Returns
    -------
    float
        k_a [-] (capped at 1: the fits exceed it only for soft steels far below their range).

    Examples
    --------
    Shigley's Example 6-3: a machined steel of 520 MPa has k_a = 4.51·520^−0.265 = 0.860:

    >>> round(surface_factor(520e6, "machined"), 3)
    0.86
    """
    _positive("ultimate strength", ultimate)
    if finish not in SURFACE_FACTORS:
        raise InputError(f"The surface finish must be one of {', '.join(SURFACE_FACTORS)}; got {finish!r}.")
    a, b = SURFACE_FACTORS[finish]
    return min(1.0, a * (ultimate / MPA) ** b)


def size_factor(diameter: float, load: str = "bending") -> float:
    """The Marin size factor of a round part (Shigley's MED, 10th ed., §6-9, eq. 6-20; d in mm inside):

    k_b = (d/7.62)^−0.107 = 1.24 d^−0.107 for 2.79 <= d <= 51 mm,  1.51 d^−0.157 for 51 < d <= 254 mm;
    k_b = 1 for an axial load. A non-rotating or non-round section enters with its equivalent diameter d_e
    (eq. 6-24, Table 6-3: d_e = 0.370 d for a non-rotating round bar).

    Parameters
    ----------
    diameter : d [m], 2.79 mm <= d <= 254 mm (bending, torsion).
    load : "bending", "torsion" or "axial".

    Returns
    -------
    float
        k_b [-].

    Examples
    --------
    Shigley's Example 6-4: a 32 mm rotating shaft, k_b = 0.858; non-rotating, d_e = 0.370·32 mm, k_b = 0.954:

    >>> round(size_factor(0.032), 3), round(size_factor(0.370 * 0.032), 3)
    (0.858, 0.954)
    """
    if load not in LOAD_FACTORS:
        raise InputError(f"The load must be one of {', '.join(LOAD_FACTORS)}; got {load!r}.")
    if load == "axial":
        return 1.0
    d = diameter * 1e3
    if not (math.isfinite(d) and 2.79 <= d <= 254.0):
        raise InputError(f"The size factor's fit holds for diameters of 2.79 to 254 mm; got {d:g} mm.")
    return (d / 7.62) ** -0.107 if d <= 51.0 else 1.51 * d**-0.157


def load_factor(load: str) -> float:
    """The Marin load factor k_c: 1 in bending, 0.85 axial, 0.59 in torsion (Shigley's MED, 10th ed., §6-9,
    eq. 6-26; for combined loading use 1 and the von Mises stresses, §6-14).

    Examples
    --------
    >>> load_factor("axial")
    0.85
    """
    if load not in LOAD_FACTORS:
        raise InputError(f"The load must be one of {', '.join(LOAD_FACTORS)}; got {load!r}.")
    return LOAD_FACTORS[load]


def temperature_factor(temperature: float) -> float:
    """The Marin temperature factor, the fourth-order fit of Shigley's MED, 10th ed., §6-9, eq. 6-27 (T in °F
    inside, 70 <= T_F <= 1000 °F):

    k_d = 0.975 + 0.432e−3 T_F − 0.115e−5 T_F² + 0.104e−8 T_F³ − 0.595e−12 T_F⁴

    Parameters
    ----------
    temperature : T [K] of the part in service, 294.3 K (21 °C) to 810.9 K (538 °C).

    Returns
    -------
    float
        k_d [-].

    Examples
    --------
    Shigley's Example 6-5: 450 °F (505.4 K) gives k_d = 1.007:

    >>> round(temperature_factor((450 - 32) * 5 / 9 + 273.15), 3)
    1.007
    """
    tf = (temperature - 273.15) * 9.0 / 5.0 + 32.0
    if not (math.isfinite(tf) and 70.0 - 1e-9 <= tf <= 1000.0 + 1e-9):
        raise InputError(f"The temperature factor's fit holds from 21 to 538 °C (294 to 811 K); got "
                         f"{temperature:g} K.")
    return 0.975 + 0.432e-3 * tf - 0.115e-5 * tf**2 + 0.104e-8 * tf**3 - 0.595e-12 * tf**4


def reliability_factor(reliability: float) -> float:
    """The Marin reliability factor k_e = 1 − 0.08 z_a, z_a the standard normal variate of the reliability
    (Shigley's MED, 10th ed., §6-9, eq. 6-28 and Table 6-5; an 8 % coefficient of variation of S_e).

    Parameters
    ----------
    reliability : R [-], 0.5 <= R < 1.

    Returns
    -------
    float
        k_e [-].

    Examples
    --------
    Table 6-5: 90 % 0.897, 99 % 0.814, 99.9 % 0.753:

    >>> [round(reliability_factor(r), 3) for r in (0.9, 0.99, 0.999)]
    [0.897, 0.814, 0.753]
    """
    if not (math.isfinite(reliability) and 0.5 <= reliability < 1.0):
        raise InputError(f"The reliability must be >= 0.5 and < 1 (a fraction); got {reliability!r}.")
    return 1.0 - 0.08 * NormalDist().inv_cdf(reliability)


@dataclass(frozen=True)
class Marin:
    """The endurance limit of a part S_e = k_a k_b k_c k_d k_e k_f S_e' [Pa] and its factors [-]."""

    endurance_limit: float
    specimen: float
    surface: float
    size: float
    load: float
    temperature: float
    reliability: float
    miscellaneous: float


def marin_endurance_limit(ultimate: float, *, finish: str = "machined", diameter: float | None = None,
                          load: str = "bending", temperature: float | None = None, reliability: float = 0.5,
                          miscellaneous: float = 1.0, specimen: float | None = None) -> Marin:
    """The endurance limit of a part, S_e = k_a k_b k_c k_d k_e k_f S_e' (Shigley's MED, 10th ed., §6-9, eq.
    6-18).

    Parameters
    ----------
    ultimate : S_ut [Pa] > 0.
    finish : the surface (:func:`surface_factor`).
    diameter : d [m] for :func:`size_factor`; None: k_b = 1.
    load : "bending", "axial" or "torsion" (:func:`load_factor`; with the von Mises stresses use "bending").
    temperature : T [K] (:func:`temperature_factor`); None: room temperature, k_d = 1.
    reliability : R [-] (:func:`reliability_factor`); 0.5: k_e = 1.
    miscellaneous : k_f [-] > 0 (corrosion, plating, ...).
    specimen : S_e' [Pa] from a test; None: :func:`specimen_endurance_limit`.

    Returns
    -------
    Marin

    Examples
    --------
    >>> m = marin_endurance_limit(690e6, diameter=0.032, reliability=0.99)
    >>> round(m.endurance_limit / 1e6, 1)
    192.1
    """
    se_prime = specimen_endurance_limit(ultimate) if specimen is None else specimen
    _positive("specimen endurance limit", se_prime)
    _positive("miscellaneous Marin factor", miscellaneous)
    ka = surface_factor(ultimate, finish)
    kb = 1.0 if diameter is None else size_factor(diameter, load)
    kc = load_factor(load)
    kd = 1.0 if temperature is None else temperature_factor(temperature)
    ke = reliability_factor(reliability)
    return Marin(ka * kb * kc * kd * ke * miscellaneous * se_prime, se_prime, ka, kb, kc, kd, ke, miscellaneous)


def neuber_sensitivity(ultimate: float, notch_radius: float, load: str = "bending") -> float:
    """Notch sensitivity of a steel by Neuber's equation, q = 1/(1 + √a/√r), with Neuber's constant fitted in
    Shigley's MED, 10th ed., §6-10, eqs. 6-34 and 6-35 (S_ut in kpsi, √a in √in inside; 50 <= S_ut <= 250 kpsi):

    bending or axial: √a = 0.246 − 3.08e−3 S_ut + 1.51e−5 S_ut² − 2.67e−8 S_ut³
    torsion:          √a = 0.190 − 2.51e−3 S_ut + 1.35e−5 S_ut² − 2.67e−8 S_ut³

    Parameters
    ----------
    ultimate : S_ut [Pa], 345 to 1724 MPa.
    notch_radius : r [m] > 0.
    load : "bending", "axial" or "torsion".

    Returns
    -------
    float
        q [-], 0 < q < 1.

    Examples
    --------
    Shigley's Example 6-6: 690 MPa, r = 3 mm, K_t = 1.65 gives K_f = 1.55:

    >>> round(fatigue_notch_factor(1.65, neuber_sensitivity(690e6, 0.003)), 2)
    1.55
    """
    _positive("notch radius", notch_radius)
    s = ultimate / KPSI
    if not (math.isfinite(s) and 50.0 - 1e-6 <= s <= 250.0 + 1e-6):
        raise InputError(f"Neuber's constant is fitted for steels of 345 to 1724 MPa; got {ultimate / MPA:g} MPa.")
    if load not in LOAD_FACTORS:
        raise InputError(f"The load must be one of {', '.join(LOAD_FACTORS)}; got {load!r}.")
    if load == "torsion":
        root_a = 0.190 - 2.51e-3 * s + 1.35e-5 * s**2 - 2.67e-8 * s**3
    else:
        root_a = 0.246 - 3.08e-3 * s + 1.51e-5 * s**2 - 2.67e-8 * s**3
    return 1.0 / (1.0 + root_a / math.sqrt(notch_radius / INCH))


def peterson_sensitivity(ultimate: float, notch_radius: float) -> float:
    """Notch sensitivity of a steel by Peterson's equation, q = 1/(1 + a/r), a = 0.0254 (2070/S_u)^1.8 mm
    (Pilkey & Pilkey, *Peterson's Stress Concentration Factors*, 3rd ed., §1.9; S_u in MPa inside, >= 550 MPa).

    Parameters
    ----------
    ultimate : S_u [Pa] >= 550 MPa; notch_radius : r [m] > 0.

    Returns
    -------
    float
        q [-].

    Examples
    --------
    >>> round(peterson_sensitivity(690e6, 0.003), 3)
    0.942
    """
    _positive("notch radius", notch_radius)
    if not (math.isfinite(ultimate) and ultimate >= 550.0 * MPA):
        raise InputError(f"Peterson's constant holds for steels of at least 550 MPa; got {ultimate / MPA:g} MPa.")
    a = 0.0254e-3 * (2070.0 * MPA / ultimate) ** 1.8
    return 1.0 / (1.0 + a / notch_radius)


def fatigue_notch_factor(stress_concentration: float, sensitivity: float) -> float:
    """K_f = 1 + q (K_t − 1) (Shigley's MED, 10th ed., §6-10, eq. 6-32).

    Parameters
    ----------
    stress_concentration : K_t [-] >= 1; sensitivity : q [-], 0 <= q <= 1.

    Examples
    --------
    >>> fatigue_notch_factor(2.0, 0.8)
    1.8
    """
    if not (math.isfinite(stress_concentration) and stress_concentration >= 1.0):
        raise InputError(f"A stress-concentration factor is >= 1; got {stress_concentration!r}.")
    if not (0.0 <= sensitivity <= 1.0):
        raise InputError(f"A notch sensitivity is between 0 and 1; got {sensitivity!r}.")
    return 1.0 + sensitivity * (stress_concentration - 1.0)
