"""Partial balance of a two-cylinder locomotive: hammer blow, variation of tractive effort and swaying couple.

The revolving masses and a fraction c of the reciprocating masses of each cylinder are balanced by masses in
the planes of the driving wheels (two-plane balance, :mod:`machdyn.shafts.balance`), the reciprocating mass being
treated as if it revolved at the crank pin. What is left:

* along the track, the primary force (1 - c) sum(m r w^2 cos(theta + phase)): the **variation of tractive
  effort**, sqrt(2) (1 - c) m r w^2 at most for cranks at 90 deg;
* about the vertical axis, its moment: the **swaying couple**, (1 - c) m r w^2 a / sqrt(2) at most for cylinders
  a apart and cranks at 90 deg;
* across the track (vertical), the balance mass B for the reciprocating part at radius b adds B b w^2 sin to the
  rail load: the **hammer blow**, B b w^2; the wheel lifts when it exceeds the dead load P, i.e. above
  w = sqrt(P / (B b)).

(Khurmi & Gupta, *Theory of Machines*, 14th ed., sec. 22.6-22.9; Rattan, *Theory of Machines*, 4th ed., sec.
14.9.) The values below are computed from the shaft line itself (exact two-plane balance, primary forces), so
they hold for any crank angle between the cylinders; the closed forms above are the 90 deg case.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError, check_positive
from .balance import Plane, correction_unbalances
from .reciprocating import Cylinder, two_term_loads
from .rotating import Mass, cycle, rotating_loads

__all__ = ["LocomotiveBalance", "locomotive_balance"]


@dataclass(frozen=True)
class LocomotiveBalance:
    """Balance masses [kg] in the two wheel planes (total, and the part for the reciprocating masses) with
    their angles [rad]; hammer blow [N] per wheel; largest variation of tractive effort [N]; largest swaying
    couple [N*m]; the speed [rad/s] at which the hammer blow equals ``dead_load`` (None without one)."""

    balance_mass: tuple[float, float]
    balance_angle: tuple[float, float]
    reciprocating_balance_mass: tuple[float, float]
    hammer_blow: float
    tractive_effort_variation: float
    swaying_couple: float
    lift_speed: float | None


def locomotive_balance(cylinders: tuple[Cylinder, ...], wheel_planes: tuple[float, float], radius: float,
                       fraction: float, speed: float, dead_load: float | None = None) -> LocomotiveBalance:
    """Balance a locomotive's cylinders (lines of stroke along x, the track; y vertical) in the wheel planes at
    axial positions ``wheel_planes`` [m] by masses at ``radius`` b [m], for all revolving mass and the fraction
    c [-] of the reciprocating masses; speed w [rad/s] of the driving wheels; dead_load P [N] per wheel.
    Centre of the swaying couple: the mid-plane of the wheels."""
    check_positive("balance radius", radius, "m")
    check_positive("crank speed", speed, "rad/s")
    if not 0.0 <= fraction <= 1.0:
        raise InputError(f"The balanced fraction of the reciprocating masses must lie in 0 ... 1; got {fraction:g}.")
    planes = (Plane("L", wheel_planes[0], radius), Plane("R", wheel_planes[1], radius))
    revolving = [c.crank_mass() for c in cylinders]
    recip = [Mass(f"{c.name} reciprocating", fraction * c.reciprocating_mass, c.crank, c.phase, c.position)
             for c in cylinders]
    total = correction_unbalances([*revolving, *recip], *planes)
    rec = correction_unbalances(recip, *planes)
    centre = 0.5 * (wheel_planes[0] + wheel_planes[1])
    theta = cycle(720)
    primary = two_term_loads(cylinders, speed, 1, theta, centre)
    rec_masses = [Mass(p.name, abs(u) / radius, radius, float(np.angle(u)), p.position)
                  for p, u in zip(planes, rec, strict=True)]
    left = primary + rotating_loads(rec_masses, speed, theta, centre)
    hammer = max(abs(u) for u in rec) * speed**2
    lift = None
    if dead_load is not None:
        check_positive("dead load per wheel", dead_load, "N")
        worst = max(abs(u) for u in rec)
        lift = float(np.sqrt(dead_load / worst)) if worst > 0 else float("inf")
    return LocomotiveBalance(
        balance_mass=(abs(total[0]) / radius, abs(total[1]) / radius),
        balance_angle=tuple(float(np.angle(u)) % (2 * np.pi) for u in total),  # type: ignore[arg-type]
        reciprocating_balance_mass=(abs(rec[0]) / radius, abs(rec[1]) / radius),
        hammer_blow=float(hammer),
        tractive_effort_variation=float(np.max(np.abs(left.fx))),
        swaying_couple=float(np.max(np.abs(left.my))),
        lift_speed=lift,
    )
