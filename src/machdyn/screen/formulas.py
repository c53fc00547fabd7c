"""The formulas of seed 002 (eqs 1-26), corrected where the paper is wrong (repro 002.x)."""

from __future__ import annotations

import numpy as np

from ..errors import check_finite, check_positive
from .model import PAPER_SCREEN, RotaryScreen, _s  # noqa: F401 - PAPER_SCREEN is used by the doctests
from .ratio import (  # noqa: F401 - re-exported: eqs 20-26 live in ratio.py
    _refined_extreme,
    pr_eq20,
    pr_first_order,
    pr_printed,
    w1_range_eq20,
    w1_range_printed,
    w1_ratio_eq20,
    w1_ratio_first_order,
    w1_ratio_printed,
)
from .slider import (  # noqa: F401 - re-exported: eqs 1-3 live in slider.py
    slider_acceleration_series,
    slider_position_exact,
    slider_position_series,
    slider_velocity_exact,
    slider_velocity_series,
)

# -------------------------------------------------------------------------------------- eqs 4-10


def rotating_mass(screen: RotaryScreen) -> float:
    """Mass substituted at the crank pin B (seed 002, eq 4): m_B = (l_AS1/R) m1 + (l_CS2/L) m2.

    Static two-point substitution of the crank and of the rod's share at B (correct; repro 002).

    Parameters
    ----------
    screen : RotaryScreen
        The screen: R, L [m]; m1, m2 [kg]; l_AS1, l_CS2 [m].

    Returns
    -------
    float
        m_B [kg].

    Examples
    --------
    >>> round(rotating_mass(PAPER_SCREEN), 4)
    567.5556
    """
    s = _s(screen)
    return s.l_AS1 / s.R * s.m1 + s.l_CS2 / s.L * s.m2


def translating_mass(screen: RotaryScreen) -> float:
    """Mass substituted at the slider C (seed 002, eq 5): m_C = (l_BS2/L) m2 + m3.

    Parameters
    ----------
    screen : RotaryScreen
        The screen: L, l_BS2 [m]; m2, m3 [kg].

    Returns
    -------
    float
        m_C [kg].

    Examples
    --------
    >>> round(translating_mass(PAPER_SCREEN), 4)
    637.3333
    """
    return _s(screen).m_C


def t1(screen: RotaryScreen, alpha, *, with_lambda: bool = True):
    """Kinetic energy of the translating mass (seed 002, eq 7): T1 = ½ m_C R² ω² f².

    f = sin α + (λ/2) sin 2α (eq 2), or f = sin α with ``with_lambda=False`` (as eq 15 does).

    Parameters
    ----------
    screen : RotaryScreen
        The screen: R, L [m], ω [rad/s] and the masses of eq 5 [kg].
    alpha : float or array
        Crank angle α [rad], any real.
    with_lambda : bool
        Keep the λ = R/L term of eq 2 [-].

    Returns
    -------
    float or array
        T1 [J], first order in λ (valid for λ ≲ 0.3).

    Examples
    --------
    >>> round(float(t1(PAPER_SCREEN, np.pi / 3)), 4)
    216.1092
    >>> round(float(t1(PAPER_SCREEN, np.pi / 3, with_lambda=False)), 4)
    213.433
    """
    s = _s(screen)
    check_finite("crank angle alpha", alpha, "rad")
    lam = s.lam if with_lambda else 0.0
    f = np.sin(alpha) + lam / 2.0 * np.sin(2.0 * np.asarray(alpha, dtype=float))
    return 0.5 * translating_mass(s) * s.R**2 * s.omega**2 * f**2


def t1_max(screen: RotaryScreen) -> float:
    """Largest kinetic energy of the translating mass (seed 002, eq 15): T1max = ½ m_C R² ω².

    Parameters
    ----------
    screen : RotaryScreen
        The screen: R [m], ω [rad/s] and the masses of eq 5 [kg].

    Returns
    -------
    float
        T1max [J] with λ = R/L ignored, as the paper does; :func:`t1_max_with_lambda` keeps λ (it is 0.0156 %
        larger for the paper's screen). Valid for λ ≲ 0.1.

    Examples
    --------
    >>> round(t1_max(PAPER_SCREEN), 4)
    284.5773
    """
    s = _s(screen)
    return 0.5 * translating_mass(s) * s.R**2 * s.omega**2


def t1_max_with_lambda(screen: RotaryScreen) -> tuple[float, float]:
    """Maximum of seed 002 eq 7 with λ kept (repro 002.2).

    d/dα (sin α + (λ/2) sin 2α) = 0 gives 2λc² + c − λ = 0, c = cos α* = (−1 + √(1 + 8λ²)) / (4λ);
    ignoring λ underestimates T1max by 0.0156 % for the paper's screen.

    Parameters
    ----------
    screen : RotaryScreen
        The screen: R, L [m], ω [rad/s] and the masses of eq 5 [kg].

    Returns
    -------
    tuple of float
        (T1max [J], α* [rad]). Valid for 0 < λ < 1.

    Examples
    --------
    >>> T, a = t1_max_with_lambda(PAPER_SCREEN)
    >>> round(T, 4), round(float(np.degrees(a)), 3)
    (284.6218, 89.284)
    """
    s = _s(screen)
    lam = s.lam
    c = (-1.0 + np.sqrt(1.0 + 8.0 * lam**2)) / (4.0 * lam)
    a = float(np.arccos(c))
    return float(t1(s, a)), a


