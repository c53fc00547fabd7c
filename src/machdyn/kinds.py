"""The registry of problem kinds and capabilities: one line each.

A problem file is of the kind named by its main table; it may add any capability table its kind accepts. To add
a kind or a capability, write its package (schema, build, analysis, report sections) and add one line here;
``docs/architecture.md`` walks through an example. Entries are ``"package.module:OBJECT"`` strings, imported
only when a file needs them, so that the command line starts without loading the analyses.
"""

from __future__ import annotations

from functools import cache
from typing import Any

from pydantic import create_model

from .pipeline import Capability, ProblemKind, import_object
from .results.catalogue import OWN, RUN_TIME, Quantity, declared

#: main table -> the :class:`~machdyn.pipeline.ProblemKind`
KINDS: dict[str, str] = {
    "mechanism": "machdyn.pipelines.mechanism:KIND",
    "rotary_screen": "machdyn.screen.kind:KIND",
    "screw_conveyor": "machdyn.conveyor.kind:KIND",
    "cam": "machdyn.cams.stage:KIND",
    "shaft_line": "machdyn.shafts.kind:KIND",
    "synthesis": "machdyn.synthesis.kind:KIND",
    "hoist": "machdyn.drivetrain.hoist_kind:KIND",
    "signals": "machdyn.vibration.records:KIND",  # records alone; beside a machine, [signals] is a capability
}

#: optional table -> the :class:`~machdyn.pipeline.Capability`
CAPABILITIES: dict[str, str] = {
    "sweep": "machdyn.studies.sweep.stage:CAPABILITY",
    "balance": "machdyn.balancing.stage:CAPABILITY",
    "frame": "machdyn.vibration.stage:FRAME",
    "signals": "machdyn.vibration.stage:SIGNALS",
    "follower_linkage": "machdyn.cams.linkage_stage:CAPABILITY",
    "flywheel": "machdyn.dynamics.stage:CAPABILITY",
    "optimise": "machdyn.studies.optimisation.stage:CAPABILITY",
    "drivetrain": "machdyn.drivetrain.stage:CAPABILITY",
    "parts": "machdyn.drivetrain.parts_stage:CAPABILITY",
    "field_records": "machdyn.shafts.record_stage:CAPABILITY",
    "shaft_cam": "machdyn.cams.shaft:CAPABILITY",
    "transient": "machdyn.transient.stage:CAPABILITY",
}


@cache
def kind(name: str) -> ProblemKind:
    """The problem kind whose main table is ``name``."""
    return import_object(KINDS[name])


@cache
def capability(table: str) -> Capability:
    """The capability of the optional table ``table``."""
    return import_object(CAPABILITIES[table])


def population_form(table: str) -> Any:
    """The population form a capability declares (:attr:`~machdyn.pipeline.Capability.population`): a function
    ``(problem, forces) -> {key: (N,) array} | None``; None for a table without one."""
    if table not in CAPABILITIES:
        return None
    path = capability(table).population
    return None if path is None else import_object(path)


@cache
def capabilities_for(kind_name: str) -> tuple[Capability, ...]:
    """The capabilities a kind accepts, ordered so that each runs after the tables it reads."""
    found = [capability(t) for t in CAPABILITIES]
    found = [c for c in found if kind_name in c.kinds]
    ordered: list[Capability] = []
    pending = list(found)
    while pending:
        ready = [c for c in pending if all(a in {o.table for o in ordered} or a not in {p.table for p in found}
                                           for a in c.after)]
        if not ready:  # a cycle of 'after' would be a programming error in the registry
            raise RuntimeError(f"capabilities wait on each other: {[c.table for c in pending]}")
        ordered += ready
        pending = [c for c in pending if c not in ready]
    return tuple(ordered)


@cache
def problem_model(kind_name: str) -> Any:
    """The pydantic model of a whole file of the kind: its own tables plus an optional field per capability."""
    base = kind(kind_name).schema
    extra: dict[str, Any] = {c.table: (c.schema | None, None) for c in capabilities_for(kind_name)}
    if base is None or not extra:
        return base
    return create_model(base.__name__, __base__=base, __module__=base.__module__, **extra)


def steps_of(kind_name: str, tables: tuple[str, ...] = ()) -> list[str]:
    """The progress-bar labels of a run of the kind with the given capability tables."""
    steps = ["reading", *kind(kind_name).steps]
    steps += [c.step for c in capabilities_for(kind_name) if c.table in tables]
    return [*steps, "tables", "report"]


@cache
def catalogue() -> tuple[Quantity, ...]:
    """Every quantity machdyn reports: the linkage results, the compactor's, the population checks
    (:data:`machdyn.results.catalogue.OWN`), each registered problem kind's and capability's declared results
    (their ``labels``; producer = the kind or the capability's table) and the keys made at run time."""
    out = list(OWN)
    seen = {q.key for q in out}
    for name in KINDS:
        out += declared(kind(name).labels, name, seen)
    for table in CAPABILITIES:
        out += declared(capability(table).labels, table, seen)
    return (*out, *RUN_TIME)
