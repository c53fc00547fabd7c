"""Two-plane balance and the ISO 21940-11 grade of N shaft lines at once: NumPy arrays, designs on the leading
axis, the M rotating masses of each design on the second.

A design's masses are the arrays mass [kg], radius [m], angle [rad] and position [m], each (N, M) (or broadcast
to it); their unbalances are U = m r e^{iα} [kg·m] and

    S0 = Σ U,  S1 = Σ U (z − z_L)      (the force and couple polygons; Khurmi & Gupta, *Theory of Machines*,
                                         14th ed., sec. 21.8; :func:`.rotating.unbalance`)
    U_M = −S1/(z_M − z_L),  U_L = −S0 − U_M   (the two corrections; :func:`.balance.correction_unbalances`)

each correction a mass |U|/r at the angle arg U in [0, 2π). The grade: U_per = G m/ω (ISO 21940-11:2016, G in
m/s), allocated to the bearing planes A and B by L_B/L and L_A/L clipped to 0.3 ... 0.7 (ISO 1940-1:2003, sec.
7.2; :func:`.grades.allocate`); the residual in each bearing plane is the pair of unbalances there with the force
and couple of the masses (:func:`.balance.equivalent_in_planes`), the margin min(allowed/residual) and the
achieved grade (|U_A| + |U_B|) ω / m.

A design the single-design functions refuse — its two planes at one axial position, its centre of mass outside
the bearings, a rotor mass or a speed <= 0 — is flagged (``valid`` False) with NaN results.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .grades import check_grade

TWO_PI = 2.0 * np.pi


def _masses(mass: Any, radius: Any, angle: Any, position: Any) -> tuple[np.ndarray, np.ndarray]:
    """U (N, M) [kg·m] and z (N, M) [m] of N designs' masses."""
    m, r, a, z = np.broadcast_arrays(*(np.atleast_2d(np.asarray(x, dtype=float)) for x in
                                       (mass, radius, angle, position)))
    return m * r * np.exp(1j * a), z


