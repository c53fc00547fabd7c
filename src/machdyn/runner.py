"""Run a problem through its stages and collect what the user sees.

>>> from machdyn.runner import run_problem
>>> result = run_problem("examples/slider_crank.toml")      # doctest: +SKIP
>>> result.summary.frame()                                  # doctest: +SKIP
>>> result.frames["torque_power"].head()                    # doctest: +SKIP
>>> result.write("out")                                     # doctest: +SKIP

The stages: read and validate the file (:mod:`machdyn.reading`), build the model and analyse it (the
problem's kind), run each capability table the file has, in order (:mod:`machdyn.kinds`), collect every result
in SI with its label (:mod:`machdyn.results`), and write the outputs (:mod:`machdyn.outputs`, the report).
"""

from __future__ import annotations

import csv
import io
import math
import os
import sys
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from rich.console import Console
from rich.table import Table

from . import __version__
from .errors import AnalysisError, AssemblyError, InputError, ProblemFileError, SingularPositionError
from .kinds import KINDS, capabilities_for, capability, kind
from .notebook import ShownInNotebook
from .outputs import STAMP_FILE, OutputSet, json_text, stamp_script
from .pipeline import Outcome, StageContext, Step, import_object, no_step
from .problem.dumper import dump_problem
from .reading import LoadedProblem, load_problem, read_problem
from .results import Results, Summary, collect, summarise
from .results.store import UNITS as RESULT_UNITS

__all__ = ["RunResult", "check_problem", "load_problem", "read_problem", "run_problem"]


@dataclass(frozen=True)
class StageResult(ShownInNotebook):
    """One stage of a run (the kind's analysis or a capability's table), as :meth:`RunResult.stage` gives it:
    its ``name``, its ``outcome`` (the typed result in ``outcome.results``) and its ``results`` (its scalars, each
    with its label and unit). Shown in Jupyter as its results table and its report sections with their plots."""

    name: str
    report: str | None
    outcome: Outcome
    results: Results

    def sections(self) -> list[tuple[str, str]]:
        """(heading, html) of the stage's report sections (none for a stage without a report)."""
        return [] if self.report is None else import_object(self.report)(self.outcome)


