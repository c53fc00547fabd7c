"""Read a problem file (TOML with units) into a validated problem; report every mistake at once.

The kind of a file is named by its main table (``[mechanism]``, ``[rotary_screen]``, ``[screw_conveyor]``; see
:mod:`machdyn.kinds`). Its tables are validated against the kind's schema together with the tables of every
capability the kind accepts (``[sweep]`` ...), and the model is built, so that the engine's own rules are
checked too; every mistake found is reported in one :class:`~machdyn.errors.ProblemFileError`.
"""

from __future__ import annotations

import os
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from ..errors import ProblemFileError
from .errors import did_you_mean, problems_from


@dataclass(frozen=True)
class LoadedProblem:
    """A validated problem with what reading it gave: its kind, the file's text and path, and the model built
    from it (so that a run neither reads the file nor builds the model a second time)."""

    kind: str
    spec: Any
    text: str
    source: str | None = None
    model: Any = None


#: The largest problem file read [bytes]: a problem file is a few kilobytes; anything near this is not one.
MAX_FILE_BYTES = 1 << 20

#: The deepest nesting of arrays and inline tables accepted (a problem file needs three or four levels).
MAX_NESTING = 16

#: The name that reads a problem from standard input.
STDIN = "-"


def _decode(raw: bytes, name: str) -> str:
    if len(raw) > MAX_FILE_BYTES:
        raise ProblemFileError([("", f"the problem file is larger than {MAX_FILE_BYTES // 1024} KiB; a problem file "
                                     "is TOML text of a few kilobytes")], name)
    try:
        return raw.decode("utf-8-sig")  # a UTF-8 byte-order mark is dropped
    except UnicodeDecodeError as exc:
        raise ProblemFileError([("", f"the problem file is not UTF-8 text ({exc.reason} at byte {exc.start})")],
                               name) from None


def _read_bounded(path: Path) -> str:
    """The text of a regular file of at most MAX_FILE_BYTES; devices, pipes and directories are refused."""
    import stat

    try:
        info = path.stat()
    except FileNotFoundError:
        raise ProblemFileError([("", f"the problem file '{path}' does not exist")]) from None
    except OSError as exc:
        raise ProblemFileError([("", f"cannot read '{path}': {exc.strerror}")]) from None
    if stat.S_ISDIR(info.st_mode):
        raise ProblemFileError([("", f"'{path}' is a directory, not a problem file")])
    if not stat.S_ISREG(info.st_mode):
        raise ProblemFileError([("", f"'{path}' is not a regular file (a device, a pipe or a socket); give a "
                                     "problem file, or '-' to read one from standard input")])
    try:
        with path.open("rb") as f:
            raw = f.read(MAX_FILE_BYTES + 1)
    except OSError as exc:
        raise ProblemFileError([("", f"cannot read '{path}': {exc.strerror}")]) from None
    return _decode(raw, str(path))


def read_stdin() -> str:
    """A problem file from standard input, at most MAX_FILE_BYTES."""
    import sys

    stream = getattr(sys.stdin, "buffer", None)
    raw = stream.read(MAX_FILE_BYTES + 1) if stream is not None else sys.stdin.read(MAX_FILE_BYTES + 1).encode()
    return _decode(raw, "<stdin>")


def read_text(source: str | os.PathLike) -> tuple[str, str | None]:
    """The text of a problem and its file name (None for text given directly).

    ``"-"`` reads standard input. A :class:`~pathlib.Path`, or a one-line string naming an existing file or
    ending in ``.toml``, is read as a file (a regular file of at most 1 MiB); any other string is the TOML text
    itself."""
    if isinstance(source, str) and source == STDIN or isinstance(source, Path) and str(source) == STDIN:
        return read_stdin(), "<stdin>"
    if isinstance(source, os.PathLike) or (
        isinstance(source, str) and "\n" not in source and (source.endswith(".toml") or os.path.isfile(source))
    ):
        path = Path(source)
        return _read_bounded(path), str(path)
    if not isinstance(source, str):
        raise ProblemFileError([("", f"a problem is a file path or TOML text; got {type(source).__name__}")])
    if len(source.encode("utf-8", "surrogatepass")) > MAX_FILE_BYTES:
        raise ProblemFileError([("", f"the problem text is larger than {MAX_FILE_BYTES // 1024} KiB")])
    return source, None


def nesting_depth(text: str) -> int:
    """The deepest nesting of ``[`` and ``{`` in TOML text, outside strings and comments (table headers
    count one level: they are not nested)."""
    depth = deepest = 0
    i, n = 0, len(text)
    while i < n:
        ch = text[i]
        if ch == "#":
            j = text.find("\n", i)
            i = n if j < 0 else j
            continue
        if ch in "\"'":
            triple = text.startswith(ch * 3, i)
            end_mark = ch * 3 if triple else ch
            j = i + len(end_mark)
            while j < n and not text.startswith(end_mark, j):
                if ch == '"' and text[j] == "\\":
                    j += 1
                elif not triple and text[j] == "\n":
                    break
                j += 1
            i = j + len(end_mark)
            continue
        if ch in "[{":
            depth += 1
            deepest = max(deepest, depth)
        elif ch in "]}":
            depth = max(0, depth - 1)
        i += 1
    return deepest


def parse_toml(text: str, source: str | None = None) -> dict[str, Any]:
    """The tables of a TOML text; malformed TOML becomes a :class:`ProblemFileError` with line and column, and
    arrays or inline tables nested deeper than MAX_NESTING are refused before parsing."""
    depth = nesting_depth(text)
    if depth > MAX_NESTING:
        raise ProblemFileError([("", f"arrays or inline tables are nested {depth} deep; a problem file needs at "
                                     f"most {MAX_NESTING}")], source)
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise ProblemFileError([("", f"malformed TOML: {exc}")], source) from None
    except RecursionError:
        raise ProblemFileError([("", "the TOML text is nested too deeply to read")], source) from None


def kind_of(data: dict[str, Any], source: str | None = None) -> str:
    """The kind of a parsed file: the one registered main table it has. A main table that is also a capability
    table (``[signals]``: records judged alone) names the kind only when no other main table is there."""
    from ..kinds import CAPABILITIES, KINDS

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


def top_level_problems(data: dict[str, Any], allowed: tuple[str, ...]) -> list[tuple[str, str]]:
    """An 'unknown key' problem (with a did-you-mean) for each top-level table not in ``allowed``."""
    out = []
    for key in data:
        if key not in allowed:
            hint = did_you_mean(key, list(allowed))
            out.append((key, f"unknown key '{key}'{hint}" + ("" if hint else f" (allowed here: {', '.join(allowed)})")))
    return out


def validate(data: dict[str, Any], kind_name: str, source: str | None = None) -> tuple[Any, Any]:
    """(problem, model) of parsed tables of the given kind, or one ProblemFileError with every mistake."""
    from ..kinds import capabilities_for, kind, problem_model

    k = kind(kind_name)
    if k.validate is not None:
        spec = k.validate(data, source)
        return spec, None
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
    if problems:
        raise ProblemFileError(problems, source)
    return spec, model


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
