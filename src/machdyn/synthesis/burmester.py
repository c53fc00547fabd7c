"""Burmester theory: the dyads through four and five positions of a coupler.

For four positions the standard dyad form (:mod:`machdyn.synthesis.dyads`) has three equations in W, Z; they
are consistent only if the determinant of the augmented matrix vanishes (Erdman, Sandor & Kota, *Mechanism
Design*, 4th ed., ch. 8, the compatibility equation; Norton, *Design of Machinery*, 5th ed., ch. 5, four- and
five-position synthesis):

    D_1 + D_2 e^{i beta_2} + D_3 e^{i beta_3} + D_4 e^{i beta_4} = 0,

with D_2..D_4 the cofactors of the column (e^{i beta_j} - 1) and D_1 = -(D_2 + D_3 + D_4). Each beta_2 (the
free choice) closes the triangle D_3 e^{i beta_3} + D_4 e^{i beta_4} = -(D_1 + D_2 e^{i beta_2}) in two ways
(or none), and each solution gives one dyad: its moving pivot traces the circle-point curve and its ground
pivot the centre-point curve as beta_2 turns (Burmester, *Lehrbuch der Kinematik*, 1888). Every circle point
takes its four positions on a circle about its centre point; that is how the tests check the curves.

Five positions: a dyad must satisfy the compatibility equations of positions (1, 2, 3, 4) and (1, 2, 3, 5)
with the same beta_2 and beta_3: the Burmester points, zero, two or four of them, found here by scanning beta_2
and refining each sign change of the mismatch with :func:`scipy.optimize.brentq`.

The trivial solution beta_j = alpha_j (W and Z not separable) is left out.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import InputError
from .dyads import Dyad, displacements, solve


@dataclass(frozen=True)
class BurmesterCurves:
    """Sampled curves of four positions: for each sample, beta_2..beta_4 [rad], the circle point and the centre
    point [m] (complex), NaN where the triangle does not close; ``branch`` 0 / 1 of the two closures."""

    betas: np.ndarray        # (2, samples, 3)
    circle_points: np.ndarray  # (2, samples)
    centre_points: np.ndarray  # (2, samples)

    def dyads(self, points: Any) -> list[Dyad]:
        """Every sampled dyad (the finite ones)."""
        p1 = complex(np.asarray(points, dtype=complex)[0])
        out = []
        for k in range(2):
            for s in range(self.betas.shape[1]):
                if np.isfinite(self.circle_points[k, s]):
                    z = p1 - self.circle_points[k, s]
                    w = self.circle_points[k, s] - self.centre_points[k, s]
                    out.append(Dyad(complex(w), complex(z), np.concatenate([[0.0], self.betas[k, s]]), p1))
        return out


def _cofactors(delta: np.ndarray, alpha: np.ndarray, rows: tuple[int, int, int]) -> np.ndarray:
    """D_1, D_a, D_b, D_c of the compatibility equation of three rows (indices into j = 2..n)."""
    a = np.exp(1j * alpha[list(rows)]) - 1.0
    d = delta[list(rows)]
    c1 = a[1] * d[2] - a[2] * d[1]
    c2 = -(a[0] * d[2] - a[2] * d[0])
    c3 = a[0] * d[1] - a[1] * d[0]
    return np.array([-(c1 + c2 + c3), c1, c2, c3])


def _close(cof: np.ndarray, beta2: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(beta_3, beta_4) [rad] of each beta_2, shape (2, len(beta2)): the two closures of the triangle
    D_3 e^{i b3} + D_4 e^{i b4} = R, R = -(D_1 + D_2 e^{i b2}); NaN where it cannot close."""
    r = -(cof[0] + cof[1] * np.exp(1j * beta2))
    r3, r4 = abs(cof[2]), abs(cof[3])
    rr = np.abs(r)
    with np.errstate(invalid="ignore", divide="ignore"):
        cos_g = (r3**2 + rr**2 - r4**2) / (2.0 * r3 * rr)
    ok = np.abs(cos_g) <= 1.0
    g = np.arccos(np.clip(cos_g, -1.0, 1.0))
    out3, out4 = [], []
    for sign in (1.0, -1.0):
        u = r3 * np.exp(1j * (np.angle(r) + sign * g))
        b3 = np.where(ok, np.angle(u) - np.angle(cof[2]), np.nan)
        b4 = np.where(ok, np.angle(r - u) - np.angle(cof[3]), np.nan)
        out3.append(b3)
        out4.append(b4)
    return np.array(out3), np.array(out4)


