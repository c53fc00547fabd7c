"""A ``[sweep]`` of one quantity: its design variants analysed together in one vectorised call. The ``[sweep]``
capability (:mod:`machdyn.explore.stage`) runs it for one-quantity tables and an exploration for several."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import ProblemFileError
from ..pipeline import Outcome, StageContext
from ..results.labels import Label

#: Per-design summaries of a sweep: (attribute of SweepResult, label, SI unit).
SWEEP_SUMMARIES = (
    ("max_driving_torque", "Peak driving torque", "N*m"),
    ("rms_driving_torque", "RMS driving torque", "N*m"),
    ("mean_input_power", "Mean input power", "W"),
    ("max_shaking_force", "Peak shaking force", "N"),
    ("max_shaking_moment", "Peak shaking moment", "N*m"),
)

LABELS = {f"sweep.{attr}": Label(f"Sweep: {text.lower()} of each design", unit) for attr, text, unit in SWEEP_SUMMARIES}
LABELS |= {
    "sweep.regular": Label("Sweep: each design regular (assembles, no dead position)"),
    "sweep.designs": Label("Sweep: designs"),
    "sweep.regular_count": Label("Sweep: regular designs"),
}


@dataclass(frozen=True)
class SweepRun:
    """A sweep's plan (parameter, values) and the engine's per-design summaries."""

    plan: Any
    result: Any


def variants(problem: Any) -> tuple[Any, list[Any]]:
    """The expanded sweep of a problem and the engine model of each variant (every variant must build)."""
    from ..problem.build import build_mechanism
    from ..problem.sweep import expand_sweep

    plan = expand_sweep(problem)
    mechs, problems = [], []
    for i, variant in enumerate(plan.problems):
        try:
            mechs.append(build_mechanism(variant))
        except ProblemFileError as exc:
            problems += [(f"sweep (value {i + 1})", f"{path}: {msg}") for path, msg in exc.problems]
    if problems:
        raise ProblemFileError(problems)
    return plan, mechs


def check(problem: Any, _table: Any, source: str | None = None) -> list[tuple[str, str]]:
    from ..limits import held_values_error
    from ..problem.build import crank_angles

    table = problem.sweep
    count = len(table.values) if table.values is not None else (table.count or 0)
    too_many = held_values_error(count, crank_angles(problem).size)
    if too_many is not None:  # refused before the variants are built
        return [("sweep.values" if table.values is not None else "sweep.count", too_many)]
    try:
        variants(problem)
    except ProblemFileError as exc:
        return list(exc.problems)
    return []


def run_sweep(problem: Any) -> SweepRun:
    """The design variants of a problem's ``[sweep]``, analysed together."""
    from ..linkage import stack_designs, sweep
    from .linkage_run import crank_range

    plan, mechs = variants(problem)
    angles, _, _ = crank_range(problem)
    speeds = np.array([v.drive.speed for v in plan.problems])
    accels = np.array([v.drive.acceleration for v in plan.problems])
    speed: Any = speeds if np.ptp(speeds) > 0 else float(speeds[0])
    accel: Any = accels if np.ptp(accels) > 0 else float(accels[0])
    if np.ndim(speed) and np.size(speed) == np.size(angles):
        raise ProblemFileError([("sweep", "a sweep of the drive needs a number of values different from "
                                          f"drive.positions ({np.size(angles)}); got as many")])
    about = tuple(problem.output.shaking_moment_about)
    result = sweep(stack_designs(mechs), angles, speed, accel, shaking_about=about)
    return SweepRun(plan, _per_variant(result, len(plan.problems)))


def _per_variant(result: Any, n: int) -> Any:
    """The summaries with one entry per variant: variants that are all alike stack into one design."""
    from dataclasses import fields, replace

    if np.size(result.regular) == n:
        return result

    def spread(values: Any) -> np.ndarray:
        return np.broadcast_to(np.asarray(values).ravel(), (n,)).copy()

    changes: dict[str, Any] = {f.name: spread(getattr(result, f.name)) for f in fields(result)
                               if isinstance(getattr(result, f.name), np.ndarray)}
    changes["max_joint_force"] = {k: spread(v) for k, v in result.max_joint_force.items()}
    return replace(result, **changes)


def run(ctx: StageContext) -> Outcome:
    done = run_sweep(ctx.problem)
    plan, res = done.plan, done.result
    unit = plan.display_unit
    regular = np.asarray(res.regular, dtype=bool)
    values: dict[str, Any] = {
        f"sweep.{plan.parameter}": [float(v) for v in plan.values_display],
        "sweep.regular": [bool(v) for v in regular],
        "sweep.designs": float(regular.size),
        "sweep.regular_count": float(regular.sum()),
    }
    labels = {f"sweep.{plan.parameter}": Label(f"Sweep: values of {plan.parameter}", unit, unit)}
    for attr, _label, _u in SWEEP_SUMMARIES:
        values[f"sweep.{attr}"] = [float(v) for v in getattr(res, attr)]
    summary = ["sweep.designs", "sweep.regular_count"]
    warnings = []
    if regular.any():
        for attr, text, u in (SWEEP_SUMMARIES[0], SWEEP_SUMMARIES[3]):
            data = np.where(regular, getattr(res, attr), np.inf)
            best = int(np.argmin(data))
            key = f"sweep.lowest_{attr}"
            values[key] = float(data[best])
            # Designs within round-off of the best tie: name them all rather than pick one arbitrarily.
            ties = np.flatnonzero(data <= data[best] + 1e-9 * max(abs(data[best]), 1e-300))
            at = ", ".join(f"{plan.values_display[i]:.6g}" for i in ties[:5]) + (" ..." if ties.size > 5 else "")
            where = (f"at {plan.parameter} = {at} {unit}" if ties.size == 1
                     else f"{ties.size} designs tie, at {plan.parameter} = {at} {unit}")
            labels[key] = Label(f"Sweep: lowest {text.lower()} ({where})", u)
            summary.append(key)
    else:
        warnings.append(f"No design of the sweep of {plan.parameter} is regular: each fails to assemble or passes "
                        "a dead position somewhere in the crank range.")
    columns: dict[str, tuple[Any, str]] = {
        plan.parameter: (np.asarray(plan.values_display, dtype=float), unit),
        "assembled": (np.asarray(res.assembled), ""),
        "regular": (regular, ""),
    }
    for attr, _label, u in SWEEP_SUMMARIES:
        columns[attr] = (getattr(res, attr), u)
    for joint, data in res.max_joint_force.items():
        columns[f"joint.{joint}.max_force"] = (data, "N")
    return Outcome(results=done, scalars=values, labels=labels, series={"sweep": columns}, summary=tuple(summary),
                   warnings=tuple(warnings))
