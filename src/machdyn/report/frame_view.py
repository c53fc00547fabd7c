"""The machine on its mounts: the frame's steady-state motion, exaggerated, played back with the mechanism.

The frame's rigid-body coordinates (x, y, θ) at crank angle φ are the steady-state response of
:mod:`machdyn.vibration.response`, q(φ) = Re Σ_k q_k e^{i k φ} (orders k of the crank speed, φ from the
analysis' first crank angle, as the loads' harmonics are taken). The displacement of a frame point p is
u = P(p) q with P = [[1, 0, −p_y], [0, 1, p_x]] (small rotations). Displacements are micrometres on a machine
of a metre, so they are drawn multiplied by a factor stated in the caption (the largest excursion of the
outline about 6 % of the drawing). The mechanism is drawn as computed; the dashed outline is the frame, moving.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from markupsafe import Markup

from .animation import Curve, scene, view_html

#: The largest drawn excursion of the frame, as a share of the drawing's size.
EXCURSION = 0.06


def _rotation(angle: float) -> np.ndarray:
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s], [s, c]])


def _base_scene(study: Any, response: Any, title: str, after: bool) -> dict[str, Any] | None:
    """The mechanism's own scene (the compared variant's with ``after``), with the acceleration at the first
    measuring point as its only curve; None without a mechanism analysis to draw."""
    mechanism, analysis = ((study.after_mechanism, study.after_analysis) if after
                           else (study.mechanism, study.analysis))
    if analysis is None or mechanism is None:
        return None
    acc_curves = []
    first = next(iter(study.points.items()), None)
    if first is not None:
        _t, ax, ay = response.time_history(first[1], "acceleration", np.size(analysis.kinematics.crank_angle))
        acc_curves.append(Curve(f"Acceleration at {first[0]}", "m/s²", np.hypot(ax, ay)))
    data = scene(analysis, mechanism, curves=acc_curves, title=title)
    data["curves"] = data["curves"][-len(acc_curves):] if acc_curves else []  # the run's own view has the rest
    return data


@dataclass(frozen=True)
class _FrameMotion:
    """The frame's outline and mount points at rest (mechanism axes) and their displacements per frame."""

    corners: np.ndarray
    mounts: list
    outline: list
    span: float
    frames: int

    @property
    def own_factor(self) -> float:
        """The exaggeration that makes the largest excursion :data:`EXCURSION` of the drawing."""
        largest = max(float(np.max(np.hypot(u[:, 0], u[:, 1]))) for u in self.outline)
        return EXCURSION * self.span / largest if largest > 0 else 1.0


def _frame_motion(study: Any, response: Any, data: dict[str, Any]) -> _FrameMotion:
    phi = np.radians(np.asarray([a if a is not None else np.nan for a in data["angles"]], dtype=float))
    to_frame, to_mech = _rotation(study.angle), _rotation(-study.angle)
    origin = np.asarray(study.origin, dtype=float)

    # the frame's outline: around the mechanism and the mount points, in mechanism coordinates
    mounts = [(m, to_mech @ (np.asarray(m.position, dtype=float) - origin)) for m in study.frame.mounts]
    x0, x1, y0, y1 = data["extent"]
    xs = [x0, x1, *(p[0] for _m, p in mounts)]
    ys = [y0, y1, *(p[1] for _m, p in mounts)]
    pad = 0.08 * max(max(xs) - min(xs), max(ys) - min(ys), 1e-9)
    corners = np.array([[min(xs) - pad, min(ys) - pad], [max(xs) + pad, min(ys) - pad],
                        [max(xs) + pad, max(ys) + pad], [min(xs) - pad, max(ys) + pad]])
    span = float(max(np.ptp(corners[:, 0]), np.ptp(corners[:, 1])))
    orders = np.asarray(response.loads.orders, dtype=float)
    q = (np.exp(1j * np.outer(phi, orders)) @ response.coordinates).real  # frames x (x, y, theta)

    def moved(point_mech: np.ndarray) -> np.ndarray:
        p = origin + to_frame @ point_mech
        u = q[:, :2] + q[:, 2:3] * np.array([-p[1], p[0]])  # P(p) q, frames x 2, frame axes
        return u @ to_mech.T  # back to the mechanism's axes

    outline = [moved(c) for c in corners] + [moved(p) for _m, p in mounts]
    return _FrameMotion(corners, mounts, outline, span, phi.size)


