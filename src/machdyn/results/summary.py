"""The summary table of a run: one builder, used by the command line, the report and the Python API alike."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..notebook import ShownInNotebook
from .store import Results


@dataclass(frozen=True)
class SummaryRow:
    """One line of the summary: the result's key, its label, its value in the display unit and that unit."""

    key: str
    label: str
    value: Any
    unit: str


@dataclass(frozen=True)
class Summary(ShownInNotebook):
    """The summary table of a run (its heading and rows)."""

    title: str
    rows: tuple[SummaryRow, ...]

    def as_tuples(self) -> list[tuple[str, Any, str]]:
        """(label, value, unit) per row."""
        return [(r.label, r.value, r.unit) for r in self.rows]

    def frame(self):
        """The rows as a pandas DataFrame with columns key, quantity, value, unit."""
        import pandas as pd

        return pd.DataFrame([(r.key, r.label, r.value, r.unit) for r in self.rows],
                            columns=["key", "quantity", "value", "unit"])


def _magnitude(value: Any) -> float:
    arr = np.abs(np.atleast_1d(np.asarray(value, dtype=float)))
    return float(np.nanmax(arr)) if arr.size and np.any(np.isfinite(arr)) else 0.0


def _zero_roundoff(value: Any, scale: float) -> Any:
    # Values that vanish in exact arithmetic (a loss-free cycle's mean torque) come out as round-off: show 0.
    limit = 1e-9 * scale
    if isinstance(value, list):
        return [0.0 if isinstance(v, float) and abs(v) <= limit else v for v in value]
    if isinstance(value, float) and abs(value) <= limit:
        return 0.0
    return value


def summarise(title: str, results: Results, keys: Iterable[str]) -> Summary:
    """The summary rows of ``keys`` (those present in ``results``), each labelled and in its display unit."""
    rows = []
    for key in keys:
        if key not in results:
            continue
        text, value, unit = results.shown(key)
        reference = results.label(key).zero_below
        if reference is not None and reference in results:
            value = _zero_roundoff(value, _magnitude(results.shown(reference)[1]))
        rows.append(SummaryRow(key, text, value, unit))
    return Summary(title, tuple(rows))
