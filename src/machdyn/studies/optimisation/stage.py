"""The ``[optimise]`` capability: the stage function, its labels and its check."""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

import numpy as np

from ...errors import ProblemFileError
from ...kinds import catalogue
from ...limits import held_values_error
from ...pipeline import Capability, Outcome, StageContext
from ...problem.build import crank_angles
from ...results.catalogue import find, label
from ...results.labels import Label
from ..capability_population import population_keys
from ..exploration.execution import current
from ..per_design import where_designs_ran
from ..views import analysed, design_problem
from .evaluate import result_unit
from .objectives import direction_advice
from .pareto import spacing
from .result import NoFeasibleDesign, OptimiseResult
from .schema import OptimiseSpec
from .study import optimise, setup

#: The status columns of the population evaluator: checks of the best design, not results to report.
STATUS_KEYS = ("assembled", "regular", "assembled_fraction", "dead_point", "branch_change", "near_dead_point",
               "poor_transmission")

LABELS = {
    "optimise.evaluations": Label("Optimisation: designs evaluated", over="count", better="none"),
    "optimise.generations": Label("Optimisation: generations", over="count", better="none"),
    "optimise.designs_per_second": Label("Optimisation: designs evaluated per second", "1/s", over="scalar",
                                         better="higher"),
    "optimise.converged": Label("Optimisation: converged (1 yes, 0 no)", over="scalar", better="true"),
    "optimise.verified": Label("Optimisation: best design verified feasible (1 yes, 0 no)", over="scalar",
                               better="true"),
    "optimise.front_size": Label("Optimisation: designs on the Pareto front", over="count", better="none"),
    "optimise.front_spacing": Label("Optimisation: spacing of the Pareto front (Schott; 0 = evenly spread)",
                                    over="scalar", better="lower"),
    "optimise.front_hypervolume": Label("Optimisation: hypervolume of the final front (normalised)", over="scalar",
                                        better="higher"),
    "optimise.feasible": Label("Optimisation: a feasible design was found (1 yes, 0 no)", over="scalar", better="true"),
    "optimise.improved": Label("Optimisation: better than the design as given (1 yes, 0 no)", over="scalar",
                               better="true"),
}


def _text(key: str) -> str:
    """The catalogue's text of a result, in lower case after "Best design: "."""
    found = label(key)
    if found is None:  # a capability's result (optimised design by design)
        declared = find(key, catalogue())
        found = declared[0].label() if declared is not None and not declared[0].is_pattern else None
    text = found.text if found is not None else key
    return text[:1].lower() + text[1:]


def check(problem: Any, table: OptimiseSpec, source: str | None = None) -> list[tuple[str, str]]:
    """The table's mistakes that need the problem: unknown quantities and results, bounds in wrong units."""
    if getattr(problem, "mechanism", None) is not None:  # a linkage population holds designs x crank angles
        too_many = held_values_error(table.population, crank_angles(problem).size)
        if too_many is not None:
            return [("optimise.population", too_many)]
    try:
        setup(problem, table)
    except ProblemFileError as exc:
        return list(exc.problems)
    return []


