"""A shaft line on a rigid frame in space, in time: the shaft's angle and the frame's six degrees of freedom.

Coordinates s = (theta, u, vartheta): the shaft angle relative to the frame [rad], the small translation u [m] of
the frame's origin and its small rotation vector vartheta [rad] (the coordinates of
:mod:`machdyn.shafts.frame6`). A mass element i of the shaft line (a rotating mass, a cylinder's crank-pin mass
and its piston, a body of a linkage) sits at g_i(theta) in frame coordinates and moves with u_i = dg_i/dtheta; a
linkage's body turns about an axis parallel to the shaft at w_i = dtheta_i/dtheta. With R(vartheta) the frame's
rotation, an element's absolute velocity is u' + R (u_i theta') + omega x R g_i, omega the frame's angular
velocity; with the body angular velocity omega_b = vartheta' - 1/2 vartheta x vartheta' of the rotation vector
(second order; Shabana, *Dynamics of Multibody Systems*, 4th ed., sec. 2.6 and 5.3) and everything kept to second
order in the frame's motion, the kinetic energy is T = 1/2 s'^T M(theta, vartheta) s' with

    M[theta, theta] = J(theta) = sum m_i |u_i|^2 + I_i w_i^2 + J_line            (the shaft line's reduced inertia)
    M[theta, u]     = p + vartheta x p,      p(theta) = sum m_i u_i               (momentum per unit shaft speed)
    M[theta, vth]   = h + 1/2 vartheta x h,  h(theta) = sum m_i g_i x u_i + (I_i w_i + H_line) e_z
                                                                                  (angular momentum per unit speed)
    M[q, q]         = M_6 + Mm(theta) - mean Mm,  Mm = [[m I, -[S]], [[S], sum m_i ([g_i]^T [g_i]) + I_i e_z e_z^T]]

([a] the cross-product matrix of a, S = sum m_i g_i). The term 1/2 theta' (vartheta x h) . vartheta' is the
gyroscopic coupling of the spinning shaft line with the frame's rocking (its moment I_p Omega x vartheta'; Genta,
*Dynamics of Rotating Systems*, Springer 2005, sec. 3.3); vartheta x p turns the shaking force with the frame.
M_6 is the frame of ``[frame]`` (:class:`machdyn.shafts.frame6.Frame6`): the whole machine with the shaft line's
masses at their mean positions, as the frame's steady response takes it; only the departure of the moving masses
from their mean, Mm - mean Mm, is added. At a constant shaft speed Omega and the frame held still, -p' Omega^2 and
-h' Omega^2 are the shaft line's shaking force and moment about the frame's origin (the loads of
:func:`machdyn.shafts.frame6.steady_response`, and the rolling moment of the inertia torque about the shaft axis,
which that response leaves out).

Lagrange's equations are taken exactly for this T: M s'' = Q - dM/dt s' + d/ds (1/2 s'^T M s'), Q the drive
torque, the load and brake on theta (the motor's stator sits on the frame: its torque does work on the relative
angle theta only) and -K q - C q' on the frame. The energy T + 1/2 q^T K q then changes only by the work of the
drive, the loads and the dampers, so the run's energy balance closes to the integrator's tolerance. Every curve of
theta is the trigonometric interpolant of exact values at evenly spaced shaft angles, its derivative the
interpolant's exact derivative.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..dynamics.tables import FourierCurve
from ..errors import InputError
from ..linkage import kinematics
from ..linkage.loads import mass_elements
from ..shafts.frame6 import Frame6
from ..shafts.model import ShaftLine

__all__ = ["ShaftFrameModel", "shaft_frame_model"]

#: channels, in order: J; p (3); h (3); S (3); the rotational block of Mm (xx, yy, zz, xy, xz, yz)
_ROWS = 16
#: rows of one dimension, scaled together so that a row of round-off alone is dropped
_FAMILIES = ((0, 10, 11, 12, 13, 14, 15), (1, 2, 3, 7, 8, 9), (4, 5, 6))


def _cross(a, b) -> np.ndarray:
    """a x b of two 3-vectors (np.cross is slow on small vectors)."""
    a0, a1, a2 = float(a[0]), float(a[1]), float(a[2])
    b0, b1, b2 = float(b[0]), float(b[1]), float(b[2])
    return np.array([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0])


def _add(rows: np.ndarray, mass: float, inertia: float, g: np.ndarray, u: np.ndarray, w: np.ndarray) -> None:
    """Add one element (mass [kg], inertia about the shaft's direction [kg*m^2], g and u (3, N) [m], w (N)) to
    the channel samples ``rows`` (16, N)."""
    rows[0] += mass * np.sum(u * u, axis=0) + inertia * w * w
    rows[1:4] += mass * u
    rows[4:7] += mass * np.cross(g.T, u.T).T
    rows[6] += inertia * w
    rows[7:10] += mass * g
    gg = np.sum(g * g, axis=0)
    rows[10] += mass * (gg - g[0] * g[0])
    rows[11] += mass * (gg - g[1] * g[1]) + 0.0
    rows[12] += mass * (gg - g[2] * g[2]) + inertia
    rows[13] -= mass * g[0] * g[1]
    rows[14] -= mass * g[0] * g[2]
    rows[15] -= mass * g[1] * g[2]


def _samples(line: ShaftLine, shaft: tuple[float, float], positions: int) -> tuple[np.ndarray, float]:
    """The channels at ``positions`` shaft angles over a turn, and the moving mass [kg]."""
    theta = np.arange(positions) * (2.0 * np.pi / positions)
    rows = np.zeros((_ROWS, positions))
    zeros = np.zeros(positions)
    xs, ys = (float(v) for v in shaft)
    total = 0.0

    def rotating(mass: float, radius: float, angle: float, z: float) -> None:
        a = theta + angle
        g = np.stack([xs + radius * np.cos(a), ys + radius * np.sin(a), np.full(positions, z)])
        u = np.stack([-radius * np.sin(a), radius * np.cos(a), zeros])
        _add(rows, mass, 0.0, g, u, zeros)

    for m in line.masses:
        rotating(m.mass, m.radius, m.angle, m.position)
        total += m.mass
    for c in line.cylinders:
        rotating(c.rotating_mass, c.crank, c.phase, c.position)
        # the piston on its line of stroke (Uicker, Pennock & Shigley, 5th ed., sec. 16.6): x = r cos phi + S
        phi = theta + c.phase - c.axis
        root = np.sqrt(c.rod ** 2 - (c.crank * np.sin(phi)) ** 2)
        x = c.crank * np.cos(phi) + root
        dx = -c.crank * np.sin(phi) - c.crank ** 2 * np.sin(phi) * np.cos(phi) / root
        e = np.array([np.cos(c.axis), np.sin(c.axis), 0.0])[:, None]
        g = np.array([xs, ys, c.position])[:, None] + x * e
        _add(rows, c.reciprocating_mass, 0.0, g, dx * e, zeros)
        total += c.rotating_mass + c.reciprocating_mass
    for lk in line.linkages:
        kin = kinematics(lk.mechanism, theta + lk.phase, 1.0, 0.0)
        ca, sa = np.cos(lk.axis), np.sin(lk.axis)
        for el in mass_elements(kin):
            mass = float(np.ravel(el.mass)[0])
            inertia = float(np.ravel(el.inertia)[0])
            px, py, vx, vy = (np.broadcast_to(np.asarray(v, dtype=float), theta.shape)
                              for v in (el.motion.x, el.motion.y, el.motion.vx, el.motion.vy))
            g = np.stack([xs + ca * px - sa * py, ys + sa * px + ca * py, np.full(positions, lk.position)])
            u = np.stack([ca * vx - sa * vy, sa * vx + ca * vy, zeros])
            w = np.broadcast_to(np.asarray(kin.body(el.body).omega, dtype=float), theta.shape)
            _add(rows, mass, inertia, g, u, w)
            total += mass
    return rows, total


@dataclass
class ShaftFrameModel:
    """The shaft line's curves on its frame, with its drive. Build it with :func:`shaft_frame_model`.

    frame : the frame of ``[frame]`` (the whole machine, the moving masses at their mean positions).
    drive : a drive of :mod:`machdyn.dynamics.drives` (its torque at the shaft, its gear and rotor), or None.
    line_inertia : inertia turning with the shaft about its axis besides the shaft line's masses (crankshaft,
        flywheel, couplings) [kg*m^2] >= 0.
    """

    frame: Frame6
    drive: Any
    line_inertia: float
    c0: np.ndarray
    ca: np.ndarray
    cb: np.ndarray
    moving_mass: float
    k: np.ndarray = field(init=False)
    added: float = field(init=False)  # J_line + i^2 I_rotor
    spin: float = field(init=False)  # J_line + i I_rotor: their angular momentum per unit shaft speed
    mass6: np.ndarray = field(init=False)
    stiffness: np.ndarray = field(init=False)
    damping: np.ndarray = field(init=False)
    _both: np.ndarray = field(init=False, repr=False)

    def __post_init__(self) -> None:
        self.k = np.arange(1, self.ca.shape[1] + 1, dtype=float)
        # values and slopes in one product: [[A, B], [B k, -A k]] (cos, sin)
        self._both = np.vstack([np.hstack([self.ca, self.cb]), np.hstack([self.cb * self.k, -self.ca * self.k])])
        rotor = float(getattr(self.drive, "rotor_inertia", 0.0) or 0.0)
        ratio = float(getattr(self.drive, "ratio", 1.0) or 1.0)
        self.added = self.line_inertia + ratio * ratio * rotor
        self.spin = self.line_inertia + ratio * rotor
        mean = self._moving_block(self.c0)
        self.mass6 = self.frame.mass_matrix() - mean
        bare = np.linalg.eigvalsh(self.mass6)
        if not bare[0] > 1e-9 * bare[-1]:
            raise InputError(
                f"The frame's mass and inertia in [frame] ({self.frame.mass:g} kg) are the whole machine's, the shaft "
                f"line's moving parts included ({self.moving_mass:g} kg); without those the frame would have no "
                "positive mass matrix: give the machine's total mass, centre of mass and inertia.")
        self.stiffness = self.frame.stiffness_matrix()
        self.damping = self.frame.damping_matrix()

    @staticmethod
    def _block(v: np.ndarray, mass: float) -> np.ndarray:
        """[[m I, -[S]], [[S], R]] of the channel values ``v``."""
        sx, sy, sz = float(v[7]), float(v[8]), float(v[9])
        return np.array([[mass, 0.0, 0.0, 0.0, sz, -sy], [0.0, mass, 0.0, -sz, 0.0, sx],
                         [0.0, 0.0, mass, sy, -sx, 0.0], [0.0, -sz, sy, v[10], v[13], v[14]],
                         [sz, 0.0, -sx, v[13], v[11], v[15]], [-sy, sx, 0.0, v[14], v[15], v[12]]])

    def _moving_block(self, v: np.ndarray) -> np.ndarray:
        return self._block(v, self.moving_mass)

    def channels(self, theta: float) -> tuple[np.ndarray, np.ndarray]:
        """Values and theta-derivatives of the 16 channels at ``theta`` [rad]."""
        arg = theta * self.k
        both = self._both @ np.concatenate([np.cos(arg), np.sin(arg)])
        return self.c0 + both[:_ROWS], both[_ROWS:]

    def matrices(self, theta: float, q: np.ndarray, ds: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The mass matrix M (7 x 7) and the velocity forces F = -dM/dt s' + d/ds (1/2 s'^T M s') at the state
        (theta, q) with rates ds = (theta', q'). Written out (dM/dt = dM/dtheta theta' + dM/dvartheta
        vartheta', only the coupling row depending on vartheta) for speed: F_theta = -1/2 J' theta'^2
        - (vartheta' x p) . u' + 1/2 q'^T Mm' q', F_q = -(c' theta' + Mm' q') theta' - theta' (vartheta' x p,
        1/2 vartheta' x h) + (0, theta' (p x u' + 1/2 h x vartheta')), c the coupling row."""
        v, d = self.channels(theta)
        w = float(ds[0])
        th = q[3:]
        du, dth = ds[1:4], ds[4:]
        p, dp = v[1:4], d[1:4]
        h = v[4:7].copy()
        h[2] += self.spin
        dh = d[4:7]
        mass = np.empty((7, 7))
        mass[0, 0] = v[0] + self.added
        cross = np.concatenate([p + _cross(th, p), h + 0.5 * _cross(th, h)])
        mass[0, 1:] = cross
        mass[1:, 0] = cross
        block = self.mass6 + self._moving_block(v)
        mass[1:, 1:] = block
        dcross = np.concatenate([dp + _cross(th, dp), dh + 0.5 * _cross(th, dh)])
        ds_ = d[7:10]
        dr = np.array([[d[10], d[13], d[14]], [d[13], d[11], d[15]], [d[14], d[15], d[12]]])
        dmm_dq = np.concatenate([-_cross(ds_, dth), _cross(ds_, du) + dr @ dth])
        turn_p = _cross(dth, p)
        force = np.empty(7)
        force[0] = -0.5 * d[0] * w * w - float(turn_p @ du) + 0.5 * float(ds[1:] @ dmm_dq)
        force[1:] = -(dcross * w + dmm_dq) * w
        force[1:4] -= w * turn_p
        force[4:] += w * (_cross(p, du) + 0.5 * _cross(h, dth) - 0.5 * _cross(dth, h))
        return mass, force

    def energy(self, theta: float, q: np.ndarray, ds: np.ndarray) -> float:
        """Kinetic energy plus the mounts' potential energy [J]."""
        mass, _ = self.matrices(theta, q, ds)
        return float(0.5 * ds @ mass @ ds + 0.5 * q @ self.stiffness @ q)

    def shaking(self, theta: float, speed: float) -> np.ndarray:
        """The shaft line's shaking force and moment about the frame's origin at a constant ``speed`` [rad/s] on a
        still frame: -(p', h') Omega^2 (6,)."""
        _, d = self.channels(theta)
        return -np.concatenate([d[1:4], d[4:7]]) * speed * speed


