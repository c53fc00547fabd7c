"""The energy figures of seed 002: as printed, by the paper's formulas corrected, and exact by the engine."""

from __future__ import annotations

import numpy as np

from ..linkage import energy, kinetostatics
from .formulas import (
    _refined_extreme,
    energy_range,
    fluctuation_power,
    input_torque,
    pr_first_order,
    pr_printed,
    rotating_mass,
    spring_stiffness,
    t1_max,
    t1_max_with_lambda,
    t2,
    t3,
    translating_mass,
    w1_range_eq20,
)
from .model import PAPER_SCREEN, RotaryScreen, _s

# ---------------------------------------------------------------------------------------- figures


def _entry(quantity, unit, paper, formula, engine, source, note=""):
    return {
        "quantity": quantity,
        "unit": unit,
        "paper": paper,
        "formula": None if formula is None else float(formula),
        "engine": None if engine is None else float(engine),
        "source": source,
        "note": note,
    }


def energy_figures(screen: RotaryScreen = PAPER_SCREEN, samples: int = 3601) -> dict[str, dict]:
    """The paper's energy figures next to machdyn's: the paper's formula and the engine's exact value.

    Returns a dict keyed by figure name; each value is a dict with ``quantity`` (text), ``unit``, ``paper``
    (the printed value for the paper's own screen, or None for another screen or where the paper prints none),
    ``formula`` (the paper's formula, corrected where it is wrong, evaluated for ``screen``), ``engine`` (the
    same quantity from the exact engine model :meth:`RotaryScreen.mechanism`, or None where not applicable),
    ``source`` (equation) and ``note``. Keys: lambda, m_B, m_C, T1max, T1max_lambda, T2, T3, W_min, W_max,
    fluctuation_power, K, W1_min_ratio, W1_max_ratio, P_r, P_r_printed, W1_fluctuation, M_in_peak,
    M_in_peak_spring.

    The engine's values are found on a uniform grid of ``samples`` crank angles with the extremes refined by
    re-sampling ever finer around them, so they are exact to far below the printed digits.
    """
    s = _s(screen)
    paper = s == PAPER_SCREEN
    w = s.omega
    grid = np.linspace(0.0, 2.0 * np.pi, int(samples))
    plain, sprung = s.mechanism(spring=False), s.mechanism(spring=True)

    def total(mech):
        return lambda a: energy(mech, a, speed=w).total

    def torque(mech):
        return lambda a: kinetostatics(mech, a, speed=w).driving_torque

    def extremes(func):
        values = func(grid)
        return _refined_extreme(func, grid, values, "min"), _refined_extreme(func, grid, values, "max")

    w_min, w_max = extremes(total(plain))
    t3_engine = float(energy(plain, np.zeros(1), speed=w).kinetic["counterweight"][0])
    t2_engine = w_min - t3_engine  # at the dead centres the slider is at rest: W = T2 + T3 exactly
    t1_engine = w_max - w_min
    # with the spring, W1 = T1 + V1 = W' - (T2 + T3)
    w1_lo, w1_hi = (v - w_min for v in extremes(total(sprung)))
    m0_lo, m0_hi = extremes(torque(plain))
    m1_lo, m1_hi = extremes(torque(sprung))
    m0_peak, m1_peak = max(-m0_lo, m0_hi), max(-m1_lo, m1_hi)
    t1m = t1_max(s)
    lam = s.lam
    lo20, hi20 = w1_range_eq20(lam)
    tl, _ = t1_max_with_lambda(s)
    fine = np.linspace(0.0, 2.0 * np.pi, 20001)
    return {
        "lambda": _entry("crank-rod ratio lambda = R/L", "", 0.0125 if paper else None, lam, None, "sec. 1"),
        "m_B": _entry("rotating mass m_B", "kg", None, rotating_mass(s), None, "eq 4"),
        "m_C": _entry("translating mass m_C", "kg", None, translating_mass(s), None, "eq 5"),
        "T1max": _entry("max kinetic energy of the translating parts T1max", "J", 284.58 if paper else None, t1m,
                        t1_engine, "eq 15", "formula ignores lambda; engine: exact kinematics"),
        "T1max_lambda": _entry("T1max with lambda kept (eq 7)", "J", None, tl, t1_engine, "eq 7",
                               "maximum of eq 7 at cos a = (-1 + sqrt(1 + 8 lam^2)) / (4 lam)"),
        "T2": _entry("kinetic energy of the rotating mass T2", "J", 253.42 if paper else None, t2(s), t2_engine,
                     "eq 8"),
        "T3": _entry("kinetic energy of the counterweight T3", "J", 1233.31 if paper else None, t3(s), t3_engine,
                     "eq 9", "eqs 10/19 print r_e without the square"),
        "W_min": _entry("total kinetic energy, minimum", "J", 1486.73 if paper else None, energy_range(s)[0],
                        w_min, "eq 10"),
        "W_max": _entry("total kinetic energy, maximum", "J", 1771.31 if paper else None, energy_range(s)[1],
                        w_max, "eq 10"),
        "fluctuation_power": _entry("power of the energy fluctuation T1max omega / pi", "W",
                                    1900.0 if paper else None, fluctuation_power(s), t1_engine * w / np.pi,
                                    "sec. 2", "two energy rises per revolution"),
        "K": _entry("spring stiffness K = m_C omega^2", "N/m", None, spring_stiffness(s), None, "eq 17"),
        "W1_min_ratio": _entry("W1 = T1 + V1, minimum / T1max", "", 0.986 if paper else None, lo20,
                               w1_lo / t1m, "eqs 20, 24", "formula: eq 20 evaluated exactly"),
        "W1_max_ratio": _entry("W1 = T1 + V1, maximum / T1max", "", 1.014 if paper else None, hi20,
                               w1_hi / t1m, "eqs 20, 23", "formula: eq 20 evaluated exactly"),
        "P_r": _entry("relative fluctuation of W1, P_r", "", 0.028 if paper else None, pr_first_order(lam),
                      (w1_hi - w1_lo) / t1m, "eq 26 corrected",
                      "paper: 4 lam sqrt(3)/3 from the wrong eq 21; correct (8/3) sqrt(2/3) lam"),
        "P_r_printed": _entry("P_r by the paper's eq 26 (wrong)", "", 0.028 if paper else None, pr_printed(lam),
                              None, "eq 26"),
        "W1_fluctuation": _entry("fluctuation of W1 with the spring", "J", None, pr_first_order(lam) * t1m,
                                 w1_hi - w1_lo, "eqs 20-26 corrected"),
        "M_in_peak": _entry("peak input torque dW/dalpha, no spring", "N*m", None,
                            float(np.max(np.abs(input_torque(s, fine)))), m0_peak, "eq 12"),
        "M_in_peak_spring": _entry("peak input torque dW/dalpha, with spring", "N*m", None,
                                   float(np.max(np.abs(input_torque(s, fine, spring=True)))), m1_peak,
                                   "eqs 12, 19"),
    }
