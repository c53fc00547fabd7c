"""Read the text of a problem file, bounded, and parse its TOML; every mistake as a path and a message.

This module knows no kind of problem: :mod:`machdyn.reading` looks the kind of a file up in the registry
(:mod:`machdyn.kinds`) and validates the parsed tables against the kind's schema.
"""

from __future__ import annotations

import os
import stat
import sys
import tomllib
from pathlib import Path
from typing import Any

from ..errors import ProblemFileError
from .errors import did_you_mean

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


def top_level_problems(data: dict[str, Any], allowed: tuple[str, ...]) -> list[tuple[str, str]]:
    """An 'unknown key' problem (with a did-you-mean) for each top-level table not in ``allowed``."""
    out = []
    for key in data:
        if key not in allowed:
            hint = did_you_mean(key, list(allowed))
            out.append((key, f"unknown key '{key}'{hint}" + ("" if hint else f" (allowed here: {', '.join(allowed)})")))
    return out