def shaft_frame_model(line: ShaftLine, frame: Frame6, shaft: tuple[float, float] = (0.0, 0.0), drive: Any = None,
                      line_inertia: float = 0.0, *, positions: int = 256) -> ShaftFrameModel:
    """The model of ``line`` on ``frame``, the shaft's axis through (x, y) = ``shaft`` [m] of the frame, driven by
    ``drive`` (None: turned only by its own inertia, or at a prescribed speed), with ``line_inertia`` [kg*m^2]
    turning with the shaft; the curves sampled at ``positions`` (>= 32) shaft angles per turn."""
    if int(positions) != positions or positions < 32:
        raise InputError(f"The shaft angles per turn of a transient model must be an integer >= 32; got {positions!r}.")
    if not (np.isfinite(line_inertia) and line_inertia >= 0):
        raise InputError(f"The drive line's inertia must be >= 0 kg*m^2; got {line_inertia!r} kg*m^2.")
    rows, total = _samples(line, shaft, int(positions))
    size = np.abs(rows).max(axis=1)
    scale = np.ones((_ROWS, 1))
    for family in _FAMILIES:
        top = max(float(size[list(family)].max()), 1e-300)
        scale[list(family)] = top
        for i in family:
            if size[i] <= 1e-11 * top:
                rows[i] = 0.0
    curve = FourierCurve.from_samples(rows / scale, 2.0 * np.pi)
    c0, ca, cb = curve.a0 * scale[:, 0], curve.a * scale, curve.b * scale
    return ShaftFrameModel(frame, drive, float(line_inertia), c0, ca, cb, total)
