"""Field balancing by influence coefficients, from vibration readings (amplitude and phase) entered by hand.

Phase convention: a reading's phase is the **phase lag**, the angle the shaft turns from the once-per-revolution
reference pulse to the positive peak of the 1x vibration (as balancing instruments show it), and a trial or
correction mass's angle is measured on the rotor from the reference mark **against the direction of rotation**.
With these two conventions a mass moved by delta moves the reading's phase by delta (a mass at angle a passes a
sensor when the shaft has turned a past the pulse), so that readings and masses are complex numbers A e^{i phi}
and m e^{i alpha} related linearly; an instrument that reports the phase the other way pairs with mass angles
measured with rotation. For a linear machine at a fixed speed

    V = V0 + sum_j a_ij W_j,     a_ij = (V_i(trial j) - V_i(original)) / W_j     (the influence coefficients),

so that the corrections W = -a^{-1} V0 cancel the original vibration (single plane: W = -V0 / a) (Thomson &
Dahleh, *Theory of Vibration with Applications*, 5th ed., sec. 3.3-3.4 (field balancing); Rao, *Mechanical
Vibrations*, 5th ed., sec. 9.2-9.3; ISO 21940-13's influence-coefficient procedure). Masses are at the trial
masses' radius in their planes. The trial runs are taken in the order given; a trial mass left on (``removed``
false) is part of the starting state of the runs after it, and the correction reported is what to add to it.

A reading without a phase cannot enter this method (the amplitude-only four-run method needs three trial runs).
Two rules keep a correction from resting on readings that hardly moved (module constants, justified in
docs/shafts.md):

* every trial run must change at least one reading by >= 30 % in amplitude or >= 30 deg in phase (the trial-mass
  rule printed in field-balancing guides, e.g. V. Wowk, *Machinery Vibration: Balancing*, McGraw-Hill 1995; the
  figure is that rule's, not a number taken from ISO 21940-13 or ISO 20806, which set criteria and safeguards
  for in-situ balancing). A smaller change leaves the influence coefficient, a difference of two nearly equal
  readings, dominated by the readings' scatter: a 0.0001 mm/s change on an 8.6 mm/s reading
  would ask for a 1.7 t correction;
* the influence matrix, its columns scaled to unit length, must have a condition number kappa <= 20: the
  corrections' relative error can reach kappa times the coefficients' (Golub & Van Loan, *Matrix
  Computations*, 4th ed., sec. 2.6.2), and coefficients from runs that just meet the 30 % rule carry errors of
  about 5 % (readings repeatable to +-1 %, +-1 deg), so kappa = 20 lets the correction's error reach its size.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ..errors import InputError, check_finite, check_positive

__all__ = ["Reading", "TrialRun", "FieldBalance", "single_plane", "two_plane", "split_onto_holes", "reading"]

#: Largest condition number of the column-scaled influence matrix accepted (module docstring).
MAX_CONDITION = 20.0
#: A trial run must change a reading by at least this share of its amplitude ...
TRIAL_AMPLITUDE_CHANGE = 0.30
#: ... or by at least this phase [rad] (the 30 % / 30 deg trial-mass rule, module docstring).
TRIAL_PHASE_CHANGE = math.radians(30.0)


@dataclass(frozen=True)
class Reading:
    """A 1x vibration reading: ``amplitude`` (any unit, the same for every reading) and ``phase`` [rad] from the
    reference mark (None when no phase reference was recorded)."""

    amplitude: float
    phase: float | None

    def vector(self, where: str) -> complex:
        check_positive(f"amplitude of {where}", self.amplitude, allow_zero=True)
        if self.phase is None:
            raise InputError(
                f"The reading {where} has no phase: influence-coefficient balancing needs amplitude and phase "
                "measured against a once-per-revolution reference mark (a keyphasor or an optical tachometer)."
            )
        check_finite(f"phase of {where}", self.phase, "rad")
        return complex(self.amplitude * np.exp(1j * self.phase))


def reading(value: complex) -> Reading:
    """The :class:`Reading` of a complex vibration vector."""
    return Reading(abs(value), math.atan2(value.imag, value.real))


@dataclass(frozen=True)
class TrialRun:
    """A run with a trial ``mass`` [kg] at ``angle`` [rad] in correction plane ``plane`` (index), and the readings
    at every sensor during it."""

    plane: int
    mass: float
    angle: float
    readings: tuple[Reading, ...]
    removed: bool = True

    @property
    def weight(self) -> complex:
        return complex(self.mass * np.exp(1j * self.angle))


@dataclass(frozen=True)
class FieldBalance:
    """Influence coefficients (sensors x planes, reading unit per kg), the corrections to add in each plane
    ([kg] at the trial radius, angle [rad] in 0 ... 2 pi), the predicted residual readings (zero for a square
    system) and the trial effects relative to the original readings (a rule of thumb wants >= 0.3)."""

    coefficients: np.ndarray
    correction_mass: tuple[float, ...]
    correction_angle: tuple[float, ...]
    original: np.ndarray
    trial_effect: tuple[float, ...]

    def correction(self) -> np.ndarray:
        return np.asarray(self.correction_mass) * np.exp(1j * np.asarray(self.correction_angle))


def _vectors(readings: Sequence[Reading], what: str) -> np.ndarray:
    return np.array([r.vector(f"{what}, sensor {i + 1}") for i, r in enumerate(readings)])


def trial_change(before: np.ndarray, after: np.ndarray) -> tuple[float, float]:
    """The largest relative amplitude change |A_T / A_0 - 1| [-] and phase change |phi_T - phi_0| [rad] (wrapped to
    0 ... pi) over the sensors between the readings ``before`` and ``after`` (complex vectors); a reading of zero
    amplitude before counts as an infinite amplitude change when it moves, its phase as undefined (0)."""
    amp, phase = 0.0, 0.0
    for b, a in zip(before, after, strict=True):
        if abs(b) == 0.0:
            amp = max(amp, math.inf if abs(a) > 0 else 0.0)
            continue
        amp = max(amp, abs(abs(a) / abs(b) - 1.0))
        if abs(a) > 0:
            phase = max(phase, abs(math.remainder(math.atan2(a.imag, a.real) - math.atan2(b.imag, b.real),
                                                  2 * math.pi)))
    return amp, phase


def _solve(original: Sequence[Reading], trials: Sequence[TrialRun]) -> FieldBalance:
    n = len(trials)
    if len(original) != n:
        raise InputError(f"Influence-coefficient balancing in {n} plane(s) needs {n} sensor reading(s) per run; "
                         f"the original run has {len(original)}.")
    if sorted(t.plane for t in trials) != list(range(n)):
        raise InputError(f"Each of the {n} correction plane(s) needs exactly one trial run; got the planes "
                         f"{[t.plane + 1 for t in trials]}.")
    v0 = _vectors(original, "of the original run")
    a = np.zeros((n, n), dtype=complex)
    effects = [0.0] * n
    kept = np.zeros(n, dtype=complex)
    baseline = v0  # the runs in the order given: a trial mass left on is part of the next run's starting state
    for t in trials:
        k = t.plane
        check_positive(f"trial mass of plane {t.plane + 1}", t.mass, "kg")
        check_finite(f"trial-mass angle of plane {t.plane + 1}", t.angle, "rad")
        if len(t.readings) != n:
            raise InputError(f"The trial run of plane {t.plane + 1} has {len(t.readings)} reading(s); {n} needed.")
        vt = _vectors(t.readings, f"of the trial run in plane {t.plane + 1}")
        amp, phase = trial_change(baseline, vt)
        if amp < TRIAL_AMPLITUDE_CHANGE and phase < TRIAL_PHASE_CHANGE:
            change = float(np.max(np.abs(vt - baseline)))
            raise InputError(
                f"The trial mass in plane {t.plane + 1} changed the readings too little to balance by: at most "
                f"{amp:.3g} of their amplitude ({change:.3g} in the readings' unit) and {math.degrees(phase):.3g} deg "
                f"in phase. A trial mass must change at least one reading by {TRIAL_AMPLITUDE_CHANGE:.0%} in "
                f"amplitude or {math.degrees(TRIAL_PHASE_CHANGE):.0f} deg in phase (the field-balancing trial-mass "
                "rule); with less, the influence coefficient is lost in the readings' scatter (the influence "
                "matrix is nearly singular). Repeat the trial run with a larger trial mass, or in another place "
                "if it sits at a node of the vibration.")
        a[:, k] = (vt - baseline) / t.weight
        scale = max(float(np.max(np.abs(baseline))), float(np.max(np.abs(vt))), 1e-300)
        effects[k] = float(np.max(np.abs(vt - baseline))) / scale
        if not t.removed:
            kept[k] += t.weight
            baseline = vt
    if n > 1:
        norms = np.linalg.norm(a, axis=0)
        sv = np.linalg.svd(a / np.maximum(norms, 1e-300), compute_uv=False)
        kappa = float(sv[0] / sv[-1]) if sv[-1] > 0 else math.inf
        if not kappa <= MAX_CONDITION:
            raise InputError(
                f"The influence matrix is nearly singular (condition number {kappa:.3g} with its columns scaled, "
                f"above {MAX_CONDITION:g}): two trial runs act almost alike on the sensors, so the corrections "
                f"would amplify the readings' scatter up to {kappa:.3g} times. Place the trial masses in planes "
                "farther apart, or read the vibration at sensors that tell the planes apart.")
    w = np.linalg.solve(a, -v0) - kept
    mass = tuple(float(abs(x)) for x in w)
    angle = tuple(float(math.atan2(x.imag, x.real) % (2 * math.pi)) if abs(x) > 0 else 0.0 for x in w)
    return FieldBalance(a, mass, angle, v0, tuple(effects))


def single_plane(original: Reading, trial_mass: float, trial_angle: float, with_trial: Reading,
                 removed: bool = True) -> FieldBalance:
    """Single-plane balance: a = (V_T - V_0) / W_T, correction W = -V_0 / a (module docstring).

    Examples
    --------
    The trial mass alone moved the reading by as much as the original: the correction equals the trial mass,
    turned by the angle between -V_0 and the change.

    >>> fb = single_plane(Reading(1.0, 0.0), 0.01, 0.0, Reading(2.0 ** 0.5, math.pi / 4))
    >>> round(fb.correction_mass[0], 12), round(math.degrees(fb.correction_angle[0]), 9)
    (0.01, 90.0)
    """
    return _solve([original], [TrialRun(0, trial_mass, trial_angle, (with_trial,), removed)])


def two_plane(original: Sequence[Reading], trials: Sequence[TrialRun]) -> FieldBalance:
    """Two-plane (or n-plane) balance from the original readings at n sensors and one trial run per plane."""
    return _solve(list(original), list(trials))


def split_onto_holes(mass: float, angle: float, holes: Sequence[float]) -> dict[int, float]:
    """Split a correction ``mass`` [kg] at ``angle`` [rad] onto the two fixed positions (``holes``, angles [rad])
    that bracket it: m1 = m sin(a2 - a) / sin(a2 - a1), m2 = m sin(a - a1) / sin(a2 - a1) (the vector sum of the
    two equals the correction). Returns hole index -> mass.

    Examples
    --------
    >>> {k: round(v, 9) for k, v in split_onto_holes(1.0, math.radians(45), [0.0, math.pi / 2, math.pi]).items()}
    {0: 0.707106781, 1: 0.707106781}
    """
    check_positive("correction mass", mass, "kg", allow_zero=True)
    h = np.mod(np.asarray(holes, dtype=float), 2 * np.pi)
    if h.size < 2:
        raise InputError(f"Splitting a correction needs at least two fixed positions; got {h.size}.")
    order = np.argsort(h)
    hs = h[order]
    a = angle % (2 * np.pi)
    for j in range(hs.size):
        lo, hi = hs[j], hs[(j + 1) % hs.size] + (2 * np.pi if j + 1 == hs.size else 0.0)
        aa = a if a >= lo else a + 2 * np.pi
        if lo <= aa <= hi:
            gap = hi - lo
            if not 0 < gap < np.pi:
                raise InputError(f"The fixed positions around {math.degrees(a):.4g} deg are {math.degrees(gap):.4g} "
                                 "deg apart; a split needs neighbours less than 180 deg apart.")
            m1 = mass * math.sin(hi - aa) / math.sin(gap)
            m2 = mass * math.sin(aa - lo) / math.sin(gap)
            out = {int(order[j]): m1, int(order[(j + 1) % hs.size]): m2}
            return {k: v for k, v in out.items() if v > 1e-15 * max(mass, 1e-300)} or {int(order[j]): 0.0}
    raise InputError("No pair of fixed positions brackets the correction angle.")  # unreachable for >= 2 holes
