"""The names of the first releases, kept working: ``load_conveyor_problem`` and ``run_conveyor``.

New code uses :mod:`machdyn.conveyor.kind` (``validate``, ``check``, ``run``) and
:func:`machdyn.conveyor.evaluate.evaluate`, whose :class:`~machdyn.conveyor.evaluate.ConveyorResult` is SI.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any

from ..results.labels import display_factor
from .evaluate import ConveyorResult, evaluate
from .labels import label_of
from .model import ConveyorProblem
from .schema import validate

__all__ = ["ConveyorProblem", "ConveyorResult", "ConveyorRun", "Quantity", "load_conveyor_problem", "run_conveyor"]


def load_conveyor_problem(data: dict, source: str | None = None) -> ConveyorProblem:
    """Validate the parsed TOML of a ``[screw_conveyor]`` file (same as :func:`machdyn.conveyor.schema.validate`)."""
    return validate(data, source)


@dataclass(frozen=True)
class Quantity:
    """One result: key, label, SI value and SI unit."""

    key: str
    label: str
    value: float
    unit: str


class ConveyorRun:
    """A :class:`ConveyorResult` with the accessors of the first releases (values in SI)."""

    def __init__(self, result: ConveyorResult):
        self.result = result

    def __getattr__(self, name: str) -> Any:
        return getattr(self.result, name)

    @property
    def quantities(self) -> list[Quantity]:
        return [Quantity(k, label_of(k).text, v, label_of(k).unit) for k, v in self.result.scalars.items()]

    def quantity(self, key: str) -> Quantity:
        return Quantity(key, label_of(key).text, self.result.scalars[key], label_of(key).unit)

    def scalars(self) -> dict[str, dict[str, Any]]:
        """``{key: {"value": SI float, "unit": SI unit}}``."""
        return {q.key: {"value": q.value, "unit": q.unit} for q in self.quantities}

    def summary_rows(self) -> list[tuple[str, str, str]]:
        """(quantity, value, unit) rows in display units."""
        rows = []
        for key, value in self.result.scalars.items():
            lab = label_of(key)
            unit = lab.shown_unit
            rows.append((lab.text, f"{value * display_factor(lab.unit, unit):.4g}", unit))
        return rows

    @property
    def checks(self) -> tuple[Any, ...]:
        """The checks in their display units (kW, MPa, mm, rpm), as the first releases showed them."""
        out = []
        for c in self.result.checks:
            value, limit, unit = c.shown()
            out.append(dataclasses.replace(c, value=value, limit=limit, unit=unit, display=unit))
        return tuple(out)


def run_conveyor(problem: ConveyorProblem) -> ConveyorRun:
    """Analyse the conveyor (see :func:`machdyn.conveyor.evaluate.evaluate`)."""
    return ConveyorRun(evaluate(problem))
