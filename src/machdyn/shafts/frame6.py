"""The machine frame as a rigid body in space on elastic mounts: six degrees of freedom under a shaft line's
forces and couples.

Coordinates q = (u, theta): the small translation u [m] of the frame's reference point (its origin) and the
small rotation vector theta [rad]. A frame point p moves by u + theta x p (linearised rigid-body motion,
Meirovitch, *Fundamentals of Vibrations*, 2001, sec. 7.1). A mount acts along a unit direction n at a point p
with stiffness k and viscous damping c; its deflection is n . (u + theta x p) = b . q with b = (n, p x n), so it
adds k b b^T and c b b^T to the stiffness and damping matrices. The kinetic energy 1/2 m |v - S w|^2 + 1/2 w^T J w
(S the cross-product matrix of the centre of mass g, so that S w = g x w, J the inertia tensor about G) gives the
mass matrix [[m I, -m S], [m S, J + m S^T S]] (Shabana, *Dynamics of Multibody Systems*, 4th ed., sec. 5.3).

For mounts in the plane z = 0 acting in that plane, a centre of mass in it and no products of inertia with z, the
in-plane coordinates (x, y, theta_z) decouple and the model is :class:`machdyn.vibration.frame.Frame` exactly.

The steady response to the shaft line's loads is found order by order: each harmonic k of the forces (F_x, F_y)
and couples (M_x, M_y) [about the shaft's reference plane] is moved to the frame origin (M + r x F, r the shaft's
reference point) and (K + i k w C - (k w)^2 M) q_k = Q_k solved (Rao, *Mechanical Vibrations*, 5th ed., sec. 6.15).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError, check_finite, check_positive
from ..vibration.frame import mount_sum
from ..vibration.gravity import gravity_stiffness

__all__ = ["Mount6", "Frame6", "modes6", "Response6", "steady_response"]


def _skew(v) -> np.ndarray:
    x, y, z = (float(c) for c in v)
    return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])


@dataclass(frozen=True)
class Mount6:
    """A mount along the unit ``direction`` (any non-zero 3-vector, normalised) at ``position`` (x, y, z) [m],
    stiffness [N/m] >= 0 and viscous damping [N s/m] >= 0."""

    name: str
    position: tuple[float, float, float]
    direction: tuple[float, float, float]
    stiffness: float
    damping: float = 0.0

    def __post_init__(self) -> None:
        check_finite(f"position of mount '{self.name}'", self.position, "m")
        check_positive(f"stiffness of mount '{self.name}'", self.stiffness, "N/m", allow_zero=True)
        check_positive(f"damping of mount '{self.name}'", self.damping, "N*s/m", allow_zero=True)
        n = np.asarray(self.direction, dtype=float)
        check_finite(f"direction of mount '{self.name}'", n)
        if n.shape != (3,) or not np.linalg.norm(n) > 0:
            raise InputError(f"The direction of mount '{self.name}' must be a non-zero 3-vector; got {self.direction}.")
        object.__setattr__(self, "direction", tuple(float(c) for c in n / np.linalg.norm(n)))

    @property
    def influence(self) -> np.ndarray:
        n = np.asarray(self.direction)
        return np.concatenate([n, np.cross(np.asarray(self.position, dtype=float), n)])


@dataclass(frozen=True)
class Frame6:
    """A rigid frame: mass [kg] > 0, inertia tensor about its centre of mass [kg m^2] (3 x 3, symmetric, positive
    definite; a 3-vector means principal values along x, y, z), centre of mass (x, y, z) [m] and its mounts;
    ``gravity`` (g_x, g_y, g_z) [m/s^2] in frame axes adds the weight's pendulum term to the rotations' stiffness
    (:mod:`machdyn.vibration.gravity`; zero: left out)."""

    mass: float
    inertia: tuple
    mounts: tuple[Mount6, ...]
    com: tuple[float, float, float] = (0.0, 0.0, 0.0)
    gravity: tuple[float, float, float] = (0.0, 0.0, 0.0)

    def __post_init__(self) -> None:
        check_positive("frame mass", self.mass, "kg")
        j = np.asarray(self.inertia, dtype=float)
        j = np.diag(j) if j.shape == (3,) else j
        check_finite("frame inertia", j, "kg*m^2")
        if j.shape != (3, 3) or not np.allclose(j, j.T) or np.min(np.linalg.eigvalsh(j)) <= 0:
            raise InputError("The frame's inertia tensor must be symmetric and positive definite (3 x 3, or 3 "
                             f"principal values > 0); got {self.inertia}.")
        object.__setattr__(self, "inertia", tuple(map(tuple, j)))
        check_finite("frame gravity", self.gravity, "m/s^2")
        if not self.mounts:
            raise InputError("The frame needs at least one mount; got none.")
        names = [m.name for m in self.mounts]
        if len(set(names)) != len(names):
            raise InputError(f"Mount names must be unique; got {names}.")

    def mass_matrix(self) -> np.ndarray:
        s = _skew(self.com)
        m = self.mass
        top = np.hstack([m * np.eye(3), -m * s])
        bottom = np.hstack([m * s, np.asarray(self.inertia) + m * s.T @ s])
        return np.vstack([top, bottom])

    def influence_matrix(self) -> np.ndarray:
        return np.array([m.influence for m in self.mounts])

    def stiffness_matrix(self) -> np.ndarray:
        """Sum k b b^T of the mounts, plus gravity's pendulum term (:mod:`machdyn.vibration.gravity`)."""
        k = mount_sum(self.mounts, "stiffness")
        return k + gravity_stiffness(self.mass, self.com, self.gravity, self.mounts, k)

    def damping_matrix(self) -> np.ndarray:
        return mount_sum(self.mounts, "damping")

    @staticmethod
    def point_matrix(point) -> np.ndarray:
        """P (3 x 6) with displacement = P q at frame point ``point`` (x, y, z) [m]."""
        return np.hstack([np.eye(3), -_skew(point)])


