"""What the frame feels, before and after balancing: shaking force and moment, driving torque, joint forces.

Every balancing method of :mod:`machdyn.balancing` evaluates the model it starts from and the model it returns
with :func:`frame_loads` and compares them in a :class:`BalanceTable`. The loads are the engine's
kinetostatics (:func:`machdyn.linkage.kinetostatics`) with gravity switched off, so that the shaking force is
the inertia force -sum(m a_G) of every moving mass (Uicker, Pennock & Shigley, *Theory of Machines and
Mechanisms*, 5th ed., sec. 16.3); springs and external loads of the model stay as they are.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from ..errors import InputError, check_finite
from ..linkage import Mechanism, kinematics, kinetostatics
from ..linkage.loads import mass_elements
from ..notebook import ShownInNotebook

__all__ = ["FrameLoads", "BalanceRow", "BalanceTable", "BalanceResult", "frame_loads", "compare", "cycle"]


def cycle(samples: int = 360) -> np.ndarray:
    """``samples`` crank angles [rad] spread uniformly over one turn, end point excluded (so that means over
    the array are cycle means)."""
    if int(samples) != samples or samples < 8:
        raise InputError(f"The number of crank angles per cycle must be an integer >= 8; got {samples!r}.")
    return np.linspace(0.0, 2.0 * np.pi, int(samples), endpoint=False)


@dataclass(frozen=True)
class FrameLoads:
    """Frame loads over one cycle of a single design (SI): crank angle [rad], crank speed [rad/s], shaking
    force components fx, fy [N], shaking moment about the crank pivot [N*m] (including the drive's reaction),
    driving torque [N*m], the largest force of every joint [N] and the total centre of mass cx, cy [m];
    ``forces`` keeps the kinetostatic result they come from (its kinematics included), for the report's
    animation."""

    crank_angle: np.ndarray
    speed: float
    fx: np.ndarray
    fy: np.ndarray
    moment: np.ndarray
    torque: np.ndarray
    joint_peaks: dict
    cx: np.ndarray
    cy: np.ndarray
    forces: Any = field(default=None, repr=False, compare=False)

    @property
    def force(self) -> np.ndarray:
        """|shaking force| [N] at each crank angle."""
        return np.hypot(self.fx, self.fy)

    @property
    def rms_force(self) -> float:
        """Root mean square of |shaking force| over the cycle [N]."""
        return float(np.sqrt(np.mean(self.fx**2 + self.fy**2)))

    @property
    def peak_force(self) -> float:
        return float(np.max(self.force))

    @property
    def rms_moment(self) -> float:
        return float(np.sqrt(np.mean(self.moment**2)))

    @property
    def peak_moment(self) -> float:
        return float(np.max(np.abs(self.moment)))

    @property
    def torque_fluctuation(self) -> float:
        """Peak-to-peak driving torque [N*m]."""
        return float(np.max(self.torque) - np.min(self.torque))

    @property
    def rms_torque(self) -> float:
        return float(np.sqrt(np.mean(self.torque**2)))

    @property
    def peak_joint_force(self) -> float:
        return max(self.joint_peaks.values()) if self.joint_peaks else 0.0

    @property
    def com_spread(self) -> float:
        """Spread [m] of the total centre of mass over the cycle: the larger of its x and y ranges."""
        return float(max(np.ptp(self.cx), np.ptp(self.cy)))


def frame_loads(mech: Mechanism, crank_angle=None, speed: float = 1.0) -> FrameLoads:
    """Shaking force and moment, driving torque, joint peaks and total centre of mass of ``mech`` (gravity off).

    Parameters
    ----------
    mech : a single-design mechanism (no design arrays)
    crank_angle : crank angles [rad]; default :func:`cycle` (360 angles over one turn)
    speed : constant crank speed [rad/s], > 0 (the inertia loads scale with its square)

    Returns :class:`FrameLoads`. The moment is taken about the crank pivot.
    """
    if mech.design_count is not None:
        raise InputError(f"frame_loads takes a single design; mechanism '{mech.name}' has {mech.design_count}.")
    check_finite("crank speed", speed, "rad/s")
    if not speed > 0:
        raise InputError(f"The crank speed must be > 0 rad/s; got {speed:g} rad/s.")
    phi = cycle() if crank_angle is None else np.asarray(crank_angle, dtype=float)
    if phi.ndim != 1 or phi.size == 0:
        raise InputError(f"crank_angle must be a non-empty 1-D array of crank angles [rad]; got shape {phi.shape}.")
    quiet = replace(mech, gravity=(0.0, 0.0))
    kin = kinematics(quiet, phi, speed, 0.0)
    forces = kinetostatics(quiet, kinematics_result=kin)
    pivot = quiet.ground[quiet.crank.pivot.split(".")[1]]
    cx, cy = centre_of_mass(kin)
    peaks = {j.name: float(np.max(forces.joint(j.name).magnitude)) for j in forces.joints}
    return FrameLoads(
        crank_angle=phi,
        speed=float(speed),
        fx=np.array(forces.frame_fx, dtype=float),
        fy=np.array(forces.frame_fy, dtype=float),
        moment=np.array(forces.shaking_moment(about=pivot), dtype=float),
        torque=np.array(forces.driving_torque, dtype=float),
        joint_peaks=peaks,
        cx=cx,
        cy=cy,
        forces=forces,
    )


def centre_of_mass(kin) -> tuple[np.ndarray, np.ndarray]:
    """Total centre of mass (x, y) [m] of every moving mass (bodies and point masses) at each position
    (zeros when no moving body or point mass has mass)."""
    total: Any = 0.0
    mx: Any = 0.0
    my: Any = 0.0
    for m in mass_elements(kin):
        total = total + m.mass
        mx = mx + m.mass * m.motion.x
        my = my + m.mass * m.motion.y
    if not np.all(np.asarray(total) > 0):  # nothing moves that has mass: no centre to travel, reported at 0
        zero = np.zeros(np.shape(kin.crank_angle))
        return zero, zero.copy()
    return np.asarray(mx / total, dtype=float), np.asarray(my / total, dtype=float)


@dataclass(frozen=True)
class BalanceRow:
    """One line of a before/after table: its ``key`` (the name of the result, ``balance.<key>_before`` /
    ``_after``), the quantity's text, SI unit, value before, value after."""

    key: str
    quantity: str
    unit: str
    before: float
    after: float

    @property
    def change(self) -> float:
        """Relative change (after - before) / before [-]; 0 when both are 0, inf for growth from 0."""
        if self.before == 0.0:
            return 0.0 if self.after == 0.0 else float("inf")
        return (self.after - self.before) / self.before


@dataclass(frozen=True)
class BalanceTable:
    """Before/after comparison of the frame loads of a balancing step."""

    rows: tuple[BalanceRow, ...]

    def row(self, key: str) -> BalanceRow:
        """The row of ``key`` (one of :data:`COMPARED`'s keys: ``rms_force``, ``peak_force``...)."""
        for r in self.rows:
            if r.key == key:
                return r
        raise KeyError(f"no row '{key}' in the balance table; rows: {', '.join(r.key for r in self.rows)}")

    def as_records(self) -> list[dict]:
        return [
            {"quantity": r.quantity, "unit": r.unit, "before": r.before, "after": r.after, "change": r.change}
            for r in self.rows
        ]


#: The rows of a before/after table: key (= the :class:`FrameLoads` property it reads, but ``com_travel`` for
#: ``com_spread``), text, SI unit.
COMPARED = (
    ("rms_force", "RMS shaking force", "N"),
    ("peak_force", "peak shaking force", "N"),
    ("rms_moment", "RMS shaking moment", "N*m"),
    ("peak_moment", "peak shaking moment", "N*m"),
    ("rms_torque", "RMS driving torque", "N*m"),
    ("torque_fluctuation", "driving torque fluctuation", "N*m"),
    ("peak_joint_force", "peak joint force", "N"),
    ("com_travel", "centre-of-mass travel", "m"),
)


def compare(before: FrameLoads, after: FrameLoads) -> BalanceTable:
    """The standard before/after table of two :class:`FrameLoads` (rows :data:`COMPARED`)."""
    def value(loads: FrameLoads, key: str) -> float:
        return loads.com_spread if key == "com_travel" else getattr(loads, key)

    return BalanceTable(tuple(BalanceRow(k, q, u, value(before, k), value(after, k)) for k, q, u in COMPARED))


@dataclass(frozen=True)
class BalanceResult:
    """A balancing step: the balanced ``model``, the frame loads ``before`` and ``after``, their ``table``,
    the added or changed masses ``counterweights`` (point masses, springs) and ``notes`` (what was assumed,
    what an optimiser reported)."""

    model: Mechanism
    before: FrameLoads
    after: FrameLoads
    table: BalanceTable
    counterweights: tuple = ()
    notes: tuple[str, ...] = ()


@dataclass(frozen=True)
class BalanceRun(ShownInNotebook):
    """The outcome of ``[balance]`` (the contract its readers, ``[frame]`` and the report, rely on): the method,
    the balance ``result`` (:class:`BalanceResult`, or :class:`~machdyn.balancing.robust.RobustResult` over
    operating states), the trade-off curve of the crank method (or None), the table's reference reduction and its
    source, and the balanced fraction of the crank method."""

    method: str
    result: Any
    tradeoff: Any
    reference_reduction: float | None
    reference_source: str
    fraction: float | None = None

    @property
    def model(self) -> Mechanism | None:
        """The single balanced mechanism (None for a balance over several operating states)."""
        return getattr(self.result, "model", None)
