"""Results of a run: SI values by key, each with its label and unit, shown in its display unit.

results.json holds every value in SI (:data:`UNITS`); display units belong to the summary, the report and the
command line's table only.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from ..notebook import ShownInNotebook
from .catalogue import label_for
from .labels import Label, display_factor

#: The unit system of every ``value`` in results.json (its top-level ``"units"``).
UNITS = "SI"


def _scaled(value: Any, factor: float) -> Any:
    if factor == 1.0 or isinstance(value, bool) or value is None or isinstance(value, str):
        return value
    if isinstance(value, list | tuple):
        return [_scaled(v, factor) for v in value]
    return value * factor


@dataclass(frozen=True)
class Results(ShownInNotebook):
    """Every scalar result of a run in SI: ``values[key]`` (a float, or one value per design variant) and the
    :class:`~machdyn.results.labels.Label` of each key (text, SI unit, display unit)."""

    values: Mapping[str, Any] = field(default_factory=dict)
    labels: Mapping[str, Label] = field(default_factory=dict)

    def __contains__(self, key: str) -> bool:
        return key in self.values

    def __getitem__(self, key: str) -> Any:
        return self.values[key]

    def label(self, key: str) -> Label:
        return self.labels[key]

    def shown(self, key: str) -> tuple[str, Any, str]:
        """(label text, value in the display unit, display unit) of ``key``."""
        lab = self.labels[key]
        unit = lab.shown_unit
        return lab.text, _scaled(self.values[key], display_factor(lab.unit, unit)), unit

    def as_json(self) -> dict[str, dict[str, Any]]:
        """The ``scalars`` of results.json: ``{key: {"value", "unit"}}`` with the value in SI and the SI unit of
        its label (m, rad, rad/s, N*m, kg ...); a key shown in another unit (mm, deg, rpm) adds ``"shown":
        {"value", "unit"}``, the value as the summary and the report give it."""
        out: dict[str, dict[str, Any]] = {}
        for key, value in self.values.items():
            entry: dict[str, Any] = {"value": value, "unit": self.labels[key].unit}
            _text, shown, unit = self.shown(key)
            if unit != entry["unit"]:
                entry["shown"] = {"value": shown, "unit": unit}
            out[key] = entry
        return out

def collect(values: Mapping[str, Any], known: Mapping[str, Label], units: Mapping[str, str]) -> Results:
    """Results from SI ``values``, labelled from ``known`` (and patterns), with ``units`` for run-time keys."""
    labels = {k: label_for(k, known, units.get(k)) for k in values}
    return Results(dict(values), labels)
