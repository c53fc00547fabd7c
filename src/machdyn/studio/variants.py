"""Named variants of a studio session, and two of them side by side.

A variant is a snapshot of the page's values (field key -> number as typed) under a name, with the machine they
gave (the live answer: view, summary, curves). Comparing two puts their summaries side by side: for every row
both give a number, its value in each and the difference B - A (absolute, and relative to A where A is not 0).
Nothing is recomputed: the comparison reads the answers kept with the variants.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

MAX_VARIANTS = 20
NAME = re.compile(r"^[\w][\w .,+=()-]{0,39}$")


class VariantRefused(ValueError):
    """A variant the session will not keep or compare: a bad name, too many, an unknown one, an invalid machine."""


@dataclass(frozen=True)
class Variant:
    name: str
    values: dict[str, str]
    answer: dict[str, Any]


def check_name(name: str) -> str:
    """The name stripped; a :class:`VariantRefused` unless it is 1-40 letters, digits, spaces or ``.,+=()-_``."""
    name = str(name).strip()
    if not NAME.fullmatch(name):
        raise VariantRefused(f"a variant's name is 1 to 40 letters, digits, spaces or .,+=()-_ ; got {name!r}")
    return name


def _numeric(row: dict[str, Any]) -> float | None:
    value = row.get("value")
    return float(value) if isinstance(value, int | float) and not isinstance(value, bool) else None


def compared(a: Variant, b: Variant) -> list[dict[str, Any]]:
    """The rows of the two variants' summaries that both give as a number, in A's order: label, unit, A, B,
    B - A and (B - A) / |A| (None where A is 0)."""
    theirs = {(r["label"], r["unit"]): _numeric(r) for r in b.answer.get("summary", [])}
    rows = []
    for row in a.answer.get("summary", []):
        mine, other = _numeric(row), theirs.get((row["label"], row["unit"]))
        if mine is None or other is None:
            continue
        rows.append({"label": row["label"], "unit": row["unit"], "a": mine, "b": other, "difference": other - mine,
                     "relative": (other - mine) / abs(mine) if mine != 0 else None})
    return rows


def changed_fields(a: Variant, b: Variant, numbers: dict[str, str]) -> list[dict[str, str]]:
    """The fields whose values differ between the variants (``numbers``: each field's value in the file)."""
    keys = [k for k in numbers if a.values.get(k, numbers[k]) != b.values.get(k, numbers[k])]
    return [{"key": k, "a": a.values.get(k, numbers[k]), "b": b.values.get(k, numbers[k])} for k in keys]
