"""A one-quantity ``[sweep]`` in a file of a kind with no linkage population — a cam, a shaft line: each variant
is written out and read back (every field's rule checked as for a file) and run whole through the file's own
stages, as ``[optimise]`` runs its designs (:mod:`machdyn.studies.optimisation.by_runs`). The columns are
results the file's tables declare in the catalogue, named by their keys (``cam.max_pressure_angle``,
``shaft.engine.primary_couple`` ...).

```toml
[sweep]
parameter = "cam.base_radius"
start = "30 mm"
stop = "60 mm"
count = 7
columns = ["cam.max_pressure_angle", "cam.min_pitch_curvature_radius"]
```

A variant that cannot be built (a value that breaks a rule of the file, a roller larger than the pitch curve's
smallest radius of curvature) or whose run fails has no values: its ``status`` says why, it is not counted as
regular and a warning names it. The table is ``sweep.csv``; the values are in results.json as lists, one value
per variant.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Any

import numpy as np

from ...errors import MachdynError, ProblemFileError
from ...kinds import KINDS, catalogue
from ...pipeline import Outcome, StageContext
from ...problem.paths import design_problem
from ...results.catalogue import find
from ...results.labels import Label
from ...results.names import did_you_mean_result, results_to_choose
from ..exploration.execution import announce_estimate, current
from ..kind_population import sweep_at_once
from ..per_design import (
    KnownResults,
    Portable,
    capability_results,
    run_in_parallel,
    unit_of,
    where_designs_ran,
)
from ..table import expand_sweep
from .population import SweepRun

#: A sweep that runs each variant whole takes at most this many variants (a cam's run takes about half a second).
MAX_VARIANTS = 1000

#: The status of a variant that was built, ran and reported every column asked for.
REGULAR = "regular"
#: The status of a variant that ran whole and reported every column but failed one of its design checks (a
#: motor overloaded, a pressure angle over its limit): its values are sound, the design is not acceptable.
FAILED_CHECK = "failed check"


def is_regular(status: str) -> bool:
    """Whether a variant's values are sound: it was built, ran and reported every column (its checks aside)."""
    return status == REGULAR or status.startswith(FAILED_CHECK)

#: Keys of ``[sweep]`` that only a linkage's sweep understands, and why.
LINKAGE_ONLY = {
    "min_transmission_angle": "is the threshold of a linkage's transmission angle",
    **{key: "is for an exploration of several quantities of a linkage" for key in
       ("quantities", "method", "samples", "seed", "partition", "objective", "scheduler", "workers", "store")},
}


@dataclass(frozen=True)
class RunSweep(SweepRun):
    """A sweep whose variants were each run whole: the plan, the columns asked for (``asked``, catalogue keys,
    SI), ``regular`` and ``status`` per variant."""

    asked: tuple[str, ...] = ()


def kind_name(problem: Any) -> str:
    """The main table of a validated problem (``cam``, ``shaft_line``), for messages."""
    fields = getattr(type(problem), "model_fields", {})
    return next((t for t in fields if t in KINDS and getattr(problem, t, None) is not None), "problem")


def _known(problem: Any) -> Any:
    return KnownResults(sorted(capability_results(problem)), lambda key: unit_of(key, problem) is not None)


def check(problem: Any, table: Any) -> list[tuple[str, str]]:
    """Every mistake of a ``[sweep]`` run variant by variant, each with its path: keys of a linkage's sweep,
    the parameter and its values (unit, sign), too many variants, and columns that no table of the file
    reports."""
    kind = kind_name(problem).replace("_", "-")
    problems: list[tuple[str, str]] = []
    for key, why in LINKAGE_ONLY.items():
        if getattr(table, key) is not None:
            problems.append((f"sweep.{key}", f"{key} {why}; a {kind} file's [sweep] varies one quantity "
                                             "(parameter = \"...\" with values = [...], or start, stop and count)"))
    count = len(table.values) if table.values is not None else int(table.count or 0)
    if count > MAX_VARIANTS:
        where = "sweep.values" if table.values is not None else "sweep.count"
        problems.append((where, f"a {kind} file's sweep runs each variant whole, at most {MAX_VARIANTS} of them; "
                                f"got {count}"))
    elif table.parameter is not None and not table.is_exploration:
        try:
            expand_sweep(problem)
        except ProblemFileError as exc:
            problems += exc.problems
    known = _known(problem)
    if not table.columns:
        problems.append(("sweep.columns", f"name the results to tabulate for each variant, such as columns = "
                                          f"[\"{known[0]}\"]; a {kind} file's results are {_some(known)}"))
    for i, key in enumerate(table.extra_columns):
        if key not in known:
            hint = f"{did_you_mean_result(key, known)} ({results_to_choose(key, known)})"
            problems.append((f"sweep.columns[{i}]", f"'{key}' is not a result of this {kind} file{hint}"))
    return problems


