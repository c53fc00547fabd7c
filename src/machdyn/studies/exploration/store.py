"""The Parquet folder of an exploration: one file per partition, kept as a transaction.

```
sweep.parquet/
  _exploration.json        what the partitions belong to (fingerprint, design space, columns and units)
  part-000000.parquet      designs 0 .. P-1: the quantities (SI), assembled, regular, summaries
  part-000001.parquet      ...
```

What a reader of the folder can rely on:

- **A file present is complete and durable**: a partition is written under a temporary name, synced to disk and
  renamed into place (the folder synced after the rename).
- **Every partition is verified before it is reused**: its schema records the exploration's fingerprint, its
  partition number, its first design, its number of rows and a SHA-256 checksum of its columns; a resumed run
  reads each partition back and recomputes (and says so) any that does not match: copied from another
  exploration, duplicated under another number, truncated, or with flipped bytes.
- **Old and new never mix**: a run of the same problem and design space resumes in place; a run of a changed
  problem writes its partitions into a hidden folder beside the store (``.NAME.pending-<fingerprint>``) and
  replaces the store only once every partition is written (the old one is renamed aside, the new one renamed
  in, the old one removed). An interrupted or failed run of a changed problem leaves the previous store whole;
  run again, it resumes in its pending folder.
- **Never another's store**: the manifest records the problem file the store was written for; a folder of
  partitions without a readable manifest, or the store of another problem file, is refused unless the run is
  asked to replace it (``replace``, the command line's ``--replace``); this problem file's own earlier store is
  replaced as above, and the run says so.
- **One run at a time**: a lock file beside the store (``.NAME.lock``) refuses a second run at once; the
  system releases it when the run ends, however it ends.

Every column carries its unit (``unit``, SI) and its label in the Arrow schema's field metadata; the folder
reads back as one table with ``pandas.read_parquet(folder)`` or ``pyarrow.dataset`` (hidden files and folders
are not read).
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
from pathlib import Path
from typing import Any

import numpy as np

from ...errors import OperationalError
from ...outputs import acquire_lock, atomic_write_text, fsync_folder, release_lock, swap_folders

MANIFEST = "_exploration.json"
_PART = re.compile(r"^part-(\d{6})\.parquet$")
_TEMPORARY = re.compile(r"^\.part-\d{6}\.parquet\.\d+\.tmp$")


def part_name(index: int) -> str:
    return f"part-{index:06d}.parquet"


def checksum(columns: dict[str, np.ndarray]) -> str:
    """SHA-256 of a partition's columns (names, types and bytes, in order)."""
    digest = hashlib.sha256()
    for name, data in columns.items():
        array = np.asarray(data)
        digest.update(name.encode())
        if array.dtype.kind in "OUS":
            # text columns (a design's status): their characters, not the bytes of pointers or padded cells,
            # so that a column read back from Parquet (object dtype) checks as it was written (str dtype)
            digest.update(b"text")
            for item in array.ravel():
                digest.update(str(item).encode() + b"\0")
            continue
        array = np.ascontiguousarray(array)
        digest.update(array.dtype.str.encode())
        digest.update(array.tobytes())
    return digest.hexdigest()


