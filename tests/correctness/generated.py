"""Problem files generated for the property ``check`` accepts => ``run`` exits 0 or 3: small, fast variants of
the shipped examples of every kind and capability, with quantities scaled, zeroed or negated."""

from __future__ import annotations

import copy
import json
import math
import re
import tomllib
from typing import Any

from .helpers import EXAMPLES

#: example -> changes that keep its run short (fewer crank positions, a given motor, a short search)
BASES: dict[str, dict[str, Any]] = {
    "four_bar": {"drive": {"positions": 72}},
    "slider_crank": {"drive": {"positions": 72}},
    "rotary_screen_drive": {"drive": {"positions": 90}, "flywheel": {"positions": 90, "start_up": False}},
    "compactor_flywheel": {"drive": {"positions": 90},
                           "flywheel": {"positions": 90, "start_up": False,
                                        "motor": {"kind": "induction", "rated_power": "0.55 kW",
                                                  "rated_speed": "1440 rpm"}}},
    "slider_crank_balance": {"drive": {"positions": 72}, "balance": {"positions": 72}},
    "four_bar_balance": {"drive": {"positions": 72}},
    "tamper_on_tyres": {"drive": {"positions": 72}},
    "vibration_record": {"drive": {"positions": 72}},
    "four_bar_sweep": {"drive": {"positions": 72}, "sweep": {"count": 4}},
    "compactor_optimise": {"drive": {"positions": 36},
                           "optimise": {"generations": 2, "population": 6, "positions": 36}},
    "conveyor_check_existing": {},
    "rotary_screen": {"drive": {"positions": 90}},
}

#: factors a quantity is scaled by: zero, a sign flip, tiny and huge changes, small ones
FACTORS = (0.0, -1.0, 1e-6, 0.1, 0.5, 0.9, 1.1, 2.0, 10.0, 1e6)

_QUANTITY = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s+(\S.*)$")


def _merge(data: dict[str, Any], changes: dict[str, Any]) -> None:
    for key, value in changes.items():
        if isinstance(value, dict) and isinstance(data.get(key), dict):
            _merge(data[key], value)
        elif key in data or not isinstance(value, dict):
            data[key] = copy.deepcopy(value)


def base(name: str) -> dict[str, Any]:
    data = tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))
    _merge(data, BASES[name])
    return data


def quantity_paths(data: Any, path: tuple = ()) -> list[tuple]:
    """Paths of every quantity ("45 mm") and every plain number of the file (meta excluded)."""
    out: list[tuple] = []
    if isinstance(data, dict):
        items = [(k, v) for k, v in data.items() if not (not path and k == "meta")]
    elif isinstance(data, list):
        items = list(enumerate(data))
    else:
        return out
    for k, v in items:
        here = (*path, k)
        if isinstance(v, dict | list):
            out += quantity_paths(v, here)
        elif isinstance(v, str) and _QUANTITY.match(v):
            out.append(here)
        elif isinstance(v, float) and not isinstance(v, bool):
            out.append(here)
    return out


def scaled(data: dict[str, Any], path: tuple, factor: float) -> dict[str, Any]:
    """A copy of ``data`` with the quantity at ``path`` multiplied by ``factor`` (its unit kept)."""
    d = copy.deepcopy(data)
    node: Any = d
    for k in path[:-1]:
        node = node[k]
    value = node[path[-1]]
    if isinstance(value, str):
        match = _QUANTITY.match(value)
        assert match is not None
        number = float(match.group(1)) * factor
        node[path[-1]] = f"{number!r} {match.group(2)}" if math.isfinite(number) else value
    else:
        node[path[-1]] = value * factor
    return d


def to_toml(data: dict[str, Any]) -> str:
    """TOML text of parsed problem data (strings, numbers, booleans, lists, tables and arrays of tables)."""
    lines: list[str] = []

    def value(v: Any) -> str:
        if isinstance(v, bool):
            return "true" if v else "false"
        if isinstance(v, int | float):
            return repr(v) if math.isfinite(v) else ("nan" if v != v else ("inf" if v > 0 else "-inf"))
        if isinstance(v, str):
            return json.dumps(v, ensure_ascii=False)
        if isinstance(v, list):
            return "[" + ", ".join(value(x) for x in v) + "]"
        return "{" + ", ".join(f"{json.dumps(k)} = {value(x)}" for k, x in v.items()) + "}"

    def tables(v: Any) -> bool:
        return isinstance(v, dict) or (isinstance(v, list) and bool(v) and all(isinstance(x, dict) for x in v))

    def table(prefix: str, body: dict[str, Any]) -> None:
        lines.extend(f"{json.dumps(k)} = {value(v)}" for k, v in body.items() if not tables(v))
        for k, v in body.items():
            name = f"{prefix}.{json.dumps(k)}" if prefix else json.dumps(k)
            if isinstance(v, dict):
                lines.append(f"\n[{name}]")
                table(name, v)
            elif tables(v):
                for item in v:
                    lines.append(f"\n[[{name}]]")
                    table(name, item)

    table("", data)
    return "\n".join(lines) + "\n"