def curves(points: Any, angles: Any, samples: int = 360) -> BurmesterCurves:
    """The circle-point and centre-point curves of four positions, ``samples`` values of beta_2 over a turn."""
    delta, alpha = displacements(points, angles)
    if delta.size != 3:
        raise InputError(f"The Burmester curves need exactly 4 positions; got {delta.size + 1}.")
    cof = _cofactors(delta, alpha, (0, 1, 2))
    beta2 = np.linspace(-np.pi, np.pi, int(samples), endpoint=False) + np.pi / samples
    b3, b4 = _close(cof, beta2)
    p1 = complex(np.asarray(points, dtype=complex)[0])
    betas = np.full((2, beta2.size, 3), np.nan)
    circle = np.full((2, beta2.size), np.nan + 0j)
    centre = np.full((2, beta2.size), np.nan + 0j)
    for k in range(2):
        for s in range(beta2.size):
            if not np.isfinite(b3[k, s]):
                continue
            bb = np.array([beta2[s], b3[k, s], b4[k, s]])
            if np.max(np.abs(np.exp(1j * bb) - np.exp(1j * alpha))) < 1e-9:
                continue  # the trivial solution
            d = solve(points, angles, bb)
            if d is None:
                continue
            betas[k, s] = bb
            circle[k, s] = p1 - d.z
            centre[k, s] = d.ground_pivot
    return BurmesterCurves(betas, circle, centre)


def points_five(points: Any, angles: Any, samples: int = 720) -> list[Dyad]:
    """The Burmester point pairs of five positions: every dyad through all five (zero, two or four)."""
    from scipy.optimize import brentq

    delta, alpha = displacements(points, angles)
    if delta.size != 4:
        raise InputError(f"The Burmester points need exactly 5 positions; got {delta.size + 1}.")
    cof_a = _cofactors(delta, alpha, (0, 1, 2))
    cof_b = _cofactors(delta, alpha, (0, 1, 3))

    def mismatch(b2: Any, ka: int, kb: int) -> Any:
        b2 = np.atleast_1d(np.asarray(b2, dtype=float))
        a3 = _close(cof_a, b2)[0][ka]
        c3 = _close(cof_b, b2)[0][kb]
        return np.angle(np.exp(1j * (a3 - c3)))

    grid = np.linspace(-np.pi, np.pi, int(samples) + 1)
    found: list[Dyad] = []
    for ka in range(2):
        for kb in range(2):
            f = mismatch(grid, ka, kb)
            for s in range(grid.size - 1):
                f0, f1 = f[s], f[s + 1]
                if not (np.isfinite(f0) and np.isfinite(f1)) or f0 * f1 > 0 or abs(f0 - f1) > np.pi / 2:
                    continue  # no root, or the mismatch wrapping through +-pi
                root = grid[s] if f0 == 0 else brentq(lambda b, i=ka, j=kb: float(mismatch(b, i, j)[0]), grid[s],
                                                      grid[s + 1], xtol=1e-15, rtol=1e-15, maxiter=200)
                b3 = float(_close(cof_a, np.array([root]))[0][ka][0])
                b4 = float(_close(cof_a, np.array([root]))[1][ka][0])
                b5 = float(_close(cof_b, np.array([root]))[1][kb][0])
                bb = np.array([root, b3, b4, b5])
                if np.max(np.abs(np.exp(1j * bb) - np.exp(1j * alpha))) < 1e-6:
                    continue
                d = solve(points, angles, bb)
                if d is not None and not any(abs(d.ground_pivot - e.ground_pivot) < 1e-9 * (1 + abs(e.w))
                                             for e in found):
                    found.append(d)
    return found
