"""The ``[sweep]`` capability: a one-quantity sweep analysed as one stacked model (as before), or a design-space
exploration of several quantities written to Parquet, with its best designs in the summary and the report."""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import numpy as np

from ...errors import ProblemFileError
from ...pipeline import Capability, Outcome, StageContext
from ...results.catalogue import find, label
from ...results.labels import Label
from ..exploration.execution import workers_error
from ..exploration.run import Exploration, explore, plan_exploration, store_in_file
from ..exploration.sampling import is_power_of_two
from ..table import SweepSpec
from ..views import MAX_VIEWS, views_of
from . import population as one_quantity
from . import runs as sweep_runs

LABELS = dict(one_quantity.LABELS) | {
    "sweep.assembled_count": Label("Sweep: designs that assemble at every crank angle", over="count", better="higher"),
    "sweep.best": Label("Sweep: best design number", over="scalar", better="none"),
}


def check(problem: Any, table: Any, source: str | None = None) -> list[tuple[str, str]]:
    """Every mistake of the table that its schema cannot see: paths, units and signs of the values, designs
    that cannot be built, the objective; in a file with no linkage (a cam, a shaft line), the checks of a sweep
    run variant by variant (:mod:`machdyn.studies.sweep.runs`)."""
    if _by_runs(problem):
        return sweep_runs.check(problem, table)
    if not table.is_exploration:
        return one_quantity.check(problem, table)
    problems: list[tuple[str, str]] = []
    if table.workers is not None and workers_error(table.workers):
        problems.append(("sweep.workers", str(workers_error(table.workers))))
    try:
        store_in_file(problem, source)
    except ProblemFileError as exc:
        problems += exc.problems
    try:
        plan_exploration(problem)
    except ProblemFileError as exc:
        problems += exc.problems
    return problems


def run(ctx: StageContext) -> Outcome:
    """The sweep of ``ctx.problem``: one quantity as before, or an exploration
    (:func:`machdyn.studies.exploration.explore`) with the execution settings in force (``--workers``,
    ``--scheduler``, the output folder); in a file with no linkage (a cam, a shaft line), each variant run whole
    through the file's stages."""
    if _by_runs(ctx.problem):
        return sweep_runs.run(ctx)
    if not ctx.table.is_exploration:
        return one_quantity.run(ctx)
    return outcome(played(explore(ctx.problem, source=ctx.source, run_design=ctx.run_design)))


def _by_runs(problem: Any) -> bool:
    """True for a file with no linkage population (a cam, a shaft line): its variants are run one by one."""
    return getattr(problem, "mechanism", None) is None


def played(done: Any) -> Any:
    """The exploration with its nominal design and its best designs analysed one by one for playback."""

    best = done.digest.best
    count = min(MAX_VIEWS - 1, len(best.get("design", [])))
    names = done.plan.space.names
    designs = {int(best["design"][r]): {n: float(best[n][r]) for n in names} for r in range(count)}
    labels = {d: ("best design" if r == 0 else f"design {d}") for r, d in enumerate(designs)}
    return replace(done, views=views_of(done.plan.problem, designs, labels=labels))


def outcome(done: Any) -> Outcome:
    """The results of an exploration: counts, the best design's objective and quantities, the best designs as a
    table (``sweep_best.csv``); every design is in the Parquet folder ``done.store``."""
    plan, digest = done.plan, done.digest
    goal = plan.objective
    unit_of = {k: u for k, (u, _) in done.units.items()}
    values: dict[str, Any] = {
        "sweep.designs": float(digest.designs),
        "sweep.assembled_count": float(digest.assembled),
        "sweep.regular_count": float(digest.regular),
    }
    labels: dict[str, Label] = {}
    summary = ["sweep.designs", "sweep.assembled_count", "sweep.regular_count"]
    warnings = list(done.notes)
    if plan.space.method == "sobol" and not is_power_of_two(plan.space.size):
        warnings.append(f"A Sobol' sample keeps its balance properties for 2^m designs; {plan.space.size} is not "
                        "a power of 2.")
    if digest.best and digest.best["design"].size:
        best = {k: v[0] for k, v in digest.best.items()}
        text = _text(goal)
        values["sweep.best"] = float(best["design"])
        values[f"sweep.best.{goal}"] = float(best[goal])
        labels[f"sweep.best.{goal}"] = Label(f"Sweep: best design, {text} (objective)", unit_of[goal])
        summary += ["sweep.best", f"sweep.best.{goal}"]
        for q in plan.space.quantities:
            key = f"sweep.best.{q.parameter}"
            values[key] = float(best[q.parameter])
            labels[key] = Label(f"Sweep: best design, {q.parameter}", q.si_unit, q.display_unit)
            summary.append(key)
        for name in digest.best:
            found = find(name)
            if name != goal and found is not None and found[0].group not in ("", "status") \
                    and found[0].kind == "number":
                values[f"sweep.best.{name}"] = float(best[name])
                labels[f"sweep.best.{name}"] = Label(f"Sweep: best design, {_text(name)}", unit_of[name])
    else:
        warnings.append(f"No design of the exploration of {', '.join(plan.space.names)} is regular: each fails to "
                        "assemble, passes or nears a dead point, changes branch or transmits poorly somewhere in the "
                        "crank range (see the status column).")
    columns = {name: (np.asarray(data), unit_of.get(name, "")) for name, data in digest.best.items()}
    return Outcome(results=done, scalars=values, labels=labels, series={"sweep_best": columns} if columns else {},
                   summary=tuple(summary), warnings=tuple(warnings))


def _text(key: str) -> str:
    found = label(key)
    text = found.text if found is not None else key
    return text[:1].lower() + text[1:]


CAPABILITY = Capability(
    table="sweep",
    schema=SweepSpec,
    run=run,
    step="design sweep",
    labels=LABELS,
    report="machdyn.report.explore:sections",
    kinds=("mechanism", "cam", "shaft_line"),
    check=check,
    result_type=(one_quantity.SweepRun, Exploration),
)
