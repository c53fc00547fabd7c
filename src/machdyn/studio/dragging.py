"""What a drag in the studio's view changes in the file: a rule per draggable point.

A rule names the point (a ground pivot ``ground:D`` or a body point ``coupler.B``, as the animated view names
them) and the fields it sets when dropped at a position p (world coordinates, metres): a *distance* field gets
|p - q| and an *angle* field atan2 of p - q, where q is another point at the frame shown (a ground pivot, or a
body point of the same crank position). The browser applies the rule and sends the new values like any edit,
so a drag is judged by the same check as a typed value.

Draggable today (where the file writes the field the rule sets):

* four-bar: the rocker pivot D (ground length and angle from O); the crank pin A (crank length); the joint B
  (coupler length from A and rocker length from D).
* slider-crank: the crank pin A (crank length); the piston pin B (rod length from A).

The crank pivot O is the origin of every standard mechanism and is not a field of the file, so it is not
draggable; other mechanism types open with typed fields only.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from .fields import Field

Rule = tuple[tuple[str, ...], list[tuple[str, str, str]]]  # points, [(field key, measure, from point)]

RULES: dict[str, list[Rule]] = {
    "four_bar": [
        (("ground:D",), [("mechanism.ground.length", "distance", "ground:O"),
                         ("mechanism.ground.angle", "angle", "ground:O")]),
        (("crank.A", "coupler.A"), [("mechanism.crank.length", "distance", "ground:O")]),
        (("coupler.B", "rocker.B"), [("mechanism.coupler.length", "distance", "coupler.A"),
                                     ("mechanism.rocker.length", "distance", "ground:D")]),
    ],
    "slider_crank": [
        (("crank.A", "rod.A"), [("mechanism.crank.length", "distance", "ground:O")]),
        (("rod.B", "slider.B"), [("mechanism.rod.length", "distance", "rod.A")]),
    ],
}


def drag_rules(problem: Any, fields: Sequence[Field], scene: dict[str, Any]) -> list[dict[str, Any]]:
    """The rules of the mechanism's type whose fields the file writes with a unit pint knows and whose points
    the view draws."""
    mechanism = getattr(problem, "mechanism", None)
    rules = RULES.get(str(getattr(mechanism, "type", "")), [])
    usable = {f.key: f for f in fields if f.si_per_unit}
    drawn = set(scene.get("points", {})) | {f"ground:{g['name']}" for g in scene.get("ground", [])}
    out = []
    for points, sets in rules:
        kept = [{"key": key, "measure": measure, "from": source, "si": usable[key].si_per_unit}
                for key, measure, source in sets if key in usable and source in drawn]
        shown = [p for p in points if p in drawn]
        if kept and shown:
            out.append({"points": shown, "set": kept})
    return out
