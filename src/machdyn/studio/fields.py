"""The editable quantities of a problem file, and the file with new values put in, its comments and layout kept.

A quantity is a string value ``"<number> <unit>"`` (``length = "40 mm"``, or an element of an array such as
``coupler_point = ["60 mm", "25 mm"]``) or a plain TOML number (``positions = 360``). Each has a key spelled
as ``machdyn check`` spells the path of a mistake (``mechanism.crank.length``, ``loads.torques[0].torque``,
``mechanism.coupler_point[1]``), so that a message of the loader lands beside its field. The ``[meta]`` table
holds no quantity. An edited value keeps the field's unit; the new text is whatever the user typed followed by
that unit, so the loader judges it exactly as it judges the file.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from typing import Any

import tomlkit
from tomlkit.items import AoT, Array, Bool, Float, InlineTable, Integer, String, Table

from ..units import quantity_of_text

QUANTITY = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")
MAX_TYPED = 40  # characters of one typed value: a number and nothing more
SKIPPED = ("meta",)

Path = tuple[str | int, ...]


@dataclass(frozen=True)
class Field:
    """One editable quantity: its key (as check names it), where it sits in the document, its number as
    written, its unit (empty for a plain number), the SI value of one unit (None where the unit is not one
    pint knows, e.g. a unit written wrongly) and whether it is a TOML integer."""

    key: str
    path: Path
    number: str
    unit: str
    si_per_unit: float | None
    integer: bool = False

    def as_json(self) -> dict[str, Any]:
        return {"key": self.key, "number": self.number, "unit": self.unit, "si": self.si_per_unit,
                "integer": self.integer}


def key_of(path: Path) -> str:
    """``("loads", "torques", 0, "torque")`` -> ``"loads.torques[0].torque"`` (the loader's spelling)."""
    text = ""
    for part in path:
        text += f"[{part}]" if isinstance(part, int) else (f".{part}" if text else str(part))
    return text


def _si_per_unit(unit: str) -> float | None:
    try:
        return float(quantity_of_text(f"1 {unit}").to_base_units().magnitude)
    except Exception:  # noqa: BLE001 - any unit pint cannot read: the field is still editable, not draggable
        return None


def _leaf(path: Path, item: Any) -> Field | None:
    if isinstance(item, Bool):
        return None
    if isinstance(item, Integer | Float):
        value = float(item)
        if not math.isfinite(value):
            return None
        return Field(key_of(path), path, str(item.as_string()), "", 1.0, isinstance(item, Integer))
    if isinstance(item, String):
        match = QUANTITY.match(str(item))
        if match is None:
            return None
        number, unit = match.groups()
        return Field(key_of(path), path, number, unit, _si_per_unit(unit) if unit else 1.0)
    return None


def _walk(path: Path, item: Any) -> Iterator[Field]:
    if isinstance(item, Table | InlineTable) or isinstance(item, dict):
        for name, sub in item.items():
            yield from _walk((*path, str(name)), sub)
    elif isinstance(item, AoT):
        for i, sub in enumerate(item):
            yield from _walk((*path, i), sub)
    elif isinstance(item, Array | list):
        for i, sub in enumerate(item):
            yield from _walk((*path, i), sub)
    else:
        found = _leaf(path, item)
        if found is not None:
            yield found


def fields_of(document: tomlkit.TOMLDocument) -> list[Field]:
    """Every editable quantity of a parsed problem file, in the file's order."""
    out: list[Field] = []
    for name, item in document.items():
        if name not in SKIPPED:
            out += _walk((str(name),), item)
    return out


def _container(document: Any, path: Path) -> Any:
    node = document
    for part in path[:-1]:
        node = node[part]
    return node


def edited_text(text: str, edits: Mapping[str, str]) -> str:
    """The problem file ``text`` with each field named in ``edits`` (key -> the number as typed) replaced, every
    other byte kept. A typed value that is not a plain number is put in as typed, for the loader to refuse with
    its own message; an unknown key is a :class:`KeyError`, a value over MAX_TYPED characters a ValueError."""
    return EditableText(text).edited(edits)


class EditableText:
    """A problem file parsed once, for many edits: :meth:`edited` puts the edits into the one parsed document,
    writes it out and puts the file's own items back (parsing the file on every keystroke took most of an
    edit's time). Not for use by two threads at once."""

    def __init__(self, text: str) -> None:
        self.text = text
        self.document = tomlkit.parse(text)
        self.fields = fields_of(self.document)
        self.known = {f.key: f for f in self.fields}

    def edited(self, edits: Mapping[str, str]) -> str:
        """The text with ``edits`` put in (see :func:`edited_text`)."""
        changed: list[tuple[Any, str | int, Any]] = []
        try:
            for key, typed in edits.items():
                field = self.known.get(key)
                if field is None:
                    raise KeyError(f"'{key}' is not an editable quantity of this file")
                typed = str(typed).strip()
                if len(typed) > MAX_TYPED:
                    raise ValueError(f"{key}: a value is a number of at most {MAX_TYPED} characters; got {len(typed)}")
                if typed == field.number:
                    continue
                node = _container(self.document, field.path)
                last = field.path[-1]
                changed.append((node, last, node[last]))
                node[last] = _value(typed, field)
            return tomlkit.dumps(self.document) if changed else self.text
        finally:
            for node, last, item in reversed(changed):
                node[last] = item


def _value(typed: str, field: Field) -> Any:
    if field.unit:
        return f"{typed} {field.unit}"
    if field.integer and re.fullmatch(r"[-+]?\d{1,18}", typed):
        return int(typed)
    try:
        number = float(typed)
    except ValueError:
        return typed  # not a number: the loader says so, as it would of the file
    return number if math.isfinite(number) else typed
