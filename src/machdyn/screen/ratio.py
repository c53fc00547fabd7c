"""The energy ratio W1/T1max of the screen with its spring and its range P_r (seed 002, eqs 20-26),
corrected where the paper is wrong (repro 002.3)."""

from __future__ import annotations

import numpy as np

from ..errors import check_positive
from ..linkage.extremes import refine_extreme


def w1_ratio_eq20(alpha, lam):
    """Seed 002 eq 20 divided by T1max: W1/T1max = (sin α + (λ/2) sin 2α)² + (cos α + (λ/4)(1 + cos 2α))².

    Evaluated as printed, without further expansion (eq 20 itself is correct).

    Parameters
    ----------
    alpha : float or array
        Crank angle α [rad].
    lam : float
        Crank-to-rod ratio λ = R/L [-], in (0, 1).

    Returns
    -------
    float or array
        W1/T1max [-].

    Examples
    --------
    >>> round(float(w1_ratio_eq20(np.pi / 4, 0.0125)), 6)
    1.013307
    """
    check_positive("lambda", lam)
    a = np.asarray(alpha, dtype=float)
    return (np.sin(a) + lam / 2.0 * np.sin(2.0 * a)) ** 2 + (np.cos(a) + lam / 4.0 * (1.0 + np.cos(2.0 * a))) ** 2


def w1_ratio_first_order(alpha, lam):
    """Corrected seed 002 eq 21: W1/T1max ≈ 1 + λ cos α (1 + sin² α) (repro 002.3).

    The paper prints 1 + 3λ sin² α cos α, which is wrong (the difference is λ cos α cos 2α); it is what eq 20
    gives with a sign error in eq 13's (1 + cos 2α).

    Parameters
    ----------
    alpha : float or array
        Crank angle α [rad].
    lam : float
        λ = R/L [-], small (first order).

    Returns
    -------
    float or array
        W1/T1max [-].

    Examples
    --------
    >>> round(float(w1_ratio_first_order(np.pi / 4, 0.0125)), 6)
    1.013258
    """
    check_positive("lambda", lam)
    a = np.asarray(alpha, dtype=float)
    return 1.0 + lam * np.cos(a) * (1.0 + np.sin(a) ** 2)


def w1_ratio_printed(alpha, lam):
    """Seed 002 eq 21 as printed (wrong, see :func:`w1_ratio_first_order`): 1 + 3λ sin² α cos α.

    Parameters
    ----------
    alpha : float or array
        Crank angle α [rad].
    lam : float
        λ = R/L [-].

    Returns
    -------
    float or array
        The printed W1/T1max [-]; kept only to document the error.

    Examples
    --------
    >>> round(float(w1_ratio_printed(np.pi / 4, 0.0125)), 6)
    1.013258
    """
    check_positive("lambda", lam)
    a = np.asarray(alpha, dtype=float)
    return 1.0 + 3.0 * lam * np.sin(a) ** 2 * np.cos(a)


def w1_range_printed(lam) -> tuple[float, float]:
    """Seed 002 eqs 23–24: W1/T1max in 1 ∓ (2λ/3)√3 (from the wrong eq 21).

    Parameters
    ----------
    lam : float
        λ = R/L [-].

    Returns
    -------
    tuple of float
        (min, max) of W1/T1max [-] as printed; the correct range is :func:`w1_range_eq20`.

    Examples
    --------
    >>> [round(float(x), 6) for x in w1_range_printed(0.0125)]
    [0.985566, 1.014434]
    """
    check_positive("lambda", lam)
    d = 2.0 * lam * np.sqrt(3.0) / 3.0
    return 1.0 - d, 1.0 + d


def w1_range_eq20(lam, samples: int = 400_001) -> tuple[float, float]:
    """Exact range of seed 002 eq 20's W1/T1max over a revolution (repro 002.3).

    The extremes (near α = 35.26° and 144.74°) are located on a uniform grid of ``samples`` points and then
    refined by re-sampling around them.

    Parameters
    ----------
    lam : float
        λ = R/L [-], in (0, 1).
    samples : int
        Number of grid points over one revolution [-].

    Returns
    -------
    tuple of float
        (min, max) of W1/T1max [-].

    Examples
    --------
    >>> [round(float(x), 6) for x in w1_range_eq20(0.0125, samples=4001)]
    [0.986444, 1.01366]
    """
    check_positive("lambda", lam)
    a = np.linspace(0.0, 2.0 * np.pi, int(samples))
    w = w1_ratio_eq20(a, lam)

    def ratio(x):
        return w1_ratio_eq20(np.asarray(x), lam)

    return _refined_extreme(ratio, a, w, "min"), _refined_extreme(ratio, a, w, "max")


def pr_printed(lam) -> float:
    """Seed 002 eq 26: P_r = 4λ√3 / 3 (the paper prints the truncated 0.028 at λ = 0.0125).

    Rests on the wrong eq 21; the correct value is :func:`pr_first_order` / :func:`pr_eq20`.

    Parameters
    ----------
    lam : float
        λ = R/L [-].

    Returns
    -------
    float
        P_r [-] as printed.

    Examples
    --------
    >>> round(float(pr_printed(0.0125)), 6)
    0.028868
    """
    check_positive("lambda", lam)
    return 4.0 * lam * np.sqrt(3.0) / 3.0


def pr_first_order(lam) -> float:
    """Corrected seed 002 eq 26: P_r = (8/3)√(2/3) λ ≈ 2.17732 λ.

    From the corrected eq 21, extremes at cos α = ±√(2/3) (repro 002.3).

    Parameters
    ----------
    lam : float
        λ = R/L [-], small (first order).

    Returns
    -------
    float
        P_r [-].

    Examples
    --------
    >>> round(float(pr_first_order(0.0125)), 6)
    0.027217
    """
    check_positive("lambda", lam)
    return 8.0 / 3.0 * np.sqrt(2.0 / 3.0) * lam


def pr_eq20(lam) -> float:
    """P_r = max − min of seed 002 eq 20's W1/T1max, evaluated without expansion (repro 002.3).

    Parameters
    ----------
    lam : float
        λ = R/L [-], in (0, 1).

    Returns
    -------
    float
        P_r [-].

    Examples
    --------
    >>> round(float(pr_eq20(0.0125)), 6)
    0.027217
    """
    lo, hi = w1_range_eq20(lam)
    return hi - lo



def _refined_extreme(func, grid, values, pick):
    """The extreme ``pick`` ('max' or 'min') of a smooth periodic func sampled on a uniform grid, refined by
    re-sampling ever finer around the best sample (:func:`machdyn.linkage.extremes.refine_extreme`)."""
    return refine_extreme(func, grid, values, pick)[1]