def _manifest(folder: Path) -> dict[str, Any]:
    """The store's manifest, or {} if there is none or it cannot be read."""
    try:
        value = json.loads((folder / MANIFEST).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    return value if isinstance(value, dict) else {}


def _manifest_fingerprint(folder: Path) -> str | None:
    value = _manifest(folder).get("fingerprint")
    return value if isinstance(value, str) else None


class PartitionStore:
    """The partitions of one exploration on disk. ``units`` maps each column to (SI unit, label).

    ``folder`` is where partitions are written now: the store itself (a new store, or the same exploration
    resumed) or its pending folder (a changed exploration, until :meth:`finish`). ``notes`` collects what a run
    should tell its user (partitions recomputed because they did not match)."""

    def __init__(self, folder: str | os.PathLike, fingerprint: str, info: dict[str, Any], *,
                 source: str | os.PathLike | None = None, replace: bool = False):
        self.final = Path(folder)
        self.fingerprint = fingerprint
        self.notes: list[str] = []
        self.source = str(Path(source).resolve()) if source else None
        self.replace = replace
        info = {**info, "problem_file": self.source}
        if self.final.exists() and not self.final.is_dir():
            raise OperationalError(f"the exploration store '{self.final}' exists and is not a folder; remove it "
                                   f"or choose another store")
        try:
            self.final.parent.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise OperationalError(f"cannot create the folder of the exploration store '{self.final}': "
                                   f"{exc.strerror or exc}") from None
        self.lock = self.final.parent / f".{self.final.name}.lock"
        try:
            acquire_lock(self.lock, f"the exploration store '{self.final}'")
        except PermissionError as exc:
            raise OperationalError(f"cannot write beside the exploration store '{self.final}': "
                                   f"{exc.strerror or exc}") from None
        try:
            self.folder = self._open(info)
        except BaseException:
            release_lock(self.lock)
            raise

    def _pending(self, fingerprint: str) -> Path:
        return self.final.parent / f".{self.final.name}.pending-{fingerprint[:16]}"

    def _open(self, info: dict[str, Any]) -> Path:
        final = self.final
        old = final.parent / f".{final.name}.old"
        mine = self._pending(self.fingerprint)
        if not final.exists() and old.exists():
            # A swap was cut between its two renames: finish it if the new store was complete, else undo it.
            complete = [p for p in final.parent.glob(f".{final.name}.pending-*") if _complete(p)]
            swap_folders(complete[0], final) if complete else os.rename(old, final)
        shutil.rmtree(old, ignore_errors=True)
        for other in final.parent.glob(f".{final.name}.pending-*"):
            if other != mine:  # a changed run that never completed: nothing of it was ever the store
                shutil.rmtree(other, ignore_errors=True)
        if final.is_dir():
            previous = _manifest_fingerprint(final)
            self._refuse_another(final, previous)
        else:
            previous = None
        in_place = not final.exists() or previous == self.fingerprint or not any(final.iterdir())
        folder = final if in_place else mine
        if in_place:
            shutil.rmtree(mine, ignore_errors=True)
        try:
            folder.mkdir(parents=True, exist_ok=True)
            for leftover in folder.iterdir():  # temporary files of a killed run
                if _TEMPORARY.match(leftover.name):
                    leftover.unlink()
            if _manifest_fingerprint(folder) != self.fingerprint:
                atomic_write_text(folder / MANIFEST, json.dumps({"fingerprint": self.fingerprint, **info},
                                                                indent=2) + "\n")
        except PermissionError as exc:
            raise OperationalError(f"cannot write the exploration store '{folder}': {exc.strerror or exc}") from None
        return folder

    def _refuse_another(self, final: Path, previous: str | None) -> None:
        """Refuse a folder that is not this problem's store: files that are not partitions, always; partitions
        without a readable manifest, or the store of another problem file, unless ``replace``. A store of this
        problem file written for another problem or design space is replaced (when this run completes), and
        the run says so."""
        names = [p.name for p in final.iterdir()]
        foreign = [n for n in names if not (_PART.match(n) or _TEMPORARY.match(n) or n in (MANIFEST, ".complete"))]
        if previous is None and foreign:
            raise OperationalError(f"'{final}' holds files that are not an exploration's partitions "
                                   f"({', '.join(sorted(foreign)[:3])}); choose another store")
        if previous == self.fingerprint or not names:
            return
        ask = "choose another store (--out, or [sweep] store), or run with --replace to replace it"
        if previous is None:
            if not self.replace:
                raise OperationalError(f"'{final}' holds partitions but no readable {MANIFEST}, so it is not known "
                                       f"to be an exploration store of machdyn; {ask}")
            self.notes.append(f"The folder '{final}' (partitions without a readable {MANIFEST}) is replaced by "
                              "this exploration (--replace).")
            return
        manifest = _manifest(final)
        owner = manifest.get("problem_file")
        if "problem_file" in manifest and owner != self.source:  # a store without the key predates it: ours
            if not self.replace:
                whose = f"the problem file {owner}" if isinstance(owner, str) else "a problem given as text"
                raise OperationalError(f"'{final}' holds the exploration of {whose}, not of this problem; {ask}")
            self.notes.append(f"The exploration store '{final}' of another problem is replaced by this one "
                              "(--replace).")
            return
        self.notes.append(f"The exploration store '{final}' held this problem's exploration of another problem or "
                          "design space; it is replaced by this one when it completes.")

    @property
    def pending(self) -> bool:
        """True while a changed exploration is written aside (the store still holds the previous one)."""
        return self.folder != self.final

    def done(self) -> set[int]:
        """The indices of the partitions on disk (not yet verified: see :meth:`verified`)."""
        return {int(m.group(1)) for p in self.folder.iterdir() if (m := _PART.match(p.name))}

    def write(self, index: int, columns: dict[str, np.ndarray], units: dict[str, tuple[str, str]]) -> Path:
        """Write partition ``index`` durably and atomically; return its path."""
        import pyarrow as pa
        import pyarrow.parquet as pq

        fields = []
        arrays = []
        for name, data in columns.items():
            unit, label = units.get(name, ("", name))
            array = pa.array(data)
            fields.append(pa.field(name, array.type, metadata={"unit": unit, "label": label}))
            arrays.append(array)
        design = np.asarray(columns["design"])
        metadata = {"machdyn.exploration": self.fingerprint, "machdyn.partition": str(index),
                    "machdyn.first_design": str(int(design[0]) if design.size else -1),
                    "machdyn.rows": str(design.size), "machdyn.sha256": checksum(columns)}
        schema = pa.schema(fields, metadata=metadata)
        table = pa.Table.from_arrays(arrays, schema=schema)
        target = self.folder / part_name(index)
        tmp = self.folder / f".{target.name}.{os.getpid()}.tmp"
        try:
            pq.write_table(table, tmp)
            fd = os.open(tmp, os.O_RDONLY)
            try:
                os.fsync(fd)
            finally:
                os.close(fd)
            os.replace(tmp, target)
            fsync_folder(self.folder)
        except OSError as exc:  # a full disk, a folder no longer writable: the partitions written stay
            tmp.unlink(missing_ok=True)
            raise OperationalError(f"cannot write partition {index} to the exploration store '{self.folder}': "
                                   f"{exc.strerror or exc}; run again to resume") from None
        except BaseException:
            tmp.unlink(missing_ok=True)
            raise
        return target

    def read(self, index: int) -> dict[str, np.ndarray]:
        """The columns of partition ``index`` as NumPy arrays."""
        import pyarrow.parquet as pq

        table = pq.read_table(self.folder / part_name(index))
        return {name: table.column(name).to_numpy() for name in table.column_names}

    def verified(self, index: int, bounds: tuple[int, int]) -> dict[str, np.ndarray] | None:
        """The columns of partition ``index`` if it belongs to this exploration, holds designs ``bounds`` (first,
        one past the last) and matches its checksum; otherwise the file is removed, the reason noted, and None
        returned (the partition is then computed again)."""
        import pyarrow.parquet as pq

        path = self.folder / part_name(index)
        start, stop = bounds
        try:
            table = pq.read_table(path)
            meta = {k.decode(): v.decode() for k, v in (table.schema.metadata or {}).items()}
            columns = {name: table.column(name).to_numpy() for name in table.column_names}
            design = columns.get("design")
            if meta.get("machdyn.exploration") != self.fingerprint:
                reason = "it belongs to another exploration"
            elif meta.get("machdyn.partition") != str(index):
                reason = f"it is partition {meta.get('machdyn.partition')} under another number"
            elif design is None or design.size != stop - start or meta.get("machdyn.rows") != str(stop - start):
                reason = f"it holds {0 if design is None else design.size} rows, not {stop - start}"
            elif not np.array_equal(design, np.arange(start, stop)):
                reason = f"its designs are not {start}..{stop - 1}"
            elif meta.get("machdyn.sha256") != checksum(columns):
                reason = "its checksum does not match its content"
            else:
                return columns
        except Exception as exc:  # noqa: BLE001 - any unreadable file is recomputed, whatever pyarrow raised
            reason = f"it cannot be read ({type(exc).__name__})"
        self.notes.append(f"Partition {index} of the exploration store was computed again: {reason}.")
        path.unlink(missing_ok=True)
        return None

    def finish(self, *, defer: bool = False) -> tuple[Path, Path] | None:
        """End the run's writing: a pending exploration, now complete, replaces the store; with ``defer`` it is
        only marked complete and ``(pending, store)`` returned, for the caller to swap in together with its
        other outputs (:meth:`machdyn.outputs.OutputSet.commit`). Releases the lock."""
        try:
            if not self.pending:
                return None
            atomic_write_text(self.folder / ".complete", self.fingerprint + "\n")
            fsync_folder(self.folder)
            if defer:
                return self.folder, self.final
            swap_folders(self.folder, self.final)
            self.folder = self.final
            return None
        finally:
            self.close()

    def close(self) -> None:
        """Release the store's lock (the partitions written stay)."""
        release_lock(self.lock)


def _complete(folder: Path) -> bool:
    return (folder / ".complete").is_file()


def read_exploration(folder: str | os.PathLike):
    """The whole exploration in ``folder`` as a pandas DataFrame, rows in design order (for spaces that fit in
    memory; read large ones by partition or with ``pyarrow.dataset``)."""
    import pandas as pd

    folder = Path(folder)
    parts = sorted(p for p in folder.iterdir() if _PART.match(p.name))
    if not parts:
        return pd.DataFrame()
    return pd.concat([pd.read_parquet(p) for p in parts], ignore_index=True)


def column_units(folder: str | os.PathLike) -> dict[str, str]:
    """The SI unit of every column of the exploration in ``folder``, read from the Parquet schema."""
    import pyarrow.parquet as pq

    parts = sorted(p for p in Path(folder).iterdir() if _PART.match(p.name))
    schema = pq.read_schema(parts[0])
    return {f.name: (f.metadata or {}).get(b"unit", b"").decode() for f in schema}
