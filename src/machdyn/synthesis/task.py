"""A ``[synthesis]`` table carried out: the candidates of its task, their defects, their dynamics and their rank."""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from ..errors import InputError
from .candidate import Candidate
from .defects import Report, Targets, check
from .function import (
    FUNCTIONS,
    chebyshev_spacing,
    freudenstein,
    freudenstein_least_squares,
    function_angles,
    output_error,
)
from .motion import motion_candidates
from .path import path_candidates
from .quick_return import crank_rocker, slider_crank
from .rank import QUANTITIES, Drive, evaluate, order


@dataclass(frozen=True)
class SynthesisResult:
    """Candidates (best first), their defect reports and per-candidate quantities, what the task asked for and
    how the candidates were run."""

    task: str
    candidates: list[Candidate]
    reports: list[Report]
    values: dict[str, np.ndarray]
    targets: Targets
    drive: Drive
    ranked_by: str
    curve: dict = field(default_factory=dict)   # what the report draws as the task (function, swing, ...)

    @property
    def best(self) -> Candidate | None:
        return self.candidates[0] if self.candidates else None

    @property
    def defect_free(self) -> int:
        return sum(r.ok for r in self.reports)


def _function_sets(spec: Any, x0: float, x1: float) -> list[tuple[str, np.ndarray]]:
    n = spec.precision_points
    sets = [("chebyshev", chebyshev_spacing(x0, x1, n))]
    if spec.spacing == "even" or n > 3:
        sets = [("even", np.linspace(x0, x1, n)), *sets]
    return sets


def placements(count: int, seed: int = 0) -> np.ndarray:
    """``count`` (input, output) shifts [rad] of the task's angle ranges: (0, 0) first (the ranges as given),
    then a scrambled grid over the whole turn of each (the designer fixes the spans, not where they start)."""
    if count <= 1:
        return np.zeros((1, 2))
    rng = np.random.default_rng(seed)
    side = int(np.ceil(np.sqrt(count - 1)))
    grid = (np.stack(np.meshgrid(np.arange(side), np.arange(side), indexing="ij"), -1).reshape(-1, 2) + 0.5) / side
    grid = 2.0 * np.pi * grid[rng.permutation(len(grid))[: count - 1]]
    return np.vstack([np.zeros((1, 2)), grid])