def run(ctx: StageContext) -> Outcome:
    """Optimise the problem's design as its ``[optimise]`` table says; the best design's variables and results,
    the search's history (``optimise_history.csv``) and, for several objectives, the front
    (``optimise_front.csv``)."""
    try:
        result = optimise(ctx.problem, ctx.table, ctx.run_design)
    except NoFeasibleDesign as exc:
        # A well-formed table whose constraints no design within the bounds meets: the design fails its
        # checks (the rest of the run is still written), with the tightest constraints listed.
        return Outcome(results=None, scalars={"optimise.feasible": 0.0}, summary=("optimise.feasible",),
                       failed_checks=(str(exc),), warnings=tuple(_where_designs_ran(ctx)))
    if ctx.mechanism is not None:  # a linkage: the nominal design and the optimum played side by side
        result = with_views(ctx.problem, result)
    mech = ctx.mechanism
    scalars: dict[str, Any] = {
        "optimise.feasible": 1.0,
        "optimise.evaluations": float(result.evaluations),
        "optimise.generations": float(len(result.history.generation)),
        "optimise.designs_per_second": float(result.designs_per_second),
        "optimise.converged": 1.0 if result.converged else 0.0,
        "optimise.verified": 1.0 if result.verified else 0.0,
    }
    labels: dict[str, Label] = {}
    summary: list[str] = []
    for name, value, unit, shown in zip(result.names, result.x, result.units, result.display_units, strict=True):
        key = f"optimise.best.variable.{name}"
        scalars[key] = float(value)
        labels[key] = Label(f"Best design: {name}", unit, shown)
        summary.append(key)
    asked = [o.result for o in result.objectives] + [c.result for c in result.constraints]
    units = {o.result: o.unit for o in (*result.objectives, *result.constraints)}  # a capability's result's too
    # The results asked for (in the summary) and the other results of the best design that were computed.
    computed = [k for k in result.results if k not in STATUS_KEYS]
    for res_key in dict.fromkeys(asked + computed):
        key = f"optimise.best.{res_key}"
        value = float(result.results.get(res_key, math.nan))
        if res_key not in asked and not math.isfinite(value):
            continue
        scalars[key] = value
        labels[key] = Label(f"Best design: {_text(res_key)}", units.get(res_key) or result_unit(res_key, mech))
        if res_key in asked:
            summary.append(key)
    summary += ["optimise.evaluations", "optimise.converged", "optimise.verified"]
    if result.improved is not None:  # one objective and a start inside the bounds: did the search beat it?
        scalars["optimise.improved"] = 1.0 if result.improved else 0.0
        summary.append("optimise.improved")
    h = result.history
    series: dict[str, Any] = {"optimise_history": {
        "generation": (h.generation.astype(float), ""),
        "evaluations": (h.evaluations.astype(float), ""),
        "best_cost": (h.best, ""),
        "feasible_share": (h.feasible_share, ""),
    }}
    if h.hypervolume is not None:
        series["optimise_history"]["hypervolume"] = (h.hypervolume, "")
    if result.front_x is not None and result.front_f is not None:
        scalars["optimise.front_size"] = float(len(result.front_x))
        summary.append("optimise.front_size")
        gap = spacing(result.front_f)
        if math.isfinite(gap):
            scalars["optimise.front_spacing"] = gap
            summary.append("optimise.front_spacing")
        if h.hypervolume is not None and np.isfinite(h.hypervolume[-1]):
            scalars["optimise.front_hypervolume"] = float(h.hypervolume[-1])
        for j, o in enumerate(result.objectives):  # the front's extent in each objective: its spread
            unit = "" if o.sense == "target" else o.unit
            for end, value in (("min", np.min(result.front_f[:, j])), ("max", np.max(result.front_f[:, j]))):
                key = f"optimise.front.{o.result}.{end}"
                scalars[key] = float(value)
                labels[key] = Label(f"Pareto front: {_text(o.result)}, {end}", unit)
                summary.append(key)
        columns: dict[str, Any] = {}
        for i, (name, unit) in enumerate(zip(result.names, result.units, strict=True)):
            columns[name] = (result.front_x[:, i], unit)
        for j, o in enumerate(result.objectives):
            columns[o.result] = (result.front_f[:, j], "" if o.sense == "target" else o.unit)
        series["optimise_front"] = columns
    warnings = list(result.warnings) + _where_designs_ran(ctx)
    failed = () if result.verified else (
        "The best design, rebuilt from its own problem file, breaks a constraint.",)
    return Outcome(results=result, scalars=scalars, labels=labels, series=series, summary=tuple(summary),
                   files={"best_design.toml": str(result.problem_text)},
                   warnings=tuple(warnings), failed_checks=failed)


def _where_designs_ran(ctx: StageContext) -> list[str]:
    """With ``--workers``: a line saying that the results no population form gives ran per design on the
    workers (as an exploration says where its partitions ran)."""
    workers = current().workers or 1
    if workers <= 1:
        return []
    try:
        ev = setup(ctx.problem, ctx.table, ctx.run_design)
    except ProblemFileError:
        return []
    varied = [v.path for v in ev.space.variables if v.path is not None] + [f.path for f in ev.space.formulas]
    at_once = population_keys(ctx.problem, ev.per_design_wanted, varied)
    per_design = sorted(k for k in ev.per_design_wanted if k not in at_once)
    if not per_design:
        return []
    return [f"{', '.join(per_design)}: no population form, evaluated {where_designs_ran(workers)} (--workers)."]


def with_views(problem: Any, result: Any) -> Any:
    """The result with the nominal design and the optimum analysed for playback, side by side."""

    views = (analysed(design_problem(problem, {}), "nominal"),
             analysed(result.problem, "optimum", 0) if result.problem is not None else None)
    return replace(result, views=tuple(v for v in views if v is not None))


CAPABILITY = Capability(
    table="optimise",
    schema=OptimiseSpec,
    run=run,
    step="design optimisation",
    labels=LABELS,
    report="machdyn.report.optimise:sections",
    kinds=("mechanism", "shaft_line", "cam"),
    check=check,
    result_type=OptimiseResult,
    advise=lambda problem, table: direction_advice(table.objectives, catalogue()),
)


def best_design_text(outcome: Outcome) -> str:
    """The best design of an ``[optimise]`` outcome as a problem file ready to run."""
    return str(outcome.results.problem_text)


def front_array(outcome: Outcome) -> np.ndarray | None:
    """The Pareto front's objective values (designs x objectives, SI), or None for one objective."""
    return outcome.results.front_f
