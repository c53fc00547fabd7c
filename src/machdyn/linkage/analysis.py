"""One call for everything: kinematics, kinetostatics, energy, diagnostics and the built-in checks."""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from .diagnostics import Diagnostics, diagnose
from .energy import Energy, WorkBalance, energy
from .kinematics import kinematics
from .kinetostatics import kinetostatics
from .model import Mechanism
from .motion import Kinematics, is_full_turn
from .reactions import Forces


@dataclass(frozen=True)
class Analysis:
    """Results of :func:`analyse`: ``kinematics``, ``forces``, ``energy``, ``work_balance`` (the built-in
    work-energy check) and ``diagnostics`` (None for design sweeps), computed when first read."""

    kinematics: Kinematics
    forces: Forces
    energy: Energy
    work_balance: WorkBalance
    with_diagnostics: bool = field(default=True, repr=False)

    @cached_property
    def diagnostics(self) -> Diagnostics | None:
        """The diagnostics of a single design over the analysed crank range (the full turn when the analysis
        covers one; see :func:`~machdyn.linkage.diagnostics.diagnose`), computed on first access and kept with
        the mechanism."""
        mech = self.mechanism
        if not self.with_diagnostics or mech.design_count is not None:
            return None
        return diagnose(mech, crank_range=analysed_range(self.kinematics.crank_angle))

    @property
    def mechanism(self) -> Mechanism:
        return self.kinematics.mechanism

    @property
    def power_balance_relative(self) -> float:
        """Largest pointwise |T*omega + P_loads - dE/dt| over the largest |dE/dt| or |T*omega| (dimensionless)."""
        res = np.abs(self.energy.power_residual())
        scale = max(float(np.max(np.abs(self.forces.input_power))), float(np.max(np.abs(self.energy.energy_rate))))
        return float(np.max(res)) / scale if scale > 0 else float(np.max(res))


def analysed_range(crank_angle) -> tuple[float, float] | None:
    """(first, last) crank angle [rad] of a partial range, or None when the angles cover a full turn (evenly
    spaced without the end point, or spanning at least 2*pi)."""
    phi = np.atleast_1d(np.asarray(crank_angle, dtype=float)).ravel()
    if phi.size < 2:
        return None if phi.size == 0 else (float(phi[0]), float(phi[0]))
    span = float(phi.max() - phi.min())
    even_turn = is_full_turn(phi) or is_full_turn(phi[::-1])  # turning either way
    if even_turn or span >= 2 * np.pi * (1.0 - 1e-9):
        return None
    return (float(phi[0]), float(phi[-1]))


def analyse(mech: Mechanism, crank_angle, speed=1.0, acceleration=0.0, *, diagnostics: bool = True) -> Analysis:
    """Kinematics, kinetostatics and energy of ``mech`` at ``crank_angle`` [rad], crank ``speed`` [rad/s] and
    ``acceleration`` [rad/s^2]; with ``diagnostics`` (single designs), the revolution diagnostics too, when
    first read (:attr:`Analysis.diagnostics`): a call that does not read them does not pay for them."""
    kin = kinematics(mech, crank_angle, speed, acceleration)
    forces = kinetostatics(mech, kinematics_result=kin)
    en = energy(mech, forces=forces)
    return Analysis(kin, forces, en, en.work_balance(), diagnostics)
