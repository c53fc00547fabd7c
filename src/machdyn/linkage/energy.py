"""Energy of a linkage: kinetic energy per body, gravity and spring potential, the reduced (equivalent)
moment of inertia and moment of forces at the crank, the input torque from the energy rate, and the
work-energy balance over a cycle.

Sources: the reduced moment of inertia I_red = 2 T / omega_1^2 = sum(m_i (v_Gi/omega_1)^2 + I_i
(omega_i/omega_1)^2) and the reduced moment M_red = sum(F_j . v_j + M_j omega_j)/omega_1 are seed 003
eqs 18-19, corrected as in seed-reproduction.md §003.3 (each force at the velocity of its own point of
application, every body's weight included). The input torque M_in = dW/dphi is seed 002 eq 12. Work-energy
theorem: Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed., §15.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .kinetostatics import kinetostatics
from .loads import applied_forces, applied_torques, mass_elements, spring_states
from .model import Mechanism
from .motion import Kinematics
from .reactions import Forces
from .refs import column, full


@dataclass(frozen=True)
class WorkBalance:
    """Work-energy balance over the analysed crank range [J].

    ``input_work`` = integral of the driving torque over phi; ``load_work`` = work of the external forces and
    torques; ``energy_change`` = change of kinetic + potential energy from the first to the last position
    (zero over a full cycle). ``residual`` = input_work + load_work - energy_change; ``relative`` divides it
    by the integral of |driving torque| dphi (the scale of the work that flows).
    """

    input_work: np.ndarray
    load_work: np.ndarray
    energy_change: np.ndarray
    residual: np.ndarray
    relative: np.ndarray
    full_cycle: bool


@dataclass(frozen=True)
class Energy:
    """Energy results at every position (arrays shaped like the crank angles, designs first)."""

    forces: Forces
    kinetic: dict
    potential_gravity: np.ndarray
    potential_spring: np.ndarray
    energy_rate: np.ndarray
    load_power: np.ndarray
    conservative_power: np.ndarray

    @property
    def kinematics(self) -> Kinematics:
        return self.forces.kinematics

    @property
    def kinetic_total(self) -> np.ndarray:
        """Total kinetic energy T [J]."""
        return sum(self.kinetic.values())

    @property
    def potential(self) -> np.ndarray:
        """Gravity plus spring potential energy V [J]."""
        return self.potential_gravity + self.potential_spring

    @property
    def total(self) -> np.ndarray:
        """T + V [J]."""
        return self.kinetic_total + self.potential

    @property
    def reduced_inertia(self) -> np.ndarray:
        """Reduced (equivalent) moment of inertia at the crank, I_red = 2 T / omega^2 [kg*m^2] (seed 003
        eq 18). Needs a non-zero crank speed."""
        w = self._speed("reduced inertia")
        return 2.0 * self.kinetic_total / (w * w)

    @property
    def reduced_moment(self) -> np.ndarray:
        """Reduced moment of all forces but inertia and the drive, M_red = P / omega [N*m] (seed 003 eq 19,
        corrected: each force at the velocity of its own point, all weights and springs included)."""
        return (self.load_power + self.conservative_power) / self._speed("reduced moment")

    @property
    def input_torque_from_energy(self) -> np.ndarray:
        """Driving torque from the energy rate, M = (dE/dt - P_loads)/omega [N*m]; with no external load and
        constant speed this is dW/dphi of seed 002 eq 12. Equals the kinetostatic driving torque."""
        return (self.energy_rate - self.load_power) / self._speed("input torque from the energy rate")

    def _speed(self, what: str) -> np.ndarray:
        w = self.kinematics.speed
        if np.any(w == 0.0):
            raise InputError(f"The {what} needs a non-zero crank speed; got 0 rad/s.")
        return w

    def power_residual(self) -> np.ndarray:
        """Pointwise power balance T*omega + P_loads - dE/dt [W]; zero up to rounding."""
        return self.forces.input_power + self.load_power - self.energy_rate

    def work_balance(self) -> WorkBalance:
        """The work-energy balance over the analysed crank angles (a built-in check of every analysis).

        Over a full revolution sampled evenly (see :func:`~machdyn.linkage.kinematics.crank_angles`) the
        integrals use the periodic trapezoidal rule, exponentially accurate for smooth periodic integrands;
        over a partial range, the trapezoidal rule (second-order accurate).
        """
        phi = self.kinematics.crank_angle
        if np.ndim(phi) != 1 or phi.size < 2:
            raise InputError("The work balance needs at least two crank angles in a 1-D array.")
        torque = self.forces.driving_torque
        load_torque = self.load_power / self._speed("work balance")
        full = _is_full_cycle(phi)
        if full:
            step = 2.0 * np.pi / phi.size
            w_in = torque.sum(axis=-1) * step
            w_load = load_torque.sum(axis=-1) * step
            scale = np.abs(torque).sum(axis=-1) * step
            change = np.zeros_like(w_in)
        else:
            w_in = np.trapezoid(torque, phi, axis=-1)
            w_load = np.trapezoid(load_torque, phi, axis=-1)
            scale = np.trapezoid(np.abs(torque), phi, axis=-1)
            change = self.total[..., -1] - self.total[..., 0]
        residual = w_in + w_load - change
        tiny = np.finfo(float).tiny
        return WorkBalance(w_in, w_load, change, residual, np.abs(residual) / np.maximum(scale, tiny), full)


def _is_full_cycle(phi: np.ndarray) -> bool:
    steps = np.diff(phi)
    step = 2.0 * np.pi / phi.size
    return bool(np.allclose(steps, step, rtol=1e-9, atol=1e-12))


def energy(
    mech: Mechanism,
    crank_angle=None,
    speed=1.0,
    acceleration=0.0,
    *,
    forces: Forces | None = None,
) -> Energy:
    """Kinetic and potential energy, energy rate and load powers of ``mech`` at each crank angle.

    Kinetic energy T = Σ(m v_G²/2 + I ω²/2) per body and per point mass; gravity potential V_g = −m g · r_G;
    spring potential k (l − l0)²/2; energy rate dT/dt − (power of gravity) + (power stored in springs). These are
    the rigid-body energy definitions of plane motion; the work balance (:class:`WorkBalance`) checks them against
    the crank torque computed by kinetostatics.

    Parameters
    ----------
    mech : Mechanism
        The linkage (SI throughout).
    crank_angle : float or array, optional
        Crank angles [rad]; not needed with ``forces``.
    speed : float or array
        Crank speed [rad/s].
    acceleration : float or array
        Crank angular acceleration [rad/s²].
    forces : Forces, optional
        An already computed :func:`~machdyn.linkage.kinetostatics.kinetostatics` result.

    Returns
    -------
    Energy
        kinetic {body: T [J]}, potential_gravity and potential_spring [J], energy_rate [W], load_power [W] and
        conservative_power [W], shaped like the crank angles. Valid away from dead positions.

    Examples
    --------
    A 2 kg slider of a 0.1 m crank, 0.3 m rod slider-crank at φ = 90° and 10 rad/s moves at 1 m/s:

    >>> import numpy as np
    >>> from machdyn.linkage import slider_crank
    >>> e = energy(slider_crank(0.1, 0.3, masses=(0.0, 0.0, 2.0)), np.pi / 2, speed=10.0)
    >>> {name: round(float(t), 6) for name, t in e.kinetic.items()}
    {'crank': 0.0, 'rod': 0.0, 'slider': 1.0}
    >>> round(float(e.energy_rate), 6)
    -7.071068
    """
    forces = forces or kinetostatics(mech, crank_angle, speed, acceleration)
    kin = forces.kinematics
    shape = kin.shape
    gx, gy = (column(v) for v in kin.mechanism.gravity)
    kinetic = {}
    v_grav = np.zeros(shape)
    rate = np.zeros(shape)
    conservative = np.zeros(shape)
    for m in mass_elements(kin):
        G, body = m.motion, kin.body(m.body)
        v2 = G.vx * G.vx + G.vy * G.vy
        kinetic[m.name] = full(0.5 * m.mass * v2 + 0.5 * m.inertia * body.omega**2, shape)
        v_grav = v_grav - m.mass * (gx * G.x + gy * G.y)
        rate = rate + m.mass * (G.vx * G.ax + G.vy * G.ay) + m.inertia * body.omega * body.alpha
        grav_power = m.mass * (gx * G.vx + gy * G.vy)
        rate = rate - grav_power
        conservative = conservative + grav_power
    v_spring = np.zeros(shape)
    for s in spring_states(kin):
        v_spring = v_spring + s.energy
        rate = rate + s.tension * s.rate
        conservative = conservative - s.tension * s.rate
    load_power = np.zeros(shape)
    for f in applied_forces(kin):
        load_power = load_power + f.fx * f.motion.vx + f.fy * f.motion.vy
    for t in applied_torques(kin):
        load_power = load_power + t.torque * kin.body(t.body).omega
    return Energy(forces, kinetic, v_grav, v_spring, rate, full(load_power, shape), conservative)
