"""One call for everything: kinematics, kinetostatics, energy, diagnostics and the built-in checks."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .diagnostics import Diagnostics, diagnose
from .energy import Energy, WorkBalance, energy
from .kinematics import Kinematics, kinematics
from .kinetostatics import Forces, kinetostatics
from .model import Mechanism


@dataclass(frozen=True)
class Analysis:
    """Results of :func:`analyse`: ``kinematics``, ``forces``, ``energy``, ``diagnostics`` (None for design
    sweeps) and ``work_balance`` (the built-in work-energy check)."""

    kinematics: Kinematics
    forces: Forces
    energy: Energy
    diagnostics: Diagnostics | None
    work_balance: WorkBalance

    @property
    def mechanism(self) -> Mechanism:
        return self.kinematics.mechanism

    @property
    def power_balance_relative(self) -> float:
        """Largest pointwise |T*omega + P_loads - dE/dt| over the largest |dE/dt| or |T*omega| (dimensionless)."""
        res = np.abs(self.energy.power_residual())
        scale = max(float(np.max(np.abs(self.forces.input_power))), float(np.max(np.abs(self.energy.energy_rate))))
        return float(np.max(res)) / scale if scale > 0 else float(np.max(res))


def analyse(mech: Mechanism, crank_angle, speed=1.0, acceleration=0.0, *, diagnostics: bool = True) -> Analysis:
    """Kinematics, kinetostatics and energy of ``mech`` at ``crank_angle`` [rad], crank ``speed`` [rad/s] and
    ``acceleration`` [rad/s^2]; with ``diagnostics`` (single designs), the revolution diagnostics too."""
    kin = kinematics(mech, crank_angle, speed, acceleration)
    forces = kinetostatics(mech, kinematics_result=kin)
    en = energy(mech, forces=forces)
    diag = diagnose(mech) if diagnostics and mech.design_count is None else None
    return Analysis(kin, forces, en, diag, en.work_balance())
