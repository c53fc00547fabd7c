"""The beams of the double tamper as offset slider-cranks: exact and series motion (seed 000 eqs 5-10).

Corrections follow ``seed-reproduction.md`` section 000.4 (cited as "repro 000.4"). SI floats or arrays.
"""

from __future__ import annotations

import numpy as np

from ...errors import InputError, check_finite, check_positive


def _check_slider_crank(r, l, e):
    check_positive("crank radius r", r, "m")
    check_positive("rod length l", l, "m")
    check_finite("offset e", e, "m")


def _u(theta, r, l, e):
    u = np.sin(theta) + np.asarray(e, dtype=float) / r
    lam = np.asarray(r, dtype=float) / l
    q = 1.0 - (lam * u) ** 2
    if np.any(q <= 0):
        raise InputError(
            "The offset slider-crank cannot close: it needs |r sin(theta) + e| < l at every angle; "
            f"got r = {r:g} m, l = {l:g} m, e = {np.max(np.abs(e)):g} m."
        )
    return u, lam, q


def exact_position(theta, r, l, e):
    """Exact slider position x [m] of the offset slider-crank of seed 000 section 3 (repro 000.4).

    Crank pin at r(cos theta, sin theta), slider on the line y = -e, x measured from the crank centre:
    x = r cos theta + l sqrt(1 - lambda^2 u^2), lambda = r/l, u = sin theta + e/r.

    Parameters: theta crank angle [rad]; r crank radius (resultant eccentricity) [m] > 0; l rod length [m] > 0;
    e offset [m] (signed). Valid where |r sin theta + e| < l (the rod can reach the slide line).
    """
    _check_slider_crank(r, l, e)
    u, lam, q = _u(theta, r, l, e)
    return r * np.cos(theta) + l * np.sqrt(q)


def exact_velocity(theta, r, l, e, omega):
    """Exact slider velocity dx/dt [m/s] at constant crank speed (repro 000.4).

    v = -r omega [sin theta + lambda cos theta u / sqrt(1 - lambda^2 u^2)], lambda = r/l, u = sin theta + e/r.
    Parameters as :func:`exact_position`, plus omega crank speed [rad/s] (theta = omega t).
    """
    _check_slider_crank(r, l, e)
    check_finite("crank speed omega", omega, "rad/s")
    u, lam, q = _u(theta, r, l, e)
    return -r * omega * (np.sin(theta) + lam * np.cos(theta) * u / np.sqrt(q))


def exact_acceleration(theta, r, l, e, omega):
    """Exact slider acceleration d2x/dt2 [m/s^2] at constant crank speed (repro 000.4).

    a = -r omega^2 [cos theta + lambda cos^2 theta / (1 - lambda^2 u^2)^(3/2) - lambda sin theta u /
    sqrt(1 - lambda^2 u^2)]. Parameters as :func:`exact_velocity`.
    """
    _check_slider_crank(r, l, e)
    check_finite("crank speed omega", omega, "rad/s")
    u, lam, q = _u(theta, r, l, e)
    c, s = np.cos(theta), np.sin(theta)
    return -r * omega**2 * (c + lam * c**2 / q**1.5 - lam * s * u / np.sqrt(q))


def series_position(theta, r, l, e):
    """First-order (small lambda) slider position x [m], consistent with eqs 6-7 (repro 000.4, corrected eq 5).

    x ~ l - e^2/(2 l) + r cos theta - lambda e sin theta - (lambda r / 4)(1 - cos 2 theta), lambda = r/l.
    Seed 000 eq 5 as printed is **wrong**: its crank terms have the opposite sign to the position whose
    derivative is eq 6, the lambda e sin term has the wrong sign, and its last term lambda^2 e^2 / (2(1 + lambda))
    has units of m^2 (the dead-centre correction is lambda^2 e^2 / (2 r (1 + lambda))). Use this function, or
    :func:`series_displacement_from_odc` for the displacement from the outer dead centre.

    Parameters: theta [rad]; r [m] > 0; l [m] > 0; e offset [m] (slider on y = -e). Valid for
    lambda (1 + |e|/r) << 1; the error of x is about (r lambda^3 / 8)(sin theta + e/r)^4.
    """
    _check_slider_crank(r, l, e)
    lam = r / l
    return l - e**2 / (2.0 * l) + r * np.cos(theta) - lam * e * np.sin(theta) - lam * r / 4.0 * (
        1.0 - np.cos(2.0 * theta)
    )


def series_displacement_from_odc(theta, r, l, e):
    """First-order displacement s = x_ODC - x [m] from the outer dead centre (repro 000.4).

    s ~ r (1 - cos theta) + lambda e sin theta + (lambda r / 4)(1 - cos 2 theta) + lambda^2 e^2 / (2 r (1 + lambda)),
    the form seed 000 eq 5 (and eq 8) evidently meant; ds/dt = -eq 6. The paper prints l_d1 instead of r_d1 as
    the constant, the wrong sign on lambda e sin theta and omits the 1/r in the last term.
    Parameters and validity as :func:`series_position`.
    """
    _check_slider_crank(r, l, e)
    lam = r / l
    return (
        r * (1.0 - np.cos(theta))
        + lam * e * np.sin(theta)
        + lam * r / 4.0 * (1.0 - np.cos(2.0 * theta))
        + lam**2 * e**2 / (2.0 * r * (1.0 + lam))
    )


def series_velocity(theta, r, l, e, omega):
    """Seed 000 eq 6 (and eq 9): v ~ -r omega (sin theta + lambda eps cos theta + (lambda/2) sin 2 theta) [m/s].

    lambda = r/l, eps = e/r (so lambda eps = e/l). Correct: it is the exact first-order expansion of
    :func:`exact_velocity` (repro 000.4). Parameters: theta [rad], r [m] > 0, l [m] > 0, e offset [m],
    omega [rad/s]. Validity: error below 2e-5 r omega for lambda ~ 0.01 and e/r <= 2 (table of repro 000.4).
    """
    _check_slider_crank(r, l, e)
    check_finite("crank speed omega", omega, "rad/s")
    lam = r / l
    eps = e / r
    return -r * omega * (np.sin(theta) + lam * eps * np.cos(theta) + lam / 2.0 * np.sin(2.0 * theta))


def series_acceleration(theta, r, l, e, omega):
    """Seed 000 eq 7 (and eq 10): a ~ -r omega^2 (cos theta - lambda eps sin theta + lambda cos 2 theta) [m/s^2].

    d(eq 6)/dt = eq 7 exactly. (Eq 10 is labelled "speed" in the paper but is the acceleration.) Parameters as
    :func:`series_velocity`. Validity: error about 0.5 lambda^3 (1 + e/r)^3 r omega^2 for small lambda (1 + e/r)
    (repro 000.4).
    """
    _check_slider_crank(r, l, e)
    check_finite("crank speed omega", omega, "rad/s")
    lam = r / l
    eps = e / r
    return -r * omega**2 * (np.cos(theta) - lam * eps * np.sin(theta) + lam * np.cos(2.0 * theta))


