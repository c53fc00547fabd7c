"""Write a validated problem back as TOML text with units; loading the text gives an equal problem.

Each quantity is written in a readable unit (mm, deg) when that gives back exactly the same float, else in
its SI unit with all the digits needed (``"0.1 m"``, ``"21 rad/s"``, ``"0.30000000000000004 m"``).
"""

from __future__ import annotations

import json
import re
import types
import typing
from typing import Any

from pydantic import BaseModel

from ..errors import InputError
from ..units import parse_quantity, ureg
from .fields import PREFERRED_UNITS, Unit

_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(name: str) -> str:
    return name if _BARE_KEY.match(name) else json.dumps(name, ensure_ascii=False)


def _number_text(value: float) -> str:
    text = format(value, ".15g")
    return text if float(text) == value else repr(value)


def format_quantity_exact(value: float, meta: Unit) -> str:
    """``value`` (SI) as ``"<number> <unit>"`` that parses back to exactly ``value`` (the shortest such text
    among the kind's preferred units and the SI unit)."""
    candidates = [f"{_number_text(value)} {meta.unit}".strip()]
    for unit in PREFERRED_UNITS.get(meta.kind, ()):
        if unit == meta.unit:
            continue
        try:
            converted = float(ureg.Quantity(value, meta.unit).to(unit).magnitude)
        except Exception:  # noqa: BLE001 - an unusable preferred unit is skipped
            continue
        text = f"{_number_text(converted)} {unit}"
        if parse_quantity(text, meta.unit) == value:
            candidates.append(text)
    return min(candidates, key=lambda t: (len(t.split()[0]), candidates.index(t)))


def _unit_of(metadata: list[Any] | tuple[Any, ...]) -> Unit | None:
    return next((m for m in metadata if isinstance(m, Unit)), None)


def _split(annotation: Any) -> tuple[Any, tuple[Any, ...]]:
    """(bare type, Annotated metadata) of an annotation."""
    if typing.get_origin(annotation) is typing.Annotated:
        args = typing.get_args(annotation)
        return args[0], tuple(args[1:])
    return annotation, ()


def _members(annotation: Any) -> list[Any]:
    bare, _ = _split(annotation)
    if typing.get_origin(bare) in (typing.Union, types.UnionType):
        out = []
        for arg in typing.get_args(bare):
            out += _members(arg)
        return out
    return [annotation]


def _value(value: Any, annotation: Any, metadata: tuple[Any, ...] = ()) -> str:
    """The TOML text of ``value`` (inline), guided by its annotation for the units."""
    meta = _unit_of(metadata)
    if meta is None:
        for member in _members(annotation):
            _bare, md = _split(member)
            meta = meta or _unit_of(md)
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float) and meta is not None:
        return json.dumps(format_quantity_exact(value, meta))
    if isinstance(value, int | float):
        return _number_text(float(value)) if isinstance(value, float) else str(value)
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, BaseModel):
        parts = [f"{_key(k)} = {_value(v, a, md)}" for k, v, a, md in _fields(value)]
        return "{" + ", ".join(parts) + "}"
    if isinstance(value, dict):
        inner = _container_args(annotation, dict)
        value_ann = inner[1] if len(inner) == 2 else Any
        items = [f"{_key(k)} = {_value(v, value_ann)}" for k, v in value.items()]
        return "{" + ", ".join(items) + "}"
    if isinstance(value, tuple | list):
        args = _container_args(annotation, tuple) or _container_args(annotation, list)
        out = []
        for i, item in enumerate(value):
            if args and args[-1] is not Ellipsis and len(args) > i:
                item_ann = args[i]
            else:
                item_ann = args[0] if args else Any
            bare, md = _split(item_ann)
            out.append(_value(item, bare, md))
        return "[" + ", ".join(out) + "]"
    raise TypeError(f"cannot write {value!r} to TOML")


def _container_args(annotation: Any, origin: type) -> tuple[Any, ...]:
    for member in _members(annotation):
        bare, _ = _split(member)
        if typing.get_origin(bare) is origin:
            return typing.get_args(bare)
    return ()


def _fields(model: BaseModel):
    """(name, value, annotation, metadata) of the fields of ``model`` that are set (None is left out). A field the
    file did not give keeps its default and is left out too: written, a default could say twice what another
    table says once (a flywheel's ``speed_ratio = 1`` beside the drive train's stages), which the reader refuses."""
    given = model.model_fields_set
    for name, info in type(model).model_fields.items():
        value = getattr(model, name)
        if value is None or (name not in given and name != "type"):
            continue
        yield name, value, info.annotation, tuple(info.metadata)


def _is_table(value: Any) -> bool:
    return isinstance(value, BaseModel)


def _is_table_array(value: Any) -> bool:
    return isinstance(value, list) and bool(value) and all(isinstance(v, BaseModel) for v in value)


def _emit(model: BaseModel, path: str, lines: list[str], header: str) -> None:
    scalars, subs = [], []
    items = sorted(_fields(model), key=lambda f: f[0] != "type")
    for name, value, ann, md in items:
        if _is_table(value) or _is_table_array(value):
            subs.append((name, value))
        elif isinstance(value, list) and not value and typing.get_origin(_split(ann)[0]) is list:
            continue
        else:
            scalars.append(f"{_key(name)} = {_value(value, ann, md)}")
    if header and (scalars or not subs):
        lines += ["", header]
    lines += scalars
    for name, value in subs:
        sub = f"{path}.{_key(name)}" if path else _key(name)
        if _is_table(value):
            _emit(value, sub, lines, f"[{sub}]")
        else:
            for item in value:
                _emit_array_item(item, sub, lines)


def _emit_array_item(model: BaseModel, path: str, lines: list[str]) -> None:
    lines += ["", f"[[{path}]]"]
    for name, value, ann, md in sorted(_fields(model), key=lambda f: f[0] != "type"):
        if isinstance(value, list) and not value:
            continue
        lines.append(f"{_key(name)} = {_value(value, ann, md)}")


def dump_problem(problem: BaseModel) -> str:
    """The TOML text of a linkage or rotary-screen problem, with units; ``load_problem`` reads it back to
    an equal problem."""
    if not isinstance(problem, BaseModel):
        raise InputError(
            f"dump_problem writes linkage and rotary-screen problems; got a {type(problem).__name__}, whose "
            "problem file is the one it was read from."
        )
    lines: list[str] = []
    _emit(problem, "", lines, "")
    return "\n".join(lines).lstrip("\n") + "\n"
