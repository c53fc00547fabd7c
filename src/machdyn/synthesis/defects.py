"""The defects of a synthesised linkage, checked for every candidate rather than left to the designer.

- **branch** (circuit) defect: the linkage, assembled one way (one branch of its closure), does not reach every
  precision position: some were met only by the other assembly (Norton, *Design of Machinery*, 5th ed., ch. 4
  and 5 on circuits and branches; Erdman, Sandor & Kota, *Mechanism Design*, ch. 8, branch and order
  rectification). Found by running the candidate's own single-branch closure through the positions.
- **order** defect: the crank, turning one way, meets the positions in another order than the task's.
- **Grashof** defect: the crank cannot turn a full revolution when the task needs a motor-driven crank
  (Grashof's rule, Norton §2.12; for the offset slider-crank b >= a + |e|).
- **assembly** defect: somewhere between two positions the linkage cannot close (it would have to be taken
  apart to go on).
- **transmission** defect: the transmission angle falls below the limit somewhere in the working range
  (Norton, ch. 3, the transmission angle: 40 deg is a common lower limit for fast machines, 30 deg the
  usual minimum).

Targets are what the task prescribes: coupler points [m] (complex), coupler angles [rad], output angles [rad];
the errors are measured at the candidate's crank angles for the positions.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from .candidate import TWO_PI, Candidate, wrap


@dataclass(frozen=True)
class Targets:
    """What the task prescribes at its positions (any may be None): ``points`` [m] complex, ``coupler_angles``
    [rad], ``outputs`` [rad] (rocker angles) or [m] (slider travel from the foot of O2 on the slide line)."""

    points: np.ndarray | None = None
    coupler_angles: np.ndarray | None = None
    outputs: np.ndarray | None = None
    scale: float = 1.0


@dataclass(frozen=True)
class Report:
    """The defects of one candidate and its kinematic errors at the precision positions."""

    defects: tuple[str, ...]
    position_error: float          # [m], largest distance of the coupler point from a target point
    angle_error: float             # [rad], largest coupler- or output-angle error
    min_transmission: float        # [rad] over the working range
    full_turn: bool                # the crank can turn a full revolution
    notes: dict = field(default_factory=dict)

    @property
    def ok(self) -> bool:
        return not self.defects


def full_turn(c: Candidate) -> bool:
    """True if the crank turns a full revolution (Grashof with the crank shortest, or a double-crank; offset
    slider-crank with rod >= crank + |offset|)."""
    if c.kind == "slider_crank":
        return c.coupler >= c.crank + abs(c.offset) - 1e-12 * c.coupler
    links = np.array([c.crank, c.coupler, c.rocker, c.ground])
    s, l_ = links.min(), links.max()
    grashof = s + l_ <= links.sum() - s - l_ + 1e-12 * links.sum()
    return bool(grashof and (c.crank <= s * (1 + 1e-12) or c.ground <= s * (1 + 1e-12)))


def errors(c: Candidate, targets: Targets) -> tuple[float, float]:
    """(largest point error [m], largest angle error [rad]) at the candidate's crank angles (inf where it cannot
    close)."""
    phi = c.angles
    pos = ang = 0.0
    if targets.points is not None:
        e = np.abs(c.point(phi) - targets.points)
        pos = float(np.max(e)) if np.isfinite(e).all() else np.inf
    if targets.coupler_angles is not None:
        e = np.abs(wrap(c.coupler_angle(phi) - targets.coupler_angles))
        ang = max(ang, float(np.max(e)) if np.isfinite(e).all() else np.inf)
    if targets.outputs is not None:
        out = c.output_angle(phi)
        if c.kind == "slider_crank":
            e = np.abs(out - targets.outputs)
            pos = max(pos, float(np.max(e)) if np.isfinite(e).all() else np.inf)
        else:
            e = np.abs(wrap(out + c.output_offset - targets.outputs))
            ang = max(ang, float(np.max(e)) if np.isfinite(e).all() else np.inf)
    return pos, ang


def _other_branch_closer(c: Candidate, targets: Targets) -> bool:
    """True if at some precision position the other assembly of the closure meets the target better."""
    other = replace(c, branch=-c.branch)
    for j in range(c.angles.size):
        one = replace(c, angles=c.angles[j:j + 1])
        two = replace(other, angles=c.angles[j:j + 1])
        pick = [None if v is None else v[j:j + 1] for v in (targets.points, targets.coupler_angles, targets.outputs)]
        t = Targets(points=pick[0], coupler_angles=pick[1], outputs=pick[2], scale=targets.scale)
        e1, e2 = errors(one, t), errors(two, t)
        if e2[0] / targets.scale + e2[1] < e1[0] / targets.scale + e1[1] - 1e-12:
            return True
    return False


def check(c: Candidate, targets: Targets, *, transmission_limit: float = np.radians(30.0),
          need_full_turn: bool = True, tolerance: float = 1e-9, samples: int = 361) -> Report:
    """The defects of ``c`` for ``targets``: see the module. ``tolerance`` is relative to ``targets.scale`` for
    points and in radians for angles."""
    defects = []
    turns = full_turn(c)
    pos, ang = errors(c, targets)
    _, _, closes = c.joints(c.angles)
    if not np.all(closes):
        defects.append("assembly: cannot be assembled at every precision position")
    elif (pos > tolerance * targets.scale or ang > tolerance) and _other_branch_closer(c, targets):
        defects.append("branch: the positions lie on different branches of the closure")
    if c.angles.size >= 3:
        steps = np.mod(c.direction * (c.angles - c.angles[0]), TWO_PI)[1:]
        if np.any(np.diff(steps) <= 0):
            defects.append("order: the crank meets the positions out of the task's order")
    if need_full_turn and not turns:
        defects.append("Grashof: the crank cannot turn a full revolution")
    phi = np.linspace(0.0, TWO_PI, samples) if turns else c.working_angles(samples)
    _, _, ok = c.joints(phi)
    if not turns and not np.all(ok):
        defects.append("assembly: the linkage cannot move between the positions without being taken apart")
    mu = c.transmission(phi)
    worst = float(np.nanmin(mu)) if np.isfinite(mu).any() else 0.0
    if worst < transmission_limit:
        defects.append(f"transmission: the transmission angle falls to {np.degrees(worst):.1f} deg "
                       f"(limit {np.degrees(transmission_limit):.0f} deg)")
    return Report(tuple(defects), pos, ang, worst, turns)


def check_all(cands: list[Candidate], targets: Any, **options: Any) -> list[Report]:
    """:func:`check` of every candidate (``targets`` one :class:`Targets` or one per candidate)."""
    ts = targets if isinstance(targets, list) else [targets] * len(cands)
    return [check(c, t, **options) for c, t in zip(cands, ts, strict=True)]