@dataclass
class RunResult(ShownInNotebook):
    """What a run computed, ready to print, convert or write. Shown in Jupyter as its summary table (values in
    their display units) and its report's sections with their plots; :meth:`stage` gives one stage alone.

    ``results`` every scalar in SI with its label; ``summary`` the summary table (the same one the command line
    prints and the report shows); ``outcomes`` each stage's outcome by name (the kind's under its own name, each
    capability's under its table); ``warnings`` and ``failed_checks`` each said once; ``mechanism`` and
    ``analysis`` for kinds built on a linkage; ``source`` the problem file (never removed by :meth:`write`);
    ``folder_notes`` what :meth:`write` left in the output folder that an earlier run listed (one line each).
    """

    kind: str
    title: str
    problem: Any
    problem_text: str
    results: Results
    summary: Summary
    outcomes: dict[str, Outcome]
    warnings: list[str] = field(default_factory=list)
    failed_checks: list[str] = field(default_factory=list)
    mechanism: Any = None
    analysis: Any = None
    source: Path | None = None
    folder_notes: list[str] = field(default_factory=list)
    _frames: dict[str, Any] | None = field(default=None, repr=False)

    @property
    def summary_rows(self) -> list[tuple[str, Any, str]]:
        """(quantity, value, unit) rows of the summary, values in their display units."""
        return self.summary.as_tuples()

    @property
    def scalars(self) -> dict[str, dict[str, Any]]:
        """Every scalar as ``{key: {"value", "unit"}}`` in SI, with ``"shown"`` in the display unit where that
        differs (the ``scalars`` of results.json)."""
        return self.results.as_json()

    @property
    def details(self) -> Any:
        """The kind's own result object (the rotary screen's energy figures, the conveyor's design)."""
        return self.outcomes[self.kind].results

    @property
    def frames(self) -> dict[str, Any]:
        """Time series and tables as pandas DataFrames by name (``motion``, ``joint_forces``, ``torque_power``,
        ``shaking``, ``energy`` for a linkage; ``sweep`` and each capability's tables); the unit in each
        column header."""
        if self._frames is None:
            from .report.tables import analysis_frames, series_frame, shaking_frame

            frames: dict[str, Any] = {}
            if self.analysis is not None:
                frames = analysis_frames(self.analysis, self.mechanism)
                about = tuple(self.problem.output.shaking_moment_about)
                if about != (0.0, 0.0):
                    frames["shaking"] = shaking_frame(self.analysis.forces, None, about=about)
            for outcome in self.outcomes.values():
                for name, columns in outcome.series.items():
                    frames[name] = series_frame(columns)
            self._frames = frames
        return self._frames

    def summary_frame(self):
        """The summary as a DataFrame with columns key, quantity, value, unit."""
        return self.summary.frame()

    def scalars_frame(self):
        """Every scalar as a DataFrame with columns quantity, value, unit (SI, as in results.json)."""
        import pandas as pd

        return pd.DataFrame([(k, v["value"], v["unit"]) for k, v in self.scalars.items()],
                            columns=["quantity", "value", "unit"])

    def results_json(self) -> dict[str, Any]:
        """The content of results.json: the problem's name and kind, ``"units": "SI"``, every scalar in SI with
        its unit (and as shown, where shown otherwise), the warnings and the failed design checks; after an
        optimisation, ``designs`` says which keys are of the design as given and which of the best design."""
        data = {
            "machdyn_version": __version__,
            "problem": self.title,
            "kind": self.kind,
            "units": RESULT_UNITS,
            "scalars": self.scalars,
            "warnings": list(self.warnings),
            "failed_checks": list(self.failed_checks),
        }
        if optimised(self.outcomes):  # two designs' results side by side: say which keys are which
            data["designs"] = {
                "as_given": "every scalar whose key does not start with 'optimise.': the design as the file gives it",
                "best_design": "the scalars 'optimise.best.*': the best design found, written to best_design.toml",
            }
        return data

    def stage(self, name: str) -> StageResult:
        """The stage ``name`` of the run: the kind's (its main table, e.g. ``"mechanism"``) or a capability's
        (its table, e.g. ``"flywheel"``), with its own results and report."""
        if name not in self.outcomes:
            raise InputError(f"This run has no stage '{name}'; it has: {', '.join(self.outcomes)}.")
        outcome = self.outcomes[name]
        stage = kind(self.kind) if name == self.kind else capability(name)
        keys = [k for k in outcome.scalars if k in self.results]
        return StageResult(name, stage.report, outcome,
                           Results({k: self.results[k] for k in keys}, {k: self.results.label(k) for k in keys}))

    def report_sections(self) -> list[tuple[str, str]]:
        """(heading, html) of every stage's report sections, in the order the stages ran."""
        out: list[tuple[str, str]] = []
        for name, outcome in self.outcomes.items():
            stage = kind(self.kind) if name == self.kind else capability(name)
            if stage.report is not None:
                out += import_object(stage.report)(outcome)
        return out

    def report_html(self, watch_stamp: str | None = None) -> str:
        """The self-contained HTML report (input echoed, summary, warnings, each stage's sections); with a
        ``watch_stamp`` the page re-loads itself when ``report.stamp.js`` beside it changes (``machdyn watch``)."""
        from .report import render_report

        return render_report(
            title=self.title, problem_text=self.problem_text, summary_rows=self.summary_rows,
            warnings=self.warnings + [f"Design check failed: {c}" for c in self.failed_checks],
            sections=self.report_sections(), watch_stamp=watch_stamp,
        )

    def write(self, out_dir: str | os.PathLike, *, step: Step = no_step, watch_stamp: str | None = None,
              folders: list | tuple = ()) -> list[Path]:
        """Write ``results.json``, ``<series>.csv`` per time series and ``report.html`` into ``out_dir``
        (created if missing) as one set: all are written first, then swapped in together, so an interrupted
        run leaves the previous set whole. With a ``watch_stamp`` (``machdyn watch``) the set also holds
        ``report.stamp.js``, which an open report polls to re-load itself. ``folders``: (new, target) folders
        swapped in with the set (an exploration's Parquet store). Returns the paths written. Files of an
        earlier set that this one does not hold are removed only if machdyn wrote them and they are unchanged
        (see :class:`~machdyn.outputs.OutputSet`); the others are named in :attr:`folder_notes`."""
        outputs = OutputSet(out_dir, protect=(self.source,) if self.source is not None else ())
        try:
            outputs.json("results.json", self.results_json())
            step("tables")
            for name, frame in self.frames.items():
                outputs.frame(f"{name}.csv", frame)
            for outcome in self.outcomes.values():
                for name, text in outcome.files.items():
                    outputs.text(name, text)
            step("report")
            outputs.text("report.html", self.report_html(watch_stamp))
            if watch_stamp is not None:
                outputs.text(STAMP_FILE, stamp_script(watch_stamp))
        except BaseException:
            outputs.abort()
            raise
        paths = outputs.commit(folders)
        self.folder_notes = outputs.notes
        return paths