def t2(screen: RotaryScreen) -> float:
    """Kinetic energy of the rotating mass (seed 002, eq 8): T2 = ½ m_B R² ω², constant.

    Parameters
    ----------
    screen : RotaryScreen
        The screen: R [m], ω [rad/s] and the masses of eq 4 [kg].

    Returns
    -------
    float
        T2 [J].

    Examples
    --------
    >>> round(t2(PAPER_SCREEN), 4)
    253.4206
    """
    s = _s(screen)
    return 0.5 * rotating_mass(s) * s.R**2 * s.omega**2


def t3(screen: RotaryScreen) -> float:
    """Kinetic energy of the eccentric (seed 002, eq 9): T3 = ½ m_e r_e² ω², constant.

    Eqs 10 and 19 print ½ m_e r_e ω² (square missing); the numbers in the text use the square
    (the paper prints 1233.31 J). See :func:`t3_printed`.

    Parameters
    ----------
    screen : RotaryScreen
        The screen: eccentric mass m_e [kg], radius r_e [m], ω [rad/s].

    Returns
    -------
    float
        T3 [J].

    Examples
    --------
    >>> round(t3(PAPER_SCREEN), 4)
    1233.3032
    """
    s = _s(screen)
    return 0.5 * s.m_e * s.r_e**2 * s.omega**2


def t3_printed(screen: RotaryScreen) -> float:
    """Seed 002 eqs 10/19 as printed: ½ m_e r_e ω² (dimensionally wrong).

    Kept only to document the misprint; use :func:`t3`.

    Parameters
    ----------
    screen : RotaryScreen
        The screen: m_e [kg], r_e [m], ω [rad/s].

    Returns
    -------
    float
        The printed expression [kg m/s²] — not an energy.

    Examples
    --------
    >>> round(t3_printed(PAPER_SCREEN), 2)
    5631.52
    """
    s = _s(screen)
    return 0.5 * s.m_e * s.r_e * s.omega**2


def total_energy(screen: RotaryScreen, alpha, *, with_lambda: bool = True):
    """Total kinetic energy of the screen (seed 002, eqs 6/10, with the square on r_e): W = T1 + T2 + T3.

    Parameters
    ----------
    screen : RotaryScreen
        The screen (see :func:`t1`, :func:`t2`, :func:`t3`).
    alpha : float or array
        Crank angle α [rad].
    with_lambda : bool
        Keep the λ term of eq 2 in T1 [-].

    Returns
    -------
    float or array
        W [J], first order in λ (valid for λ ≲ 0.3).

    Examples
    --------
    >>> round(float(total_energy(PAPER_SCREEN, np.pi / 2, with_lambda=False)), 4)
    1771.3012
    """
    return t1(screen, alpha, with_lambda=with_lambda) + t2(screen) + t3(screen)


def energy_range(screen: RotaryScreen) -> tuple[float, float]:
    """Range of W over a revolution (seed 002, text after eq 10), λ ignored.

    Parameters
    ----------
    screen : RotaryScreen
        The screen (see :func:`t1_max`, :func:`t2`, :func:`t3`).

    Returns
    -------
    tuple of float
        (T2 + T3, T2 + T3 + T1max) [J]; the paper prints 1486.73 ~ 1771.31 J.

    Examples
    --------
    >>> lo, hi = energy_range(PAPER_SCREEN)
    >>> round(lo, 4), round(hi, 4)
    (1486.7239, 1771.3012)
    """
    base = t2(screen) + t3(screen)
    return base, base + t1_max(screen)


def fluctuation_power(screen: RotaryScreen) -> float:
    """Power of the energy fluctuation (seed 002, section 2): 2 T1max per revolution, P = T1max ω / π.

    Counts the two energy rises per revolution only; counting rises and falls would double it
    (repro 002.1 item 7). The paper prints 1.90 kW.

    Parameters
    ----------
    screen : RotaryScreen
        The screen: R [m], ω [rad/s], masses [kg].

    Returns
    -------
    float
        P [W].

    Examples
    --------
    >>> round(fluctuation_power(PAPER_SCREEN), 2)
    1902.26
    """
    s = _s(screen)
    return t1_max(s) * s.omega / np.pi


# ---------------------------------------------------------------------------------- eqs 13-26, spring


