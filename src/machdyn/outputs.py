"""Atomic output files: each is written to a temporary file in its target directory, then renamed over.

An interrupted run (Ctrl-C, a full disk, a crash) leaves either the previous file or the new one, never half
of one; the temporary file is removed on any failure. A set of files (:class:`OutputSet`) is swapped in under a
journal and a lock, so that old and new files never mix.
"""

from __future__ import annotations

import fcntl
import hashlib
import json
import math
import os
import shutil
import stat
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import IO, Any

from .errors import OperationalError


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
#: The lock file of an output folder: held (``flock``) by the run writing the folder and removed when it ends; the
#: kernel releases the lock when the process ends, however it ends, so a killed run never leaves a stale lock.
LOCK = ".machdyn.lock"
#: The journal of a set being swapped in: written (and synced) before the first rename, so a run killed during
#: the swap is completed by the next one that opens the folder.
JOURNAL = ".commit.json"

_HELD: dict[str, tuple[int, int]] = {}


def acquire_lock(path: str | os.PathLike, what: str) -> None:
    """Hold the lock file ``path`` (created if missing) for this process; a second process asking for it gets
    :class:`~machdyn.errors.OperationalError` at once, naming the process that holds it. Re-entrant within a
    process (each acquire needs a :func:`release_lock`)."""

    key = str(Path(path).resolve())
    if key in _HELD:
        fd, count = _HELD[key]
        _HELD[key] = (fd, count + 1)
        return
    while True:
        fd = os.open(key, os.O_RDWR | os.O_CREAT, 0o644)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            holder = os.pread(fd, 32, 0).decode(errors="replace").strip() or "?"
            os.close(fd)
            raise OperationalError(f"another machdyn run (process {holder}) is writing {what}; wait for it to end "
                                   f"or choose another folder") from None
        try:
            same = os.stat(key).st_ino == os.fstat(fd).st_ino
        except FileNotFoundError:
            same = False
        if same:
            break
        os.close(fd)  # the holder removed the file as we opened it: lock the new one
    os.ftruncate(fd, 0)
    os.pwrite(fd, f"{os.getpid()}\n".encode(), 0)
    _HELD[key] = (fd, 1)


def release_lock(path: str | os.PathLike) -> None:
    """Release one hold of the lock file ``path`` (see :func:`acquire_lock`)."""
    key = str(Path(path).resolve())
    if key not in _HELD:
        return
    fd, count = _HELD.pop(key)
    if count > 1:
        _HELD[key] = (fd, count - 1)
        return
    try:
        os.unlink(key)  # removed while held, so that a finished run leaves no file behind
    except OSError:
        pass
    os.close(fd)


def lock_folder(out: Path) -> bool:
    """Create the output folder ``out`` if missing and hold its lock (:data:`LOCK`) for this process; return
    whether it was created. :class:`~machdyn.errors.OperationalError` for a path that is a file, a folder that
    cannot be created or written, or another run holding it."""
    created = not out.exists()
    if out.exists() and not out.is_dir():
        raise OperationalError(f"cannot write the outputs to '{out}': it exists and is not a folder")
    try:
        out.mkdir(parents=True, exist_ok=True)
        acquire_lock(out / LOCK, f"the output folder '{out}'")
    except OSError as exc:
        raise OperationalError(f"cannot write the outputs to '{out}': {exc.strerror or exc}") from None
    return created


def unlock_folder(out: Path, created: bool) -> None:
    """Release :func:`lock_folder`'s hold; remove ``out`` if it was ``created`` and is left empty."""
    release_lock(out / LOCK)
    if created:
        try:
            out.rmdir()
        except OSError:
            pass


