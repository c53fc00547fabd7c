"""The Parquet folder of an exploration: one file per partition, written atomically as it finishes.

```
sweep.parquet/
  _exploration.json        what the partitions belong to (fingerprint, design space, columns and units)
  part-000000.parquet      designs 0 .. P-1: the quantities (SI), assembled, regular, summaries
  part-000001.parquet      ...
```

A partition file is written under a temporary name and renamed into place, so a file present is complete. A
run finding the folder with the same fingerprint keeps its partitions and computes only the missing ones (an
interrupted run resumes); a folder of another problem or design space is emptied of its partitions first.
Every column carries its unit (``unit``, SI) and its label in the Arrow schema's field metadata; the folder
reads back as one table with ``pandas.read_parquet(folder)`` or ``pyarrow.dataset``.
"""

from __future__ import annotations

import json
import os
import re
from pathlib import Path
from typing import Any

import numpy as np

from ..outputs import atomic_write_text

MANIFEST = "_exploration.json"
_PART = re.compile(r"^part-(\d{6})\.parquet$")


def part_name(index: int) -> str:
    return f"part-{index:06d}.parquet"


class PartitionStore:
    """The partitions of one exploration on disk. ``units`` maps each column to (SI unit, label)."""

    def __init__(self, folder: str | os.PathLike, fingerprint: str, info: dict[str, Any]):
        self.folder = Path(folder)
        if self.folder.exists() and not self.folder.is_dir():
            raise OSError(f"the exploration store '{self.folder}' exists and is not a folder")
        self.folder.mkdir(parents=True, exist_ok=True)
        self.fingerprint = fingerprint
        manifest = self.folder / MANIFEST
        try:
            previous = json.loads(manifest.read_text(encoding="utf-8")).get("fingerprint")
        except (OSError, ValueError, AttributeError):
            previous = None
        if previous != fingerprint:
            for path in self.folder.iterdir():  # partitions of another problem must never mix with these
                if _PART.match(path.name) or (path.name.startswith(".part-") and path.name.endswith(".tmp")):
                    path.unlink()
        atomic_write_text(manifest, json.dumps({"fingerprint": fingerprint, **info}, indent=2) + "\n")

    def done(self) -> set[int]:
        """The indices of the partitions on disk."""
        return {int(m.group(1)) for p in self.folder.iterdir() if (m := _PART.match(p.name))}

    def write(self, index: int, columns: dict[str, np.ndarray], units: dict[str, tuple[str, str]]) -> Path:
        """Write partition ``index`` atomically; return its path."""
        import pyarrow as pa
        import pyarrow.parquet as pq

        fields = []
        arrays = []
        for name, data in columns.items():
            unit, label = units.get(name, ("", name))
            array = pa.array(data)
            fields.append(pa.field(name, array.type, metadata={"unit": unit, "label": label}))
            arrays.append(array)
        schema = pa.schema(fields, metadata={"machdyn.exploration": self.fingerprint})
        table = pa.Table.from_arrays(arrays, schema=schema)
        target = self.folder / part_name(index)
        tmp = self.folder / f".{target.name}.{os.getpid()}.tmp"
        try:
            pq.write_table(table, tmp)
            os.replace(tmp, target)
        except BaseException:
            tmp.unlink(missing_ok=True)
            raise
        return target

    def read(self, index: int) -> dict[str, np.ndarray]:
        """The columns of partition ``index`` as NumPy arrays."""
        import pyarrow.parquet as pq

        table = pq.read_table(self.folder / part_name(index))
        return {name: table.column(name).to_numpy() for name in table.column_names}


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