def spring_stiffness(screen: RotaryScreen) -> float:
    """Stiffness of the energy-storing spring (seed 002, eq 17): K = m_C ω².

    From T1max = V1max = ½ K R² (eqs 14–16); √(K/m_C) = ω, i.e. the spring tunes the translating mass to
    resonate at the running speed.

    Parameters
    ----------
    screen : RotaryScreen
        The screen: ω [rad/s] and the masses of eq 5 [kg].

    Returns
    -------
    float
        K [N/m].

    Examples
    --------
    >>> round(spring_stiffness(PAPER_SCREEN))
    281064
    """
    s = _s(screen)
    return translating_mass(s) * s.omega**2


def spring_displacement_series(alpha, R, L):
    """Spring extension, first order in λ (seed 002, eq 13): S' = S − √(L² − R²) ≈ R [cos α + (λ/4)(1 + cos 2α)].

    Correct to first order (repro 002.3).

    Parameters
    ----------
    alpha : float or array
        Crank angle α [rad].
    R : float
        Crank radius [m], > 0.
    L : float
        Rod length [m], > R.

    Returns
    -------
    float or array
        S' [m]; valid for λ = R/L ≲ 0.3.

    Examples
    --------
    >>> round(float(spring_displacement_series(0.0, 0.1, 0.8)), 7)
    0.10625
    """
    check_positive("crank radius R", R, "m")
    check_positive("rod length L", L, "m")
    lam = R / L
    return R * (np.cos(alpha) + lam / 4.0 * (1.0 + np.cos(2.0 * alpha)))


def spring_displacement_exact(alpha, R, L):
    """Exact spring extension S' = S − √(L² − R²), zero at α = 90° and 270°.

    The exact form of seed 002 eq 13, from :func:`slider_position_exact`.

    Parameters
    ----------
    alpha : float or array
        Crank angle α [rad].
    R : float
        Crank radius [m], > 0.
    L : float
        Rod length [m], > R.

    Returns
    -------
    float or array
        S' [m], valid for any 0 < R < L.

    Examples
    --------
    >>> round(float(spring_displacement_exact(0.0, 0.1, 0.8)), 7)
    0.1062746
    """
    return slider_position_exact(alpha, R, L) - np.sqrt(L**2 - R**2)


def spring_energy(screen: RotaryScreen, alpha, *, exact: bool = False):
    """Energy stored in the spring (seed 002, eq 18): V1 = ½ K S'² with K from eq 17.

    S' from eq 13 (:func:`spring_displacement_series`) or exact with ``exact=True``.

    Parameters
    ----------
    screen : RotaryScreen
        The screen: R, L [m], ω [rad/s], masses [kg].
    alpha : float or array
        Crank angle α [rad].
    exact : bool
        Use the exact spring extension [-].

    Returns
    -------
    float or array
        V1 [J].

    Examples
    --------
    >>> round(float(spring_energy(PAPER_SCREEN, 0.0)), 4)
    288.1456
    >>> round(float(spring_energy(PAPER_SCREEN, 0.0, exact=True)), 4)
    288.1458
    """
    s = _s(screen)
    sp = spring_displacement_exact(alpha, s.R, s.L) if exact else spring_displacement_series(alpha, s.R, s.L)
    return 0.5 * spring_stiffness(s) * sp**2


def input_torque(screen: RotaryScreen, alpha, *, spring: bool = False):
    """Input torque at constant speed (seed 002, eq 12): M_in = dW/dα, W from eq 10 (and eq 19 with ``spring``).

    dT1/dα = m_C R² ω² f f' with f = sin α + (λ/2) sin 2α, f' = cos α + λ cos 2α; the spring adds
    K S' dS'/dα = −K R² g f with g = cos α + (λ/4)(1 + cos 2α) (eq 13).

    Parameters
    ----------
    screen : RotaryScreen
        The screen: R, L [m], ω [rad/s], masses [kg].
    alpha : float or array
        Crank angle α [rad].
    spring : bool
        Include the energy-storing spring of eqs 17–19 [-].

    Returns
    -------
    float or array
        M_in [N m], first order in λ (valid for λ ≲ 0.3).

    Examples
    --------
    >>> a = np.linspace(0.0, 2.0 * np.pi, 3601)
    >>> round(float(np.max(np.abs(input_torque(PAPER_SCREEN, a)))), 2)
    287.16
    >>> round(float(np.max(np.abs(input_torque(PAPER_SCREEN, a, spring=True)))), 3)
    7.115
    """
    s = _s(screen)
    check_finite("crank angle alpha", alpha, "rad")
    a = np.asarray(alpha, dtype=float)
    lam = s.lam
    f = np.sin(a) + lam / 2.0 * np.sin(2.0 * a)
    fp = np.cos(a) + lam * np.cos(2.0 * a)
    m = translating_mass(s) * s.R**2 * s.omega**2 * f * fp
    if spring:
        g = np.cos(a) + lam / 4.0 * (1.0 + np.cos(2.0 * a))
        m = m - spring_stiffness(s) * s.R**2 * g * f
    return m
