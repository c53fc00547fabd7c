"""Fatigue of machine parts beyond the Goodman line: the Soderberg, Gerber and ASME-elliptic fatigue criteria with
Langer's first-cycle yield line, a compressive mean stress handled as Shigley does, the Marin factors that turn a
specimen's endurance limit into a part's, notch sensitivity (Neuber, Peterson), multiaxial stresses by their von
Mises amplitude and mean, and the finite life of a part stressed above its endurance limit (the S–N line). The
Marin factors and notch sensitivity live in :mod:`.marin` and are re-exported here.

Every function takes and returns SI floats: Pa, m, K. The empirical fits of the sources are in the units they were
fitted in (MPa, kpsi, inches, °F); each function converts at its boundary and says so.

Sources
-------
- R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., McGraw-Hill 2015, ch. 6:
  §6-7 the S–N line (f, a = (f S_ut)²/S_e, b = −log(f S_ut/S_e)/3, S_f = a N^b) and the low-cycle line
  S_f = S_ut N^{(log f)/3}; §6-8 S_e' = 0.5 S_ut (S_ut <= 1400 MPa), else 700 MPa; §6-9 the Marin factors
  (Table 6-2 surface factor k_a = a S_ut^b, eq. 6-20 size factor k_b, eq. 6-26 load factor k_c, eq. 6-27
  temperature factor k_d, eq. 6-28 and Table 6-5 reliability factor k_e = 1 − 0.08 z_a); §6-10 notch
  sensitivity, K_f = 1 + q (K_t − 1) and Neuber's equation with √a of eq. 6-35; §6-12 the fatigue criteria
  (Soderberg, modified Goodman, Gerber, ASME-elliptic and Langer, Table 6-7 and the factors of safety of
  Tables 6-6 to 6-8) and the compressive-mean side of the Goodman diagram (the fatigue line σ_a = S_e, the
  Langer line σ_a − σ_m = S_y); §6-14 combined loading modes (von Mises amplitude and mean, eqs. 6-66 and 6-67);
  §6-13 the fully reversed stress equivalent to a fluctuating one, σ_rev = σ_a/(1 − σ_m/S_ut).
- W. D. Pilkey, D. F. Pilkey, *Peterson's Stress Concentration Factors*, 3rd ed., Wiley 2008, §1.9 "Notch
  sensitivity": q = 1/(1 + a/r) with a = 0.0254 (2070/S_u)^1.8 mm for steels (S_u in MPa, >= 550 MPa).
- R. L. Norton, *Machine Design*, 5th ed., Pearson 2014, ch. 6 (the same criteria and Marin factors, and the
  von Mises alternating and mean stresses of multiaxial fatigue, §6.12).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np

from ..errors import InputError
from .marin import (
    INCH,
    KPSI,
    LOAD_FACTORS,
    MPA,
    SURFACE_FACTORS,
    Marin,
    _positive,
    fatigue_notch_factor,
    load_factor,
    marin_endurance_limit,
    neuber_sensitivity,
    peterson_sensitivity,
    reliability_factor,
    size_factor,
    specimen_endurance_limit,
    surface_factor,
    temperature_factor,
)

__all__ = [
    "CRITERIA",
    "Criterion",
    "FatigueSafety",
    "INCH",
    "KPSI",
    "LOAD_FACTORS",
    "MPA",
    "Marin",
    "SNLine",
    "SURFACE_FACTORS",
    "amplitude_and_mean",
    "combined_loading",
    "failure_amplitude",
    "fatigue_notch_factor",
    "fatigue_safety",
    "fatigue_strength_fraction",
    "load_factor",
    "marin_endurance_limit",
    "neuber_sensitivity",
    "peterson_sensitivity",
    "reliability_factor",
    "reversed_equivalent",
    "size_factor",
    "sn_line",
    "specimen_endurance_limit",
    "surface_factor",
    "temperature_factor",
    "von_mises",
]

Criterion = Literal["goodman", "soderberg", "gerber", "asme_elliptic"]
CRITERIA: tuple[str, ...] = ("goodman", "soderberg", "gerber", "asme_elliptic")

def von_mises(sx: float, sy: float = 0.0, txy: float = 0.0, sz: float = 0.0, tyz: float = 0.0,
              tzx: float = 0.0) -> float:
    """The von Mises equivalent of a stress state (Shigley's MED, 10th ed., §5-5, eq. 5-14):

    σ' = √(½[(σx − σy)² + (σy − σz)² + (σz − σx)² + 6(τxy² + τyz² + τzx²)])

    For fatigue apply it to the amplitudes and to the means separately (§6-14, eqs. 6-66, 6-67; Norton §6.12).

    Parameters
    ----------
    sx, sy, sz, txy, tyz, tzx : [Pa].

    Returns
    -------
    float
        σ' [Pa] >= 0.

    Examples
    --------
    Bending with torsion: √(σ² + 3τ²):

    >>> round(von_mises(100e6, txy=50e6) / 1e6, 3)
    132.288
    """
    return math.sqrt(0.5 * ((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2) + 3.0 * (txy**2 + tyz**2 + tzx**2))


def combined_loading(bending: tuple[float, float] = (0.0, 0.0), axial: tuple[float, float] = (0.0, 0.0),
                     torsion: tuple[float, float] = (0.0, 0.0), *, kf_bending: float = 1.0, kf_axial: float = 1.0,
                     kf_torsion: float = 1.0) -> tuple[float, float]:
    """The von Mises amplitude and mean of combined bending, axial and torsional stresses, each with its fatigue
    notch factor (Shigley's MED, 10th ed., §6-14, eqs. 6-66 and 6-67; the axial amplitude divided by its load
    factor 0.85 so that the endurance limit is that of bending):

    σ'_a = √[((K_f)_b σ_a,b + (K_f)_ax σ_a,ax/0.85)² + 3((K_fs) τ_a)²]
    σ'_m = √[((K_f)_b σ_m,b + (K_f)_ax σ_m,ax)² + 3((K_fs) τ_m)²]

    Parameters
    ----------
    bending, axial, torsion : (amplitude, mean) [Pa] of the nominal stresses.
    kf_bending, kf_axial, kf_torsion : the fatigue notch factors [-] >= 1.

    Returns
    -------
    (σ'_a, σ'_m) [Pa]
        The mean is signed by its normal stress (negative: a compressive mean).

    Examples
    --------
    >>> [round(x / 1e6, 2) for x in combined_loading((60e6, 0.0), torsion=(0.0, 40e6))]
    [60.0, 69.28]
    """
    amp = math.hypot(kf_bending * bending[0] + kf_axial * axial[0] / 0.85, math.sqrt(3.0) * kf_torsion * torsion[0])
    normal_mean = kf_bending * bending[1] + kf_axial * axial[1]
    mean = math.hypot(normal_mean, math.sqrt(3.0) * kf_torsion * torsion[1])
    return amp, math.copysign(mean, normal_mean) if normal_mean else mean


@dataclass(frozen=True)
class FatigueSafety:
    """Factors of safety of a fluctuating stress: against fatigue by the chosen criterion, against first-cycle
    yielding (Langer; inf without a yield strength), and the lower of the two."""

    fatigue: float
    yielding: float
    criterion: str

    @property
    def governing(self) -> float:
        return min(self.fatigue, self.yielding)


def fatigue_safety(amplitude: float, mean: float, endurance: float, ultimate: float,
                   yield_strength: float | None = None, criterion: Criterion = "goodman") -> FatigueSafety:
    """The factor of safety of a stress σ_a ± σ_m by a fatigue criterion, with Langer's yield line (Shigley's MED,
    10th ed., §6-12, Tables 6-6 to 6-8), for a tensile mean σ_m >= 0:

    Soderberg:      1/n = σ_a/S_e + σ_m/S_y
    mod. Goodman:   1/n = σ_a/S_e + σ_m/S_ut
    Gerber:         n = ½ (S_ut/σ_m)² (σ_a/S_e) [−1 + √(1 + (2 σ_m S_e/(S_ut σ_a))²)]
    ASME-elliptic:  n = 1/√((σ_a/S_e)² + (σ_m/S_y)²)
    Langer (yield): n_y = S_y/(σ_a + σ_m)

    For a compressive mean (σ_m < 0) the fatigue line is σ_a = S_e (n = S_e/σ_a, every criterion) and the
    yield line σ_a − σ_m = S_y (n_y = S_y/(σ_a + |σ_m|)) (§6-12, the compressive half of Fig. 6-27).

    Parameters
    ----------
    amplitude : σ_a [Pa] >= 0; mean : σ_m [Pa] (signed).
    endurance : S_e [Pa] > 0, the part's (Marin-corrected) endurance limit; below S_ut.
    ultimate : S_ut [Pa] > 0.
    yield_strength : S_y [Pa], S_y <= S_ut; needed by Soderberg and ASME-elliptic and for the yield factor.
    criterion : "goodman", "soderberg", "gerber" or "asme_elliptic".

    Returns
    -------
    FatigueSafety
        inf where a stress is zero.

    Raises
    ------
    InputError
        for a peak stress |σ_m| + σ_a at or above S_ut (the part breaks in its first cycle), a negative amplitude,
        S_e >= S_ut or S_y > S_ut, or a criterion that needs S_y without it.

    Examples
    --------
    >>> s = fatigue_safety(100e6, 100e6, 150e6, 600e6, 450e6, "gerber")
    >>> round(s.fatigue, 3), round(s.yielding, 3)
    (1.416, 2.25)
    """
    _positive("endurance limit", endurance)
    _positive("ultimate strength", ultimate)
    if criterion not in CRITERIA:
        raise InputError(f"The fatigue criterion must be one of {', '.join(CRITERIA)}; got {criterion!r}.")
    if not (math.isfinite(amplitude) and amplitude >= 0) or not math.isfinite(mean):
        raise InputError(f"A stress amplitude is finite and >= 0, a mean finite; got {amplitude!r}, {mean!r}.")
    if endurance >= ultimate:
        raise InputError(f"The endurance limit {endurance / MPA:g} MPa must be below the ultimate strength "
                         f"{ultimate / MPA:g} MPa.")
    if yield_strength is not None:
        _positive("yield strength", yield_strength)
        if yield_strength > ultimate:
            raise InputError(f"The yield strength {yield_strength / MPA:g} MPa exceeds the ultimate strength "
                             f"{ultimate / MPA:g} MPa.")
    elif criterion in ("soderberg", "asme_elliptic"):
        raise InputError(f"The {criterion} criterion needs the yield strength.")
    peak = amplitude + abs(mean)
    if peak >= ultimate:
        raise InputError(f"The peak stress σ_a + |σ_m| = {peak / MPA:.4g} MPa is not below the ultimate strength "
                         f"{ultimate / MPA:.4g} MPa: the part breaks in its first cycle.")
    yielding = math.inf if yield_strength is None or peak == 0 else yield_strength / peak
    if mean < 0 or mean == 0:
        fatigue = math.inf if amplitude == 0 else endurance / amplitude
        return FatigueSafety(fatigue, yielding, criterion)
    sa, sm, se, su = amplitude, mean, endurance, ultimate
    if criterion == "goodman":
        fatigue = 1.0 / (sa / se + sm / su)
    elif criterion == "soderberg":
        assert yield_strength is not None
        fatigue = 1.0 / (sa / se + sm / yield_strength)
    elif criterion == "gerber":
        if sa == 0:
            fatigue = su / sm
        else:
            ratio = 2.0 * sm * se / (su * sa)
            # −1 + √(1 + x²) = x² / (1 + √(1 + x²)): no cancellation for a small mean
            fatigue = 0.5 * (su / sm) ** 2 * (sa / se) * ratio**2 / (1.0 + math.sqrt(1.0 + ratio**2))
    else:
        assert yield_strength is not None
        fatigue = 1.0 / math.hypot(sa / se, sm / yield_strength)
    return FatigueSafety(fatigue, yielding, criterion)


def failure_amplitude(mean: float, endurance: float, ultimate: float, yield_strength: float | None = None,
                      criterion: Criterion = "goodman") -> float:
    """The amplitude on a criterion's failure line at the mean σ_m >= 0 (Shigley's MED, 10th ed., §6-12,
    Table 6-7 with n = 1): Goodman S_e (1 − σ_m/S_ut), Soderberg S_e (1 − σ_m/S_y), Gerber S_e (1 − (σ_m/S_ut)²),
    ASME-elliptic S_e √(1 − (σ_m/S_y)²); 0 beyond the line's end.

    Parameters
    ----------
    mean : σ_m [Pa] >= 0; endurance, ultimate, yield_strength : S_e, S_ut, S_y [Pa]; criterion : as
        :func:`fatigue_safety`.

    Returns
    -------
    float
        S_a [Pa].

    Examples
    --------
    >>> failure_amplitude(300e6, 200e6, 600e6, criterion="gerber") / 1e6
    150.0
    """
    if criterion in ("soderberg", "asme_elliptic"):
        if yield_strength is None:
            raise InputError(f"The {criterion} criterion needs the yield strength.")
        x = mean / yield_strength
    else:
        x = mean / ultimate
    if x >= 1.0:
        return 0.0
    if criterion in ("goodman", "soderberg"):
        return endurance * (1.0 - x)
    if criterion == "gerber":
        return endurance * (1.0 - x * x)
    return endurance * math.sqrt(1.0 - x * x)


def fatigue_strength_fraction(ultimate: float) -> float:
    """Shigley's fatigue strength fraction f, the strength at 10³ cycles over S_ut: the fit of Fig. 6-18 (Shigley's
    MED, 10th ed., §6-7, S_ut in kpsi inside, 70 <= S_ut <= 200 kpsi); 0.9 below 70 kpsi (the book's
    conservative value there), refused above 200 kpsi.

    f = 1.06 − 2.8e−3 S_ut + 6.9e−6 S_ut² − 5.8e−9 S_ut³

    Examples
    --------
    >>> round(fatigue_strength_fraction(90 * 6.894757e6), 3)
    0.86
    """
    _positive("ultimate strength", ultimate)
    s = ultimate / KPSI
    if s < 70.0:
        return 0.9
    if s > 200.0 + 1e-9:
        raise InputError(f"Shigley's f is fitted up to 200 kpsi (1379 MPa); got {ultimate / MPA:g} MPa: give f.")
    return 1.06 - 2.8e-3 * s + 6.9e-6 * s**2 - 5.8e-9 * s**3


@dataclass(frozen=True)
class SNLine:
    """The S–N line of a steel, S_f = a N^b between 10³ and 10⁶ cycles: a [Pa], b [-], and the fraction f."""

    a: float
    b: float
    fraction: float
    ultimate: float
    endurance: float

    def strength(self, cycles: float) -> float:
        """S_f [Pa] at N cycles (10³ <= N <= 10⁶; S_ut N^{(log f)/3} below 10³; S_e above 10⁶)."""
        if not (math.isfinite(cycles) and cycles >= 1.0):
            raise InputError(f"A number of cycles is >= 1; got {cycles!r}.")
        if cycles >= 1e6:
            return self.endurance
        if cycles <= 1e3:
            return self.ultimate * cycles ** (math.log10(self.fraction) / 3.0)
        return self.a * cycles**self.b

    def cycles(self, reversed_stress: float) -> float:
        """N [cycles] to failure under a fully reversed stress [Pa]: inf at or below S_e; refused at or above S_ut."""
        if not (math.isfinite(reversed_stress) and reversed_stress >= 0):
            raise InputError(f"A reversed stress is finite and >= 0; got {reversed_stress!r}.")
        if reversed_stress <= self.endurance:
            return math.inf
        if reversed_stress >= self.ultimate:
            raise InputError(f"The reversed stress {reversed_stress / MPA:.4g} MPa reaches the ultimate strength "
                             f"{self.ultimate / MPA:.4g} MPa: the part breaks in its first cycle.")
        if reversed_stress >= self.fraction * self.ultimate:
            return (reversed_stress / self.ultimate) ** (3.0 / math.log10(self.fraction))
        return (reversed_stress / self.a) ** (1.0 / self.b)


def sn_line(ultimate: float, endurance: float, fraction: float | None = None) -> SNLine:
    """The S–N line through (10³, f S_ut) and (10⁶, S_e) (Shigley's MED, 10th ed., §6-7, eqs. 6-13 to 6-16):

    a = (f S_ut)²/S_e,  b = −⅓ log(f S_ut/S_e),  S_f = a N^b,  N = (σ_rev/a)^{1/b}

    Parameters
    ----------
    ultimate : S_ut [Pa]; endurance : S_e [Pa], below f S_ut; fraction : f [-] (default
        :func:`fatigue_strength_fraction`).

    Returns
    -------
    SNLine

    Examples
    --------
    >>> line = sn_line(600e6, 200e6, 0.9)
    >>> round(line.strength(1e3) / 1e6, 6), round(line.strength(1e6) / 1e6, 6)
    (540.0, 200.0)
    """
    f = fatigue_strength_fraction(ultimate) if fraction is None else fraction
    if not (0.0 < f < 1.0):
        raise InputError(f"The fatigue strength fraction f is between 0 and 1; got {f!r}.")
    _positive("endurance limit", endurance)
    if not endurance < f * ultimate:
        raise InputError(f"The endurance limit {endurance / MPA:g} MPa must be below f·S_ut = "
                         f"{f * ultimate / MPA:g} MPa for an S–N line.")
    a = (f * ultimate) ** 2 / endurance
    b = -math.log10(f * ultimate / endurance) / 3.0
    return SNLine(a, b, f, ultimate, endurance)


def reversed_equivalent(amplitude: float, mean: float, ultimate: float) -> float:
    """The fully reversed stress with the life of σ_a ± σ_m, by the Goodman line σ_rev = σ_a/(1 − σ_m/S_ut) for a
    tensile mean, σ_a for a compressive one (Shigley's MED, 10th ed., §6-13, eq. 6-59).

    Examples
    --------
    >>> round(reversed_equivalent(100e6, 300e6, 600e6) / 1e6, 3)
    200.0
    """
    _positive("ultimate strength", ultimate)
    if mean >= ultimate:
        raise InputError(f"The mean stress {mean / MPA:g} MPa reaches the ultimate strength {ultimate / MPA:g} MPa.")
    return amplitude / (1.0 - mean / ultimate) if mean > 0 else amplitude


def amplitude_and_mean(stress_max: np.ndarray | float, stress_min: np.ndarray | float) -> tuple[float, float]:
    """σ_a = (σ_max − σ_min)/2 and σ_m = (σ_max + σ_min)/2 of the extremes of a stress history [Pa].

    Examples
    --------
    >>> amplitude_and_mean(200e6, -50e6)
    (125000000.0, 75000000.0)
    """
    hi, lo = float(np.max(stress_max)), float(np.min(stress_min))
    return 0.5 * (hi - lo), 0.5 * (hi + lo)
