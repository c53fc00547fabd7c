"""The parts and the clutch of N designs at once: NumPy arrays with the designs on the leading axis.

The formulas are those of the single-design functions beside them, written over arrays of shape (N, K) (N designs,
K crank positions) instead of (K,); where a single-design function refuses a design (an InputError), the
population form flags it (``valid`` False) and gives NaN for its results, so a study can count it infeasible
without stopping the population:

The whole ``[parts]`` table of N designs from their kinetostatics is :mod:`.parts_population`.

- the basic rating life of a rolling bearing under the cycle's varying load (ISO 281:2007, L10 = (C/P)^p, with
  the equal-life load of Mott, *Machine Elements in Mechanical Design*, 4th ed., eq. 14-11) — the formula
  :func:`machdyn.drivetrain.parts.size_parts` itself calls with N = 1;
- the plain bearing's peak pressure and mean p·v (Shigley's MED, 8th ed., §12-15);
- pin shear and bearing pressure (Shigley's MED, 8th ed., ch. 3 and 8; :func:`.strength.pin_stresses`);
- a two-pin link's fatigue safety factor by the Goodman, Soderberg, Gerber or ASME-elliptic criterion with
  Langer's yield factor and the Palmgren–Miner damage of its required cycles (Shigley's MED, 10th ed., §6-7,
  §6-12, §6-13; :func:`.fatigue.fatigue_safety`, :func:`.parts.link_fatigue_checks`);
- the slip time, common speed and dissipated energy of a clutch engagement with constant torques (Shigley's MED,
  8th ed., §16-8; :func:`.clutch.engage`, which calls :func:`engagement_arrays`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .bearings import life_exponent, reliability_factor
from .fatigue import sn_line

HOUR = 3600.0


def _rows(x: Any) -> np.ndarray:
    """An (N, K) float array of a per-position history (a (K,) history is one design)."""
    a = np.asarray(x, dtype=float)
    return a[None, :] if a.ndim == 1 else a


def _per_design(x: Any, n: int) -> np.ndarray:
    """An (N,) float array of a per-design value (a scalar is every design's)."""
    return np.broadcast_to(np.ravel(np.asarray(x, dtype=float)), (n,)) if np.size(x) in (1, n) else \
        np.asarray(x, dtype=float)


def rolling_bearing_life(load: Any, turned: Any, period: Any, capacity: Any, kind: str = "ball",
                         reliability: float = 90.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The rating life [s] of N rolling bearings under their cycles' varying loads.

    Fm = (Σ Fi^p θi / Σ θi)^(1/p) (Mott, 4th ed., eq. 14-11; ISO 281 §7.2), L = a1 (C/Fm)^p 10^6 rev (ISO
    281:2007 §6.2 and Table 12), turned at Σθ/2π revolutions per cycle of ``period`` seconds.

    Parameters
    ----------
    load : |F| [N], (N, K) (or (K,) for one design).
    turned : the relative rotation [rad] the bearing makes at each position, (N, K).
    period : the cycle's duration [s], (N,) or a float.
    capacity : C [N] > 0, (N,) or a float.
    kind : "ball" (p = 3) or "roller" (p = 10/3).
    reliability : R [%], 90 <= R <= 99.95 (ISO 281 a1).

    Returns
    -------
    (life [s], equal-life load Fm [N], valid) each (N,)
        valid is False (life and Fm NaN) where the bearing does not turn over the cycle or a load is not finite;
        the life is inf for a bearing without load.
    """
    p = life_exponent(kind)
    a1 = reliability_factor(reliability)
    f, th = np.abs(_rows(load)), np.abs(_rows(turned))
    n = f.shape[0]
    total = th.sum(axis=1)
    valid = (total > 0) & np.all(np.isfinite(f), axis=1) & np.isfinite(total)
    safe_total = np.where(valid, total, 1.0)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        equivalent = (np.sum(f**p * th, axis=1) / safe_total) ** (1.0 / p)
        c = _per_design(capacity, n)
        life_revs = np.where(equivalent > 0, (c / np.where(equivalent > 0, equivalent, 1.0)) ** p, np.inf) \
            * a1 * 1e6
        revs_per_hour = safe_total / (2 * np.pi) * HOUR / _per_design(period, n)
        life = life_revs / revs_per_hour * HOUR
    return np.where(valid, life, np.nan), np.where(valid, equivalent, np.nan), valid


def plain_bearing(load: Any, relative_speed: Any, dt: Any, period: Any, diameter: Any,
                  length: Any) -> tuple[np.ndarray, np.ndarray]:
    """Peak pressure p = F/(d l) [Pa] and the time-mean p·v [Pa·m/s], v = |ω_rel| d/2, of N plain bearings over
    their cycles (Shigley's MED, 8th ed., §12-15). load, relative_speed [rad/s], dt [s]: (N, K); period [s],
    diameter, length [m]: (N,) or floats."""
    f = _rows(load)
    n = f.shape[0]
    d, ln = _per_design(diameter, n)[:, None], _per_design(length, n)[:, None]
    p = f / (d * ln)
    pv = p * np.abs(_rows(relative_speed) * d / 2.0)
    return np.max(p, axis=1), np.sum(pv * _rows(dt), axis=1) / _per_design(period, n)


def pin_peaks(load: Any, diameter: Any, length: Any, shear_planes: int = 2) -> tuple[np.ndarray, np.ndarray]:
    """Peak shear τ = F/(n π d²/4) and peak bearing pressure p = F/(d l) [Pa] of N pins over their cycles
    (Shigley's MED, 8th ed., ch. 3 and 8). load |F| [N]: (N, K); diameter, length [m] > 0: (N,) or floats;
    shear_planes 1 or 2. NaN for a design with a diameter or length <= 0 (the single form refuses it)."""
    f = np.abs(_rows(load))
    n = f.shape[0]
    d, ln = _per_design(diameter, n), _per_design(length, n)
    ok = (d > 0) & (ln > 0)
    peak = np.max(f, axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        tau = peak / (shear_planes * np.pi * d**2 / 4.0)
        p = peak / (d * ln)
    return np.where(ok, tau, np.nan), np.where(ok, p, np.nan)


def fatigue_safety_arrays(amplitude: Any, mean: Any, endurance: float, ultimate: float,
                          yield_strength: float | None = None,
                          criterion: str = "goodman") -> tuple[np.ndarray, np.ndarray]:
    """The fatigue and Langer yield factors of safety of N stresses σ_a ± σ_m (Shigley's MED, 10th ed., §6-12,
    Tables 6-6 to 6-8; the formulas of :func:`.fatigue.fatigue_safety`, whose checks of the strengths the caller
    has made): for σ_m <= 0, n = S_e/σ_a; for σ_m > 0 the criterion's line. inf where a stress is zero; NaN where
    the peak σ_a + |σ_m| reaches S_ut (the single form refuses it: the part breaks in its first cycle)."""
    sa, sm = np.asarray(amplitude, dtype=float), np.asarray(mean, dtype=float)
    se, su = endurance, ultimate
    peak = sa + np.abs(sm)
    with np.errstate(divide="ignore", invalid="ignore"):
        yielding = np.full(sa.shape, np.inf) if yield_strength is None else \
            np.where(peak == 0, np.inf, yield_strength / peak)
        compressive = np.where(sa == 0, np.inf, se / sa)
        tensile_mean = np.where(sm > 0, sm, 1.0)
        if criterion == "goodman":
            tensile = 1.0 / (sa / se + tensile_mean / su)
        elif criterion == "soderberg":
            assert yield_strength is not None
            tensile = 1.0 / (sa / se + tensile_mean / yield_strength)
        elif criterion == "gerber":
            ratio = 2.0 * tensile_mean * se / (su * np.where(sa == 0, 1.0, sa))
            gerber = 0.5 * (su / tensile_mean) ** 2 * (sa / se) * ratio**2 / (1.0 + np.sqrt(1.0 + ratio**2))
            tensile = np.where(sa == 0, su / tensile_mean, gerber)
        else:
            assert yield_strength is not None
            tensile = 1.0 / np.hypot(sa / se, tensile_mean / yield_strength)
    fatigue = np.where(sm > 0, tensile, compressive)
    broken = peak >= su
    return np.where(broken, np.nan, fatigue), np.where(broken, np.nan, yielding)


@dataclass(frozen=True)
class LinkFatiguePopulation:
    """A link's fatigue over N designs, each (N,): amplitude and mean [Pa] (notch factor applied), peak σ_a + |σ_m|
    [Pa], broken (peak >= S_ut: no fatigue factor), the fatigue and yield factors of safety (NaN if broken) and
    the damage of the required cycles (NaN without them or if broken)."""

    amplitude: np.ndarray
    mean: np.ndarray
    peak: np.ndarray
    broken: np.ndarray
    fatigue: np.ndarray
    yielding: np.ndarray
    damage: np.ndarray


def link_fatigue(link: Any, top: Any, bottom: Any) -> LinkFatiguePopulation:
    """The fatigue of a link (a :class:`.parts.LinkSpec`) in N designs from the (N, K) stress histories of its
    extreme fibres; the worse fibre (larger |σ|) of each design governs (as :func:`.parts.link_fatigue_checks`).
    The damage n/N of ``link.required_cycles`` uses the S–N line (Shigley's MED, 10th ed., §6-7) at the
    Goodman-equivalent reversed stress σ_a/(1 − σ_m/S_ut) (eq. 6-59), 0 at or below S_e."""
    hi, lo = _rows(top), _rows(bottom)
    use_top = np.max(np.abs(hi), axis=1) >= np.max(np.abs(lo), axis=1)
    worst = np.where(use_top[:, None], hi, lo) * link.notch_factor
    top_stress, bottom_stress = np.max(worst, axis=1), np.min(worst, axis=1)
    amp, mean = 0.5 * (top_stress - bottom_stress), 0.5 * (top_stress + bottom_stress)
    peak = amp + np.abs(mean)
    broken = peak >= link.ultimate_strength
    fatigue, yielding = fatigue_safety_arrays(amp, mean, link.endurance_limit, link.ultimate_strength,
                                              link.yield_strength, link.criterion)
    damage = np.full(amp.shape, np.nan)
    if link.required_cycles is not None:
        line = sn_line(link.ultimate_strength, link.endurance_limit, link.fraction)
        su = link.ultimate_strength
        with np.errstate(divide="ignore", invalid="ignore"):
            rev = np.where(mean > 0, amp / (1.0 - mean / su), amp)
            low = (rev / su) ** (3.0 / np.log10(line.fraction))
            high = (rev / line.a) ** (1.0 / line.b)
            cycles = np.where(rev >= line.fraction * su, low, high)
            damage = np.where(rev <= line.endurance, 0.0, link.required_cycles / cycles)
        damage = np.where(broken | (rev >= su), np.nan, damage)
    return LinkFatiguePopulation(amp, mean, peak, broken, fatigue, yielding, damage)


def engagement_arrays(j1: Any, w1: Any, j2: Any, w2: Any, slip_torque: Any, driving_torque: Any = 0.0,
                      load_torque: Any = 0.0) -> dict[str, Any]:
    """The closed forms of a clutch engagement with constant torques (Shigley's MED, 8th ed., §16-8, with the
    motor torque T1 and load torque T2 added), element-wise over arrays (or floats):

    α1 = (T_c − T1)/J1,  α2 = (T_c − T2)/J2,  t_s = (ω1 − ω2)/(α1 + α2),  ω = ω1 − α1 t_s,
    θ1 = ω1 t_s − α1 t_s²/2,  θ2 = ω2 t_s + α2 t_s²/2,  E = T_c (θ1 − θ2).

    Parameters: j1, j2 [kg·m²]; w1, w2 [rad/s]; slip_torque T_c, driving_torque T1, load_torque T2 [N·m].
    Returns the slip time [s], common speed [rad/s], dissipated energy [J], the angles [rad] and works [J] of the
    two sides, and α2, α1 [rad/s²], by the names of :class:`.clutch.Engagement`. Valid for J1, J2, T_c > 0,
    ω1 > ω2, T1 < T_c and T2 < T_c (:func:`engage_population` flags the rest).
    """
    a1 = (slip_torque - driving_torque) / j1
    a2 = (slip_torque - load_torque) / j2
    ts = (w1 - w2) / (a1 + a2)
    theta1 = w1 * ts - 0.5 * a1 * ts**2
    theta2 = w2 * ts + 0.5 * a2 * ts**2
    return {"slip_time": ts, "common_speed": w1 - a1 * ts, "dissipated": slip_torque * (theta1 - theta2),
            "driving_angle": theta1, "driven_angle": theta2, "driving_work": driving_torque * theta1,
            "load_work": load_torque * theta2, "driven_acceleration": a2, "driving_deceleration": a1}


def engage_population(j1: Any, w1: Any, j2: Any, w2: Any, slip_torque: Any, driving_torque: Any = 0.0,
                      load_torque: Any = 0.0) -> dict[str, np.ndarray]:
    """Clutch engagements of N designs (each argument (N,) or a float; :func:`engagement_arrays`), with
    ``valid`` (N,) False — and every result NaN — where :func:`.clutch.engage` refuses the design (an inertia or
    the slip torque not finite and > 0, ω1 <= ω2, or a motor or load torque at or above the slip torque)."""
    args = np.broadcast_arrays(*(np.atleast_1d(np.asarray(x, dtype=float)) for x in
                                 (j1, w1, j2, w2, slip_torque, driving_torque, load_torque)))
    a_j1, a_w1, a_j2, a_w2, tc, t1, t2 = args
    valid = (np.isfinite(a_j1) & (a_j1 > 0) & np.isfinite(a_j2) & (a_j2 > 0) & np.isfinite(tc) & (tc > 0)
             & (a_w1 > a_w2) & (t2 < tc) & (t1 < tc))
    safe = [np.where(valid, x, 1.0) for x in (a_j1, a_j2, tc)]
    w1s, w2s = np.where(valid, a_w1, 1.0), np.where(valid, a_w2, 0.0)
    t1s, t2s = np.where(valid, t1, 0.0), np.where(valid, t2, 0.0)
    found = engagement_arrays(safe[0], w1s, safe[1], w2s, safe[2], t1s, t2s)
    return {k: np.where(valid, v, np.nan) for k, v in found.items()} | {"valid": valid}