def _some(known: list[str]) -> str:
    shown = ", ".join(known[:8])
    return shown + (f" and {len(known) - 8} more (see docs/results.md)" if len(known) > 8 else "")


def _first(problems: list[tuple[str, str]]) -> str:
    path, message = problems[0]
    return message if not path or message.startswith(path) else f"{path}: {message}"


def _run_one(problem: Any, path: str, value: float, run_design: Any, asked: tuple[str, ...],
             row: dict[str, float]) -> str:
    """Run one variant, filling ``row`` with the values it reports; returns its status."""
    try:
        design = design_problem(problem, {path: value})
        values = run_design(design)
    except ProblemFileError as exc:
        return f"not built: {_first(exc.problems)}"
    except (MachdynError, ArithmeticError, ValueError) as exc:  # a variant the run refuses or cannot analyse
        return f"run failed: {exc}"
    missing = []
    for key in asked:
        v = values.get(key)
        if v is not None and np.ndim(v) == 0 and math.isfinite(float(v)):
            row[key] = float(v)
        else:
            missing.append(key)
    if missing:
        return f"not reported: {', '.join(missing)}"
    failed = getattr(values, "failed_checks", ())
    return f"{FAILED_CHECK}: {failed[0]}" if failed else REGULAR


def _variant(problem: Any, path: str, value: float, run_design: Any,
             asked: tuple[str, ...]) -> tuple[str, dict[str, float]]:
    """(status, values) of one variant: :func:`_run_one` as one call a worker process can make."""
    row: dict[str, float] = {}
    return _run_one(problem, path, value, run_design, asked, row), row


def _portable_variant(portable: Portable, path: str, value: float, run_design: Any,
                      asked: tuple[str, ...]) -> tuple[str, dict[str, float]]:
    """:func:`_variant` in a worker process, of the problem sent to it."""
    return _variant(portable.problem, path, value, run_design, asked)


def run_sweep(problem: Any, run_design: Any) -> RunSweep:
    """The variants of ``problem``'s ``[sweep]``, each run by ``run_design`` (a validated problem -> its results
    by key, SI): the columns asked for (NaN where a variant has no value), ``regular`` and ``status``."""
    if run_design is None:
        raise RuntimeError("a sweep run variant by variant needs a way to run a design (StageContext.run_design)")
    plan = expand_sweep(problem)
    asked = tuple(dict.fromkeys(problem.sweep.extra_columns))
    n = len(plan.problems)
    columns: dict[str, np.ndarray] = {key: np.full(n, math.nan) for key in asked}
    status = []
    progress = current().progress
    workers = current().workers or 1
    started = time.perf_counter()
    at_once = sweep_at_once(problem, plan.parameter, plan.values_si, asked) if asked else None
    # the kind's population form gives a variant at once; the others are run whole (on --workers processes)
    done: dict[int, tuple[str, dict[str, float]]] = {}
    whole = []
    for i in range(n):
        if at_once is not None and all(np.isfinite(at_once[k][i]) for k in asked):
            done[i] = (REGULAR, {k: float(at_once[k][i]) for k in asked})
        else:
            whole.append(i)
    if workers > 1 and len(whole) > 1:
        portable = Portable(problem)
        ran = run_in_parallel(_portable_variant, [(portable, plan.parameter, float(plan.values_si[i]), run_design,
                                                   asked) for i in whole], workers)
        done.update(zip(whole, ran, strict=True))
    else:
        for j, i in enumerate(whole):
            done[i] = _variant(problem, plan.parameter, float(plan.values_si[i]), run_design, asked)
            if j == 0 and at_once is None:  # the first variant's time, for the whole sweep
                announce_estimate((time.perf_counter() - started) * n,
                                  f"{n} variants of {plan.parameter}, each run whole")
            if progress is not None:
                progress(len(done), n)
    if progress is not None and (not whole or (workers > 1 and len(whole) > 1)):  # else the loop said n of n
        progress(n, n)
    for i in range(n):
        said, row = done[i]
        status.append(said)
        for key, v in row.items():
            columns[key][i] = v
    units = {key: unit_of(key, problem) or "" for key in asked}
    columns["regular"] = np.array([is_regular(s) for s in status], dtype=bool)
    columns["status"] = np.array(status, dtype=object)
    return RunSweep(plan, columns, units, asked=asked)


