"""The formulas of seed 002 (eqs 1-26), corrected where the paper is wrong (repro 002.x)."""

from __future__ import annotations

import numpy as np

from ...errors import check_finite, check_positive
from .model import PAPER_SCREEN, RotaryScreen, _s  # noqa: F401 - PAPER_SCREEN is used by the doctests

# ---------------------------------------------------------------------------------------- eqs 1-3


def slider_position_series(alpha, R, L):
    """Slider position of a centred slider-crank, first order in λ (seed 002, eq 1).

    S ≈ L + R [cos α − (λ/4)(1 − cos 2α)], λ = R/L: the expansion of the exact
    S = R cos α + √(L² − R² sin² α) (:func:`slider_position_exact`), correct (repro 002.3).

    Parameters
    ----------
    alpha : float or array
        Crank angle α [rad], any real.
    R : float
        Crank radius [m], > 0.
    L : float
        Rod length [m], > R.

    Returns
    -------
    float or array
        S [m], measured from the crank centre along the slide line. Valid for λ ≲ 0.3: the error is about
        R λ³ sin⁴ α / 8.

    Examples
    --------
    >>> round(float(slider_position_series(np.pi / 3, 0.1, 0.8)), 7)
    0.8453125
    >>> round(float(slider_position_exact(np.pi / 3, 0.1, 0.8)), 7)
    0.8452987
    """
    check_positive("crank radius R", R, "m")
    check_positive("rod length L", L, "m")
    lam = R / L
    return L + R * (np.cos(alpha) - lam / 4.0 * (1.0 - np.cos(2.0 * alpha)))


def slider_velocity_series(alpha, R, L, omega):
    """Slider velocity, first order in λ (seed 002, eq 2): v ≈ −ω R (sin α + (λ/2) sin 2α).

    Parameters
    ----------
    alpha : float or array
        Crank angle α [rad].
    R, L : float
        Crank radius and rod length [m], 0 < R < L.
    omega : float
        Constant crank speed ω [rad/s].

    Returns
    -------
    float or array
        v [m/s]; correct to first order in λ = R/L (valid for λ ≲ 0.3).

    Examples
    --------
    >>> round(float(slider_velocity_series(np.pi / 3, 0.1, 0.8, 21.0)), 6)
    -1.932319
    """
    check_positive("crank radius R", R, "m")
    check_positive("rod length L", L, "m")
    lam = R / L
    return -omega * R * (np.sin(alpha) + lam / 2.0 * np.sin(2.0 * alpha))


def slider_acceleration_series(alpha, R, L, omega):
    """Slider acceleration, first order in λ (seed 002, eq 3): a ≈ −ω² R (cos α + λ cos 2α).

    Parameters
    ----------
    alpha : float or array
        Crank angle α [rad].
    R, L : float
        Crank radius and rod length [m], 0 < R < L.
    omega : float
        Constant crank speed ω [rad/s].

    Returns
    -------
    float or array
        a [m/s²]; correct to first order in λ = R/L (valid for λ ≲ 0.3).

    Examples
    --------
    >>> round(float(slider_acceleration_series(np.pi / 3, 0.1, 0.8, 21.0)), 5)
    -19.29375
    """
    check_positive("crank radius R", R, "m")
    check_positive("rod length L", L, "m")
    lam = R / L
    return -omega**2 * R * (np.cos(alpha) + lam * np.cos(2.0 * alpha))


def slider_position_exact(alpha, R, L):
    """Exact slider position S = R cos alpha + sqrt(L^2 - R^2 sin^2 alpha) [m] (centred slider-crank).

    Parameters: alpha [rad]; R [m] > 0; L [m] > R.
    """
    check_positive("crank radius R", R, "m")
    check_positive("rod length L", L, "m")
    return R * np.cos(alpha) + np.sqrt(L**2 - (R * np.sin(alpha)) ** 2)


