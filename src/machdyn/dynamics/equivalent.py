"""The equivalent one-degree-of-freedom machine of a linkage: reduced inertia J(phi), its exact slope, the reduced
moment of every load, and loads that depend on the crank speed.

With the crank angle phi as the one coordinate, every point moves with v = u(phi) omega and every body turns
with omega_i = w_i(phi) omega, where u = dr/dphi and w_i = dtheta_i/dphi are the velocity ratios. They, and their
derivatives u' = d^2 r/dphi^2 and w_i', are exactly the velocities and accelerations the engine's kinematics
returns at unit crank speed and zero crank acceleration. Hence, with no finite differences:

* J(phi) = sum(m_i |u_Gi|^2 + I_i w_i^2)            (seed 003 eq 18, corrected as in repro 003.3)
* J'(phi) = 2 sum(m_i u_Gi . u_Gi' + I_i w_i w_i')
* M(phi) = sum(F_j . u_j + T_j w_j) - dV/dphi         (seed 003 eq 19, each force at its own point)

and the motion obeys J phi'' + J'/2 phi'^2 = M_drive(phi') + M(phi, phi') (Lagrange's equation of the
one-degree-of-freedom machine; Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, the chapter on flywheels;
Artobolevsky, *Theory of Mechanisms and Machines*, the dynamic model with reduced quantities).

Loads that depend on speed live here, not in the engine: a linear damper between two points, a rotary damper on
a body, or any force law F(phi, v) at a point. They enter the reduced moment through the same velocity ratios,
M = (F . u) with v = u omega; a viscous damper of coefficient c gives M = -c (dl/dphi)^2 omega.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError, check_positive
from ..linkage import crank_angles, energy, kinematics
from ..linkage.loads import mass_elements
from ..linkage.model import Mechanism, split_ref
from .tables import Curve, FourierCurve, PeriodicCurve


@dataclass(frozen=True)
class LinearDamper:
    """A viscous damper [N*s/m] between two points ``"body.point"`` (either may be on the ground): it resists
    the rate of change of their distance with the force c * dl/dt."""

    name: str
    point_1: str
    point_2: str
    coefficient: float

    def __post_init__(self):
        check_positive(f"coefficient of damper '{self.name}'", self.coefficient, "N*s/m", allow_zero=True)


@dataclass(frozen=True)
class RotaryDamper:
    """A viscous rotary damper [N*m*s/rad] on ``body``, resisting its rotation relative to ``relative_to``
    (the ground by default): torque -c (omega_body - omega_other). Bearing friction of the crank shaft is a
    rotary damper on the crank."""

    name: str
    body: str
    coefficient: float
    relative_to: str = "ground"

    def __post_init__(self):
        check_positive(f"coefficient of rotary damper '{self.name}'", self.coefficient, "N*m*s/rad", allow_zero=True)


@dataclass(frozen=True)
class SpeedForce:
    """A force [N] at a point that depends on the crank angle and the point's velocity, e.g. a process force
    growing with the working speed: ``law(phi, vx, vy) -> (fx, fy)`` in global axes, arrays in, arrays out."""

    name: str
    point: str
    law: Callable


SpeedLoad = LinearDamper | RotaryDamper | SpeedForce


@dataclass(frozen=True)
class _PointRatio:
    """Velocity ratio u = dr/dphi of a point and its derivative, as Hermite curves of x and y."""

    ux: Curve
    uy: Curve


@dataclass(frozen=True)
class EquivalentMachine:
    """The reduced machine over one cycle (designs first; see the module docstring).

    inertia : J(phi) [kg*m^2] with its exact slope (Hermite curve).
    potential : V(phi) [J] of gravity and springs with its exact slope -M_conservative.
    moment : reduced moment of the position-dependent external loads [N*m] (spline, or linear where loads
        switch on and off).
    damping : reduced viscous coefficient c(phi) [N*m*s/rad], M = -c omega.
    forces : speed-dependent point forces with the velocity ratios of their points.
    mechanism : the linkage it was reduced from (None for a machine given by tables).
    """

    inertia: Curve
    potential: Curve
    moment: Curve
    damping: Curve
    forces: tuple = ()
    mechanism: Mechanism | None = None
    speed_loads: tuple = ()
    single: bool = True
    _speed_step: float = field(default=1e-6, repr=False)

    @property
    def period(self) -> float:
        """Length of the cycle [rad]."""
        return self.inertia.period

    @property
    def designs(self) -> int:
        return max(self.inertia.designs, self.potential.designs, self.moment.designs, self.damping.designs)

    def position_moment(self, phi) -> np.ndarray:
        """Reduced moment of the loads that depend on the position only [N*m]: external loads - dV/dphi."""
        return self.moment(phi) - self.potential.derivative(phi)

    def speed_moment(self, phi, omega) -> tuple[np.ndarray, np.ndarray]:
        """Reduced moment of the speed-dependent loads [N*m] at crank speed omega [rad/s] and its derivative
        with respect to omega [N*m*s/rad]."""
        c = self.damping(phi)
        m = -c * omega
        dm = -c + 0.0 * omega
        for law, ratio in self.forces:
            f, df = _force_moment(law, ratio, phi, omega, self._speed_step)
            m, dm = m + f, dm + df
        return m, dm

    def moment_at(self, phi, omega) -> np.ndarray:
        """Total reduced moment of all loads [N*m] at (phi, omega) (the drive not included)."""
        return self.position_moment(phi) + self.speed_moment(phi, omega)[0]

    def take(self, index) -> EquivalentMachine:
        """The machine of the designs ``index``."""
        def pick(c: Curve) -> Curve:
            return c if c.designs == 1 else c.take(index)

        forces = tuple((law, _PointRatio(pick(r.ux), pick(r.uy))) for law, r in self.forces)
        mech = self.mechanism
        if mech is not None and mech.design_count is not None:
            mech = mech.take_designs(index)
        return EquivalentMachine(pick(self.inertia), pick(self.potential), pick(self.moment), pick(self.damping),
                                 forces, mech, self.speed_loads, np.ndim(index) == 0)

    @classmethod
    def from_tables(cls, moment: PeriodicCurve, inertia=0.0, damping=0.0) -> EquivalentMachine:
        """A machine given by a turning-moment diagram (the sum of driving and resisting torques, as a curve of
        :func:`~machdyn.dynamics.tables.torque_table`) and a constant reduced inertia [kg*m^2] (or a curve)."""
        period = moment.period
        j = inertia if isinstance(inertia, PeriodicCurve) else PeriodicCurve.constant(inertia, period)
        if np.any(j.y < 0):
            raise InputError(f"The reduced moment of inertia must be >= 0 kg*m^2; got {float(np.min(j.y)):g} kg*m^2.")
        c = damping if isinstance(damping, PeriodicCurve) else PeriodicCurve.constant(damping, period)
        return cls(j, PeriodicCurve.constant(0.0, period), moment, c, single=moment.designs == 1)


def _force_moment(law, ratio: _PointRatio, phi, omega, step):
    ux, uy = ratio.ux(phi), ratio.uy(phi)

    def moment(w):
        fx, fy = law(phi, ux * w, uy * w)
        return np.asarray(fx, dtype=float) * ux + np.asarray(fy, dtype=float) * uy

    m = moment(omega)
    h = step * np.maximum(np.abs(omega), 1.0)
    return m, (moment(omega + h) - moment(omega - h)) / (2.0 * h)


def equivalent_machine(
    mech: Mechanism,
    positions: int = 720,
    *,
    speed_loads=(),
    load_interpolation: str = "auto",
) -> EquivalentMachine:
    """Reduce a linkage to its equivalent one-degree-of-freedom machine over one crank revolution.

    Parameters
    ----------
    mech : the linkage (parameters may be arrays of N design variants).
    positions : number of crank positions sampled evenly over the revolution (>= 16); the curves between them
        are cubic Hermite pieces through the exact values and slopes (error O(h^4)).
    speed_loads : :class:`LinearDamper`, :class:`RotaryDamper` and :class:`SpeedForce` loads.
    load_interpolation : "spline", "linear" or "auto": where a force or torque of the mechanism acts over part of
        the cycle only, cubic splines between its switching angles and straight pieces across the intervals that
        hold them (a spline through a jump would ring); the trigonometric interpolant or a periodic spline
        otherwise.

    Returns
    -------
    EquivalentMachine with J(phi), V(phi), the external reduced moment, the reduced damping and the
    speed-dependent forces (seed 003 eqs 18-19, see the module docstring).
    """
    if int(positions) != positions or positions < 16:
        raise InputError(f"The number of crank positions of the equivalent machine must be an integer >= 16; "
                         f"got {positions!r}.")
    if load_interpolation not in ("auto", "spline", "linear"):
        raise InputError(f"load_interpolation must be 'auto', 'spline' or 'linear'; got {load_interpolation!r}.")
    phi = crank_angles(int(positions))
    kin = kinematics(mech, phi, 1.0, 0.0)
    shape = kin.shape
    j = np.zeros(shape)
    dj = np.zeros(shape)
    for m in mass_elements(kin):
        g, body = m.motion, kin.body(m.body)
        j = j + m.mass * (g.vx * g.vx + g.vy * g.vy) + m.inertia * body.omega**2
        dj = dj + 2.0 * (m.mass * (g.vx * g.ax + g.vy * g.ay) + m.inertia * body.omega * body.alpha)
    en = energy(mech, phi, 1.0, 0.0)
    period = 2.0 * np.pi
    inertia = _smooth(phi, np.broadcast_to(j, shape), np.broadcast_to(dj, shape), period)
    potential = _smooth(phi, np.broadcast_to(en.potential, shape), np.broadcast_to(-en.conservative_power, shape),
                        period)
    windows = [f.active for f in mech.forces if f.active is not None]
    windows += [t.active for t in mech.torques if t.active is not None]
    kind = load_interpolation if load_interpolation != "auto" else ("jumps" if windows else "spline")
    load = np.broadcast_to(en.load_power, shape)
    moment: Curve
    if kind == "linear":
        moment = PeriodicCurve.linear(phi, load, period)
    elif kind == "jumps":
        moment = PeriodicCurve.smooth_with_jumps(phi, load, period, _jump_intervals(phi, windows))
    else:
        fourier = FourierCurve.from_samples(load, period)
        moment = fourier if fourier.resolved else PeriodicCurve.spline(phi, load, period)
    c, dc, forces = _speed_load_curves(kin, speed_loads)
    damping = _smooth(phi, np.broadcast_to(c, shape), np.broadcast_to(dc, shape), period)
    forces = tuple(
        (law, _PointRatio(_smooth(phi, ux, ax, period), _smooth(phi, uy, ay, period)))
        for law, ux, uy, ax, ay in forces
    )
    return EquivalentMachine(inertia, potential, moment, damping, forces, mech, tuple(speed_loads),
                             single=mech.design_count is None)


def _jump_intervals(phi, windows) -> np.ndarray:
    """True for each interval between evenly spaced nodes that holds the start or end of a load window (and its
    neighbour, where the edge falls on a node)."""
    m = phi.size
    h = 2.0 * np.pi / m
    jumps = np.zeros(m, dtype=bool)
    for window in windows:
        if window[1] - window[0] >= 2.0 * np.pi:
            continue
        for edge in window:
            pos = np.mod(edge, 2.0 * np.pi) / h
            k = int(np.floor(pos + 1e-9)) % m
            jumps[k] = True
            jumps[(k - 1) % m] = True
    return jumps


def _smooth(phi, values, slopes, period):
    """The trigonometric interpolant of the samples if it is resolved and its slope agrees with the exact slope
    at the nodes (a smooth curve); cubic Hermite pieces through values and exact slopes otherwise."""
    fourier = FourierCurve.from_samples(values, period)
    if fourier.resolved:
        scale = float(np.max(np.abs(slopes))) + 1e-300
        scale = max(scale, float(np.max(np.abs(values))) * 1e-12)
        if float(np.max(np.abs(fourier.derivative(phi) - slopes))) <= 1e-7 * scale:
            return fourier
    return PeriodicCurve.hermite(phi, values, slopes, period)


def _speed_load_curves(kin, loads):
    """Reduced damping c(phi) = sum c_k r_k^2 with slope 2 c_k r_k r_k', and the point forces' ratios."""
    shape = kin.shape
    c = np.zeros(shape)
    dc = np.zeros(shape)
    forces = []
    for load in loads:
        if isinstance(load, LinearDamper):
            p1, p2 = kin.point(load.point_1), kin.point(load.point_2)
            dx, dy = p2.x - p1.x, p2.y - p1.y
            length = np.hypot(dx, dy)
            if np.any(length <= 0):
                raise InputError(f"The points of damper '{load.name}' coincide at some crank angle; its direction "
                                 "is undefined there.")
            ex, ey = dx / length, dy / length
            vx, vy = p2.vx - p1.vx, p2.vy - p1.vy
            rate = ex * vx + ey * vy
            drate = ex * (p2.ax - p1.ax) + ey * (p2.ay - p1.ay) + (vx * vx + vy * vy - rate * rate) / length
            c, dc = c + load.coefficient * rate**2, dc + 2.0 * load.coefficient * rate * drate
        elif isinstance(load, RotaryDamper):
            b = kin.body(load.body)
            w, a = b.omega, b.alpha
            if load.relative_to != "ground":
                o = kin.body(load.relative_to)
                w, a = w - o.omega, a - o.alpha
            w, a = np.broadcast_to(w, shape), np.broadcast_to(a, shape)
            c, dc = c + load.coefficient * w**2, dc + 2.0 * load.coefficient * w * a
        elif isinstance(load, SpeedForce):
            if not callable(load.law):
                raise InputError(f"The law of speed force '{load.name}' must be a function (phi, vx, vy) -> (fx, fy).")
            split_ref(load.point)
            p = kin.point(load.point)
            forces.append((load.law, *(np.broadcast_to(v, shape) for v in (p.vx, p.vy, p.ax, p.ay))))
        else:
            raise InputError(f"Unknown speed-dependent load {load!r}; expected LinearDamper, RotaryDamper or "
                             "SpeedForce.")
    return c, dc, forces
