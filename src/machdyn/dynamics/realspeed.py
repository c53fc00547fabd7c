"""Forces at the real speed: the engine's kinetostatics re-run with the simulated omega(phi) and epsilon(phi).

The speed fluctuation adds inertia forces (epsilon != 0, omega^2 varying) to every joint; this module runs the
engine's kinetostatics twice over the steady-state cycle, once at the simulated speed and acceleration and once at
the constant mean speed, and reports the difference. Speed-dependent loads of :mod:`.equivalent` enter the
engine as forces and torques that are functions of the crank angle, evaluated with the simulated speed.

Check: the engine's driving torque at the real speed equals the torque the drive puts on the crank less the
inertia torque of the flywheel and rotor, T = M_drive - (J_f + J_rotor) epsilon (the crank shaft's equilibrium).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import partial

import numpy as np

from ..errors import InputError
from ..linkage import kinetostatics
from ..linkage.kinematics import kinematics
from ..linkage.model import GROUND, BodyTorque, PointForce, split_ref
from ..linkage.reactions import Forces
from .equivalent import LinearDamper, RotaryDamper, SpeedForce
from .simulate import SteadyState


@dataclass(frozen=True)
class RealSpeedForces:
    """Kinetostatics at the simulated speed (``real``) and at the constant time-mean speed (``constant``).

    ``joint_peaks`` maps each joint to (peak force at real speed, at constant speed) [N];
    ``shaking_peak`` likewise for the shaking force [N]; ``torque_peak`` for the driving torque into the
    linkage [N*m]."""

    real: Forces
    constant: Forces
    joint_peaks: dict
    shaking_peak: tuple
    torque_peak: tuple

    def largest_change(self) -> tuple[str, float]:
        """The joint whose peak force changes most, and the relative change (real / constant - 1)."""
        best, value = "", 0.0
        for name, (real, const) in self.joint_peaks.items():
            rel = float(np.max(np.abs(np.asarray(real) / np.maximum(np.asarray(const), 1e-300) - 1.0)))
            if rel >= value:
                best, value = name, rel
        return best, value


def _speed_loads_as_engine_loads(mech, loads, omega_of_phi):
    """Engine forces and torques (functions of phi) equal to the speed-dependent loads at the simulated speed."""
    forces, torques = [], []
    for load in loads:
        if isinstance(load, SpeedForce):
            def fx(phi, load=load, axis=0):
                return _speed_force(mech, load, phi, omega_of_phi)[axis]

            forces.append(PointForce(load.name, load.point, fx, partial(fx, axis=1)))
        elif isinstance(load, LinearDamper):
            for sign, point in ((1.0, load.point_1), (-1.0, load.point_2)):
                if split_ref(point)[0] == GROUND:
                    continue  # the reaction on the frame: not a load on the moving linkage

                def comp(phi, load=load, sign=sign, axis=0):
                    kin = kinematics(mech, phi, omega_of_phi(phi), 0.0)
                    p1, p2 = kin.point(load.point_1), kin.point(load.point_2)
                    dx, dy = p2.x - p1.x, p2.y - p1.y
                    length = np.hypot(dx, dy)
                    ex, ey = dx / length, dy / length
                    rate = ex * (p2.vx - p1.vx) + ey * (p2.vy - p1.vy)
                    f = sign * load.coefficient * rate
                    return f * (ex if axis == 0 else ey)

                forces.append(PointForce(f"{load.name}@{point}", point, comp, partial(comp, axis=1)))
        elif isinstance(load, RotaryDamper):
            def torque(phi, load=load, sign=1.0):
                kin = kinematics(mech, phi, omega_of_phi(phi), 0.0)
                rel = kin.body(load.body).omega
                if load.relative_to != GROUND:
                    rel = rel - kin.body(load.relative_to).omega
                return -sign * load.coefficient * rel

            torques.append(BodyTorque(load.name, load.body, torque))
            if load.relative_to != GROUND:
                torques.append(BodyTorque(f"{load.name}@{load.relative_to}", load.relative_to,
                                          partial(torque, sign=-1.0)))
    return tuple(forces), tuple(torques)


def _speed_force(mech, load: SpeedForce, phi, omega_of_phi):
    kin = kinematics(mech, phi, omega_of_phi(phi), 0.0)
    p = kin.point(load.point)
    fx, fy = load.law(phi, p.vx, p.vy)
    return np.asarray(fx, dtype=float), np.asarray(fy, dtype=float)


def forces_at_speed(steady: SteadyState) -> RealSpeedForces:
    """Joint forces, driving torque and shaking force of the linkage over the steady-state cycle at the real
    (simulated) speed, against the constant time-mean speed.

    Raises InputError for a machine given by tables (no linkage to re-run).
    """
    machine = steady.machine
    mech = machine.mechanism
    if mech is None:
        raise InputError("The forces at the real speed need a linkage; this machine was given by tables.")
    phi = steady.phi
    omega = np.asarray(steady.omega)
    eps = np.asarray(steady.acceleration)
    curve = steady.speed_curve()

    def omega_of_phi(p):
        return curve(np.asarray(p, dtype=float))

    extra_f, extra_t = _speed_loads_as_engine_loads(mech, machine.speed_loads, omega_of_phi)
    real_mech = replace(mech, forces=mech.forces + extra_f, torques=mech.torques + extra_t)
    real = kinetostatics(real_mech, phi, omega, eps)
    w_mean = np.asarray(steady.time_mean_speed, dtype=float)

    def omega_const(p):
        if np.ndim(w_mean) == 0:
            return np.broadcast_to(w_mean, np.shape(p))
        return np.broadcast_to(w_mean[:, None], (w_mean.size, np.size(p)))

    extra_f, extra_t = _speed_loads_as_engine_loads(mech, machine.speed_loads, omega_const)
    const_mech = replace(mech, forces=mech.forces + extra_f, torques=mech.torques + extra_t)
    constant = kinetostatics(const_mech, phi, np.broadcast_to(omega_const(phi), np.shape(omega)), 0.0)
    peaks = {}
    for j in real.joints:
        r, c = real.joint(j.name), constant.joint(j.name)
        peaks[j.name] = (np.max(r.magnitude, axis=-1), np.max(c.magnitude, axis=-1))
    shaking = (np.max(real.shaking_force, axis=-1), np.max(constant.shaking_force, axis=-1))
    torque = (np.max(np.abs(real.driving_torque), axis=-1), np.max(np.abs(constant.driving_torque), axis=-1))
    return RealSpeedForces(real, constant, peaks, shaking, torque)
