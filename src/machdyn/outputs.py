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


MANIFEST = ".machdyn-outputs.json"


class OutputSet:
    """The files of one run, written into a hidden staging folder inside ``out_dir`` and swapped in together.

    Until :meth:`commit` the folder keeps the previous run's set untouched; an interrupted or failed run removes
    its staging folder (and ``out_dir`` itself if the run created it and left it empty). At commit each new file
    replaces its old one and the files of the previous set that this run did not write (a CSV of a capability
    no longer in the file) are removed, as listed in the folder's manifest, so old and new never mix.
    """

    def __init__(self, out_dir: str | os.PathLike):
        self.out = Path(out_dir)
        if self.out.exists() and not self.out.is_dir():
            raise OSError(f"the output path '{self.out}' exists and is not a directory")
        self._created = not self.out.exists()
        self.out.mkdir(parents=True, exist_ok=True)
        for stale in self.out.glob(".machdyn-partial-*"):  # left by a run that was killed
            _remove_tree(stale)
        self.stage = Path(tempfile.mkdtemp(dir=self.out, prefix=".machdyn-partial-"))
        self.names: list[str] = []

    def _target(self, name: str) -> Path:
        self.names.append(name)
        return self.stage / name

    def text(self, name: str, text: str) -> None:
        atomic_write_text(self._target(name), text)

    def json(self, name: str, data: Any) -> None:
        write_json(self._target(name), data)

    def frame(self, name: str, frame) -> None:
        write_frame_csv(self._target(name), frame)

    def commit(self) -> list[Path]:
        """Move the set into place; return the final paths."""
        previous: list[str] = []
        try:
            previous = list(json.loads((self.out / MANIFEST).read_text(encoding="utf-8")))
        except (OSError, ValueError, TypeError):
            previous = []
        paths = []
        for name in self.names:
            os.replace(self.stage / name, self.out / name)
            paths.append(self.out / name)
        for name in set(previous) - set(self.names):
            if isinstance(name, str) and "/" not in name and name not in (MANIFEST, ""):
                try:
                    (self.out / name).unlink()
                except OSError:
                    pass
        atomic_write_text(self.out / MANIFEST, json.dumps(self.names) + "\n")
        _remove_tree(self.stage)
        return paths

    def abort(self) -> None:
        """Remove the staging folder (and the output folder if this run created it and it is empty)."""
        _remove_tree(self.stage)
        if self._created:
            try:
                self.out.rmdir()
            except OSError:
                pass


def _remove_tree(path: Path) -> None:
    import shutil

    shutil.rmtree(path, ignore_errors=True)
