"""Hoists and branched gear trains: the torque a motor needs to accelerate several loads, and what it sees of them.

The train is a tree of shafts rooted at the motor's: every other shaft is driven from its parent through a stage
of ratio i = omega_parent / omega_shaft (> 1 reduces the speed) and efficiency eta. A shaft carries its own
inertia J [kg m^2], a friction torque T_f [N m] opposing its motion, and rope drums: a drum of radius R [m] lifts
a cage of mass m_c [kg] on one side and lowers a counterweight m_w [kg] on the other (the rope's moving mass
m_r [kg] with them), so its shaft turning at omega moves them at v = omega R.

Each shaft's own need at the motor's angular acceleration alpha_m (the shaft's alpha = alpha_m r, r = omega /
omega_m the product of the inverse ratios from the motor) is

    Q = J alpha + T_f + sum_drums [ (m_c + m_w + m_r) R^2 alpha + (m_c - m_w) g R ],

and a stage passes its shaft's whole demand D (its own Q plus its children's, referred to it) to the parent as
D / (i eta) when the power flows down to the load (D >= 0) and D eta / i when the load drives back (D < 0):
the power balance P_in = P_out / eta (Khurmi & Gupta, *Theory of Machines*, 14th ed., ch. 3, "torque required
to accelerate a geared system", T = (I_A + G^2 I_B / eta) alpha_A, and the hoist examples of that chapter;
J. J. Uicker, G. R. Pennock, J. E. Shigley, *Theory of Machines and Mechanisms*, 4th ed., equivalent inertia).
The motor's torque is its own J_m alpha_m + T_f,m plus its children's demands.

Referred to the motor (loss-free, by equal kinetic energy and equal power): the equivalent inertia
J_eq = sum_k r_k^2 (J_k + sum (m_c + m_w + m_r) R^2) and the load torque sum_k r_k (T_f,k + sum (m_c - m_w) g R).

Validity: rigid shafts and ropes (no stretch, no slack: the cage's acceleration stays above -g), constant ratios,
an efficiency that depends only on the direction of the power through its stage, friction torques constant and
opposing a motion in the lifting direction (alpha_m of either sign, omega_m >= 0).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..constants import STANDARD_GRAVITY
from ..errors import InputError


@dataclass(frozen=True)
class Drum:
    """A rope drum [m] lifting ``cage`` [kg] and lowering ``counterweight`` [kg]; ``rope`` the rope's moving mass
    [kg]; ``name`` for the report."""

    radius: float
    cage: float
    counterweight: float = 0.0
    rope: float = 0.0
    name: str = "drum"


@dataclass(frozen=True)
class Shaft:
    """A shaft driven from ``parent`` (a shaft's name; None for the motor's) through a stage of ``ratio``
    omega_parent / omega_this and ``efficiency``; its own ``inertia`` [kg m^2], ``friction`` torque [N m] and
    ``drums``."""

    name: str
    parent: str | None = None
    ratio: float = 1.0
    efficiency: float = 1.0
    inertia: float = 0.0
    friction: float = 0.0
    drums: tuple[Drum, ...] = field(default_factory=tuple)


@dataclass(frozen=True)
class HoistResult:
    """The train at one motor acceleration [rad/s^2]: the motor's torque [N m], the equivalent inertia [kg m^2]
    and load torque [N m] at the motor (loss-free), each shaft's speed ratio to the motor, its own need referred
    to the motor without loss [N m] (``loss_torque`` [N m] the stages' share: the motor torque minus their sum),
    and each drum's cage acceleration [m/s^2]."""

    motor_acceleration: float
    motor_torque: float
    equivalent_inertia: float
    load_torque: float
    speed_ratio: dict[str, float]
    shaft_demand: dict[str, float]
    cage_acceleration: dict[str, float]

    @property
    def loss_torque(self) -> float:
        return self.motor_torque - sum(self.shaft_demand.values())


def _checked(shafts: tuple[Shaft, ...]) -> tuple[Shaft, ...]:
    names = [s.name for s in shafts]
    if len(set(names)) != len(names):
        raise InputError(f"Every shaft of a train needs its own name; got {names}.")
    roots = [s.name for s in shafts if s.parent is None]
    if len(roots) != 1:
        raise InputError(f"A train has one motor shaft (without a parent); got {len(roots)}: {roots}.")
    for s in shafts:
        if s.parent is not None and s.parent not in names:
            raise InputError(f"Shaft '{s.name}': its parent '{s.parent}' is not a shaft of the train ({names}).")
        if not (np.isfinite(s.ratio) and s.ratio > 0.0):
            raise InputError(f"Shaft '{s.name}': the ratio must be > 0; got {s.ratio!r}.")
        if not 0.0 < s.efficiency <= 1.0:
            raise InputError(f"Shaft '{s.name}': the efficiency must be in (0, 1]; got {s.efficiency!r}.")
        if not (s.inertia >= 0.0 and s.friction >= 0.0):
            raise InputError(f"Shaft '{s.name}': inertia and friction torque must be >= 0; got {s.inertia!r} "
                             f"kg*m^2, {s.friction!r} N*m.")
        for d in s.drums:
            if not (d.radius > 0.0 and d.cage >= 0.0 and d.counterweight >= 0.0 and d.rope >= 0.0):
                raise InputError(f"Drum '{d.name}' on shaft '{s.name}': the radius must be > 0 and the masses >= 0; "
                                 f"got R = {d.radius!r} m, {d.cage!r}, {d.counterweight!r}, {d.rope!r} kg.")
    # every shaft reaches the motor (no loop)
    parent = {s.name: s.parent for s in shafts}
    for s in shafts:
        seen: set[str] = set()
        at: str | None = s.name
        while at is not None:
            if at in seen:
                raise InputError(f"The shafts' parents make a loop through '{at}'.")
            seen.add(at)
            at = parent[at]
    return shafts


def speed_ratios(shafts: tuple[Shaft, ...]) -> dict[str, float]:
    """omega_shaft / omega_motor of every shaft: the product of 1 / i along its path from the motor.

    >>> speed_ratios((Shaft("motor"), Shaft("drum", "motor", 4.0)))
    {'motor': 1.0, 'drum': 0.25}
    """
    by_name = {s.name: s for s in _checked(shafts)}
    out: dict[str, float] = {}

    def ratio(name: str) -> float:
        if name not in out:
            s = by_name[name]
            out[name] = 1.0 if s.parent is None else ratio(s.parent) / s.ratio
        return out[name]

    for s in shafts:
        ratio(s.name)
    return out


def own_need(s: Shaft, alpha: float, gravity: float = STANDARD_GRAVITY) -> float:
    """The torque [N m] shaft ``s`` needs at its own angular acceleration ``alpha`` [rad/s^2] (module docstring):
    J alpha + T_f + sum [(m_c + m_w + m_r) R^2 alpha + (m_c - m_w) g R].

    >>> round(own_need(Shaft("d", drums=(Drum(0.5, 1000.0, 600.0),)), 0.0), 6)
    1961.33
    """
    need = s.inertia * alpha + s.friction
    for d in s.drums:
        moving = d.cage + d.counterweight + d.rope
        need += moving * d.radius**2 * alpha + (d.cage - d.counterweight) * gravity * d.radius
    return float(need)


def hoist(shafts: tuple[Shaft, ...], motor_acceleration: float, gravity: float = STANDARD_GRAVITY) -> HoistResult:
    """The motor torque [N m] that gives the train the motor acceleration ``motor_acceleration`` [rad/s^2], with
    each stage's loss taken in the direction its power flows; equivalent inertia and load at the motor."""
    if not np.isfinite(motor_acceleration):
        raise InputError(f"The motor's acceleration must be finite; got {motor_acceleration!r} rad/s^2.")
    r = speed_ratios(shafts)
    by_name = {s.name: s for s in shafts}
    children: dict[str, list[str]] = {s.name: [] for s in shafts}
    for s in shafts:
        if s.parent is not None:
            children[s.parent].append(s.name)

    def demand(name: str) -> float:  # on this shaft: its own need and its children's through their stages
        s = by_name[name]
        total = own_need(s, motor_acceleration * r[name], gravity)
        for c in children[name]:
            child, d = by_name[c], demand(c)
            total += d / (child.ratio * child.efficiency) if d >= 0.0 else d * child.efficiency / child.ratio
        return total

    root = next(s.name for s in shafts if s.parent is None)
    # each shaft's own need referred to the motor without loss (equal power); what the stages lose is the rest
    per_shaft = {s.name: float(r[s.name] * own_need(s, motor_acceleration * r[s.name], gravity)) for s in shafts}
    j_eq = sum(r[s.name] ** 2 * (s.inertia + sum((d.cage + d.counterweight + d.rope) * d.radius**2 for d in s.drums))
               for s in shafts)
    load = sum(r[s.name] * own_need(s, 0.0, gravity) for s in shafts)
    cages = {d.name: motor_acceleration * r[s.name] * d.radius for s in shafts for d in s.drums}
    return HoistResult(motor_acceleration=float(motor_acceleration), motor_torque=float(demand(root)),
                       equivalent_inertia=float(j_eq), load_torque=float(load), speed_ratio=r,
                       shaft_demand=per_shaft, cage_acceleration=cages)


def acceleration(shafts: tuple[Shaft, ...], motor_torque: float, gravity: float = STANDARD_GRAVITY) -> float:
    """The motor's angular acceleration [rad/s^2] a motor torque [N m] gives the train: the root of
    hoist(alpha).motor_torque = ``motor_torque`` (increasing in alpha; linear between the alphas where a stage's
    power turns round)."""
    from scipy.optimize import brentq

    def excess(alpha: float) -> float:
        return hoist(shafts, alpha, gravity).motor_torque - motor_torque

    lo, hi = -1.0, 1.0
    for _ in range(200):
        if excess(lo) <= 0.0 <= excess(hi):
            break
        lo, hi = 2.0 * lo, 2.0 * hi
    else:
        raise InputError(f"No motor acceleration gives the torque {motor_torque!r} N*m.")
    return float(brentq(excess, lo, hi, xtol=1e-14, rtol=1e-14))


def optimum_ratio(motor_inertia: float, load_inertia: float) -> float:
    """The gear ratio G = omega_motor / omega_load [-] that gives a load of inertia ``load_inertia`` [kg m^2] the
    largest acceleration from a motor torque with a rotor of ``motor_inertia`` [kg m^2] (loss-free, no load
    torque): G = sqrt(I_load / I_motor), where the reflected load inertia equals the motor's (Khurmi & Gupta,
    *Theory of Machines*, 14th ed., ch. 3, example 3.14, p. 51).

    >>> optimum_ratio(2.0, 32.0)
    4.0
    """
    if not (motor_inertia > 0.0 and load_inertia > 0.0):
        raise InputError(f"Both inertias must be > 0; got I_motor = {motor_inertia!r}, I_load = {load_inertia!r} "
                         "kg*m^2.")
    return float(np.sqrt(load_inertia / motor_inertia))
