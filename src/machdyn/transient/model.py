"""The coupled model: the cranks of one or more mechanisms, their drives, and the frame on its mounts.

Coordinates s = (phi_1 .. phi_N, x, y, beta): the crank angle of each mechanism relative to the frame [rad] and
the frame's small translation [m] and rotation [rad] (:mod:`machdyn.vibration.frame`). A mass element i of
mechanism k (a body's centre or a point mass) sits at g_i(phi_k) in frame coordinates and moves with
u_i = dg_i/dphi_k; its body turns at w_i = dtheta_i/dphi_k (the engine's velocity coefficients, its kinematics at
unit crank speed). With the frame's rigid motion the element's absolute velocity is R(beta) u_i phi_k' + P(g_i) q',
P = [[1, 0, -g_y], [0, 1, g_x]], and the body's absolute rate w_i phi_k' + beta'. Kept to second order in the frame's
small motion (q, q'), the kinetic energy is T = 1/2 s'^T M(phi, beta) s' with (Lagrange; Meirovitch, *Fundamentals of
Vibrations*, 2001, §7.1 for the frame, Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, the flywheel
chapter for the crank):

    M[phi_k, phi_k] = J_k(phi_k) = sum m_i |u_i|^2 + I_i w_i^2            (the reduced inertia of the engine)
    M[phi_k, q]     = a_k + beta c_k, a_k(phi_k) = sum m_i P(g_i)^T u_i + I_i w_i e_3
                      (the mechanism's momentum per crank speed), c_k = (-a_k,y, a_k,x, 0): R(beta) a_k to first
                      order, the momentum turning with the frame
    M[q, q]         = M_frame + sum_k Mm_k(phi_k),
                      Mm_k = [[m, 0, -S_y], [0, m, S_x], [-S_y, S_x, R]], S = sum m_i g_i, R = sum m_i |g_i|^2 + I_i

Lagrange's equations d/dt dT/ds' - dT/ds = Q give, with ' on a curve its derivative in phi_k:

    M s'' = Q + F,   F_phi_k = -1/2 J_k' phi_k'^2 + 1/2 q'^T Mm_k' q' - beta' c_k.q',
                     F_q = -sum_k ((a_k' + beta c_k') phi_k'^2 + Mm_k' q' phi_k' + beta' phi_k' c_k - e_3 phi_k' c_k.q')

The terms in c_k are of the same order in the frame's motion as those in Mm_k' (the shaking force turns with the
frame by beta); without them the frame's response is off by a relative O(beta) (2 % of the vertical motion of a
frame whose horizontal shaking tilts it by 4.5e-3 rad, against a multibody model of the same machine).

At a constant crank speed Omega and a frame held still, -a_k' Omega^2 is the mechanism's shaking force and moment
(the loads of :mod:`machdyn.vibration.response`); with the frame held still the crank row is the engine's
J phi'' + J'/2 phi'^2 = M (:mod:`machdyn.dynamics.simulate`). The generalised forces Q are the drive torque and
the reduced moment of the mechanism's loads on phi_k (the motor's stator and the process loads react on the
frame through the joints: they do work on phi_k only), -K q - C q' on the frame, and gravity: the weight of the
moving masses turns with the frame, V_c = -q^T (W_k(phi_k) - mean W_k), W_k = (0, 0, g_y S_x - g_x S_y), so that q is
measured from the static equilibrium of the frame under the mean weight.

Every curve of phi is a trigonometric interpolant of the engine's values at evenly spaced crank angles, and its
derivative that interpolant's exact derivative: the equations are those of an exactly Lagrangian system, so the
energy balance of a run closes to the integrator's tolerance.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..dynamics.equivalent import EquivalentMachine, equivalent_machine
from ..dynamics.tables import FourierCurve
from ..errors import InputError, check_finite
from ..linkage import crank_angles, kinematics
from ..linkage.loads import mass_elements
from ..linkage.model import Mechanism
from ..vibration.frame import Frame
from ..vibration.modes import check_supported

__all__ = ["CoupledModel", "Exciter", "carried_frame", "coupled_model"]

#: channels of a mechanism's smooth curves, in this order
_CHANNELS = ("J", "V", "ax", "ay", "ab", "Sx", "Sy", "R", "moment", "damping")
#: rows of one dimension: inertias, first moments of mass, energies and moments
_FAMILIES = ((0, 4, 7), (2, 3, 5, 6), (1, 8), (9,))


@dataclass(frozen=True)
class Exciter:
    """One mechanism on the frame with its drive.

    Parameters
    ----------
    mechanism : the linkage (one design).
    drive : a drive of :mod:`machdyn.dynamics.drives` (its torque at the crank, gear and rotor inertia), or None
        for a crank turned only by the frame's motion and its own loads.
    flywheel : inertia on the crank [kg*m^2] >= 0.
    origin : (x, y) [m] of the mechanism's origin in frame coordinates.
    angle : rotation [rad] of the mechanism's axes relative to the frame's.
    mirror : True mirrors the mechanism's x axis: its crank then turns clockwise in frame axes (the second of two
        counter-rotating exciters).
    speed_loads : speed-dependent loads of :mod:`machdyn.dynamics.equivalent` (dampers, bearing friction).
    name : label.
    machine : its equivalent machine, if already made (with the same ``speed_loads``).
    torsion : the drive line's shafts upstream of a torsionally stiff stage
        (:class:`~machdyn.transient.torsion.TorsionalLine`), or None for a rigid line; ``flywheel`` is then the
        inertia of the crank's rigid group only, and the drive's torque acts on the motor's group.
    """

    mechanism: Mechanism
    drive: Any = None
    flywheel: float = 0.0
    origin: tuple[float, float] = (0.0, 0.0)
    angle: float = 0.0
    mirror: bool = False
    speed_loads: tuple = ()
    name: str = "crank"
    machine: EquivalentMachine | None = field(default=None, repr=False)
    torsion: Any = None

    def __post_init__(self) -> None:
        check_finite(f"flywheel inertia of exciter '{self.name}'", self.flywheel, "kg*m^2")
        if self.flywheel < 0:
            raise InputError(f"The flywheel inertia of exciter '{self.name}' must be >= 0 kg*m^2; got "
                             f"{self.flywheel:g} kg*m^2.")
        if self.mechanism.design_count is not None:
            raise InputError(f"Exciter '{self.name}': a transient run takes one design; the mechanism holds "
                             f"{self.mechanism.design_count} (a sweep runs each design on its own).")

    @property
    def transform(self) -> np.ndarray:
        """A (2 x 2): frame vector = A mechanism vector (a rotation, times a mirror of x)."""
        c, s = np.cos(self.angle), np.sin(self.angle)
        rot = np.array([[c, -s], [s, c]])
        return rot @ np.diag([-1.0 if self.mirror else 1.0, 1.0])

    @property
    def turn(self) -> float:
        """+1 if the crank turns counter-clockwise in frame axes as phi grows, -1 if mirrored."""
        return -1.0 if self.mirror else 1.0


def _drive_inertias(drive) -> tuple[float, float, float]:
    """(inertia reduced to the crank i^2 I_r, coupling i I_r, own inertia I_r) of the drive's rotor [kg*m^2]."""
    if drive is None:
        return 0.0, 0.0, 0.0
    rotor = float(np.asarray(getattr(drive, "rotor_inertia", 0.0)))
    ratio = float(np.asarray(getattr(drive, "ratio", 1.0)))
    reduced = float(np.asarray(getattr(drive, "inertia", 0.0)))
    return reduced, ratio * rotor if rotor else 0.0, rotor


