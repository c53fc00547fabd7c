"""Read a problem file of any registered kind into a validated problem; report every mistake at once.

The kind of a file is named by its main table (``[mechanism]``, ``[rotary_screen]``, ``[screw_conveyor]``; see
:mod:`machdyn.kinds`). Its tables are validated against the kind's schema together with the tables of every
capability the kind accepts (``[sweep]`` ...), and the model is built, so that the engine's own rules are
checked too; every mistake found is reported in one :class:`~machdyn.errors.ProblemFileError`. Reading the
text and parsing it is :mod:`machdyn.problem.loader`, which knows no kind: the registry sits above validation.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Any

from pydantic import ValidationError

from .errors import ProblemFileError
from .kinds import CAPABILITIES, KINDS, capabilities_for, kind, problem_model
from .problem.errors import did_you_mean, problems_from
from .problem.loader import parse_toml, read_text, top_level_problems

__all__ = ["LoadedProblem", "kind_of", "load_problem", "read_problem", "validate"]


@dataclass(frozen=True)
class LoadedProblem:
    """A validated problem with what reading it gave: its kind, the file's text and path, and the model built
    from it (so that a run neither reads the file nor builds the model a second time)."""

    kind: str
    spec: Any
    text: str
    source: str | None = None
    model: Any = None


def kind_of(data: dict[str, Any], source: str | None = None) -> str:
    """The kind of a parsed file: the one registered main table it has. A main table that is also a capability
    table (``[signals]``: records judged alone) names the kind only when no other main table is there."""
    found = [k for k in KINDS if k in data]
    if len(found) > 1:
        found = [k for k in found if k not in CAPABILITIES] or found
    if len(found) == 1:
        return found[0]
    if len(found) > 1:
        raise ProblemFileError(
            [("", f"a problem file describes one machine; got the tables {', '.join('[' + k + ']' for k in found)}")],
            source,
        )
    problems = []
    for key in data:
        if key in CAPABILITIES:  # a known table of its own (e.g. [shaft_cam]), not a misspelt main table
            continue
        hint = did_you_mean(key, list(KINDS))
        if hint:
            problems.append((key, f"unknown table '{key}'{hint}"))
    if not problems:
        tables = ", ".join(f"[{k}]" for k in KINDS)
        problems.append(
            ("", f"the file needs one main table, one of {tables}; "
                 f"got {', '.join('[' + k + ']' for k in data) or 'an empty file'}")
        )
    raise ProblemFileError(problems, source)


def validate(data: dict[str, Any], kind_name: str, source: str | None = None) -> tuple[Any, Any]:
    """(problem, model) of parsed tables of the given kind, or one ProblemFileError with every mistake."""
    k = kind(kind_name)
    if k.validate is not None:
        return _validate_alone(k, data, kind_name, source), None
    schema = problem_model(kind_name)
    allowed = tuple(schema.model_fields)
    problems = top_level_problems(data, allowed)
    spec = None
    try:
        spec = schema.model_validate({key: v for key, v in data.items() if key in allowed})
    except ValidationError as exc:
        problems += problems_from(exc, schema)
        problems += _build_problems_of_valid_tables(k, schema, data, allowed, exc, kind_name)
    model = None
    if spec is not None:
        model, found = k.build(spec)
        problems += found
        for cap in capabilities_for(kind_name):
            table = getattr(spec, cap.table, None)
            if table is not None and cap.check is not None and model is not None:
                problems += cap.check(spec, table, source)
            if table is not None and cap.check_model is not None and model is not None and not found:
                problems += cap.check_model(model, table)
    if problems:
        raise ProblemFileError(problems, source)
    return spec, model


def _machine_kinds() -> list[str]:
    return [k for k in KINDS if k not in CAPABILITIES]


def _machine_tables() -> set[str]:
    """The tables of the files of the kinds that describe a machine, by their schemas (capabilities included)."""
    tables = set(CAPABILITIES)
    for name in _machine_kinds():
        model = problem_model(name) if kind(name).schema is not None else None
        tables |= set(getattr(model, "model_fields", {}))
    return tables


def _validate_alone(k: Any, data: dict[str, Any], kind_name: str, source: str | None) -> Any:
    """The problem of a kind that validates its tables itself; a file whose main table is also a capability's
    (``[signals]``: records judged alone) and that holds a machine's tables has lost (or misspelt) the machine's
    main table, which is said first, with the kind's own mistakes in the other tables."""
    machine = sorted(t for t in data if t in _machine_tables() - {"meta", kind_name}) if kind_name in CAPABILITIES \
        else []
    if not machine:
        return k.validate(data, source)
    mains = ", ".join(f"[{m}]" for m in _machine_kinds())
    problems = [("", f"the tables {', '.join('[' + t + ']' for t in machine)} describe a machine, but the file has "
                     f"no machine's main table ({mains}); a file with [{kind_name}] and no machine holds only "
                     f"[meta] and [{kind_name}]")]
    try:
        k.validate({t: v for t, v in data.items() if t not in machine}, source)
    except ProblemFileError as exc:
        problems += exc.problems
    raise ProblemFileError(problems, source)