def modes6(frame: Frame6) -> tuple[np.ndarray, np.ndarray]:
    """Undamped natural frequencies [Hz] (ascending) and mass-normalised mode shapes (columns) of K - w^2 M.
    Refuses a frame whose mounts leave a rigid-body motion free (a zero eigenvalue of K)."""
    from scipy.linalg import eigh

    k, m = frame.stiffness_matrix(), frame.mass_matrix()
    bare = np.linalg.eigvalsh(mount_sum(frame.mounts, "stiffness"))
    if bare[0] <= 1e-9 * max(bare[-1], 1e-300):
        raise InputError("The frame's mounts leave it free to move in some direction (its stiffness matrix is "
                         "singular): add mounts that restrain all six rigid-body motions.")
    ev = np.linalg.eigvalsh(k)
    if ev[0] <= 1e-9 * max(ev[-1], 1e-300):
        raise InputError("The frame tips over on its mounts: its weight's pendulum term (its centre of gravity "
                         "above the mounts) exceeds their rocking stiffness. Spread the mounts, stiffen them or "
                         "lower the centre of gravity.")
    w2, shapes = eigh(k, m)
    return np.sqrt(np.maximum(w2, 0.0)) / (2 * np.pi), shapes


@dataclass(frozen=True)
class Response6:
    """Steady response by order: orders, complex q per order (orders x 6), the peak force of each mount [N] (sum of
    the orders' amplitudes, an upper bound of the peak over the turn) and RMS velocity [m/s] at named points."""

    orders: np.ndarray
    q: np.ndarray
    mount_force: dict
    rms_velocity: dict


def steady_response(frame: Frame6, loads, shaft_point=(0.0, 0.0), orders: int = 6, points=None) -> Response6:
    """Response of ``frame`` to a :class:`~machdyn.shafts.rotating.ShaftLoads` over one turn (uniform angles),
    the shaft's axis passing through (x, y) = ``shaft_point`` [m] of the frame, the loads' reference plane at
    z = loads.reference. Orders 1 .. ``orders`` of the shaft speed."""
    n = loads.angle.size
    if not 1 <= orders < n // 2:
        raise InputError(f"The orders of the frame response must lie in 1 ... {n // 2 - 1}; got {orders!r}.")
    r = np.array([shaft_point[0], shaft_point[1], loads.reference], dtype=float)
    spectra = [np.fft.rfft(v) * 2.0 / n for v in (loads.fx, loads.fy, loads.mx, loads.my)]
    k, c, m = frame.stiffness_matrix(), frame.damping_matrix(), frame.mass_matrix()
    b = frame.influence_matrix()
    ks = np.arange(1, orders + 1)
    qs = []
    for order in ks:
        f = np.array([spectra[0][order], spectra[1][order], 0.0], dtype=complex)
        mom = np.array([spectra[2][order], spectra[3][order], 0.0], dtype=complex) + np.cross(r, f)
        w = order * loads.speed
        qs.append(np.linalg.solve(k + 1j * w * c - w * w * m, np.concatenate([f, mom])))
    q = np.array(qs)
    deflection = q @ b.T  # orders x mounts
    w = ks[:, None] * loads.speed
    force = np.abs(deflection * (np.array([mt.stiffness for mt in frame.mounts]) + 1j * w *
                                 np.array([mt.damping for mt in frame.mounts])))
    mount_force = {mt.name: float(force[:, i].sum()) for i, mt in enumerate(frame.mounts)}
    rms = {}
    for name, p in (points or {}).items():
        v = (q @ Frame6.point_matrix(p).T) * (1j * w)  # orders x 3
        rms[name] = float(np.sqrt(0.5 * np.sum(np.abs(v) ** 2)))
    return Response6(ks, q, mount_force, rms)