def _fourier_rows(samples: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(c0 (C,), A (C, K), B (C, K)) of the trigonometric interpolants of the rows of ``samples`` (C, M) over
    one turn (Trefethen, *Spectral Methods in MATLAB*, SIAM 2000, ch. 3), harmonics below 1e-14 of the largest
    value dropped."""
    curve = FourierCurve.from_samples(samples, 2.0 * np.pi)
    return curve.a0.copy(), curve.a.copy(), curve.b.copy()


@dataclass
class _Part:
    """The curves of one exciter as Fourier channels, and the loads evaluated per call where they are not
    smooth."""

    exciter: Exciter
    machine: EquivalentMachine
    c0: np.ndarray
    ca: np.ndarray
    cb: np.ndarray
    k: np.ndarray
    mass: float
    added: float  # flywheel + reduced rotor inertia on the crank
    coupling: float  # flywheel + i I_r: their share of the crank row's coupling with beta
    own: float  # flywheel + I_r: their rotational inertia about the frame's normal
    gravity: np.ndarray  # g in frame axes
    moment_curve: Any  # None when the moment is a channel
    damping_curve: Any
    resolved: bool

    def channels(self, phi: float) -> tuple[np.ndarray, np.ndarray]:
        """Values and phi-derivatives of every channel at phi."""
        arg = phi * self.k
        cos, sin = np.cos(arg), np.sin(arg)
        value = self.c0 + self.ca @ cos + self.cb @ sin
        slope = (self.cb * self.k) @ cos - (self.ca * self.k) @ sin
        return value, slope

    def loads(self, phi: float, omega: float, value: np.ndarray) -> float:
        """Reduced moment of the mechanism's non-conservative loads on the crank [N*m] (process loads, dampers,
        speed forces; gravity and springs are in V)."""
        m = self.machine
        moment = float(value[8]) if self.moment_curve is None else float(self.moment_curve(phi))
        c = float(value[9]) if self.damping_curve is None else float(self.damping_curve(phi))
        out = moment - c * omega
        if m.forces:
            extra = m.speed_moment(np.array([phi]), np.array([omega]))[0]
            out += float(extra[0]) + float(m.damping(np.array([phi]))[0]) * omega
        return out


def _part(exciter: Exciter, positions: int) -> _Part:
    mech = exciter.mechanism
    machine = exciter.machine or equivalent_machine(mech, positions, speed_loads=exciter.speed_loads)
    phi = crank_angles(positions)
    kin = kinematics(mech, phi, 1.0, 0.0)
    a_mat = exciter.transform
    turn = exciter.turn
    origin = np.asarray(exciter.origin, dtype=float)
    rows = {name: np.zeros(positions) for name in _CHANNELS}
    total = 0.0
    for m in mass_elements(kin):
        mass = float(np.ravel(m.mass)[0])
        inertia = float(np.ravel(m.inertia)[0])
        g, body = m.motion, kin.body(m.body)
        gm = np.stack(np.broadcast_arrays(g.x, g.y, phi)[:2])
        um = np.stack(np.broadcast_arrays(g.vx, g.vy, phi)[:2])
        gx, gy = origin[:, None] + a_mat @ gm
        ux, uy = a_mat @ um
        w = turn * np.broadcast_to(body.omega, phi.shape)
        rows["J"] += mass * (ux * ux + uy * uy) + inertia * w * w
        rows["ax"] += mass * ux
        rows["ay"] += mass * uy
        rows["ab"] += mass * (gx * uy - gy * ux) + inertia * w
        rows["Sx"] += mass * gx
        rows["Sy"] += mass * gy
        rows["R"] += mass * (gx * gx + gy * gy) + inertia
        total += mass
    rows["V"] = np.broadcast_to(machine.potential(phi), phi.shape).astype(float)
    moment_curve = None if isinstance(machine.moment, FourierCurve) else machine.moment
    damping_curve = None if isinstance(machine.damping, FourierCurve) else machine.damping
    if moment_curve is None:
        rows["moment"] = np.broadcast_to(machine.moment(phi), phi.shape).astype(float)
    if damping_curve is None:
        rows["damping"] = np.broadcast_to(machine.damping(phi), phi.shape).astype(float)
    samples = np.stack([rows[name] for name in _CHANNELS])
    # each row scaled by the largest of its family, so that the round-off of a small row (a centre of mass near the
    # x axis: S_y ~ 1e-17 kg*m) does not keep every harmonic; a row of round-off alone is zero
    size = np.abs(samples).max(axis=1)
    scale = np.ones((len(_CHANNELS), 1))
    for family in _FAMILIES:
        top = max(float(size[list(family)].max()), 1e-300)
        scale[list(family)] = top
        for i in family:
            if size[i] <= 1e-11 * top:
                samples[i] = 0.0
    c0, ca, cb = _fourier_rows(samples / scale)
    c0, ca, cb = c0 * scale[:, 0], ca * scale, cb * scale
    resolved = ca.shape[1] < int(0.8 * (positions // 2))
    reduced, coupling, own = _drive_inertias(exciter.drive)
    gravity = a_mat @ np.asarray(mech.gravity, dtype=float)
    return _Part(exciter, machine, c0, ca, cb, np.arange(1, ca.shape[1] + 1, dtype=float), total,
                 exciter.flywheel + reduced, turn * (exciter.flywheel + coupling), exciter.flywheel + own, gravity,
                 moment_curve, damping_curve, resolved)


@dataclass
class CoupledModel:
    """The coupled machine: exciters (cranks with drives) on a frame (or on a rigid ground, ``frame`` None).

    Build it with :func:`coupled_model`; :mod:`machdyn.transient.run` integrates it in time.
    """

    parts: list[_Part]
    frame: Frame | None
    positions: int
    mass_f: np.ndarray = field(init=False)
    stiffness: np.ndarray = field(init=False)
    damping: np.ndarray = field(init=False)
    mean_weight: np.ndarray = field(init=False)

    def __post_init__(self) -> None:
        if self.frame is None:
            self.mass_f = self.stiffness = self.damping = np.zeros((0, 0))
            self.mean_weight = np.zeros(len(self.parts))
            return
        self.mass_f = self.frame.mass_matrix()
        # the mounts, and the pendulum term of the weight they carry: the frame's and the mechanisms' at their mean
        self.stiffness = carried_frame(self).stiffness_matrix()
        self.damping = self.frame.damping_matrix()
        self.mean_weight = np.array([p.gravity[1] * p.c0[5] - p.gravity[0] * p.c0[6] for p in self.parts])

    @property
    def cranks(self) -> int:
        return len(self.parts)

    @property
    def size(self) -> int:
        """Number of coordinates (cranks plus 3 for a frame)."""
        return self.cranks + (3 if self.frame is not None else 0)

    @property
    def exciters(self) -> tuple[Exciter, ...]:
        return tuple(p.exciter for p in self.parts)

    def matrices(self, phis, omegas, q, dq):
        """Mass matrix M, the velocity forces F, channel values and slopes per crank (see the module docstring)."""
        n, size = self.cranks, self.size
        mass = np.zeros((size, size))
        force = np.zeros(size)
        values, slopes = [], []
        for k, part in enumerate(self.parts):
            v, d = part.channels(phis[k])
            values.append(v)
            slopes.append(d)
            w = omegas[k]
            mass[k, k] = v[0] + part.added
            force[k] = -0.5 * d[0] * w * w
            if self.frame is None:
                continue
            # the momentum per crank speed turns with the frame: R(beta) (a_x, a_y) to first order in beta
            beta, turned = q[2], np.array([-v[3], v[2], 0.0])
            a = np.array([v[2], v[3], v[4] + part.coupling]) + beta * turned
            da = d[2:5] + beta * np.array([-d[3], d[2], 0.0])
            mass[k, n:] = a
            mass[n:, k] = a
            mm = np.array([[part.mass, 0.0, -v[6]], [0.0, part.mass, v[5]], [-v[6], v[5], v[7] + part.own]])
            dmm = np.array([[0.0, 0.0, -d[6]], [0.0, 0.0, d[5]], [-d[6], d[5], d[7]]])
            mass[n:, n:] += mm
            force[k] += 0.5 * dq @ dmm @ dq - dq[2] * (turned @ dq)
            force[n:] -= da * w * w + dmm @ dq * w + dq[2] * w * turned
            force[-1] += w * (turned @ dq)
        if self.frame is not None:
            mass[n:, n:] += self.mass_f
        return mass, force, values, slopes

    def gravity_terms(self, q, values, slopes):
        """(generalised force on the cranks, on the frame) of the moving masses' weight as the frame turns."""
        n = self.cranks
        on_cranks = np.zeros(n)
        on_frame = np.zeros(3)
        if self.frame is None:
            return on_cranks, on_frame
        for k, part in enumerate(self.parts):
            gx, gy = part.gravity
            v, d = values[k], slopes[k]
            on_frame[2] += gy * v[5] - gx * v[6] - self.mean_weight[k]
            on_cranks[k] += q[2] * (gy * d[5] - gx * d[6])
        return on_cranks, on_frame

    def energy(self, phis, omegas, q, dq) -> float:
        """Kinetic plus potential energy [J] (mechanisms' springs and weight, mounts, weight turning with the
        frame), measured from the static equilibrium."""
        mass, _, values, _ = self.matrices(phis, omegas, q, dq)
        s_dot = np.concatenate([omegas, dq])
        e = 0.5 * s_dot @ mass @ s_dot + sum(float(v[1]) for v in values)
        if self.frame is not None:
            e += 0.5 * q @ self.stiffness @ q
            for k, part in enumerate(self.parts):
                gx, gy = part.gravity
                e -= q[2] * (gy * values[k][5] - gx * values[k][6] - self.mean_weight[k])
        return float(e)


