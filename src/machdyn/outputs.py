"""Atomic output files: each is written to a temporary file in its target directory, then renamed over.

An interrupted run (Ctrl-C, a full disk, a crash) leaves either the previous file or the new one, never half
of one; the temporary file is removed on any failure.
"""

from __future__ import annotations

import json
import math
import os
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import IO, Any


def atomic_write(path: str | os.PathLike, write: Callable[[IO[str]], object], *, encoding: str = "utf-8") -> Path:
    """Call ``write(file)`` on a temporary text file beside ``path`` and move it into place; return ``path``."""
    target = Path(path)
    target.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=target.parent, prefix=f".{target.name}.", suffix=".part")
    try:
        with os.fdopen(fd, "w", encoding=encoding, newline="") as handle:
            write(handle)
            handle.flush()
            os.fsync(handle.fileno())
        os.chmod(tmp, 0o644)
        os.replace(tmp, target)
    except BaseException:
        try:
            os.unlink(tmp)
        except FileNotFoundError:
            pass
        raise
    return target


def atomic_write_text(path: str | os.PathLike, text: str) -> Path:
    """Write ``text`` to ``path`` atomically."""
    return atomic_write(path, lambda f: f.write(text))


def _jsonable(value: Any) -> Any:
    """Plain JSON values: numpy scalars and arrays become floats and lists; NaN and infinity become null."""
    if isinstance(value, dict):
        return {str(k): _jsonable(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [_jsonable(v) for v in value]
    if hasattr(value, "tolist"):
        return _jsonable(value.tolist())
    if isinstance(value, bool) or value is None or isinstance(value, str | int):
        return value
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    return str(value)


def json_text(data: Any) -> str:
    """``data`` as indented JSON (NaN written as null, so every reader accepts the file)."""
    return json.dumps(_jsonable(data), indent=2, ensure_ascii=False, allow_nan=False) + "\n"


def write_json(path: str | os.PathLike, data: Any) -> Path:
    """Write ``data`` to ``path`` as JSON, atomically."""
    return atomic_write_text(path, json_text(data))


def write_frame_csv(path: str | os.PathLike, frame) -> Path:
    """Write a pandas DataFrame (units in its column headers) to ``path`` as CSV without the index, atomically."""
    return atomic_write(path, lambda f: frame.to_csv(f, index=False, float_format="%.10g", lineterminator="\n"))
