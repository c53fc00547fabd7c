"""Quantities of a problem by their path in the file (``mechanism.crank.length``, ``loads.forces[0].fx``,
``mechanism.coupler_point[0]``): their unit and sign rule, their value, and a copy of the problem with another
value there. Used by the sweep, the exploration, the optimiser and the balance over operating states."""

from __future__ import annotations

import re
import tomllib
import typing
from typing import Any

import numpy as np
from pydantic import BaseModel, ValidationError

from ..errors import ProblemFileError
from .dumper import dump_problem
from .errors import did_you_mean, problems_from
from .fields import FieldError, Unit

__all__ = ["assign", "quantity_unit", "segments", "value_at"]


def segments(path: str) -> list[tuple[str, int | None]]:
    """``"loads.forces[0].fx"`` -> [("loads", None), ("forces", 0), ("fx", None)]."""
    out = []
    for part in path.split("."):
        match = re.fullmatch(r"([A-Za-z_][A-Za-z0-9_]*)(?:\[(\d+)\])?", part)
        if not match:
            raise FieldError(f"'{path}' is not a key path like 'mechanism.crank.length' or 'loads.forces[0].fx'")
        out.append((match.group(1), None if match.group(2) is None else int(match.group(2))))
    return out


def _unit_in(annotation: Any, index: int | None) -> Unit | None:
    """The :class:`Unit` of an annotation (or of item ``index`` of a tuple/list annotation)."""
    stack = [annotation]
    while stack:
        kind = stack.pop()
        found = next((m for m in getattr(kind, "__metadata__", ()) if isinstance(m, Unit)), None)
        if found is not None and index is None:
            return found
        args = [a for a in typing.get_args(kind) if a is not type(None) and a is not Ellipsis]
        if index is not None and typing.get_origin(kind) in (tuple, list):
            item = args[index] if len(args) > index else (args[0] if args else None)
            return _unit_in(item, None) if item is not None else None
        stack += args
    return None


def quantity_unit(problem: BaseModel, path: str) -> Unit:
    """The unit and sign rule of the quantity at ``path``; a :class:`FieldError` with a did-you-mean if the
    path names no quantity of the file. A table of named entries (a custom body's ``points``) is entered by the
    entry's name: ``mechanism.bodies[1].points.C[0]``."""
    parts = segments(path)
    node: Any = problem
    entry_type: Any = None  # the type of the entries of ``node`` when it is a table of named entries
    metadata: list[Any]
    for i, (name, index) in enumerate(parts):
        where = ".".join(p for p, _ in parts[:i]) or "the file"
        if isinstance(node, dict):
            if name not in node:
                raise FieldError(f"'{path}' is not a quantity of this file: {where} has no entry '{name}'"
                                 f"{did_you_mean(name, [str(k) for k in node])}")
            value, annotation, metadata = node[name], entry_type, []
        else:
            fields = type(node).model_fields if isinstance(node, BaseModel) else {}
            if name not in fields:
                raise FieldError(f"'{path}' is not a quantity of this file: {where} has no key '{name}'"
                                 f"{did_you_mean(name, list(fields))}")
            value, annotation, metadata = getattr(node, name), fields[name].annotation, list(fields[name].metadata)
        if value is None:
            raise FieldError(f"'{path}' is not set in this file; give it a value first")
        if index is not None and (not isinstance(value, list | tuple) or index >= len(value)):
            size = len(value) if isinstance(value, list | tuple) else 0
            raise FieldError(f"'{path}' refers to item {index} of '{name}', which has {size} item(s)")
        last = i == len(parts) - 1
        if last:
            unit = _unit_in(annotation, index) if index is not None else (
                next((m for m in metadata if isinstance(m, Unit)), None) or _unit_in(annotation, None))
            if unit is None or isinstance(value if index is None else value[index], BaseModel | dict):
                raise FieldError(f"'{path}' is not a quantity with a unit, so it cannot vary")
            return unit
        node = value if index is None else value[index]
        entry_type = _entry_type(annotation) if isinstance(node, dict) else None
    raise FieldError(f"'{path}' is not a quantity of this file")


def _entry_type(annotation: Any) -> Any:
    """The value type of a ``dict[key, value]`` annotation (through Optional and Annotated), None if none."""
    stack = [annotation]
    while stack:
        kind = stack.pop()
        args = typing.get_args(kind)
        if typing.get_origin(kind) is dict and len(args) == 2:
            return args[1]
        stack += [a for a in args if a is not type(None)]
    return None


def assign(model: BaseModel, path: str, value: Any) -> BaseModel:
    """A copy of ``model`` with the quantity at ``path`` replaced by ``value`` (a float or an array of
    designs; not re-validated, so the caller checks the rules)."""
    return _assign(model, segments(path), value)


def _assign(model: Any, parts: list[tuple[str, int | None]], value: Any) -> Any:
    name, index = parts[0]
    child = model[name] if isinstance(model, dict) else getattr(model, name)
    if len(parts) == 1:
        if index is None:
            return _with(model, name, value)
        items = list(child)
        items[index] = value
        if np.ndim(value):
            # A point (x, y) with one coordinate per design: the other coordinate as an array too, so that the
            # point converts to one (2, N) array.
            items = [np.broadcast_to(np.asarray(v, dtype=float), np.shape(value)) for v in items]
        return _with(model, name, type(child)(items))
    if index is None:
        return _with(model, name, _assign(child, parts[1:], value))
    items = list(child)
    items[index] = _assign(items[index], parts[1:], value)
    return _with(model, name, type(child)(items))


def _with(model: Any, name: str, value: Any) -> Any:
    """A copy of ``model`` (a table or a table of named entries) with ``name`` set to ``value``."""
    if isinstance(model, dict):
        return {**model, name: value}
    return model.model_copy(update={name: value})


def value_at(model: Any, path: str) -> float:
    """The value [SI] of the quantity at ``path`` of a validated problem."""
    node = model
    for name, index in segments(path):
        node = node[name] if isinstance(node, dict) else getattr(node, name)
        if index is not None:
            node = node[index]
    return float(node)


def design_problem(problem: Any, values: typing.Mapping[str, float]) -> Any:
    """The validated problem of one design: ``problem`` with each quantity path of ``values`` set to its SI
    value and without its design-space tables (``[sweep]``, ``[optimise]``), written out and read back so that
    every field's rule is checked as for a file (by the problem's own schema: this package knows no kind); it
    runs on its own, its model built where it is analysed. Raises :class:`~machdyn.errors.ProblemFileError`
    naming each broken rule."""

    schema = type(problem)
    candidate = problem.model_copy(update={t: None for t in ("sweep", "optimise") if t in schema.model_fields})
    for path, value in values.items():
        candidate = assign(candidate, path, float(value))
    try:
        return schema.model_validate(tomllib.loads(dump_problem(candidate)))
    except ValidationError as exc:
        raise ProblemFileError(problems_from(exc, schema)) from None