def _build_problems_of_valid_tables(k: Any, schema: Any, data: dict[str, Any], allowed: tuple[str, ...],
                                    exc: ValidationError, kind_name: str) -> list[tuple[str, str]]:
    """The model-building mistakes (unknown body or point names in loads, ...) of a file whose schema has
    mistakes elsewhere, so that every mistake is said in one pass: the optional tables with a mistake are left
    out, a required one keeps only its valid keys; if the main table itself is wrong, nothing more is said."""
    bad: dict[str, set[Any]] = {}
    for err in exc.errors():
        loc = err.get("loc") or ()
        if loc:
            bad.setdefault(str(loc[0]), set()).add(loc[1] if len(loc) > 1 else None)
    if kind_name in bad:
        return []
    trimmed = {}
    for key, value in data.items():
        if key not in allowed:
            continue
        if key not in bad:
            trimmed[key] = value
        elif schema.model_fields[key].is_required() and isinstance(value, dict) and None not in bad[key]:
            trimmed[key] = {sub: v for sub, v in value.items() if sub not in bad[key]}
    try:
        spec = schema.model_validate(trimmed)
        _, found = k.build(spec)
    except (ValidationError, ValueError, KeyError, AttributeError, TypeError):
        return []  # the rest of the file does not stand on its own: the schema mistakes are said already
    return [(path, message) for path, message in found if str(path).split(".")[0].split("[")[0] not in bad]


def read_problem(source: str | os.PathLike) -> LoadedProblem:
    """Read and validate a problem file (a path, or the TOML text itself), building its model once."""
    text, name = read_text(source)
    data = parse_toml(text, name)
    kind_name = kind_of(data, name)
    try:
        spec, model = validate(data, kind_name, name)
    except ProblemFileError as exc:
        if exc.source is None and name is not None:
            raise ProblemFileError(exc.problems, name) from None
        raise
    return LoadedProblem(kind_name, spec, text, name, model)


def load_problem(source: str | os.PathLike) -> Any:
    """Read and validate a problem file (a path, or the TOML text itself); returns the validated problem.

    A ``[mechanism]`` file gives a :class:`~machdyn.problem.schema.LinkageProblem`, a ``[rotary_screen]`` file a
    :class:`~machdyn.screen.schema.RotaryScreenProblem`, a ``[screw_conveyor]`` file the conveyor's problem;
    each capability table the file has is an attribute of the same name (``problem.sweep``). Raises
    :class:`~machdyn.errors.ProblemFileError` listing every mistake with its path (``mechanism.coupler.length``),
    the rule broken and the value received; assembly at every crank angle is checked by
    :func:`~machdyn.runner.check_problem`.
    """
    return read_problem(source).spec
