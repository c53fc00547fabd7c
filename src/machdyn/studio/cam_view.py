"""What the studio shows of a cam file, and what a drag in its displacement diagram changes.

The view is the run's own numbers, sampled: the displacement s(theta), the pressure angle and the contact force
along the follower's path at every analysed cam angle (at most :data:`MAX_POINTS`), the cam's surface and pitch
curve in the cam's frame (the page turns them by the cam angle: a point F of the frame is R(theta) P on a
counter-clockwise cam with P its place on the cam, :mod:`machdyn.cams.profile`) and the follower program's points.

The points of the program are the boundaries between segments, at the cam angle where one segment ends and the
next begins and at the follower's level there. Dragging one sideways moves that boundary: the segment before it
grows by as much as the one after it shrinks (the segments keep filling the turn). Dragging one up or down moves
the level of the stroke end it sits on: the rise or return that reaches that level and the one that leaves it
both change their lift by as much (rises and returns keep closing the cycle), the dwells between them follow.
A rule is offered only where the file writes the fields it sets, with units pint knows, and where no segment is
placed by ``start`` or shaped by a contour law (whose angles follow from its radii); the edited values are then
judged by the same check as typed ones.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .fields import Field

MAX_POINTS = 720


def _sampled(values: Any, step: int) -> list[float | None]:
    arr = np.asarray(values, dtype=float)[::step]
    return [float(f"{v:.6g}") if np.isfinite(v) else None for v in arr]


def _set(key: str, sign: float, usable: dict[str, Field]) -> dict[str, Any] | None:
    field = usable.get(key)
    return None if field is None else {"key": key, "sign": sign, "si": field.si_per_unit}


def program_points(spec: Any, program: Any, fields: list[Field]) -> list[dict[str, Any]]:
    """The draggable points of the follower program (module docstring): each with its cam angle [deg], level
    (in the diagram's unit: mm, or deg for an oscillating follower) and the fields a drag along x and along y
    sets, each with the sign of its change and the SI value of its unit."""
    segments = spec.cam.segments
    if any(s.start is not None or s.law in ("circular_arc", "tangent") for s in segments):
        return []
    osc = spec.cam.follower.motion == "oscillating"
    name = "swing" if osc else "lift"
    usable = {f.key: f for f in fields if f.si_per_unit}
    scale = np.degrees(1.0) if osc else 1e3
    moving = [s.motion != "dwell" for s in segments]
    points = []
    for k in range(len(segments) - 1):
        x = [_set(f"cam.segments[{k}].angle", 1.0, usable), _set(f"cam.segments[{k + 1}].angle", -1.0, usable)]
        before = next((j for j in range(k, -1, -1) if moving[j]), None)
        after = next((j for j in range(k + 1, len(segments)) if moving[j]), None)
        y: list[dict[str, Any] | None] = []
        if before is not None and after is not None:  # the stroke end between a motion reaching it and one leaving
            y = [_set(f"cam.segments[{before}].{name}", 1.0 if segments[before].motion == "rise" else -1.0, usable),
                 _set(f"cam.segments[{after}].{name}", -1.0 if segments[after].motion == "rise" else 1.0, usable)]
        points.append({"segment": k, "theta": float(np.degrees(program.starts[k + 1])),
                       "s": float(program.levels[k + 1] * scale),
                       "x": [r for r in x if r] if all(x) else [], "y": [r for r in y if r] if y and all(y) else [],
                       "unit": "deg" if osc else "mm"})
    return points


def cam_scene(spec: Any, outcome: Any, fields: list[Field]) -> dict[str, Any]:
    """The cam's view for the page: curves against the cam angle, the profile, the program's points."""
    result = outcome.results
    prof = result.model.profile
    m = prof.svaj
    step = max(1, int(np.ceil(m.theta.size / MAX_POINTS)))
    osc = result.model.follower.motion == "oscillating"
    scale = np.degrees(1.0) if osc else 1e3
    curves = [{"title": "Follower displacement s", "unit": "deg" if osc else "mm", "y": _sampled(m.s * scale, step)},
              {"title": "Pressure angle", "unit": "deg", "y": _sampled(np.degrees(prof.pressure_angle), step)}]
    if result.forces is not None:
        curves.append({"title": "Contact force along the follower's path", "unit": "N",
                       "y": _sampled(result.forces.contact / result.model.arm, step)})
    follower = result.model.follower
    return {
        "angles": _sampled(np.degrees(m.theta), step),
        "curves": curves,
        "surface": [_sampled(prof.surface[0], step), _sampled(prof.surface[1], step)],
        "pitch": [_sampled(prof.pitch[0], step), _sampled(prof.pitch[1], step)],
        "base_radius": float(follower.base_radius), "roller_radius": float(follower.roller_radius),
        "contact": follower.contact, "turn": -1.0 if result.clockwise else 1.0,
        # an oscillating follower's pivot, fixed in the frame at (d, 0) (mirrored for a clockwise cam)
        "pivot": [(-1.0 if result.clockwise else 1.0) * float(follower.pivot_distance), 0.0] if osc else None,
        "points": program_points(spec, result.model.program, fields),
        "max_pressure_angle": float(np.degrees(outcome.scalars["cam.max_pressure_angle"])),
        "pressure_angle_limit": float(np.degrees(outcome.scalars["cam.pressure_angle_limit"])),
    }
