"""Design sweeps in problem files: one quantity of the file takes several values, and every variant is
analysed in one vectorised call of the engine.

```toml
[sweep]
parameter = "mechanism.crank.length"     # the dotted path of any quantity of the file
values = ["30 mm", "35 mm", "40 mm"]      # or: start = "30 mm", stop = "45 mm", count = 16
```

Each value is checked by the same rule as the quantity it replaces (unit, sign); the variants are built into
engine models, stacked into one model with array parameters (:func:`machdyn.linkage.stack_designs`) and
analysed by :func:`machdyn.linkage.sweep` in bounded memory.
"""

from __future__ import annotations

import re
import typing
from dataclasses import dataclass
from typing import Any

import numpy as np
from pydantic import BaseModel, Field, model_validator

from ..errors import ProblemFileError
from .errors import did_you_mean
from .fields import FieldError, Unit, to_si


class SweepSpec(BaseModel):
    """``[sweep]``: the quantity to vary and its values (a list, or start/stop/count evenly spaced)."""

    model_config = {"extra": "forbid", "frozen": True}

    parameter: str
    values: list[Any] | None = None
    start: Any = None
    stop: Any = None
    count: int | None = Field(None, ge=2, le=1_000_000, strict=True)

    @model_validator(mode="after")
    def _one_way_of_giving_values(self):
        ranged = (self.start, self.stop, self.count)
        if self.values is None and any(v is None for v in ranged):
            raise ValueError("give either values = [...] or all of start, stop and count")
        if self.values is not None and any(v is not None for v in ranged):
            raise ValueError("give either values = [...] or start, stop and count, not both")
        if self.values is not None and len(self.values) < 1:
            raise ValueError("values must list at least one value")
        return self


@dataclass(frozen=True)
class SweepPlan:
    """The expanded sweep: the parameter's path, its values in SI and in the file's unit, and the variants."""

    parameter: str
    si_unit: str
    display_unit: str
    values_si: np.ndarray
    values_display: np.ndarray
    problems: tuple


def _segments(path: str) -> list[tuple[str, int | None]]:
    """``"loads.forces[0].fx"`` -> [("loads", None), ("forces", 0), ("fx", None)]."""
    out = []
    for part in path.split("."):
        match = re.fullmatch(r"([A-Za-z_][A-Za-z0-9_]*)(?:\[(\d+)\])?", part)
        if not match:
            raise FieldError(f"'{path}' is not a key path like 'mechanism.crank.length' or 'loads.forces[0].fx'")
        out.append((match.group(1), None if match.group(2) is None else int(match.group(2))))
    return out


def _target(problem: BaseModel, path: str) -> Unit:
    """The unit metadata of the quantity at ``path`` (e.g. ``mechanism.crank.length``)."""
    if path.split(".")[0] == "drive" and path.split(".")[-1] in ("start", "stop"):
        raise FieldError(f"'{path}' sets the crank angles, which every variant of a sweep shares")
    segments = _segments(path)
    node: Any = problem
    for i, (name, index) in enumerate(segments):
        fields = type(node).model_fields if isinstance(node, BaseModel) else {}
        if name not in fields:
            where = ".".join(p for p, _ in segments[:i]) or "the file"
            hint = did_you_mean(name, list(fields))
            raise FieldError(f"'{path}' is not a quantity of this file: {where} has no key '{name}'{hint}")
        value = getattr(node, name)
        if index is not None:
            if not isinstance(value, list | tuple) or index >= len(value):
                size = len(value) if isinstance(value, list | tuple) else 0
                raise FieldError(f"'{path}' refers to item {index} of '{name}', which has {size} item(s)")
        if i == len(segments) - 1:
            unit = _unit_of(fields[name])
            if unit is None or index is not None:
                raise FieldError(f"'{path}' is not a quantity with a unit, so it cannot be swept")
            return unit
        node = value if index is None else value[index]
        if node is None:
            raise FieldError(f"'{path}' is not set in this file; give it a value first")
    raise FieldError(f"'{path}' is not a quantity of this file")


def _unit_of(field) -> Unit | None:
    """The :class:`Unit` of a quantity field, also when it is optional (``Mass | None``)."""
    found = next((m for m in field.metadata if isinstance(m, Unit)), None)
    stack = [field.annotation]
    while found is None and stack:
        kind = stack.pop()
        found = next((m for m in getattr(kind, "__metadata__", ()) if isinstance(m, Unit)), None)
        stack += [a for a in typing.get_args(kind) if a is not type(None)]
    return found


def _replace_at(model: BaseModel, segments: list[tuple[str, int | None]], value: float) -> BaseModel:
    name, index = segments[0]
    if len(segments) == 1:
        return model.model_copy(update={name: value})
    child = getattr(model, name)
    if index is None:
        return model.model_copy(update={name: _replace_at(child, segments[1:], value)})
    items = list(child)
    items[index] = _replace_at(items[index], segments[1:], value)
    return model.model_copy(update={name: type(child)(items)})


def _display_unit(text: Any, meta: Unit) -> str:
    from ..units import Q_

    try:
        return f"{Q_(str(text)).units:~}" or meta.unit
    except Exception:  # the value itself is reported by to_si; fall back to SI here
        return meta.unit


def expand_sweep(problem: Any) -> SweepPlan:
    """The variants of a problem with a ``[sweep]`` table; every mistake reported at once with its path."""
    from ..units import convert

    spec: SweepSpec = problem.sweep
    try:
        meta = _target(problem, spec.parameter)
    except FieldError as exc:
        raise ProblemFileError([("sweep.parameter", str(exc))]) from None
    problems = []
    if spec.values is not None:
        raw = list(spec.values)
        si = []
        for i, value in enumerate(raw):
            try:
                si.append(to_si(value, meta))
            except FieldError as exc:
                problems.append((f"sweep.values[{i}]", f"{exc} (for {spec.parameter})"))
        display = _display_unit(raw[0], meta)
    else:
        si = []
        for key in ("start", "stop"):
            try:
                si.append(to_si(getattr(spec, key), meta))
            except FieldError as exc:
                problems.append((f"sweep.{key}", f"{exc} (for {spec.parameter})"))
        display = _display_unit(spec.start, meta)
        if not problems:
            si = list(np.linspace(si[0], si[1], spec.count))
    if problems:
        raise ProblemFileError(problems)
    values_si = np.asarray(si, dtype=float)
    segments = _segments(spec.parameter)
    variants = tuple(_replace_at(problem, segments, float(v)) for v in values_si)
    shown = np.array([convert(v, meta.unit, display) for v in values_si]) if display != meta.unit else values_si
    return SweepPlan(spec.parameter, meta.unit, display, values_si, shown, variants)