def slider_velocity_exact(alpha, R, L, omega):
    """Exact slider velocity dS/dt = -omega R sin alpha [1 + R cos alpha / sqrt(L^2 - R^2 sin^2 alpha)] [m/s].

    Parameters: alpha [rad]; R [m] > 0; L [m] > R; omega [rad/s] (constant).
    """
    check_positive("crank radius R", R, "m")
    check_positive("rod length L", L, "m")
    s, c = np.sin(alpha), np.cos(alpha)
    return -omega * R * s * (1.0 + R * c / np.sqrt(L**2 - (R * s) ** 2))


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
    """Seed 002 eq 7: kinetic energy of the translating mass, T1 = 1/2 m_C R^2 omega^2 f^2 [J].

    f = sin alpha + (lambda/2) sin 2 alpha (eq 2), or f = sin alpha with ``with_lambda=False`` (as eq 15 does).
    alpha [rad] (any real); first order in lambda.
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
    """Maximum of eq 7 with lambda kept (repro 002.2): (T1max [J], alpha* [rad]).

    d/dalpha (sin alpha + (lambda/2) sin 2 alpha) = 0 gives 2 lambda c^2 + c - lambda = 0,
    c = cos alpha* = (-1 + sqrt(1 + 8 lambda^2)) / (4 lambda). 284.6218 J at 89.284 deg for the paper's screen
    (ignoring lambda underestimates T1max by 0.0156 %). Valid for 0 < lambda < 1.
    """
    s = _s(screen)
    lam = s.lam
    c = (-1.0 + np.sqrt(1.0 + 8.0 * lam**2)) / (4.0 * lam)
    a = float(np.arccos(c))
    return float(t1(s, a)), a


def t2(screen: RotaryScreen) -> float:
    """Seed 002 eq 8: T2 = 1/2 m_B R^2 omega^2 [J], constant (253.4206 J for the paper's screen)."""
    s = _s(screen)
    return 0.5 * rotating_mass(s) * s.R**2 * s.omega**2


def t3(screen: RotaryScreen) -> float:
    """Seed 002 eq 9: T3 = 1/2 m_e r_e^2 omega^2 [J], constant (1233.3032 J; the paper prints 1233.31).

    Eqs 10 and 19 print 1/2 m_e r_e omega^2 (square missing); the numbers in the text use the square.
    """
    s = _s(screen)
    return 0.5 * s.m_e * s.r_e**2 * s.omega**2


def t3_printed(screen: RotaryScreen) -> float:
    """Seed 002 eqs 10/19 as printed: 1/2 m_e r_e omega^2 (dimensionally wrong: kg m/s^2; 5631.52 for the
    paper's screen). Kept only to document the misprint; use :func:`t3`."""
    s = _s(screen)
    return 0.5 * s.m_e * s.r_e * s.omega**2


def total_energy(screen: RotaryScreen, alpha, *, with_lambda: bool = True):
    """Seed 002 eqs 6/10 (with the square on r_e): W = T1 + T2 + T3 [J]. alpha [rad]."""
    return t1(screen, alpha, with_lambda=with_lambda) + t2(screen) + t3(screen)


def energy_range(screen: RotaryScreen) -> tuple[float, float]:
    """Range of W (seed 002, text after eq 10): (T2 + T3, T2 + T3 + T1max) [J], lambda ignored.

    1486.7239 ... 1771.3012 J for the paper's screen (paper: 1486.73 ~ 1771.31 J).
    """
    base = t2(screen) + t3(screen)
    return base, base + t1_max(screen)


def fluctuation_power(screen: RotaryScreen) -> float:
    """Power of the energy fluctuation (seed 002 section 2): 2 T1max per revolution, T1max omega / pi [W].

    1902.26 W for the paper's screen (paper: 1.90 kW). This counts the two energy rises per revolution only;
    counting rises and falls would double it (repro 002.1 item 7).
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
    """Seed 002 eq 13: S' = S - sqrt(L^2 - R^2) ~ R [cos alpha + (lambda/4)(1 + cos 2 alpha)] [m].

    Correct to first order (repro 002.3). Parameters: alpha [rad]; R [m] > 0; L [m] > R.
    """
    check_positive("crank radius R", R, "m")
    check_positive("rod length L", L, "m")
    lam = R / L
    return R * (np.cos(alpha) + lam / 4.0 * (1.0 + np.cos(2.0 * alpha)))


def spring_displacement_exact(alpha, R, L):
    """Exact spring extension S' = S - sqrt(L^2 - R^2) [m], zero at alpha = 90 deg and 270 deg.

    Parameters: alpha [rad]; R [m] > 0; L [m] > R.
    """
    return slider_position_exact(alpha, R, L) - np.sqrt(L**2 - R**2)


def spring_energy(screen: RotaryScreen, alpha, *, exact: bool = False):
    """Seed 002 eq 18: V1 = 1/2 K S'^2 [J] with K from eq 17 and S' from eq 13 (or exact with ``exact``)."""
    s = _s(screen)
    sp = spring_displacement_exact(alpha, s.R, s.L) if exact else spring_displacement_series(alpha, s.R, s.L)
    return 0.5 * spring_stiffness(s) * sp**2


def w1_ratio_eq20(alpha, lam):
    """Seed 002 eq 20 divided by T1max: W1/T1max = (sin a + (lam/2) sin 2a)^2 + (cos a + (lam/4)(1 + cos 2a))^2.

    Evaluated as printed, without further expansion (eq 20 itself is correct). alpha [rad]; lam = R/L in (0, 1).
    """
    check_positive("lambda", lam)
    a = np.asarray(alpha, dtype=float)
    return (np.sin(a) + lam / 2.0 * np.sin(2.0 * a)) ** 2 + (np.cos(a) + lam / 4.0 * (1.0 + np.cos(2.0 * a))) ** 2


def w1_ratio_first_order(alpha, lam):
    """Corrected seed 002 eq 21: W1/T1max ~ 1 + lam cos alpha (1 + sin^2 alpha) (repro 002.3).

    The paper prints 1 + 3 lam sin^2 alpha cos alpha, which is **wrong** (the difference is lam cos a cos 2a); it
    is what eq 20 gives with a sign error in eq 13's (1 + cos 2a). alpha [rad]; lam = R/L, small.
    """
    check_positive("lambda", lam)
    a = np.asarray(alpha, dtype=float)
    return 1.0 + lam * np.cos(a) * (1.0 + np.sin(a) ** 2)


def w1_ratio_printed(alpha, lam):
    """Seed 002 eq 21 as printed (wrong, see :func:`w1_ratio_first_order`): 1 + 3 lam sin^2 alpha cos alpha."""
    check_positive("lambda", lam)
    a = np.asarray(alpha, dtype=float)
    return 1.0 + 3.0 * lam * np.sin(a) ** 2 * np.cos(a)


def w1_range_printed(lam) -> tuple[float, float]:
    """Seed 002 eqs 23-24: W1/T1max in 1 -+ (2 lam / 3) sqrt 3 (from the wrong eq 21). lam = R/L."""
    check_positive("lambda", lam)
    d = 2.0 * lam * np.sqrt(3.0) / 3.0
    return 1.0 - d, 1.0 + d


def w1_range_eq20(lam, samples: int = 400_001) -> tuple[float, float]:
    """Exact range of eq 20's W1/T1max over a revolution [-] (repro 002.3: [0.986444, 1.013660] at lam = 0.0125).

    The extremes (near alpha = 35.26 deg and 144.74 deg) are located on a uniform grid of ``samples`` points
    and then refined by re-sampling around them. lam = R/L in (0, 1).
    """
    check_positive("lambda", lam)
    a = np.linspace(0.0, 2.0 * np.pi, int(samples))
    w = w1_ratio_eq20(a, lam)

    def ratio(x):
        return w1_ratio_eq20(np.asarray(x), lam)

    return _refined_extreme(ratio, a, w, "min"), _refined_extreme(ratio, a, w, "max")


def pr_printed(lam) -> float:
    """Seed 002 eq 26: P_r = 4 lam sqrt(3) / 3 (0.028868 at lam = 0.0125; the paper prints the truncated 0.028).

    Rests on the wrong eq 21; the correct value is :func:`pr_first_order` / :func:`pr_eq20`.
    """
    check_positive("lambda", lam)
    return 4.0 * lam * np.sqrt(3.0) / 3.0


def pr_first_order(lam) -> float:
    """Corrected seed 002 eq 26: P_r = (8/3) sqrt(2/3) lam = 2.17732 lam (0.027217 at lam = 0.0125).

    From the corrected eq 21, extremes at cos alpha = +-sqrt(2/3) (repro 002.3). lam = R/L, small.
    """
    check_positive("lambda", lam)
    return 8.0 / 3.0 * np.sqrt(2.0 / 3.0) * lam


def pr_eq20(lam) -> float:
    """P_r = (max - min) of eq 20's W1/T1max, evaluated exactly (repro 002.3: 0.027217 at lam = 0.0125)."""
    lo, hi = w1_range_eq20(lam)
    return hi - lo


def input_torque(screen: RotaryScreen, alpha, *, spring: bool = False):
    """Seed 002 eq 12: M_in = dW/dalpha [N m] at constant omega, W from eq 10 (and eq 19 with ``spring``).

    dT1/dalpha = m_C R^2 omega^2 f f' with f = sin a + (lam/2) sin 2a, f' = cos a + lam cos 2a; the spring adds
    K S' dS'/dalpha = -K R^2 g f with g = cos a + (lam/4)(1 + cos 2a) (eq 13). Peak |M_in| of the paper's screen:
    287.16 N m without the spring, 7.115 N m with it (repro 002.3). alpha [rad].
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


def _refined_extreme(func, grid, values, pick):
    """The extreme ``pick`` ('max' or 'min') of a smooth periodic func sampled on a uniform grid, refined by
    re-sampling ever finer around the best sample (:func:`machdyn.linkage.extremes.refine_extreme`)."""
    from ...linkage.extremes import refine_extreme

    return refine_extreme(func, grid, values, pick)[1]
