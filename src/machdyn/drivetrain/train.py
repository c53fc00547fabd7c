"""The drive train between the motor and the crank: stages of gears and belts, the inertia of every shaft
reflected to the crank, and the torque and speed of every shaft.

Shafts are numbered from the motor (shaft 0) to the crank (shaft n); stage k joins shaft k to shaft k+1 with
the ratio i_k = ω_k / ω_(k+1) (> 1 reduces the speed) and the efficiency η_k.

Sources
-------
- Reflected (equivalent) inertia by equal kinetic energy, J_c = Σ J_k (ω_k/ω_c)²: R. S. Khurmi, J. K. Gupta,
  *Theory of Machines*, the section "torque required to accelerate a geared system" (I_A + G² I_B on the
  driving shaft, G = ω_B/ω_A). The identity is checked by a test: the kinetic energy of the train at any speed
  equals ½·J_c·ω_c².
- Torque through a lossy stage: T_out = T_in · i · η when power flows to the output (motoring), T_out =
  T_in · i / η when it flows back (the output drives the input): power balance P_out = η P_in.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import InputError


@dataclass(frozen=True)
class Stage:
    """A gear or belt stage: ``ratio`` i = input speed / output speed (> 0), ``efficiency`` η in (0, 1],
    ``kind`` ("gear", "belt", "chain") for the drawing and the report."""

    ratio: float
    efficiency: float = 1.0
    kind: str = "gear"
    name: str = ""


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
