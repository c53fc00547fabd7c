"""The screw flight as an annular plate clamped at the pipe and free at its rim (seed 004, eqs 2.56-2.70).

A uniform pressure p acts on an annulus R2 ≤ r ≤ R1 (R2: pipe radius, clamped; R1: flight radius, free).
Two independent forms are given: the exact solution of the axisymmetric plate equation
(:func:`flight_moments`) and the seed's closed forms with their misprints corrected
(:func:`flight_moments_seed`, :func:`flight_edge_moments`). They agree to rounding.

Moments are per unit length of section [N·m/m = N]; stresses σ = 6M/h² [Pa].
Corrections to the printed seed (each checked against the exact solution):

* 2.56: N = p·π(R1² − R2²), not R1² + R2² (2.57 holds only with the minus sign);
* 2.58: R1²/r in the inner integrand, not R1/r; 2.60 and 2.64 (R2⁴/R1⁴) misprinted;
* constant C2 = −C1·R2² (the printed C2 has the wrong sign);
* 2.68: the λ⁻² coefficient is 2λ⁻²(α² − 1 − μ − μα²), not (α² − 1 − 2μ − 2μα²);
* 2.70, inner M_r: the term is −4μα⁻² (the μ is missing in print).
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError


def _check(p: float, r1: float, r2: float, mu: float) -> None:
    if not (np.all(np.asarray(r1) > r2) and np.all(np.asarray(r2) > 0)):
        raise InputError(f"The flight needs outer radius > pipe radius > 0; got R1 = {r1:g} m, R2 = {r2:g} m.")
    if not 0.0 <= mu < 0.5:
        raise InputError(f"The Poisson ratio must be in [0, 0.5); got {mu:g}.")
    if not np.all(np.isfinite(p)):
        raise InputError(f"The flight pressure must be a finite number; got {p}.")


def plate_coefficient(alpha: float, mu: float) -> float:
    """Coefficient A of seed 004, eq 2.66 (verified against the exact solution).

    A = [1 + 3μ − α⁻⁴(1 − μ) − 4μα⁻² − 4(1 + μ) ln α] / [1 + μ + α⁻²(1 − μ)]

    alpha = R1/R2 [-] (> 1), mu Poisson's ratio [-].

    Examples
    --------
    >>> round(float(plate_coefficient(2.0, 0.3)), 6)  # seed-reproduction test vector
    -1.388553
    """
    num = 1 + 3 * mu - alpha**-4 * (1 - mu) - 4 * mu * alpha**-2 - 4 * (1 + mu) * np.log(alpha)
    return num / (1 + mu + alpha**-2 * (1 - mu))


def _particular(r: float, p: float, r1: float, r2: float) -> tuple[float, float]:
    """F(r) and F'(r) of the particular slope θ_p = −(p/2D)·F(r)/r (double integral of 2.58)."""
    lnr = np.log(r / r2)
    f = r**4 / 8 - r2**2 * r**2 / 4 + r2**4 / 8 - r1**2 * r**2 / 2 * lnr + r1**2 * r**2 / 4 - r1**2 * r2**2 / 4
    fp = r**3 / 2 - r2**2 * r / 2 - r1**2 * r * lnr
    return f, fp


def flight_moments(r: float, p: float, r1: float, r2: float, mu: float = 0.3) -> tuple[float, float]:
    """Radial and tangential bending moments (M_r, M_τ) [N·m/m] at radius r of the flight, exact.

    Solves D·d/dr[(1/r)·d(rθ)/dr] = Q(r) with the shear Q = −(p/2)(r − R1²/r) of the annulus loaded by p
    and free at R1 (seed 004, eq 2.57 corrected), θ(R2) = 0 (clamped at the pipe) and M_r(R1) = 0, with
    M_r = D(θ' + μθ/r), M_τ = D(θ/r + μθ'). The plate stiffness D cancels out of the moments.

    r [m] with R2 ≤ r ≤ R1, p pressure [Pa], r1 = R1 flight radius [m], r2 = R2 pipe radius [m], mu [-].
    Sign: with p > 0 the clamped-edge M_r is negative (the seed's convention).

    Examples
    --------
    >>> m_r, m_t = flight_moments(0.05, 1e6, 0.1, 0.05, 0.3)  # at the pipe: M_τ = μ·M_r
    >>> round(float(m_r), 3), round(float(m_t), 3)
    (-1735.691, -520.707)
    """
    _check(p, r1, r2, mu)
    f1, fp1 = _particular(r1, p, r1, r2)
    # M_r(R1) = 0 with C2 = −C1·R2² and K = D·C1
    k = (p / 2) * (fp1 / r1 - (1 - mu) * f1 / r1**2) / ((1 + mu) + (1 - mu) * r2**2 / r1**2)
    f, fp = _particular(r, p, r1, r2)
    m_r = (1 + mu) * k + (1 - mu) * k * r2**2 / r**2 - (p / 2) * (fp / r - (1 - mu) * f / r**2)
    m_t = (1 + mu) * k - (1 - mu) * k * r2**2 / r**2 - (p / 2) * (mu * fp / r + (1 - mu) * f / r**2)
    return m_r, m_t