def coupled_model(exciters, frame: Frame | None = None, *, positions: int = 256) -> CoupledModel:
    """The coupled model of ``exciters`` (:class:`Exciter`) on ``frame`` (None: a rigid ground).

    Parameters
    ----------
    exciters : one or more :class:`Exciter`.
    frame : :class:`~machdyn.vibration.frame.Frame` on its mounts, or None.
    positions : crank positions per turn at which the engine's values are taken (>= 32); the curves between them
        are their trigonometric interpolants (exact for the smooth curves of a linkage that turns fully).
    """
    exciters = tuple(exciters)
    if not exciters:
        raise InputError("A transient model needs at least one exciter (a mechanism with its crank); got none.")
    if int(positions) != positions or positions < 32:
        raise InputError(f"The crank positions of a transient model must be an integer >= 32; got {positions!r}.")
    names = [e.name for e in exciters]
    dupes = sorted({n for n in names if names.count(n) > 1})
    if dupes:
        raise InputError(f"The exciters' names must be unique; got {', '.join(dupes)} twice.")
    if frame is not None:
        check_supported(frame)
    return CoupledModel([_part(e, int(positions)) for e in exciters], frame, int(positions))


def carried_frame(model: CoupledModel) -> Frame:
    """The frame with the mechanisms' moving masses (and flywheels and rotors) carried at their mean positions
    over a turn: the mass matrix M_frame + mean Mm_k as a rigid body (mass, centre of mass, centroidal inertia).
    Its modes are the frame's natural frequencies as the coupled model sees them, and at a constant crank speed
    the coupled frame moves as this frame does under the shaking loads, but for the change of Mm_k over the turn
    (a parametric term of the relative size of that change)."""
    frame = model.frame
    if frame is None:
        raise InputError("A rigid ground has no frame to carry the mechanisms.")
    mass = frame.mass + sum(p.mass for p in model.parts)
    sx = frame.mass * frame.com[0] + sum(float(p.c0[5]) for p in model.parts)
    sy = frame.mass * frame.com[1] + sum(float(p.c0[6]) for p in model.parts)
    about_origin = (frame.inertia + frame.mass * (frame.com[0] ** 2 + frame.com[1] ** 2)
                    + sum(float(p.c0[7]) + p.own for p in model.parts))
    com = (sx / mass, sy / mass)
    inertia = about_origin - mass * (com[0] ** 2 + com[1] ** 2)
    return Frame(mass, inertia, frame.mounts, com=com, name=frame.name, gravity=frame.gravity)