def _loaded(problem: Any, text: str | None) -> LoadedProblem:
    """A :class:`LoadedProblem` from a path or TOML text, a loaded problem, or a validated problem object."""
    if isinstance(problem, LoadedProblem):
        return problem
    if isinstance(problem, str | os.PathLike):
        loaded = read_problem(problem)
        return loaded if text is None else LoadedProblem(loaded.kind, loaded.spec, text, loaded.source, loaded.model)
    for name in KINDS:
        k = kind(name)
        if k.owns(problem):
            model, problems = k.build(problem)
            if problems:
                raise ProblemFileError(problems)
            if text is None:
                text = k.dump(problem) if k.dump is not None else _dump(problem)
            return LoadedProblem(name, problem, text, None, model)
    raise InputError(f"run_problem takes a problem file, TOML text or a loaded problem; got {type(problem).__name__}")


def _dump(problem: Any) -> str:
    return dump_problem(problem)


def _tables(loaded: LoadedProblem) -> list[Any]:
    return [c for c in capabilities_for(loaded.kind) if getattr(loaded.spec, c.table, None) is not None]


def check_problem(problem: Any) -> list[str]:
    """Every validation a run relies on, without the analysis: the model assembles at every crank angle asked
    for and each capability table's own checks pass. Returns warnings; raises
    :class:`~machdyn.errors.ProblemFileError` for bad input and the engine's errors for a linkage that cannot
    close or passes a dead position."""
    loaded = _loaded(problem, None)
    found = list(kind(loaded.kind).check(loaded.spec, loaded.model))
    return found + [w for w in _advice(loaded) if w not in found]


def _advice(loaded: LoadedProblem) -> list[str]:
    """The capability tables' advice on a valid file (:attr:`~machdyn.pipeline.Capability.advise`), said by
    ``check`` and ``run`` alike."""
    return [w for cap in _tables(loaded) if cap.advise is not None
            for w in cap.advise(loaded.spec, getattr(loaded.spec, cap.table))]


class DesignResults(dict):
    """The results (SI, by key) of one design of a study, and the design checks its run failed."""

    def __init__(self, values: Mapping[str, Any], failed_checks: tuple[str, ...] = ()) -> None:
        super().__init__(values)
        self.failed_checks = failed_checks


def design_results(problem: Any) -> DesignResults:
    """The results (SI, by key) of one design of a study: its validated problem run as ``machdyn run`` would run
    it, but without the file's studies (``[sweep]``, ``[optimise]``), which would otherwise start again."""
    studies = {t: None for t in ("sweep", "optimise") if getattr(problem, t, None) is not None}
    plain = problem.model_copy(update=studies) if studies else problem
    done = run_problem(plain)
    return DesignResults(done.results.values, tuple(done.failed_checks))


def run_problem(problem: Any, *, text: str | None = None, step: Step = no_step) -> RunResult:
    """Analyse a problem: a path or TOML text, a :class:`LoadedProblem` or a problem from
    :func:`~machdyn.reading.load_problem`. ``text`` is the problem file echoed in the report (by default the
    problem written back as TOML). Raises :class:`~machdyn.errors.ProblemFileError` for bad input and the
    engine's errors (:class:`~machdyn.errors.AssemblyError`, ...) when the linkage cannot close."""
    loaded = _loaded(problem, text)
    k = kind(loaded.kind)
    step("model")
    first = k.analyse(loaded.spec, loaded.model, step)
    outcomes: dict[str, Outcome] = {loaded.kind: first}
    known = dict(k.labels)
    for cap in capabilities_for(loaded.kind):
        table = getattr(loaded.spec, cap.table, None)
        if table is None:
            continue
        step(cap.step)
        ctx = StageContext(loaded.spec, table, first.mechanism, first.analysis, dict(outcomes), loaded.source,
                           run_design=design_results)
        outcomes[cap.table] = done = cap.run(ctx)
        if cap.result_type is not None and done.results is not None and not isinstance(done.results,
                                                                                       cap.result_type):
            raise TypeError(f"the [{cap.table}] stage returned {type(done.results).__name__}, not its declared "
                            f"result type {cap.result_type}")
        known |= cap.labels
    values: dict[str, Any] = {}
    units: dict[str, str] = {}
    summary: list[str] = []
    warnings: list[str] = _advice(loaded)
    failed: list[str] = []
    for name, outcome in outcomes.items():
        clash = sorted(set(values) & set(outcome.scalars))
        if clash:  # two stages naming one result would overwrite each other silently
            raise RuntimeError(f"the stage '{name}' reports results another stage already reported: {clash}")
        values |= outcome.scalars
        units |= outcome.units
        known |= outcome.labels
        summary += outcome.summary
        warnings += [w for w in outcome.warnings if w not in warnings]
        failed += [c for c in outcome.failed_checks if c not in failed]
    _refuse_non_finite(values)
    results = collect(values, known, units)
    title = k.title(loaded.spec)
    table = summarise(title, results, summary)
    return RunResult(
        kind=loaded.kind, title=title, problem=loaded.spec, problem_text=loaded.text, results=results,
        summary=name_the_designs(table) if optimised(outcomes) else table, outcomes=outcomes, warnings=warnings,
        failed_checks=failed,
        mechanism=first.mechanism, analysis=first.analysis,
        source=Path(loaded.source) if loaded.source is not None else None,
    )