def flight_moments_seed(r: float, p: float, r1: float, r2: float, mu: float = 0.3) -> tuple[float, float]:
    """(M_r, M_τ) [N·m/m] by seed 004, eqs 2.67 (as printed) and 2.68 (corrected); λ = r/R2, α = R1/R2.

    M_r = (pR1²/16)·A·(1 + λ⁻² + μ − μλ⁻²) − (p r²/16)·[3 + μ − λ⁻⁴(1 − μ)(1 − 2α²)
          − 2λ⁻²(1 + μ + α² − μα²) − 4(1 + μ)α²λ⁻² ln λ]
    M_τ = (pR1²/16)·A·(1 − λ⁻² + μ + μλ⁻²) − (p r²/16)·[1 + 3μ + λ⁻⁴(1 − μ)(1 − 2α²)
          + 2λ⁻²(α² − 1 − μ − μα²) − 4(1 + μ)α²λ⁻² ln λ]

    The printed 2.68 has (α² − 1 − 2μ − 2μα²) in the λ⁻² term, which is off by μ·p·R2²(1 + α²)/8.
    """
    _check(p, r1, r2, mu)
    a = r1 / r2
    lam = r / r2
    big_a = plate_coefficient(a, mu)
    ln = np.log(lam)
    m_r = (p * r1**2 / 16) * big_a * (1 + lam**-2 + mu - mu * lam**-2) - (p * r**2 / 16) * (
        3 + mu - lam**-4 * (1 - mu) * (1 - 2 * a**2) - 2 * lam**-2 * (1 + mu + a**2 - mu * a**2)
        - 4 * (1 + mu) * a**2 * lam**-2 * ln
    )
    m_t = (p * r1**2 / 16) * big_a * (1 - lam**-2 + mu + mu * lam**-2) - (p * r**2 / 16) * (
        1 + 3 * mu + lam**-4 * (1 - mu) * (1 - 2 * a**2) + 2 * lam**-2 * (a**2 - 1 - mu - mu * a**2)
        - 4 * (1 + mu) * a**2 * lam**-2 * ln
    )
    return m_r, m_t


def flight_edge_moments(p: float, r1: float, r2: float, mu: float = 0.3) -> dict[str, float]:
    """Edge moments of the flight [N·m/m] by seed 004, eq 2.70 (corrected).

    inner (r = R2): M_r = (pR1²/8)·A, M_τ = μ·M_r  (print lacks the μ in the −4μα⁻² term of A)
    outer (r = R1): M_r = 0,
                    M_τ = (pR1²/16)·A·[1 + μ − α⁻²(1 − μ)] − (pR1²/16)·[3 + μ + α⁻⁴(1 − μ) − 4α⁻²
                          − 4(1 + μ) ln α]   (print has ln λ for ln α)

    p [Pa], r1 = R1 [m], r2 = R2 [m], mu [-]. Keys: ``mr_inner``, ``mt_inner``, ``mr_outer``, ``mt_outer``.

    Examples
    --------
    >>> round(float(flight_edge_moments(1e6, 0.1, 0.05, 0.3)["mt_outer"]), 4)
    -188.4416
    """
    _check(p, r1, r2, mu)
    a = r1 / r2
    big_a = plate_coefficient(a, mu)
    mr_in = p * r1**2 / 8 * big_a
    mt_out = (p * r1**2 / 16) * big_a * (1 + mu - a**-2 * (1 - mu)) - (p * r1**2 / 16) * (
        3 + mu + a**-4 * (1 - mu) - 4 * a**-2 - 4 * (1 + mu) * np.log(a)
    )
    return {"mr_inner": mr_in, "mt_inner": mu * mr_in, "mr_outer": 0.0, "mt_outer": mt_out}


def flight_max_stress(p: float, r1: float, r2: float, thickness: float, mu: float = 0.3) -> float:
    """Largest bending stress magnitude in the flight [Pa]: max |6M/h²| over the edge moments (eq 2.69).

    The clamped edge (radial moment at the pipe) governs for all practical α = R1/R2.
    thickness h [m].

    Examples
    --------
    >>> round(float(flight_max_stress(1e6, 0.1, 0.05, 0.004, 0.3)) / 1e6, 2)  # 6·|M_r(R2)|/h²
    650.88
    """
    if np.any(np.asarray(thickness) <= 0):
        raise InputError(f"The flight thickness must be > 0 m; got {np.min(thickness):g} m.")
    m = flight_edge_moments(p, r1, r2, mu)
    largest = np.abs(m["mr_inner"])
    for key in ("mt_inner", "mr_outer", "mt_outer"):
        largest = np.maximum(largest, np.abs(m[key]))
    return largest * 6.0 / thickness**2