def fsync_folder(folder: str | os.PathLike) -> None:
    """Make the renames inside ``folder`` durable (where the system supports syncing a folder)."""
    try:
        fd = os.open(folder, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


def swap_folders(new: Path, target: Path) -> None:
    """Put the folder ``new`` in the place of ``target`` (which may not exist): ``target`` is renamed aside,
    ``new`` renamed in, the old one removed. Idempotent: called again after a kill at any point, it completes
    the swap (``new`` gone means it was already renamed in)."""
    old = target.parent / f".{target.name}.old"
    if new.exists():
        if target.exists():
            _remove_tree(old)
            os.rename(target, old)
        os.rename(new, target)
        fsync_folder(target.parent)
    _remove_tree(old)


class OutputSet:
    """The files of one run, written into a hidden staging folder inside ``out_dir`` and swapped in together.

    Until :meth:`commit` the folder keeps the previous run's set untouched; an interrupted or failed run removes
    its staging folder (and ``out_dir`` itself if the run created it and left it empty). :meth:`commit` first
    writes a journal of the set (the files, and folders such as an exploration's Parquet store to swap in with
    them) and syncs it: from then on the set is committed, and a run killed while moving the files in is
    completed by the next run that opens the folder. The files of the previous set that this run did not write
    (a CSV of a capability no longer in the file) are removed, so old and new never mix, but only those that the
    folder's manifest (:data:`MANIFEST`) lists with the digest of the content machdyn wrote and that still have
    it: regular files directly in the folder, of an output's kind, never a link, a hidden file or a ``protect``
    ed file (the problem file). Any other file is left alone and named in :attr:`notes`. The folder is locked
    (:data:`LOCK`) from the set's creation to its commit or abort.
    """

    def __init__(self, out_dir: str | os.PathLike, *, protect: tuple[str | os.PathLike, ...] = ()):
        self.out = Path(out_dir)
        self.protect = [str(Path(p).resolve()) for p in protect]
        #: what the commit left in place that an earlier run listed (one line each; see :func:`_apply`)
        self.notes: list[str] = []
        if self.out.exists() and not self.out.is_dir():
            raise OSError(f"the output path '{self.out}' exists and is not a directory")
        self._created = not self.out.exists()
        self.out.mkdir(parents=True, exist_ok=True)
        acquire_lock(self.out / LOCK, f"the output folder '{self.out}'")
        try:
            recover_outputs(self.out)
            self.stage = Path(tempfile.mkdtemp(dir=self.out, prefix=".machdyn-partial-"))
        except BaseException:
            release_lock(self.out / LOCK)
            raise
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

    def commit(self, folders: list[tuple[Path, Path]] | tuple = ()) -> list[Path]:
        """Move the set into place, with each ``(new, target)`` folder swapped in first; return the final
        paths."""
        journal = {"files": self.names, "folders": [[str(Path(a).resolve()), str(Path(b).resolve())]
                                                    for a, b in folders],
                   "digests": {n: _digest(self.stage / n) for n in self.names if (self.stage / n).is_file()},
                   "protect": self.protect}
        try:
            atomic_write_text(self.stage / JOURNAL, json.dumps(journal) + "\n")  # the commit point
            fsync_folder(self.stage)
            self.notes = _apply(self.out, self.stage)
        finally:
            release_lock(self.out / LOCK)
        return [self.out / name for name in self.names]

    def abort(self) -> None:
        """Remove the staging folder (and the output folder if this run created it and it is empty)."""
        _remove_tree(self.stage)
        release_lock(self.out / LOCK)
        if self._created:
            try:
                self.out.rmdir()
            except OSError:
                pass


def recover_outputs(out: Path) -> None:
    """Complete the sets of ``out`` that were committed but not fully moved in (a kill during a commit) and
    remove what interrupted runs left: staging folders never committed, temporary files."""
    for stale in sorted(out.glob(".machdyn-partial-*")):
        if (stale / JOURNAL).is_file():
            _apply(out, stale)  # its notes were the killed run's to say
        else:
            _remove_tree(stale)
    for leftover in out.glob(".*.part"):  # atomic_write's temporary files of a killed run
        leftover.unlink(missing_ok=True)


def _apply(out: Path, stage: Path) -> list[str]:
    """Move the committed set of ``stage`` into ``out`` (idempotent; see :meth:`OutputSet.commit`); return a
    note on the earlier outputs left in place (empty when there are none)."""
    journal = json.loads((stage / JOURNAL).read_text(encoding="utf-8"))
    for new, target in journal.get("folders", []):
        swap_folders(Path(new), Path(target))
    names = [n for n in journal.get("files", []) if _plain_name(n)]
    digests = journal.get("digests") or {}
    protected = [Path(p) for p in journal.get("protect", []) if isinstance(p, str)]
    previous, unreadable = _read_manifest(out)
    for name in names:
        if (stage / name).exists():
            os.replace(stage / name, out / name)
    kept = sorted(name for name, digest in previous.items()
                  if name not in names and not _remove_own_output(out, name, digest, protected))
    written = {name: digests.get(name) or _digest(out / name) for name in names if (out / name).is_file()}
    atomic_write_text(out / MANIFEST, json.dumps({"machdyn_outputs": MANIFEST_FORMAT, "files": written},
                                                 indent=1) + "\n")
    fsync_folder(out)
    _remove_tree(stage)
    notes = []
    if unreadable:
        notes.append(f"the list of earlier outputs ({out / MANIFEST}) {unreadable}; no earlier output was removed")
    if kept:
        shown = ", ".join(kept[:5]) + (f" and {len(kept) - 5} more" if len(kept) > 5 else "")
        notes.append(f"left in {out}/ as they are not unchanged outputs of an earlier run: {shown}")
    return notes


#: The format of :data:`MANIFEST`: ``{"machdyn_outputs": 2, "files": {name: sha-256 of the content written}}``.
MANIFEST_FORMAT = 2


#: The kinds of file an output set writes (results, tables, report, designs, drawings): no other is ever removed.
_OUTPUT_SUFFIXES = frozenset({".json", ".csv", ".html", ".js", ".toml", ".dxf"})


def _plain_name(name: object) -> bool:
    """A file name directly inside the output folder and not hidden (``.env``, ``.git``): the only names an output
    set writes or removes."""
    return (isinstance(name, str) and name != "" and not name.startswith(".") and "/" not in name
            and "\\" not in name and "\0" not in name)


def _digest(path: Path) -> str:
    """The SHA-256 of a file's content (hex)."""
    sha = hashlib.sha256()
    with open(path, "rb") as handle:
        for block in iter(lambda: handle.read(1 << 20), b""):
            sha.update(block)
    return sha.hexdigest()


def _read_manifest(out: Path) -> tuple[dict[str, str], str]:
    """The earlier outputs of ``out`` by name with their digests, and why the list cannot be trusted ("" if it
    can): only a manifest in machdyn's own format names files that a run may remove."""
    path = out / MANIFEST
    if path.is_symlink():
        return {}, "is a symbolic link"
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        return {}, ""
    except (OSError, ValueError):
        return {}, "cannot be read"
    if isinstance(data, list):  # an earlier machdyn's list of names, without digests: nothing is provably ours
        stale = sorted(n for n in data if _plain_name(n) and (out / n).exists())
        return {}, "holds no content digests" if stale else ""
    files = data.get("files") if isinstance(data, dict) and data.get("machdyn_outputs") == MANIFEST_FORMAT else None
    if not isinstance(files, dict):
        return {}, "is not in machdyn's format"
    return {n: d for n, d in files.items() if isinstance(n, str) and isinstance(d, str)}, ""


def _remove_own_output(out: Path, name: str, digest: str, protected: list[Path]) -> bool:
    """Remove ``out/name`` if it is a regular file (not a link) directly in ``out`` whose content is still the
    one machdyn wrote (``digest``) and is not a protected file (the problem file); True if it is gone."""
    if not _plain_name(name) or Path(name).suffix.lower() not in _OUTPUT_SUFFIXES:
        return False
    path = out / name
    try:
        info = path.lstat()
    except FileNotFoundError:
        return True
    except OSError:
        return False
    if not stat.S_ISREG(info.st_mode) or info.st_nlink > 1:  # a link could reach a file outside the folder
        return False
    try:
        if any(p.exists() and os.path.samefile(p, path) for p in protected):
            return False
        if _digest(path) != digest:
            return False
        path.unlink()
    except OSError:
        return False
    return True


def _remove_tree(path: Path) -> None:
    shutil.rmtree(path, ignore_errors=True)


#: ``machdyn watch``'s stamp of the report beside it, which an open report polls (see :mod:`machdyn.watching`)
STAMP_FILE = "report.stamp.js"

def stamp_script(stamp: str, invalid: dict[str, str] | None = None) -> str:
    """The text of ``report.stamp.js``: the stamp of the report on disk and, while the saved file cannot be run,
    what the open report shows in its banner (``message``: the lines ``check`` prints; ``at``: the time of the
    save)."""
    return (f"window.machdynStamp = {json.dumps(stamp)};\n"
            f"window.machdynInvalid = {json.dumps(invalid)};\n")
