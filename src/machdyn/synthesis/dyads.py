"""The standard dyad form: one ground-pivoted link W and one coupler vector Z through n positions.

A dyad is a link from a ground pivot to a moving pivot (the vector W in the first position) and the coupler
vector Z from that moving pivot to the coupler's precision point P. Through positions j = 2..n of the coupler
(P_j, coupler angle theta_j) it satisfies (Erdman, Sandor & Kota, *Mechanism Design*, 4th ed., ch. 8, the standard
form; Norton, *Design of Machinery*, 5th ed., ch. 5, two- and three-position analytical synthesis)

    W (e^{i beta_j} - 1) + Z (e^{i alpha_j} - 1) = delta_j,

with alpha_j = theta_j - theta_1 the coupler's rotations, delta_j = P_j - P_1 the point's displacements and
beta_j the link's rotations. Two positions: Z and beta_2 are free choices, W follows. Three positions: beta_2 and
beta_3 are free, W and Z follow from a 2x2 complex linear system (Norton, ch. 5). Four and five
positions: :mod:`machdyn.synthesis.burmester`. The ground pivot is P_1 - Z - W and the moving pivot P_1 - Z.

Valid wherever the linear system is not singular (beta_j = alpha_j for all j gives no dyad).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import InputError


@dataclass(frozen=True)
class Dyad:
    """One dyad: W and Z [m] (complex, first position), its rotations beta_j [rad] (beta_1 = 0) and the point
    P_1 [m] it is built for."""

    w: complex
    z: complex
    beta: np.ndarray
    p1: complex

    @property
    def ground_pivot(self) -> complex:
        """The centre point (fixed pivot) [m]."""
        return self.p1 - self.z - self.w

    @property
    def moving_pivot(self) -> complex:
        """The circle point (moving pivot, first position) [m]."""
        return self.p1 - self.z


def displacements(points: Any, angles: Any) -> tuple[np.ndarray, np.ndarray]:
    """(delta_j, alpha_j) for j = 2..n: the point's displacements [m] (complex) and the coupler's rotations
    [rad] from the first position, of ``points`` (complex [m]) and coupler ``angles`` [rad]."""
    p = np.asarray(points, dtype=complex)
    t = np.asarray(angles, dtype=float)
    if p.ndim != 1 or p.shape != t.shape or p.size < 2:
        raise InputError(f"Motion synthesis needs at least 2 positions, each a point and an angle; got {p.size} "
                         f"points and {t.size} angles.")
    return p[1:] - p[0], t[1:] - t[0]


def two_positions(points: Any, angles: Any, z: complex, beta2: float) -> Dyad:
    """The dyad through two positions with the free choices ``z`` [m] (the coupler vector) and ``beta2`` [rad]:
    W = (delta_2 - Z (e^{i alpha_2} - 1)) / (e^{i beta_2} - 1) (Norton, ch. 5, two positions)."""
    delta, alpha = displacements(points, angles)
    den = np.exp(1j * beta2) - 1.0
    if abs(den) < 1e-12:
        raise InputError(f"The link rotation beta2 must not be a whole turn; got {np.degrees(beta2):.6g} deg.")
    w = (delta[0] - z * (np.exp(1j * alpha[0]) - 1.0)) / den
    return Dyad(complex(w), complex(z), np.array([0.0, float(beta2)]), complex(np.asarray(points)[0]))


def solve(points: Any, angles: Any, betas: Any) -> Dyad | None:
    """The dyad through the positions with link rotations ``betas`` = (beta_2, ..., beta_n) [rad]: exact for
    three positions (2x2 system, Norton, ch. 5); for four or five, the first two equations give W and Z
    and the rest must hold (the Burmester condition), else None. None also when the system is singular."""
    delta, alpha = displacements(points, angles)
    b = np.asarray(betas, dtype=float)
    if b.shape != delta.shape:
        raise InputError(f"One link rotation per position after the first is needed: {delta.size}; got {b.size}.")
    m = np.stack([np.exp(1j * b) - 1.0, np.exp(1j * alpha) - 1.0], axis=1)
    sub = m[:2]
    det = sub[0, 0] * sub[1, 1] - sub[0, 1] * sub[1, 0]
    scale = max(float(np.max(np.abs(delta))), 1e-300)
    if abs(det) < 1e-10:
        return None
    w, z = np.linalg.solve(sub, delta[:2])
    if delta.size > 2:
        residual = np.abs(m @ np.array([w, z]) - delta)
        if residual.max() > 1e-8 * scale:
            return None
    return Dyad(complex(w), complex(z), np.concatenate([[0.0], b]), complex(np.asarray(points)[0]))


def three_positions(points: Any, angles: Any, beta2: float, beta3: float) -> Dyad | None:
    """The dyad through three positions with the free choices ``beta2``, ``beta3`` [rad] (None if singular)."""
    return solve(points, angles, [beta2, beta3])


def with_ground_pivot(points: Any, angles: Any, pivot: complex) -> Dyad | None:
    """The dyad through three positions whose ground pivot is ``pivot`` [m] (Norton, ch. 5, "synthesis for a
    specified fixed pivot location"; the inversion construction of the circle point).

    The circle point's offset q from P_1 (complex, [m], in the first position) keeps its three positions
    X_j = P_j + q e^{i alpha_j} at one distance from the pivot: |X_j - pivot|^2 = |X_1 - pivot|^2 for j = 2, 3,
    two equations linear in q,

        2 Re(q [conj(P_j - pivot) e^{i alpha_j} - conj(P_1 - pivot)]) = |P_1 - pivot|^2 - |P_j - pivot|^2.

    The link's rotations follow as beta_j = arg((X_j - pivot) / (X_1 - pivot)): the non-trivial root of
    Norton's eq. 5.34 (the other being beta_j = alpha_j). None when the system is singular (the pivot at a pole).
    """
    p = np.asarray(points, dtype=complex)
    t = np.asarray(angles, dtype=float)
    if p.size != 3 or t.size != 3:
        raise InputError(f"A dyad with a given ground pivot takes 3 positions; got {p.size}.")
    r = p - pivot
    rows, rhs = [], []
    for j in (1, 2):
        c = np.conj(r[j]) * np.exp(1j * (t[j] - t[0])) - np.conj(r[0])
        rows.append([2.0 * c.real, -2.0 * c.imag])  # Re(q c) = qx cx - qy cy
        rhs.append(abs(r[0]) ** 2 - abs(r[j]) ** 2)
    a = np.array(rows)
    scale = max(float(np.max(np.abs(r))), 1e-300)
    if abs(np.linalg.det(a)) < 1e-12 * scale**2:
        return None
    qx, qy = np.linalg.solve(a, np.array(rhs))
    q = complex(qx, qy)
    x = p + q * np.exp(1j * (t - t[0]))
    if abs(x[0] - pivot) < 1e-12 * scale:
        return None
    beta = np.angle((x - pivot) / (x[0] - pivot))
    return Dyad(complex(x[0] - pivot), complex(-q), beta, complex(p[0]))


def dyad_positions(dyad: Dyad, points: Any, angles: Any) -> np.ndarray:
    """The dyad's coupler point in every position [m]: ground pivot + W e^{i beta_j} + Z e^{i alpha_j} (it equals
    the given points when the dyad satisfies its equations)."""
    t = np.asarray(angles, dtype=float)
    return dyad.ground_pivot + dyad.w * np.exp(1j * dyad.beta) + dyad.z * np.exp(1j * (t - t[0]))