def _function_task(spec: Any) -> tuple[list[Candidate], list[Targets], dict]:
    """Freudenstein candidates of a function task. With ``candidates`` given in the file, the placement of the
    input and output ranges is searched as well (:func:`placements`); each candidate keeps its shifts in
    ``free`` ("input_shift", "output_shift" [rad]) and its Freudenstein constants ("K1", "K2", "K3")."""
    f = FUNCTIONS[spec.function]
    x0, x1 = spec.x_range
    ground = 0.1 if spec.ground is None else spec.ground
    dense = np.linspace(x0, x1, 201)
    t2d, t4d = function_angles(f, spec.x_range, spec.input_range, spec.output_range, dense)
    search = "candidates" in spec.model_fields_set
    n = spec.precision_points
    per_place = len(_function_sets(spec, x0, x1)) + (1 if n == 3 else 0)
    shifts = placements(max(1, -(-spec.candidates // per_place)), spec.seed) if search else np.zeros((1, 2))
    cands, targets = [], []
    for s_in, s_out in shifts:
        moved = {"input_shift": float(s_in), "output_shift": float(s_out)}
        for name, xs in _function_sets(spec, x0, x1):
            t2, t4 = function_angles(f, spec.x_range, spec.input_range, spec.output_range, xs)
            t2, t4 = t2 + s_in, t4 + s_out
            try:
                c = freudenstein(t2, t4, ground) if n == 3 else freudenstein_least_squares(t2, t4, ground)
            except InputError:
                continue
            cands.append(replace(c, free={**c.free, "spacing": name, **moved}))
            targets.append(Targets(outputs=t4, scale=ground))
        if n == 3:  # the many-point least-squares fit over the whole range, beside the precision-point ones
            try:
                c = freudenstein_least_squares(t2d[::10] + s_in, t4d[::10] + s_out, ground)
                cands.append(replace(c, free={**c.free, **moved}))
                targets.append(Targets(outputs=np.asarray(t4d[::10] + s_out), scale=ground))
            except InputError:
                pass
    if search:
        cands, targets = cands[: spec.candidates], targets[: spec.candidates]
    return cands, targets, {"theta2": t2d, "theta4": t4d}


def shifted_error(c: Candidate, theta2: Any, theta4: Any) -> np.ndarray:
    """:func:`output_error` [rad] of a function candidate over the task's angles moved by its own placement."""
    return output_error(c, np.asarray(theta2) + c.free.get("input_shift", 0.0),
                        np.asarray(theta4) + c.free.get("output_shift", 0.0))


def candidates_of(spec: Any) -> tuple[list[Candidate], list[Targets], dict]:
    """The candidates of the table's task, the targets each is checked against, and what the report draws."""
    n = spec.candidates
    if spec.task == "function":
        return _function_task(spec)
    if spec.task in ("quick_return", "slider_quick_return"):
        per_side = max(1, (n + 1) // 2)
        grid = (np.arange(per_side) + 0.5) / per_side
        cands = []
        for side in (1, -1):
            for pos in grid:
                if spec.task == "quick_return":
                    cands.append(crank_rocker(spec.swing, spec.time_ratio, spec.rocker, position=float(pos),
                                              side=side, start=spec.start, slow_stroke=spec.slow_stroke))
                else:
                    cands.append(slider_crank(spec.stroke, spec.time_ratio, position=float(pos), side=side,
                                              slow_stroke=spec.slow_stroke))
        cands = cands[:n]
        if spec.task == "quick_return":
            psi1 = np.pi / 2 - spec.swing / 2 if spec.start is None else spec.start
            t = Targets(outputs=np.array([psi1, psi1 + spec.swing]), scale=spec.rocker)
            return cands, [t] * len(cands), {"swing": (psi1, psi1 + spec.swing), "rocker": spec.rocker}
        ts = [Targets(outputs=c.output_angle(c.angles)[0] + np.array([0.0, spec.stroke]), scale=spec.stroke)
              for c in cands]
        return cands, ts, {"stroke": spec.stroke}
    if spec.task == "motion":
        pos = np.array(spec.positions, dtype=float)
        p = pos[:, 0] + 1j * pos[:, 1]
        pivots = [None if v is None else complex(v[0], v[1]) for v in (spec.crank_pivot, spec.rocker_pivot)]
        cands = motion_candidates(p, pos[:, 2], count=n, seed=spec.seed, max_length=spec.max_length,
                                  crank_pivot=pivots[0], rocker_pivot=pivots[1])
        t = Targets(points=p, coupler_angles=pos[:, 2], scale=_size(p))
        return cands, [t] * len(cands), {"points": p, "angles": pos[:, 2]}
    pts = np.array(spec.points, dtype=float)
    p = pts[:, 0] + 1j * pts[:, 1]
    timing = np.array(spec.timing, dtype=float) if spec.timing else None
    cands = path_candidates(p, timing=timing, count=n, seed=spec.seed, seeds=min(4 * n, 16) if p.size > 3 else None,
                            max_length=spec.max_length, transmission_limit=spec.transmission_limit + np.radians(2.0),
                            full_turn=spec.full_turn)
    t = Targets(points=p, scale=_size(p))
    return cands, [t] * len(cands), {"points": p}


def _size(p: np.ndarray) -> float:
    span = float(np.max(np.abs(p - p.mean()))) if p.size > 1 else 0.0
    return span if span > 0 else 1.0


def synthesise(spec: Any) -> SynthesisResult:
    """Carry out a validated ``[synthesis]`` table (:class:`~machdyn.synthesis.schema.SynthesisSpec`)."""
    cands, targets, curve = candidates_of(spec)
    if not cands:
        raise InputError(f"The task '{spec.task}' gave no linkage within the limits (max_length, the sampled free "
                         "choices): widen them or change the task.")
    turn = spec.full_turn and spec.task != "function"
    reports = [check(c, t, transmission_limit=spec.transmission_limit, need_full_turn=turn)
               for c, t in zip(cands, targets, strict=True)]
    r = spec.ranking
    drive = Drive(speed=r.speed, linear_density=r.linear_density,
                  load=r.output_force if spec.task == "slider_quick_return" else r.output_torque,
                  positions=r.positions, full_turn=spec.full_turn, gravity=r.gravity,
                  speed_fluctuation=r.speed_fluctuation)
    values = evaluate(cands, reports, drive)
    if spec.task == "function":  # the structural error over the whole range, not only at the points
        for i, c in enumerate(cands):
            e = np.abs(shifted_error(c, curve["theta2"], curve["theta4"]))
            values["error"][i] = float(np.max(e)) if np.isfinite(e).all() else np.inf
    idx = order(values, reports, r.by)
    return SynthesisResult(
        task=spec.task, candidates=[cands[i] for i in idx], reports=[reports[i] for i in idx],
        values={k: np.asarray(v)[idx] for k, v in values.items()},
        targets=targets[idx[0]], drive=drive, ranked_by=r.by, curve=curve,
    )


__all__ = ["QUANTITIES", "SynthesisResult", "candidates_of", "placements", "shifted_error", "synthesise"]
