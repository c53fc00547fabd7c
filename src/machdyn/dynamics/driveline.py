"""The drive line: the shafts between the motor and the crank, the stages that join them (gear, belt, chain: ratio
and efficiency), and where the motor, the flywheel, the clutch and the brake sit. Declared once (the problem
file's ``[drivetrain]`` with ``[flywheel]``) and read by every capability that needs it: flywheel sizing and
steady state, start-up, clutch, brake, single stroke, motor duty, the forces at the real speed.

Shafts are numbered from the motor (shaft 0) to the crank (shaft n); stage k joins shaft k to shaft k+1 with
the ratio i_k = ω_k / ω_(k+1) (> 1 reduces the speed) and the efficiency η_k. Shaft k turns r_k = Π_(j>=k) i_j
times as fast as the crank.

Sources
-------
- Reduced (equivalent) inertia by equal kinetic energy, J_red = Σ J_k r_k²: J. J. Uicker, G. R. Pennock,
  J. E. Shigley, *Theory of Machines and Mechanisms*, 4th ed., Oxford 2011, the chapter on the dynamics of
  machines (equivalent inertia of a geared system); R. S. Khurmi, J. K. Gupta, *Theory of Machines*, the section
  "torque required to accelerate a geared system" (I_A + G² I_B on the driving shaft, G = ω_B/ω_A). A test
  checks the identity: the kinetic energy of the line at any speed equals ½·J_red·ω_c².
- Torque through a lossy stage: T_out = T_in · i · η when power flows to the output (driving), T_out =
  T_in · i / η when it flows back (the output drives the input, overrunning): the power balance P_out = η P_in
  (Khurmi & Gupta, as above, with the efficiency of the gearing; H. H. Mabie, C. F. Reinholtz, *Mechanisms and
  Dynamics of Machinery*, 4th ed., Wiley 1987, gear trains).

Validity: rigid shafts, constant ratios (no belt slip), an efficiency that depends on the direction of the power
flow only. The inertia torque of a shaft upstream of a stage is carried through the stage as the kinetic-energy
definition of J_red says, without that stage's loss; the motor's torque takes the loss of every stage. For a
motor shaft of negligible inertia this is exact; otherwise the accelerating torque of the upstream inertias is
off by their share times (1 − η) (Khurmi & Gupta count it: I_A + G² I_B/η).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from ..errors import InputError


@dataclass(frozen=True)
class Stage:
    """A gear or belt stage: ``ratio`` i = input speed / output speed (> 0), ``efficiency`` η in (0, 1],
    ``kind`` ("gear", "belt", "chain") for the drawing and the report; optionally its shafts and coupling as a
    torsional spring of ``torsional_stiffness`` k [N·m/rad] with a damper ``torsional_damping`` c [N·m·s/rad],
    referred to the output shaft: the stage passes k (θ_in / i − θ_out) + c (ω_in / i − ω_out) to it (None:
    rigid). Only the machine in time (``[transient]``) reads them; the other analyses take the line as rigid."""

    ratio: float
    efficiency: float = 1.0
    kind: str = "gear"
    name: str = ""
    torsional_stiffness: float | None = None
    torsional_damping: float = 0.0


@dataclass(frozen=True)
class DriveTrain:
    """Stages from the motor to the crank and the inertia [kg·m²] on each shaft (``shaft_inertia[0]`` on the
    motor shaft, the motor's rotor included; the last on the crank shaft besides the linkage)."""

    stages: tuple[Stage, ...]
    shaft_inertia: tuple[float, ...]

    def __post_init__(self) -> None:
        if len(self.shaft_inertia) != len(self.stages) + 1:
            raise InputError(f"A drive train of {len(self.stages)} stage(s) has {len(self.stages) + 1} shafts; got "
                             f"{len(self.shaft_inertia)} inertia value(s).")
        for k, s in enumerate(self.stages):
            if not (np.isfinite(s.ratio) and s.ratio > 0):
                raise InputError(f"Stage {k + 1} ({s.name or s.kind}): the ratio must be > 0; got {s.ratio!r}.")
            if not (0.0 < s.efficiency <= 1.0):
                raise InputError(f"Stage {k + 1} ({s.name or s.kind}): the efficiency must be in (0, 1]; got "
                                 f"{s.efficiency!r}.")
            if s.torsional_stiffness is not None and not (np.isfinite(s.torsional_stiffness)
                                                          and s.torsional_stiffness > 0):
                raise InputError(f"Stage {k + 1} ({s.name or s.kind}): the torsional stiffness must be > 0 N*m/rad; "
                                 f"got {s.torsional_stiffness!r}.")
            if not (np.isfinite(s.torsional_damping) and s.torsional_damping >= 0):
                raise InputError(f"Stage {k + 1} ({s.name or s.kind}): the torsional damping must be >= 0 "
                                 f"N*m*s/rad; got {s.torsional_damping!r}.")
        for k, j in enumerate(self.shaft_inertia):
            if not (np.isfinite(j) and j >= 0):
                raise InputError(f"Shaft {k}: the inertia must be >= 0 kg*m^2; got {j!r}.")

    @property
    def speed_ratios(self) -> np.ndarray:
        """ω_k / ω_crank of every shaft k (the crank's is 1).

        Examples
        --------
        >>> DriveTrain((Stage(4.0), Stage(2.5)), (0.1, 0.5, 2.0)).speed_ratios.tolist()
        [10.0, 2.5, 1.0]
        """
        ratios = [1.0]
        for s in reversed(self.stages):
            ratios.append(ratios[-1] * s.ratio)
        return np.array(ratios[::-1])

    @property
    def total_ratio(self) -> float:
        """Motor speed / crank speed [-]."""
        return float(self.speed_ratios[0])

    @property
    def efficiency(self) -> float:
        """Product of the stages' efficiencies [-]."""
        return float(np.prod([s.efficiency for s in self.stages])) if self.stages else 1.0

    def reflected_inertia(self, upto: int | None = None) -> float:
        """Inertia of the shafts ``0 .. upto`` (all by default) reflected to the crank, J_c = Σ J_k (ω_k/ω_c)²
        [kg·m²] (equal kinetic energy).

        Examples
        --------
        A 0.1 kg·m² motor shaft geared 10:1 to the crank counts as 10 kg·m² there:

        >>> DriveTrain((Stage(10.0),), (0.1, 0.0)).reflected_inertia()
        10.0
        """
        r = self.speed_ratios
        j = np.asarray(self.shaft_inertia, dtype=float)
        last = len(j) if upto is None else upto + 1
        return float(np.sum(j[:last] * r[:last] ** 2))

    def shaft_torques(self, crank_torque: Any) -> np.ndarray:
        """The torque [N·m] each shaft transmits towards the crank when the crank needs ``crank_torque`` (any
        shape; leading axis of the result: shafts 0..n). Where the crank torque is negative the power flows back
        to the motor and each stage's loss is taken on the other side.

        Examples
        --------
        >>> train = DriveTrain((Stage(5.0, 0.9),), (0.0, 0.0))
        >>> train.shaft_torques([90.0, -90.0]).round(3).tolist()
        [[20.0, -16.2], [90.0, -90.0]]
        """
        t = np.asarray(crank_torque, dtype=float)
        out = [t]
        for s in reversed(self.stages):
            down = out[-1]
            # motoring: T_in = T_out / (i η); back-driven: T_in = T_out η / i
            out.append(np.where(down >= 0, down / (s.ratio * s.efficiency), down * s.efficiency / s.ratio))
        return np.array(out[::-1])

    def kinetic_energy(self, crank_speed: Any) -> Any:
        """Kinetic energy [J] of the train's shafts at ``crank_speed`` [rad/s], Σ ½ J_k ω_k²."""
        w = np.asarray(crank_speed, dtype=float)
        return sum(0.5 * j * (r * w) ** 2 for j, r in zip(self.shaft_inertia, self.speed_ratios, strict=True))


#: the names every drive line knows: its first and its last shaft
MOTOR, CRANK = "motor", "crank"


@dataclass(frozen=True)
class DriveLine:
    """The one drive line of a machine: the :class:`DriveTrain` (stages and shaft inertias, motor shaft first,
    crank shaft last), a name per shaft, and the shafts the flywheel, the clutch and the brake sit on.

    ``declared`` is False for a machine with no ``[drivetrain]``: the line then has the crank shaft and, for a
    flywheel on a faster shaft (``[flywheel] speed_ratio``), that shaft joined to the crank by a loss-free stage;
    the motor keeps its own ratio and efficiency (``[flywheel.motor]``).

    Examples
    --------
    A 6 kg·m² flywheel on a shaft turning 10 times the crank counts 600 kg·m² at the crank:

    >>> line = DriveLine(DriveTrain((Stage(10.0),), (0.0, 0.0)), ("flywheel shaft", "crank"), flywheel_shaft=0)
    >>> line.at_crank(6.0, line.flywheel_shaft)
    600.0
    """

    train: DriveTrain
    names: tuple[str, ...]
    flywheel_shaft: int
    clutch_shaft: int | None = None
    brake_shaft: int | None = None
    declared: bool = True

    def __post_init__(self) -> None:
        n = len(self.train.shaft_inertia)
        if len(self.names) != n:
            raise InputError(f"A drive line of {n} shafts needs {n} names; got {len(self.names)}.")
        for what, k in (("flywheel", self.flywheel_shaft), ("clutch", self.clutch_shaft),
                        ("brake", self.brake_shaft)):
            if k is not None and not 0 <= k < n:
                raise InputError(f"The {what}'s shaft must be 0 to {n - 1}; got {k}.")

    @classmethod
    def crank_only(cls, flywheel_ratio: float = 1.0) -> DriveLine:
        """The line of a machine with no ``[drivetrain]``: the crank shaft, and a flywheel shaft turning
        ``flywheel_ratio`` times as fast where that is not 1."""
        if flywheel_ratio == 1.0:
            return cls(DriveTrain((), (0.0,)), (CRANK,), 0, declared=False)
        return cls(DriveTrain((Stage(flywheel_ratio, 1.0, "gear", "flywheel drive"),), (0.0, 0.0)),
                   ("flywheel shaft", CRANK), 0, declared=False)

    @property
    def crank(self) -> int:
        """The index of the crank shaft (the last)."""
        return len(self.names) - 1

    def ratio(self, shaft: int) -> float:
        """Speed of ``shaft`` / speed of the crank [-]."""
        return float(self.train.speed_ratios[shaft])

    def at_crank(self, inertia: float, shaft: int) -> float:
        """An inertia [kg·m²] about ``shaft`` referred to the crank: J r² (equal kinetic energy)."""
        return float(inertia) * self.ratio(shaft) ** 2

    def about_shaft(self, inertia_at_crank: float, shaft: int) -> float:
        """An inertia [kg·m²] referred to the crank, taken back to ``shaft``: J_c / r²."""
        return float(inertia_at_crank) / self.ratio(shaft) ** 2

    @property
    def shaft_inertia(self) -> float:
        """Every shaft's inertia referred to the crank, Σ J_k r_k² [kg·m²] (the motor's rotor on shaft 0
        included; the flywheel and the linkage not)."""
        return self.train.reflected_inertia()

    @property
    def motor_ratio(self) -> float:
        """Motor speed / crank speed [-] of a declared line."""
        return self.train.total_ratio

    @property
    def motor_efficiency(self) -> float:
        """Product of the stages' efficiencies, motor to crank [-]."""
        return self.train.efficiency

    def inertia_between(self, first: int, last: int) -> float:
        """The inertia [kg·m²] of shafts ``first .. last`` (inclusive) referred to the crank."""
        r = self.train.speed_ratios[first:last + 1]
        j = np.asarray(self.train.shaft_inertia[first:last + 1], dtype=float)
        return float(np.sum(j * r**2))

    def efficiency_between(self, first: int, last: int) -> float:
        """The product of the efficiencies of the stages from shaft ``first`` to shaft ``last`` (> first) [-]."""
        return float(np.prod([s.efficiency for s in self.train.stages[first:last]])) if last > first else 1.0

    def motor_drive(self, drive: Any) -> Any:
        """``drive`` (a drive of :mod:`machdyn.dynamics.drives` with ``ratio`` and ``efficiency``) through this
        line: its ratio and efficiency those of the stages; its rotor inertia 0 (the line's motor shaft holds
        it). A line with no ``[drivetrain]`` leaves the drive as it is."""
        if not self.declared:
            return drive
        return replace(drive, ratio=self.motor_ratio, efficiency=self.motor_efficiency, rotor_inertia=0.0)

    def describe(self, shaft: int) -> str:
        """The shaft by name and speed, e.g. "shaft 1 'flywheel shaft' (8 × the crank's speed)"."""
        if shaft == self.crank:
            return "the crank shaft"
        return f"shaft {shaft} '{self.names[shaft]}' ({self.ratio(shaft):.6g} × the crank's speed)"
