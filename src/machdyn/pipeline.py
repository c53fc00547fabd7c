"""The shapes every stage of a run shares: problem kinds, capabilities, their context and their outcome.

A run goes one way: read the file -> validate it against the kind's schema (with the tables of every capability
the kind accepts) -> build the model -> analyse it (the kind) -> each capability whose table the file has ->
results (SI, with labels and units from :mod:`machdyn.results.labels`) -> outputs (JSON, CSV, HTML).

A **problem kind** is told apart by the main table of a file (``[mechanism]``, ``[rotary_screen]``,
``[screw_conveyor]``); a **capability** is an optional table that adds an analysis to a kind (``[sweep]``,
``[flywheel]``, ``[balance]`` ...). Both are listed in :mod:`machdyn.kinds`, each by one line.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from importlib import import_module
from typing import TYPE_CHECKING, Any, TypeVar

from pydantic import BaseModel

if TYPE_CHECKING:  # the results package reads the registry, which reads this module
    from .results.labels import Label

#: The type of an earlier stage's result that a capability reads (see :meth:`StageContext.result_of`).
R = TypeVar("R")

#: A progress callback: called with the label of the step about to start.
Step = Callable[[str], None]


def no_step(_label: str) -> None:
    """The progress callback that shows nothing."""
    return None


#: Columns of a time series or table written as ``<name>.csv``: column -> (1-D values, SI unit).
Series = Mapping[str, tuple[Any, str]]


@dataclass(frozen=True)
class Outcome:
    """What one stage (a kind's analysis or a capability) adds to a run.

    results : the stage's own frozen result object (SI), for the Python API and its report sections.
    scalars : result key -> SI value (a float, or a list with one value per design variant).
    units : SI unit of keys whose unit the labels do not know (keys made at run time).
    labels : labels of keys made at run time (they take precedence over the stage's registered labels).
    series : name -> columns, each written as ``<name>.csv`` (the unit in every header).
    files : file name -> text, written beside the other outputs (an optimised design as a problem file).
    summary : the keys shown in the summary table, in order.
    warnings : messages for the user, each said once.
    failed_checks : design checks the result fails, each said once; any makes the command line exit with 3.
    mechanism, analysis : the engine's model and constant-speed analysis, for kinds built on a linkage.
    """

    results: Any = None
    scalars: Mapping[str, Any] = field(default_factory=dict)
    units: Mapping[str, str] = field(default_factory=dict)
    labels: Mapping[str, Label] = field(default_factory=dict)
    series: Mapping[str, Series] = field(default_factory=dict)
    files: Mapping[str, str] = field(default_factory=dict)
    summary: Sequence[str] = ()
    warnings: Sequence[str] = ()
    failed_checks: Sequence[str] = ()
    mechanism: Any = None
    analysis: Any = None


@dataclass(frozen=True)
class StageContext:
    """What a capability reads: the validated problem, its own table, the kind's model and analysis, the
    outcomes of the stages before it (by table name, the kind's under its name) and the problem file's path
    (relative file names in a table are resolved against its folder)."""

    problem: Any
    table: Any
    mechanism: Any
    analysis: Any
    outcomes: Mapping[str, Outcome]
    source: str | None = None
    #: runs one design's validated problem through the kind's and capabilities' stages, without the studies
    #: ([sweep], [optimise]), and returns its results (SI) by key: what a study needs for results no population
    #: group computes (a capability's). None where no runner is at hand.
    run_design: Callable[[Any], Mapping[str, Any]] | None = None

    def result_of(self, table: str, expected: type[R]) -> R | None:
        """The result of the earlier stage of ``table`` (a capability's table or the kind's name), typed: None
        when the file has no such table or the stage produced no result object (a flywheel with no steady state,
        an optimisation with no feasible design). The reading capability lists ``table`` in its ``after``; a
        result of another type than the contract ``expected`` is a programming error (TypeError)."""
        outcome = self.outcomes.get(table)
        if outcome is None or outcome.results is None:
            return None
        if not isinstance(outcome.results, expected):
            raise TypeError(f"the [{table}] stage returned {type(outcome.results).__name__}, "
                            f"not the {expected.__name__} its readers expect")
        return outcome.results


@dataclass(frozen=True)
class Capability:
    """An optional table of a problem file that adds an analysis.

    table : the table's name in the file.
    schema : the pydantic model of the table (quantities from :mod:`machdyn.problem.fields`).
    run : ``(StageContext) -> Outcome``.
    step : the progress-bar label of the stage.
    kinds : the problem kinds whose files may hold the table.
    labels : result key -> :class:`~machdyn.results.labels.Label` of the keys the stage reports.
    report : ``"package.module:function"``, a function ``(Outcome) -> [(heading, html), ...]`` imported only
        when a report is written (so analysis never loads matplotlib).
    check : ``(problem, table, source) -> [(path, message), ...]``: the validations of the table that need more
        than its schema (run by ``check`` and by ``run`` alike); ``source`` is the problem file's path (None for
        TOML text), against whose folder relative file names resolve.
    check_model : ``(model, table) -> [(path, message), ...]``: the validations of the table against the model the
        kind built from the file (run by ``check`` and by ``run`` alike, when the model was built without problems).
    after : tables whose outcome this stage reads (they run first), through :meth:`StageContext.result_of`.
    result_type : the type of the stage's ``Outcome.results`` (the typed contract its readers and its report rely
        on); the runner checks it after every run. None only for a stage whose results object is None.
    population : ``"package.module:function"``, the table's population form: ``(problem, forces) -> {key: (N,)
        array} | None``, the stage's results for N linkage designs at once from their kinetostatics over the
        cycle (:func:`machdyn.linkage.kinetostatics` of a mechanism of N designs), None where it cannot stand in
        for a run of each design (the studies then run each design). Imported only by a study that asks for
        the table's results (:func:`machdyn.kinds.population_form`).
    advise : ``(problem, table) -> [warning, ...]``: advice on a valid table (an objective against its result's
        declared better direction), said by ``check`` and by ``run`` alike.
    result_keys : ``(problem) -> {key: SI unit}``, the results a run of the table reports whose keys are made from
        the file's own names (``parts.bearing.O.rating_life``), as for :class:`ProblemKind`: a study accepts only
        these of the table's patterns. None: the patterns alone.
    """

    table: str
    schema: type[BaseModel]
    run: Callable[[StageContext], Outcome]
    step: str
    kinds: tuple[str, ...] = ("mechanism",)
    labels: Mapping[str, Label] = field(default_factory=dict)
    report: str | None = None
    check: Callable[[Any, Any, str | None], list[tuple[str, str]]] | None = None
    check_model: Callable[[Any, Any], list[tuple[str, str]]] | None = None
    after: tuple[str, ...] = ()
    result_type: type | tuple[type, ...] | None = None
    population: str | None = None
    advise: Callable[[Any, Any], list[str]] | None = None
    result_keys: Callable[[Any], Mapping[str, str]] | None = None


@dataclass(frozen=True)
class ProblemKind:
    """A kind of problem file, told apart by its main table.

    name : the main table (``"mechanism"``).
    schema : the pydantic model of the kind's own tables; the capabilities' tables are added to it.
    build : ``(problem) -> (model, [(path, message), ...])``: the model the analysis works on and the problems
        found while building it (None for a kind without a separate model).
    check : ``(problem, model) -> [warning, ...]``: every validation the analysis relies on (assembly at every
        crank angle, ...), raising :class:`~machdyn.errors.ProblemFileError` or an engine error.
    analyse : ``(problem, model, step) -> Outcome``.
    title : ``(problem) -> str``, the report's heading.
    steps : the progress-bar labels of ``analyse``, in order.
    labels, report : as for :class:`Capability`.
    validate : ``(data, source) -> problem`` for a kind that validates its tables itself, instead of the schema.
    dump : ``(problem) -> str``, the problem written back as TOML (None: the generic dumper).
    problem_type : ``() -> type`` of the kind's validated problems, where that is not ``schema``.
    result_keys : ``(problem) -> {key: SI unit}``, the results a run of ``problem`` reports whose keys are made
        from its own names (a bearing's, a frame point's), for a kind whose catalogue entries are patterns; a study
        ([sweep] columns, [optimise] results) accepts only these of the pattern's keys. None: the patterns alone.
    population : ``"package.module:function"``, the kind's population form: ``(problem, values, keys) -> {key: (N,)
        array} | None`` with ``values`` the design variables' values by path (``{"cam.base_radius": (N,) array}``,
        SI): every key asked for, for the N designs at once (NaN for a design whose run would fail), or None when
        a path or a key is one it cannot vectorise (the studies then run each design whole). None: no such form.
    """

    name: str
    schema: type[BaseModel] | None
    build: Callable[[Any], tuple[Any, list[tuple[str, str]]]]
    check: Callable[[Any, Any], list[str]]
    analyse: Callable[[Any, Any, Step], Outcome]
    title: Callable[[Any], str]
    steps: tuple[str, ...]
    labels: Mapping[str, Label] = field(default_factory=dict)
    report: str | None = None
    validate: Callable[[dict[str, Any], str | None], Any] | None = None
    dump: Callable[[Any], str] | None = None
    problem_type: Callable[[], type] | None = None
    result_keys: Callable[[Any], Mapping[str, str]] | None = None
    population: str | None = None

    def owns(self, problem: Any) -> bool:
        """True if ``problem`` is a validated problem of this kind."""
        cls = self.problem_type() if self.problem_type is not None else self.schema
        return cls is not None and isinstance(problem, cls)


def import_object(path: str) -> Any:
    """The object named by ``"package.module:name"``."""
    module, _, name = path.partition(":")
    return getattr(import_module(module), name)