def _with_frame(study: Any, data: dict[str, Any], motion: _FrameMotion, factor: float) -> dict[str, Any]:
    """``data`` with the frame's outline and mounts added, their displacements drawn ``factor`` times larger."""
    to_mech = _rotation(-study.angle)
    corners, span = motion.corners, motion.span

    def series(base: np.ndarray, u: np.ndarray) -> list[list[float]]:
        return [[float(v) for v in base[0] + factor * u[:, 0]], [float(v) for v in base[1] + factor * u[:, 1]]]

    bodies = [{"name": "frame", "shape": "frame", "colour": "#7f7f7f", "points": ["c1", "c2", "c3", "c4"],
               "angle": None}]
    points = {f"frame.c{i + 1}": series(c, motion.outline[i]) for i, c in enumerate(corners)}
    ground = []
    for k, (m, p) in enumerate(motion.mounts):
        line = to_mech @ np.array([np.cos(m.direction), np.sin(m.direction)])
        anchor = p - 0.12 * span * line
        name = f"mount {m.name}"
        bodies.append({"name": name, "shape": "link", "colour": "#8c564b", "points": ["anchor", "at"], "angle": None})
        points[f"{name}.anchor"] = [[float(anchor[0])] * motion.frames, [float(anchor[1])] * motion.frames]
        points[f"{name}.at"] = series(p, motion.outline[len(corners) + k])
        ground.append({"name": name, "x": float(anchor[0]), "y": float(anchor[1])})
    x0, x1, y0, y1 = data["extent"]
    every = np.concatenate([np.asarray(v[0] + [c[0] for c in corners], dtype=float) for v in points.values()])
    every_y = np.concatenate([np.asarray(v[1] + [c[1] for c in corners], dtype=float) for v in points.values()])
    return {**data, "bodies": bodies + data["bodies"], "points": {**points, **data["points"]},
            "ground": ground + data["ground"],
            "extent": [min(x0, float(every.min())), max(x1, float(every.max())),
                       min(y0, float(every_y.min())), max(y1, float(every_y.max()))]}


def frame_scene(study: Any, response: Any, title: str = "", factor: float | None = None, *,
                after: bool = False) -> tuple[dict[str, Any], float] | None:
    """The scene of ``study``'s mechanism with its frame outline and mounts moving as ``response`` (a
    :class:`~machdyn.vibration.response.FrameResponse`) says, drawn ``factor`` times larger (by default so that
    the largest excursion is :data:`EXCURSION` of the drawing), and that factor; None without a mechanism
    analysis to draw. ``after``: draw the variant compared (the balanced machine) instead of the mechanism."""
    data = _base_scene(study, response, title, after)
    if data is None:
        return None
    motion = _frame_motion(study, response, data)
    factor = motion.own_factor if factor is None else factor
    return _with_frame(study, data, motion, factor), factor


def frame_view(study: Any) -> Markup | None:
    """The machine on its mounts, before (and after) side by side on one slider, the frame's motion
    exaggerated; None when the study holds no mechanism to draw."""
    shown = [(study.labels[0] or "before", study.before, False)]
    if study.after is not None and study.after_analysis is not None:
        shown.append((study.labels[1] or "after", study.after, True))
    drawn = []
    for label, response, after in shown:
        data = _base_scene(study, response, label, after)
        if data is None:
            return None
        drawn.append((label, data, _frame_motion(study, response, data)))
    factor = min(m.own_factor for _l, _d, m in drawn)  # one exaggeration for all: like compared with like
    scenes = {label: _with_frame(study, data, motion, factor) for label, data, motion in drawn}
    return view_html(scenes, caption=(
        f"The machine on its mounts at the current crank angle: the dashed outline is the frame, its steady-state "
        f"motion drawn {factor:.3g} times larger than it is; brown lines are the mounts. The curve is the "
        "acceleration at the first measuring point."))
