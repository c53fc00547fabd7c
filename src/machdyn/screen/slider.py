"""Slider-crank kinematics of seed 002 (eqs 1-3) and their exact forms."""

from __future__ import annotations

import numpy as np

from ..errors import check_positive


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
    """Exact slider position of a centred slider-crank: S = R cos α + √(L² − R² sin² α).

    The closed form that seed 002 eq 1 expands to first order in λ = R/L (repro 002.3); any textbook
    slider-crank analysis (e.g. Norton, *Design of Machinery*, slider-crank position analysis) gives it.

    Parameters
    ----------
    alpha : float or array
        Crank angle α [rad], any real, measured from the slide line.
    R : float
        Crank radius [m], > 0.
    L : float
        Rod length [m], > R (valid for any 0 < R < L).

    Returns
    -------
    float or array
        S [m], from the crank centre along the slide line.

    Examples
    --------
    >>> round(float(slider_position_exact(np.pi / 3, 0.1, 0.8)), 7)
    0.8452987
    """
    check_positive("crank radius R", R, "m")
    check_positive("rod length L", L, "m")
    return R * np.cos(alpha) + np.sqrt(L**2 - (R * np.sin(alpha)) ** 2)


def slider_velocity_exact(alpha, R, L, omega):
    """Exact slider velocity: dS/dt = −ω R sin α [1 + R cos α / √(L² − R² sin² α)].

    The time derivative of :func:`slider_position_exact` at constant ω; seed 002 eq 2 is its first-order
    expansion in λ = R/L.

    Parameters
    ----------
    alpha : float or array
        Crank angle α [rad], any real.
    R : float
        Crank radius [m], > 0.
    L : float
        Rod length [m], > R.
    omega : float
        Constant crank speed ω [rad/s].

    Returns
    -------
    float or array
        v [m/s], valid for any 0 < R < L.

    Examples
    --------
    >>> round(float(slider_velocity_exact(np.pi / 3, 0.1, 0.8, 21.0)), 6)
    -1.932991
    """
    check_positive("crank radius R", R, "m")
    check_positive("rod length L", L, "m")
    s, c = np.sin(alpha), np.cos(alpha)
    return -omega * R * s * (1.0 + R * c / np.sqrt(L**2 - (R * s) ** 2))