def column_label(key: str, unit: str) -> Label:
    """The catalogue's label of a result a file's table declares (``cam.max_pressure_angle``), in ``unit``."""
    found = find(key, catalogue())
    if found is None:
        return Label(key, unit)
    q, parts = found
    lab = q.label(**parts)
    return lab if lab.unit == unit else Label(lab.text, unit, None, lab.zero_below)


#: At most this many variants are listed in the summary table, one value per variant (all are in sweep.csv).
SUMMARY_VARIANTS = 25


def run(ctx: StageContext) -> Outcome:
    """The ``[sweep]`` stage of a cam or shaft-line file: the table of the variants (``sweep.csv``), the values
    per variant in results.json and, for a short sweep, in the summary; a warning for each variant that is not
    regular."""
    done = run_sweep(ctx.problem, ctx.run_design)
    plan, cols = done.plan, done.columns
    unit = plan.display_unit
    regular = np.asarray(cols["regular"], dtype=bool)
    swept = f"sweep.{plan.parameter}"
    values: dict[str, Any] = {
        swept: [float(v) for v in plan.values_si],
        "sweep.regular": [bool(v) for v in regular],
        "sweep.status": [str(v) for v in cols["status"]],
        "sweep.designs": float(regular.size),
        "sweep.regular_count": float(regular.sum()),
    }
    labels = {swept: Label(f"Sweep: values of {plan.parameter}", plan.si_unit, unit)}
    listed = [swept]
    for key in done.asked:
        if key == plan.parameter:  # the swept quantity itself: its values are listed already
            continue
        lab = column_label(key, done.units[key])
        values[f"sweep.{key}"] = [float(v) for v in cols[key]]
        labels[f"sweep.{key}"] = Label(f"Sweep: {lab.text[:1].lower() + lab.text[1:]} of each variant", lab.unit,
                                       lab.display, lab.zero_below)
        listed.append(f"sweep.{key}")
    summary = ["sweep.designs", "sweep.regular_count"] + (listed if regular.size <= SUMMARY_VARIANTS else [])
    warnings = [f"sweep variant {i + 1} ({plan.parameter} = {plan.values_display[i]:.6g} {unit}) {status}"
                for i, status in enumerate(values["sweep.status"]) if status != REGULAR]
    settings = current()
    if settings.workers is not None:
        warnings.append(f"The variants of this sweep of {plan.parameter} ran {where_designs_ran(settings.workers)} "
                        "(--workers).")
    elif settings.scheduler is not None:
        warnings.append("--scheduler spreads a linkage exploration's designs; the variants of this "
                        f"sweep of {plan.parameter} ran one after another in this process.")
    if not regular.any():
        warnings.append(f"No variant of the sweep of {plan.parameter} was built, ran and reported every column "
                        "(see sweep.status).")
    columns: dict[str, tuple[Any, str]] = {plan.parameter: (np.asarray(plan.values_si, dtype=float), plan.si_unit)}
    for key in done.asked:
        if key != plan.parameter:
            columns[key] = (cols[key], done.units[key])
    columns["regular"] = (regular, "")
    columns["status"] = (cols["status"], "")
    return Outcome(results=done, scalars=values, labels=labels, series={"sweep": columns},
                   summary=tuple(summary), warnings=tuple(warnings))
