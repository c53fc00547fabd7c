"""What a result is called and in which unit it is shown: one registry for every output.

Results are kept in SI (:class:`Label.unit`); each output (the command line's table, ``results.json``, the
report) shows them in :class:`Label.display` (degrees for angles, kW for a conveyor's power). Keys made at run
time (``joint.B.max_force``, ``stroke.slider``) are labelled by the patterns below.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass


@dataclass(frozen=True)
class Label:
    """The text of a result, its SI ``unit`` and the unit it is shown in (``display``; the SI unit if None).

    ``zero_below`` names a result whose magnitude sets the round-off scale of this one: a value smaller than
    1e-9 of it vanishes in exact arithmetic (the mean torque over a loss-free cycle) and is shown as 0.
    """

    text: str
    unit: str = ""
    display: str | None = None
    zero_below: str | None = None

    @property
    def shown_unit(self) -> str:
        return DEFAULT_DISPLAY.get(self.unit, self.unit) if self.display is None else self.display


#: display units chosen by SI unit when a label does not say
DEFAULT_DISPLAY = {"rad": "deg"}

_SCALES = {("rad", "deg"): 180.0 / math.pi}


def display_factor(unit: str, display: str) -> float:
    """The factor from ``unit`` to ``display`` (1 for equal units)."""
    if unit == display:
        return 1.0
    if (unit, display) in _SCALES:
        return _SCALES[(unit, display)]
    from ..units import ureg

    return float(ureg.Quantity(1.0, unit or "dimensionless").to(display or "dimensionless").magnitude)


def _pattern(key: str, unit: str) -> Label | None:
    parts = key.split(".")
    if parts[0] == "joint" and len(parts) == 3 and parts[2] == "max_force":
        return Label(f"Joint {parts[1]}, max force", "N")
    if parts[0] == "load" and len(parts) == 3 and parts[2] == "mean_power":
        return Label(f"Load {parts[1]}, mean power (negative: the drive works against it)", "W")
    if parts[0] == "time_ratio" and len(parts) == 2:
        return Label(f"Time ratio (advance / return) of {parts[1]}", "")
    if parts[0] == "transmission_angle" and len(parts) == 3 and parts[2] in ("min", "max"):
        return Label(f"Transmission angle of the dyad driving {parts[1]}, {parts[2]}", "rad", "deg")
    if parts[0] == "stroke" and len(parts) == 2:
        return Label(f"Stroke of {parts[1]}", unit)
    if len(parts) >= 3 and parts[-2].startswith("harmonic_"):
        order = parts[-2].removeprefix("harmonic_")
        what = ".".join(parts[:-2]).replace("_", " ").replace(".", " ")
        if parts[-1] == "amplitude":
            return Label(f"{what.capitalize()}, harmonic {order}, amplitude", unit)
        return Label(f"{what.capitalize()}, harmonic {order}, phase", "rad", "deg")
    return None


def label_for(key: str, labels: Mapping[str, Label], unit: str | None = None) -> Label:
    """The label of ``key``: from ``labels``, else a pattern, else the key itself in ``unit``."""
    if key in labels:
        found = labels[key]
        if unit is not None and found.unit != unit:
            return Label(found.text, unit, None, found.zero_below)
        return found
    si = unit or ""
    guessed = _pattern(key, si)
    if guessed is not None:
        return guessed if unit is None or guessed.unit == si else Label(guessed.text, si)
    return Label(key, si)
