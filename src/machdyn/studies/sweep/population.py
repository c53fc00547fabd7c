"""A ``[sweep]`` of one quantity: its design variants analysed together in one vectorised call. The ``[sweep]``
capability (:mod:`machdyn.studies.sweep.stage`) runs it for one-quantity tables and an exploration for several."""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from ...errors import ProblemFileError
from ...limits import held_values_error
from ...linkage import stack_designs
from ...notebook import ShownInNotebook
from ...pipeline import Outcome, StageContext
from ...pipelines.linkage_run import crank_range
from ...problem.build import build_mechanism, crank_angles, harmonics_of
from ...results.catalogue import label
from ...results.labels import Label
from ...results.names import did_you_mean_result, results_to_choose
from ...results.population import FAULTS, result_names, result_unit, sweep_columns
from ..capability_population import population_keys as population_results_keys
from ..evaluator import PopulationEvaluator
from ..exploration.execution import current
from ..per_design import capability_results, where_designs_ran
from ..table import expand_sweep
from ..views import MAX_VIEWS, analysed, design_problem

#: The per-design results a sweep ranks its designs by in the summary (the lowest of each is named).
RANKED = ("driving_torque.max_abs", "frame_force.max")

LABELS = {
    "sweep.regular": Label("Sweep: each design regular (assembles, no dead point, branch change, near dead point "
                           "or poor transmission)", over="scalar", better="none"),
    "sweep.status": Label("Sweep: status of each design (regular or its first fault)", over="scalar", better="none"),
    "sweep.designs": Label("Sweep: designs", over="count", better="none"),
    "sweep.regular_count": Label("Sweep: regular designs", over="count", better="higher"),
    **{f"sweep.count.{fault.replace(' ', '_')}": Label(f"Sweep: designs whose first fault is: {fault}",
                                                       over="count", better="lower")
       for _flag, fault in FAULTS},
}


@dataclass(frozen=True)
class SweepRun(ShownInNotebook):
    """A sweep's plan (parameter, values) and the per-design columns (catalogue keys, SI; the status columns
    ``assembled``, ``regular``, ``status``... among them)."""

    plan: Any
    columns: dict[str, np.ndarray]
    units: dict[str, str]
    views: tuple = ()


def variants(problem: Any) -> tuple[Any, list[Any]]:
    """The expanded sweep of a problem and the engine model of each variant (every variant must build)."""
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
    table = problem.sweep
    count = len(table.values) if table.values is not None else (table.count or 0)
    too_many = held_values_error(count, crank_angles(problem).size)
    if too_many is not None:  # refused before the variants are built
        return [("sweep.values" if table.values is not None else "sweep.count", too_many)]
    try:
        _, mechs = variants(problem)
    except ProblemFileError as exc:
        return list(exc.problems)
    return unknown_columns(problem, mechs[0])


def unknown_columns(problem: Any, mech: Any) -> list[tuple[str, str]]:
    """The ``[sweep] columns`` that name no result of this mechanism or of the file's other tables (a capability's
    result, computed by a run of each variant), as (path, message)."""
    known = result_names(mech, getattr(problem.mechanism, "machine", None), harmonics_of(problem)) \
        + sorted(capability_results(problem))
    return [(f"sweep.columns[{i}]", f"'{key}' is not a result of this file{did_you_mean_result(key, known)} "
                                    f"({results_to_choose(key, known)})")
            for i, key in enumerate(problem.sweep.extra_columns) if key not in known]


def run_sweep(problem: Any, run_design: Any = None) -> SweepRun:
    """The design variants of a problem's ``[sweep]``, evaluated together by the population evaluator; the
    columns that are results of the file's other tables (a capability's, :mod:`machdyn.studies.per_design`)
    by ``run_design`` running each regular variant through the file's stages."""
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
    mech = stack_designs(mechs)
    machine = getattr(problem.mechanism, "machine", None)
    by_run = {k: u for k, u in capability_results(problem).items() if k in problem.sweep.extra_columns}
    wanted = sweep_columns(mech, machine, extra=tuple(k for k in problem.sweep.extra_columns if k not in by_run))
    evaluator = PopulationEvaluator(angles, speed, accel, about, machine, problem.sweep.transmission_limit,
                                    run_design=run_design, problem=problem, varied=(plan.parameter,),
                                    workers=current().workers or 1)
    per_design = by_run if run_design is not None else {}
    columns = evaluator(mech, wanted, len(plan.problems), per_design, plan.problems.__getitem__)
    units = {k: per_design[k] if k in per_design else result_unit(k, mech) for k in columns}
    return SweepRun(plan, columns, units)


