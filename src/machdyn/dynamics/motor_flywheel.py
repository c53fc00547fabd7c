"""The flywheel sized for the chosen motor, not for a constant-torque drive.

The classic and the energy-mass (Wittenbauer) sizings of :mod:`machdyn.dynamics.flywheel` assume a drive whose
torque does not depend on the speed. An induction motor slows down along its slip line when the load rises and
so gives more torque exactly when the machine needs it: part of the energy fluctuation comes from the motor, and
a smaller flywheel keeps the same coefficient of speed fluctuation δ. Here the flywheel is found for the real
drive: the inertia J_f whose periodic steady state (:func:`machdyn.dynamics.simulate.steady_state`, the
machine's equation of motion with the drive's torque–speed curve) has δ(J_f) equal to the target.

δ falls monotonically with J_f and log δ is close to linear in log J_f (δ ≈ ΔE/(J ω²) for a large flywheel), so
a vectorised batch of steady states over a geometric grid of inertias brackets the target, and interpolation of
log δ against log J_f, refined once about the estimate, finds it to well below 0.1 % of δ.

Sources: the equation of motion of the machine with a variable reduced inertia, seed 003 eqs 18–19 (solved
for its periodic steady state by :mod:`machdyn.dynamics.simulate`); the induction motor's torque–speed curve
(Kloss's formula), :mod:`machdyn.dynamics.drives`. Valid where the steady state exists: a flywheel so small that
the machine stalls is outside the search.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import InputError
from .simulate import NotSettledError, steady_state

#: The search grid, relative to the constant-torque flywheel, widened outward when the target lies beyond it.
GRIDS = ((0.4, 1.2), (1.2, 4.0), (0.12, 0.4), (4.0, 16.0), (0.03, 0.12))


@dataclass(frozen=True)
class MotorFlywheel:
    """The flywheel for the drive: ``inertia`` [kg·m²] reduced to the crank, the δ it gives, and the constant-
    torque flywheel it replaces (``saving`` = 1 − inertia / constant_torque)."""

    inertia: float
    delta: float
    constant_torque: float

    @property
    def saving(self) -> float:
        return 1.0 - self.inertia / self.constant_torque


def _deltas(machine: Any, drive: Any, inertias: np.ndarray) -> np.ndarray | None:
    try:
        return np.asarray(steady_state(machine, drive, inertias).delta, dtype=float).ravel()
    except (InputError, NotSettledError, ValueError):
        return None  # a flywheel this small lets the machine stall somewhere in the grid


def flywheel_for_drive(machine: Any, drive: Any, target: float, constant_torque: float,
                       points: int = 6, added: float = 0.0) -> MotorFlywheel:
    """The flywheel inertia [kg·m², at the crank] that gives the coefficient of speed fluctuation ``target``
    with ``drive`` (a drive of :mod:`machdyn.dynamics.drives`, e.g. the selected induction motor).

    Parameters
    ----------
    machine : :class:`~machdyn.dynamics.equivalent.EquivalentMachine` of one design.
    drive : the drive; a constant-torque drive gives back about ``constant_torque``.
    target : δ, 0 < δ < 1.
    constant_torque : the flywheel sized for a constant-torque drive [kg·m²] > 0 (the search starts there).
    points : inertias per vectorised batch of steady states.
    added : a constant inertia at the crank [kg·m²] >= 0 that turns with the flywheel whatever its size (the
        drive line's shafts): ``constant_torque`` counts it, and the flywheel returned is the rest.

    Where the motor's slip alone keeps δ under the target down to 3 % of ``constant_torque``, that smallest
    flywheel is returned with the δ it gives.

    Raises
    ------
    InputError : no inertia within 0.03 to 16 times ``constant_torque`` reaches the target.
    """
    if not (0.0 < target < 1.0 and constant_torque > 0):
        raise InputError(f"Sizing a flywheel for a drive needs 0 < delta < 1 and a constant-torque flywheel > 0; "
                         f"got {target!r} and {constant_torque!r} kg*m^2.")
    found: tuple[np.ndarray, np.ndarray] | None = None
    below: tuple[float, float] | None = None  # the smallest inertia that ran, where every δ was under the target
    for lo, hi in GRIDS:
        grid = constant_torque * np.geomspace(lo, hi, points)
        deltas = _deltas(machine, drive, grid)
        if deltas is None:
            grid = grid[points // 2:]  # the smaller half stalls: try the larger half alone
            deltas = _deltas(machine, drive, grid)
            if deltas is None:
                continue
        if deltas.min() <= target <= deltas.max():
            found = (grid, deltas)
            break
        if deltas.max() < target and (below is None or grid[0] < below[0]):
            below = (float(grid[0]), float(deltas[0]))
    if found is None and below is not None and below[0] <= GRIDS[-1][0] * constant_torque * (1 + 1e-12):
        # the motor's slip alone holds δ under the target down to the smallest flywheel tried (3 % of the
        # constant-torque one): that flywheel is reported, with the δ it gives
        return MotorFlywheel(inertia=max(below[0] - added, 0.0), delta=below[1],
                             constant_torque=float(constant_torque) - added)
    if found is None:
        raise InputError(f"No flywheel between {0.03 * constant_torque:.4g} and {16 * constant_torque:.4g} kg*m^2 "
                         f"gives the coefficient of speed fluctuation {target:g} with this drive.")

    def estimate(grid: np.ndarray, deltas: np.ndarray) -> float:
        order = np.argsort(deltas)
        return float(np.exp(np.interp(np.log(target), np.log(deltas[order]), np.log(grid[order]))))

    first = estimate(*found)
    near = first * np.array([0.99, 1.0, 1.01])
    deltas = _deltas(machine, drive, near)
    if deltas is None or not deltas.min() <= target <= deltas.max():
        best = first
        delta = float(np.exp(np.interp(np.log(first), np.log(found[0]), np.log(found[1]))))
    else:
        best = estimate(near, deltas)
        delta = target
    return MotorFlywheel(inertia=max(best - added, 0.0), delta=delta, constant_torque=float(constant_torque) - added)
