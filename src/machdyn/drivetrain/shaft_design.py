"""Shafts: a round section under fluctuating bending and torsion judged by the distortion-energy (DE) fatigue
criteria, its diameter for a factor of safety, and the bending deflection and first critical speed of a simply
supported shaft carrying point masses (Rayleigh and Dunkerley, and the exact first eigenvalue of the lumped model).

SI floats: m, N, N·m, Pa, kg, rad/s.

Sources
-------
- R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., McGraw-Hill 2015, ch. 7:
  §7-4 "Shaft design for stress": σ_a = K_f 32 M_a/(π d³), τ_a = K_fs 16 T_a/(π d³) (eqs. 7-1, 7-2), their von
  Mises combination (eqs. 7-5, 7-6) put into the fatigue criteria — DE-Goodman 1/n = 16/(π d³) {[4(K_f M_a)² +
  3(K_fs T_a)²]^½ / S_e + [4(K_f M_m)² + 3(K_fs T_m)²]^½ / S_ut} (eq. 7-7) and its diameter (eq. 7-8), DE-Gerber,
  DE-ASME elliptic (the ANSI/ASME B106.1M form) and DE-Soderberg; §7-6 "Critical speeds for shafts": Rayleigh's
  ω1 = √(g Σ w_i y_i / Σ w_i y_i²) (eq. 7-23), Dunkerley's 1/ω1² = Σ 1/ω_ii² (eq. 7-32) with ω_ii² = 1/(m_i
  δ_ii), the simply supported uniform shaft ω = (π/l)² √(E I/(m/l)) (eq. 7-22), and the influence coefficients
  of a simply supported beam (eq. 7-24, Table A-9-6).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from ..errors import InputError
from .fatigue import Criterion, FatigueSafety, fatigue_safety

G = 9.80665


def section_stresses(diameter: float, bending: tuple[float, float], torque: tuple[float, float],
                     kf: float = 1.0, kfs: float = 1.0) -> tuple[float, float]:
    """The von Mises amplitude and mean of a round solid section under (amplitude, mean) bending moment and
    torque (Shigley's MED, 10th ed., eqs. 7-1, 7-2, 7-5, 7-6):

    σ'_a = √((32 K_f M_a/(π d³))² + 3 (16 K_fs T_a/(π d³))²),  σ'_m the same with M_m, T_m.

    Parameters
    ----------
    diameter : d [m] > 0; bending : (M_a, M_m) [N·m]; torque : (T_a, T_m) [N·m]; kf, kfs : K_f, K_fs [-] >= 1.

    Returns
    -------
    (σ'_a, σ'_m) [Pa]

    Examples
    --------
    >>> [round(s / 1e6, 3) for s in section_stresses(0.04, (200.0, 0.0), (0.0, 300.0))]
    [31.831, 41.35]
    """
    if not (math.isfinite(diameter) and diameter > 0):
        raise InputError(f"A shaft's diameter must be > 0; got {diameter!r}.")
    if kf < 1 or kfs < 1:
        raise InputError(f"Fatigue notch factors are >= 1; got K_f = {kf!r}, K_fs = {kfs!r}.")
    z = math.pi * diameter**3
    amp = math.hypot(32 * kf * bending[0] / z, math.sqrt(3) * 16 * kfs * torque[0] / z)
    mean = math.hypot(32 * kf * bending[1] / z, math.sqrt(3) * 16 * kfs * torque[1] / z)
    return amp, mean


def shaft_safety(diameter: float, bending: tuple[float, float], torque: tuple[float, float], endurance: float,
                 ultimate: float, yield_strength: float | None = None, *, kf: float = 1.0, kfs: float = 1.0,
                 criterion: Criterion = "goodman") -> FatigueSafety:
    """The DE fatigue factor of safety of a shaft section (DE-Goodman, DE-Gerber, DE-ASME elliptic or
    DE-Soderberg: :func:`section_stresses` in :func:`~machdyn.drivetrain.fatigue.fatigue_safety`), with the
    first-cycle yield factor n_y = S_y/σ'_max on the von Mises stress of the maximum moment and torque
    (Shigley's MED, 10th ed., §7-4, eqs. 7-7 to 7-16).

    Parameters
    ----------
    diameter, bending, torque, kf, kfs : as :func:`section_stresses`.
    endurance : S_e [Pa] of the shaft (Marin factors applied); ultimate : S_ut [Pa]; yield_strength : S_y [Pa].
    criterion : "goodman", "gerber", "asme_elliptic" or "soderberg".

    Returns
    -------
    FatigueSafety

    Examples
    --------
    >>> round(shaft_safety(0.04, (200.0, 0.0), (0.0, 300.0), 200e6, 600e6).fatigue, 3)
    4.385
    """
    amp, mean = section_stresses(diameter, bending, torque, kf, kfs)
    safety = fatigue_safety(amp, mean, endurance, ultimate, yield_strength, criterion)
    if yield_strength is None:
        return safety
    # first-cycle yield on the von Mises stress of the maxima (eq. 7-15), less conservative than σ'_a + σ'_m
    peak, _ = section_stresses(diameter, (bending[0] + bending[1], 0.0), (torque[0] + torque[1], 0.0), kf, kfs)
    return FatigueSafety(safety.fatigue, yield_strength / peak if peak > 0 else math.inf, criterion)


def de_goodman_diameter(safety: float, bending: tuple[float, float], torque: tuple[float, float], endurance: float,
                        ultimate: float, *, kf: float = 1.0, kfs: float = 1.0) -> float:
    """The diameter at which the DE-Goodman factor of safety is n (Shigley's MED, 10th ed., eq. 7-8):

    d = (16 n/π {[4(K_f M_a)² + 3(K_fs T_a)²]^½ / S_e + [4(K_f M_m)² + 3(K_fs T_m)²]^½ / S_ut})^{1/3}

    Examples
    --------
    >>> round(de_goodman_diameter(2.0, (200.0, 0.0), (0.0, 300.0), 200e6, 600e6) * 1e3, 2)
    30.79
    """
    if not (math.isfinite(safety) and safety > 0):
        raise InputError(f"A factor of safety is > 0; got {safety!r}.")
    a = math.sqrt(4 * (kf * bending[0]) ** 2 + 3 * (kfs * torque[0]) ** 2)
    m = math.sqrt(4 * (kf * bending[1]) ** 2 + 3 * (kfs * torque[1]) ** 2)
    return (16 * safety / math.pi * (a / endurance + m / ultimate)) ** (1.0 / 3.0)


def influence(span: float, stiffness: float, at: float, load_at: float) -> float:
    """The deflection at x of a simply supported beam under a unit load at a (Shigley's MED, 10th ed., eq. 7-24,
    Table A-9-6): for x <= a, δ = b x (l² − b² − x²)/(6 E I l) with b = l − a; symmetric otherwise.

    Parameters
    ----------
    span : l [m] > 0, between the bearings; stiffness : E I [N·m²] > 0; at : x, load_at : a [m] in [0, l].

    Returns
    -------
    float
        δ [m/N].

    Examples
    --------
    At the centre: l³/(48 E I):

    >>> influence(1.0, 1.0, 0.5, 0.5) == 1 / 48
    True
    """
    if not (span > 0 and stiffness > 0):
        raise InputError(f"A shaft needs a span and a bending stiffness > 0; got {span!r}, {stiffness!r}.")
    if not (0.0 <= at <= span and 0.0 <= load_at <= span):
        raise InputError(f"Positions on the shaft are between its bearings, 0 to {span:g} m; got {at!r} and "
                         f"{load_at!r}.")
    x, a = (at, load_at) if at <= load_at else (span - at, span - load_at)
    b = span - a
    return b * x * (span**2 - b**2 - x**2) / (6.0 * stiffness * span)


def _matrix(span: float, stiffness: float, positions: Sequence[float]) -> np.ndarray:
    return np.array([[influence(span, stiffness, x, a) for a in positions] for x in positions])


def uniform_shaft_speed(span: float, stiffness: float, mass_per_length: float) -> float:
    """The first critical speed of a simply supported uniform shaft, ω = (π/l)² √(E I/(m/l)) (Shigley's MED, 10th
    ed., eq. 7-22) [rad/s].

    Examples
    --------
    >>> round(uniform_shaft_speed(1.0, 1.0, 1.0), 4)
    9.8696
    """
    if not (span > 0 and stiffness > 0 and mass_per_length > 0):
        raise InputError("A uniform shaft needs a span, a stiffness and a mass per length > 0.")
    return (math.pi / span) ** 2 * math.sqrt(stiffness / mass_per_length)


def critical_speeds(span: float, stiffness: float, masses: Sequence[float], positions: Sequence[float],
                    shaft_mass_per_length: float = 0.0) -> tuple[float, float, float]:
    """The first critical speed of a simply supported shaft carrying point masses [rad/s] by three methods:
    Rayleigh's energy quotient with the static deflection under the weights (an upper bound), Dunkerley's sum
    (a lower bound; the shaft's own mass enters as the uniform shaft's speed), and the exact first eigenvalue of
    the lumped model, ω² = 1/λ_max(δ·M) (the masses only) (Shigley's MED, 10th ed., §7-6, eqs. 7-22, 7-23, 7-32).

    Parameters
    ----------
    span : l [m]; stiffness : E I [N·m²]; masses : m_i [kg] > 0; positions : x_i [m] from a bearing;
    shaft_mass_per_length : [kg/m] >= 0, added by Dunkerley's sum.

    Returns
    -------
    (ω_Rayleigh, ω_Dunkerley, ω_exact) [rad/s]

    Examples
    --------
    One mass at the centre: all three are √(48 E I/(m l³)):

    >>> [round(w, 6) for w in critical_speeds(1.0, 1.0, [1.0], [0.5])] == [round(48 ** 0.5, 6)] * 3
    True
    """
    m = np.asarray(masses, dtype=float)
    if m.size == 0 or len(positions) != m.size or np.any(~np.isfinite(m)) or np.any(m <= 0):
        raise InputError("A shaft's critical speed needs masses > 0 kg, one position for each.")
    d = _matrix(span, stiffness, positions)
    static = d @ (m * G)
    rayleigh = math.sqrt(G * float(np.sum(m * static)) / float(np.sum(m * static**2)))
    inverse = float(np.sum(m * np.diag(d)))
    if shaft_mass_per_length > 0:
        inverse += 1.0 / uniform_shaft_speed(span, stiffness, shaft_mass_per_length) ** 2
    exact = 1.0 / math.sqrt(float(np.max(np.linalg.eigvals(d @ np.diag(m)).real)))
    return rayleigh, 1.0 / math.sqrt(inverse), exact