#: The heading of the rows of the file's own design when an optimisation reports a best design beside them.
AS_GIVEN = "As given: "


def optimised(outcomes: Mapping[str, Outcome]) -> bool:
    """True when an ``[optimise]`` table found a best design (whose rows sit beside the file's own design)."""
    done = outcomes.get("optimise")
    return done is not None and done.results is not None


def name_the_designs(summary: Summary) -> Summary:
    """The summary with each row of the design as the file gives it headed "As given: ", so that it is never
    read as the best design's (those rows are headed "Best design: ", the search's own "Optimisation: ")."""
    rows = tuple(row if row.key.startswith("optimise.") else replace(row, label=AS_GIVEN + row.label)
                 for row in summary.rows)
    return Summary(summary.title, rows)


def _refuse_non_finite(values: dict[str, Any]) -> None:
    """Never a silent NaN or infinity: an infinite result anywhere, or NaN where one value is expected (a list
    over design variants may hold NaN for a design that does not assemble), fails the run naming the results."""
    bad = []
    for key, value in values.items():
        items = value if isinstance(value, list) else [value]
        for v in items:
            if isinstance(v, float) and (math.isinf(v) or (math.isnan(v) and not isinstance(value, list))):
                bad.append(key)
                break
    if bad:
        shown = ", ".join(bad[:6]) + (f" and {len(bad) - 6} more" if len(bad) > 6 else "")
        raise AnalysisError(f"the analysis produced non-finite results ({shown}): an input is far outside the "
                            "range of a real machine, or the mechanism is singular at a sampled position")


# re-exported for callers that catch what a run may raise
ERRORS = (ProblemFileError, AssemblyError, InputError, SingularPositionError)


# ------------------------------------------------------------------------------------------- printing


def _cell(value: Any) -> str:
    if isinstance(value, float):
        return f"{value:.7g}"
    if isinstance(value, list):
        return ", ".join(_cell(v) for v in value)
    return str(value)


def print_summary(summary: Any, fmt: str, warnings: list[str]) -> None:
    """Print a :class:`~machdyn.results.Summary` to stdout in ``fmt`` ("table", "csv", "json" or "markdown"; JSON rows
    also carry the result key), the warnings of a table to stderr."""
    out = Console(highlight=False, soft_wrap=False)
    title = summary.title
    rows = summary.as_tuples()
    if fmt == "table":
        table = Table(title=title, title_justify="left", show_lines=False)
        table.add_column("quantity")
        table.add_column("value", justify="right")
        table.add_column("unit")
        for q, v, u in rows:
            table.add_row(str(q), _cell(v), str(u or ""))
        out.print(table)
        for w in warnings:
            print(f"warning: {w}", file=sys.stderr)
    elif fmt == "csv":
        buf = io.StringIO()
        writer = csv.writer(buf, lineterminator="\n")
        writer.writerow(["quantity", "value", "unit"])
        for q, v, u in rows:
            writer.writerow([q, _cell(v), u or ""])
        sys.stdout.write(buf.getvalue())
    elif fmt == "json":
        data = {"problem": title,
                "summary": [{"key": r.key, "quantity": r.label, "value": r.value, "unit": r.unit or ""}
                            for r in summary.rows],
                "warnings": warnings}
        sys.stdout.write(json_text(data))
    else:
        def esc(text: str) -> str:
            return text.replace("|", "\\|")

        lines = [f"## {esc(title)}", "", "| quantity | value | unit |", "|---|---:|---|"]
        lines += [f"| {esc(str(q))} | {esc(_cell(v))} | {esc(str(u or ''))} |" for q, v, u in rows]
        if warnings:
            lines += ["", "Warnings:", ""] + [f"- {esc(w)}" for w in warnings]
        sys.stdout.write("\n".join(lines) + "\n")