def unbalance_arrays(mass: Any, radius: Any, angle: Any, position: Any,
                     reference: Any = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """S0 = Σ U [kg·m] and S1 = Σ U (z − z_ref) [kg·m²] of N designs, each (N,) complex (module docstring)."""
    u, z = _masses(mass, radius, angle, position)
    ref = np.reshape(np.asarray(reference, dtype=float), (-1, 1))
    return u.sum(axis=1), (u * (z - ref)).sum(axis=1)


def polar_arrays(u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """|U| and its angle in [0, 2π) (0 for U = 0), as :func:`.balance.polar` element-wise."""
    angle = np.mod(np.arctan2(u.imag, u.real), TWO_PI)
    angle = np.where(angle >= TWO_PI - 1e-12, 0.0, angle)
    size = np.abs(u)
    return size, np.where(size == 0.0, 0.0, angle)


def _apart(za: np.ndarray, zb: np.ndarray) -> np.ndarray:
    return np.abs(zb - za) > 1e-9 * np.maximum(1.0, np.maximum(np.abs(za), np.abs(zb)))


def two_plane_population(mass: Any, radius: Any, angle: Any, position: Any, plane_l: Any, plane_m: Any,
                         radius_l: Any, radius_m: Any) -> dict[str, np.ndarray]:
    """The two correction masses of N shaft lines (module docstring; Khurmi & Gupta, 14th ed., sec. 21.8).

    Parameters
    ----------
    mass, radius, angle, position : the masses [kg, m, rad, m], (N, M).
    plane_l, plane_m : axial positions of the correction planes [m], (N,) or floats.
    radius_l, radius_m : radii of the correction masses [m] > 0, (N,) or floats.

    Returns
    -------
    dict of (N,) arrays: ``L.mass``, ``L.angle``, ``M.mass``, ``M.angle`` [kg, rad], the complex ``U_L``, ``U_M``
    [kg·m] and ``valid``.
    """
    zl, zm = (np.ravel(np.asarray(x, dtype=float)) for x in (plane_l, plane_m))
    s0, s1 = unbalance_arrays(mass, radius, angle, position, zl)
    n = s0.shape[0]
    zl, zm = np.broadcast_to(zl, (n,)), np.broadcast_to(zm, (n,))
    rl, rm = (np.broadcast_to(np.ravel(np.asarray(x, dtype=float)), (n,)) for x in (radius_l, radius_m))
    valid = _apart(zl, zm) & (rl > 0) & (rm > 0) & np.isfinite(s0) & np.isfinite(s1)
    span = np.where(valid, zm - zl, 1.0)
    u_m = -s1 / span
    u_l = -s0 - u_m
    out: dict[str, np.ndarray] = {"U_L": np.where(valid, u_l, np.nan), "U_M": np.where(valid, u_m, np.nan)}
    for name, u, r in (("L", u_l, rl), ("M", u_m, rm)):
        size, where = polar_arrays(u)
        out[f"{name}.mass"] = np.where(valid, size / np.where(valid, r, 1.0), np.nan)
        out[f"{name}.angle"] = np.where(valid, where, np.nan)
    return out | {"valid": valid}


def grade_population(grade: float, rotor_mass: Any, speed: Any, centre: Any, bearing_a: Any, bearing_b: Any,
                     mass: Any, radius: Any, angle: Any, position: Any) -> dict[str, np.ndarray]:
    """The ISO 21940-11 check of N rotors (module docstring).

    Parameters
    ----------
    grade : G [mm/s], one of :data:`.grades.GRADES` (the same for every design).
    rotor_mass : m [kg] > 0; speed : ω [rad/s] > 0; centre : the centre of mass [m]; bearing_a, bearing_b : the
        bearing planes [m] — each (N,) or a float.
    mass, radius, angle, position : the masses whose residual is judged (the line's, with the corrections fitted
        for a balanced rotor), (N, M).

    Returns
    -------
    dict of (N,) arrays: ``U_per`` [kg·m], ``A.allowed``, ``B.allowed``, ``A.residual``, ``B.residual`` [kg·m],
    ``margin`` [-], ``achieved_G`` [m/s], ``passes`` (bool) and ``valid``.
    """
    check_grade(grade)
    za = np.ravel(np.asarray(bearing_a, dtype=float))
    s0, s1 = unbalance_arrays(mass, radius, angle, position, za)
    n = s0.shape[0]
    rotor, w, com, za, zb = (np.broadcast_to(np.ravel(np.asarray(x, dtype=float)), (n,)) for x in
                             (rotor_mass, speed, centre, za, bearing_b))
    apart = _apart(za, zb)
    span = np.where(apart, zb - za, 1.0)
    la, lb = (com - za) / span, (zb - com) / span
    valid = apart & (rotor > 0) & (w > 0) & (la >= 0.0) & (lb >= 0.0) & np.isfinite(s0) & np.isfinite(s1)
    with np.errstate(divide="ignore", invalid="ignore"):
        u_per = grade * 1e-3 * rotor / w
        allowed_a = u_per * np.minimum(0.7, np.maximum(0.3, lb))
        allowed_b = u_per * np.minimum(0.7, np.maximum(0.3, la))
        u_b = s1 / span
        residual_a, residual_b = np.abs(s0 - u_b), np.abs(u_b)
        margin = np.minimum(np.where(residual_a > 0, allowed_a / residual_a, np.inf),
                            np.where(residual_b > 0, allowed_b / residual_b, np.inf))
        achieved = (residual_a + residual_b) / rotor * w
    passes = (residual_a <= allowed_a * (1 + 1e-12)) & (residual_b <= allowed_b * (1 + 1e-12))
    out = {"U_per": u_per, "A.allowed": allowed_a, "B.allowed": allowed_b, "A.residual": residual_a,
           "B.residual": residual_b, "margin": margin, "achieved_G": achieved}
    return {k: np.where(valid, v, np.nan) for k, v in out.items()} | {"passes": passes & valid, "valid": valid}