def _where_columns_ran(problem: Any, run_design: Any) -> list[str]:
    """With ``--workers``: a line saying that the columns no population form gives ran per design on them."""
    workers = current().workers or 1
    if workers <= 1 or run_design is None:
        return []
    by_run = [k for k in capability_results(problem) if k in problem.sweep.extra_columns]
    if not by_run:
        return []
    at_once = population_results_keys(problem, by_run)
    per_design = sorted(k for k in by_run if k not in at_once)
    if not per_design:
        return []
    return [f"{', '.join(per_design)}: no population form, evaluated {where_designs_ran(workers)} (--workers)."]


def _shown(values: np.ndarray) -> list:
    return [v if isinstance(v, str | bool) else float(v) for v in np.asarray(values).tolist()]


def _played(done: SweepRun) -> SweepRun:
    """The sweep with up to :data:`~machdyn.studies.views.MAX_VIEWS` regular designs, evenly spread
    over the swept values, analysed for playback."""

    plan = done.plan
    regular = np.flatnonzero(np.asarray(done.columns["regular"], dtype=bool))
    if not regular.size:
        return done
    chosen = regular[np.unique(np.linspace(0, regular.size - 1, min(MAX_VIEWS, regular.size)).round().astype(int))]
    views = []
    for i in chosen:
        label = f"{plan.parameter} = {plan.values_display[i]:.6g} {plan.display_unit}"
        view = analysed(design_problem(plan.problems[i], {}), label, int(i))
        if view is not None:
            views.append(view)
    return replace(done, views=tuple(views))


def run(ctx: StageContext) -> Outcome:
    done = _played(run_sweep(ctx.problem, ctx.run_design))
    plan, cols = done.plan, done.columns
    unit = plan.display_unit
    regular = np.asarray(cols["regular"], dtype=bool)
    values: dict[str, Any] = {
        f"sweep.{plan.parameter}": [float(v) for v in plan.values_si],
        "sweep.regular": [bool(v) for v in regular],
        "sweep.status": [str(v) for v in cols["status"]],
        "sweep.designs": float(regular.size),
        "sweep.regular_count": float(regular.sum()),
    }
    labels = {f"sweep.{plan.parameter}": Label(f"Sweep: values of {plan.parameter}", plan.si_unit, unit)}
    units: dict[str, str] = {}
    for key, data in cols.items():
        if key in ("regular", "status") or key.startswith("sweep."):
            continue
        values[f"sweep.{key}"] = _shown(data)
        found = label(key, done.units.get(key))
        text = found.text if found is not None else key
        labels[f"sweep.{key}"] = Label(f"Sweep: {text[:1].lower() + text[1:]} of each design",
                                       done.units.get(key, ""), found.display if found is not None else None)
    summary = ["sweep.designs", "sweep.regular_count"]
    status = np.asarray(cols["status"]).astype(str)
    for _flag, fault in FAULTS:
        key = f"sweep.count.{fault.replace(' ', '_')}"
        values[key] = float(np.count_nonzero(status == fault))
        if values[key]:
            summary.append(key)
    warnings = _where_columns_ran(ctx.problem, ctx.run_design)
    if regular.any():
        for key in RANKED:
            data = np.where(regular, cols[key], np.inf)
            best = int(np.argmin(data))
            out = f"sweep.lowest_{key}"
            values[out] = float(data[best])
            # Designs within round-off of the best tie: name them all rather than pick one arbitrarily.
            ties = np.flatnonzero(data <= data[best] + 1e-9 * max(abs(data[best]), 1e-300))
            at = ", ".join(f"{plan.values_display[i]:.6g}" for i in ties[:5]) + (" ..." if ties.size > 5 else "")
            where = (f"at {plan.parameter} = {at} {unit}" if ties.size == 1
                     else f"{ties.size} designs tie, at {plan.parameter} = {at} {unit}")
            text = label(key).text  # type: ignore[union-attr]
            labels[out] = Label(f"Sweep: lowest {text[:1].lower() + text[1:]} ({where})", done.units[key])
            summary.append(out)
    else:
        warnings.append(f"No design of the sweep of {plan.parameter} is regular: each fails to assemble, passes or "
                        "nears a dead point, changes branch or transmits poorly somewhere in the crank range "
                        "(see sweep.status).")
    columns: dict[str, tuple[Any, str]] = {  # SI throughout, as every other column
        plan.parameter: (np.asarray(plan.values_si, dtype=float), plan.si_unit),
    }
    for key, data in cols.items():
        columns[key] = (data, done.units.get(key, ""))
    return Outcome(results=done, scalars=values, labels=labels, units=units, series={"sweep": columns},
                   summary=tuple(summary), warnings=tuple(warnings))
