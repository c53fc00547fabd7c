"""Read a problem file (TOML with units) into a validated problem; report every mistake at once.

A file is one of three kinds, told apart by its main table: ``[mechanism]`` (a generic linkage),
``[rotary_screen]`` (the rotary grading screen of seed 002) or ``[screw_conveyor]``.
"""

from __future__ import annotations

import os
import tomllib
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from ..errors import ProblemFileError
from .errors import did_you_mean, problems_from
from .schema import LinkageProblem

#: The main table of each kind of problem and the other top-level tables it may have.
KINDS: dict[str, tuple[str, ...]] = {
    "mechanism": ("meta", "mechanism", "drive", "loads", "counterweights", "output", "sweep"),
    "rotary_screen": ("meta", "rotary_screen", "drive", "output"),
    "screw_conveyor": (),  # the conveyor's own loader checks its tables
}


def read_text(source: str | os.PathLike) -> tuple[str, str | None]:
    """The text of a problem and its file name (None for text given directly).

    A :class:`~pathlib.Path`, or a one-line string naming an existing file or ending in ``.toml``, is read
    as a file; any other string is the TOML text itself."""
    if isinstance(source, os.PathLike) or (
        isinstance(source, str) and "\n" not in source and (source.endswith(".toml") or os.path.isfile(source))
    ):
        path = Path(source)
        try:
            return path.read_text(encoding="utf-8-sig"), str(path)  # a UTF-8 byte-order mark is dropped
        except FileNotFoundError:
            raise ProblemFileError([("", f"the problem file '{path}' does not exist")]) from None
        except IsADirectoryError:
            raise ProblemFileError([("", f"'{path}' is a directory, not a problem file")]) from None
        except UnicodeDecodeError as exc:
            raise ProblemFileError([("", f"the problem file is not UTF-8 text ({exc.reason} at byte {exc.start})")],
                                   str(path)) from None
        except OSError as exc:
            raise ProblemFileError([("", f"cannot read '{path}': {exc.strerror}")]) from None
    if not isinstance(source, str):
        raise ProblemFileError([("", f"a problem is a file path or TOML text; got {type(source).__name__}")])
    return source, None


def parse_toml(text: str, source: str | None = None) -> dict[str, Any]:
    """The tables of a TOML text; malformed TOML becomes a :class:`ProblemFileError` with line and column."""
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise ProblemFileError([("", f"malformed TOML: {exc}")], source) from None


def problem_kind(data: dict[str, Any], source: str | None = None) -> str:
    """``"mechanism"``, ``"rotary_screen"`` or ``"screw_conveyor"``: the main table of the file."""
    found = [k for k in KINDS if k in data]
    if len(found) == 1:
        return found[0]
    if len(found) > 1:
        raise ProblemFileError(
            [("", f"a problem file describes one machine; got the tables {', '.join('[' + k + ']' for k in found)}")],
            source,
        )
    problems = []
    for key in data:
        hint = did_you_mean(key, list(KINDS))
        if hint:
            problems.append((key, f"unknown table '{key}'{hint}"))
    if not problems:
        problems.append(
            ("", "the file needs one main table: [mechanism], [rotary_screen] or [screw_conveyor]; "
                 f"got {', '.join('[' + k + ']' for k in data) or 'an empty file'}")
        )
    raise ProblemFileError(problems, source)


def top_level_problems(data: dict[str, Any], allowed: tuple[str, ...]) -> list[tuple[str, str]]:
    out = []
    for key in data:
        if key not in allowed:
            hint = did_you_mean(key, list(allowed))
            out.append((key, f"unknown key '{key}'{hint}" + ("" if hint else f" (allowed here: {', '.join(allowed)})")))
    return out


def validate_linkage(data: dict[str, Any], source: str | None = None) -> LinkageProblem:
    """A :class:`LinkageProblem` from the parsed tables, or one ProblemFileError with every mistake."""
    problems = top_level_problems(data, KINDS["mechanism"])
    try:
        clean = {k: v for k, v in data.items() if k in KINDS["mechanism"]}
        problem = LinkageProblem.model_validate(clean)
    except ValidationError as exc:
        problems += problems_from(exc, LinkageProblem)
        problem = None
    if problems:
        raise ProblemFileError(problems, source)
    return problem


def load_problem(source: str | os.PathLike):
    """Read and validate a problem file (a path, or the TOML text itself).

    Returns a :class:`~machdyn.problem.schema.LinkageProblem`, a
    :class:`~machdyn.problem.rotary.RotaryScreenProblem` or the screw conveyor's problem object. Raises
    :class:`~machdyn.errors.ProblemFileError` listing every mistake with its path (``mechanism.coupler.length``),
    the rule broken and the value received. For linkages the mechanism is also built, so that references to
    unknown bodies or points and the engine's own rules are checked; assembly is checked by
    :func:`check_problem`.
    """
    text, name = read_text(source)
    data = parse_toml(text, name)
    kind = problem_kind(data, name)
    if kind == "mechanism":
        problem = validate_linkage(data, name)
        from .build import build_mechanism

        try:
            build_mechanism(problem)
        except ProblemFileError as exc:
            raise ProblemFileError(exc.problems, name) from None
        return problem
    if kind == "rotary_screen":
        from .rotary import validate_rotary_screen

        return validate_rotary_screen(data, name)
    from ..conveyor.problem import load_conveyor_problem

    try:
        return load_conveyor_problem(data, source=name)
    except ProblemFileError as exc:
        if exc.source is None and name is not None:
            raise ProblemFileError(exc.problems, name) from None
        raise
