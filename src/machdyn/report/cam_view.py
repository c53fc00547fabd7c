"""The cam and its follower, animated in the report from the run's own profile and follower motion.

Nothing is solved again: the cam surface is the computed profile (cam frame), turned at each drawn cam angle so
that its contact point meets the follower where the follower's own motion puts it; the follower is drawn at its
computed lift. For a translating follower whose path is the line x = e (e the offset, the follower above the
cam): a knife edge or roller centre sits at (e, √(|p|² − e²)), p the pitch point in the cam frame, and a flat face's
contact point at (v, R_b + s) (v its offset along the face). The turn of the cam at that angle is the angle between
p and that point, so the same drawing works whichever way the cam turns. An oscillating follower's roller
centre (or knife edge) is where its arm (length l, pivot at (d, 0)) meets the circle of radius |p| about the cam
centre: x = (|p|² − l² + d²)/(2d), y = √(|p|² − x²), the arm above the line of centres as in
:func:`machdyn.cams.followers.follower_path`.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from markupsafe import Markup

from .animation import _rounded, view_html

#: Cam angles and surface points drawn (the computed profile is sampled evenly).
FRAMES = 180
SURFACE_POINTS = 72


def _pick(count: int, wanted: int) -> np.ndarray:
    return np.unique(np.linspace(0, count - 1, min(count, wanted)).round().astype(int))


def cam_scene(result: Any) -> dict[str, Any] | None:
    """The view's scene of a :class:`~machdyn.cams.stage.CamResult`: the cam turning under its translating or
    oscillating follower."""
    model = result.model
    follower, profile = model.follower, model.profile
    oscillating = follower.motion == "oscillating"
    theta = np.asarray(profile.svaj.theta, dtype=float)
    s = np.asarray(profile.svaj.s, dtype=float)
    frames = _pick(theta.size, FRAMES)
    pitch = np.asarray(profile.pitch, dtype=float)
    if follower.contact == "flat":
        fixed = np.vstack([np.asarray(profile.contact_offset, dtype=float), follower.base_radius + s])
    elif oscillating:
        radius = np.hypot(pitch[0], pitch[1])
        d, arm = follower.pivot_distance, follower.arm_length
        x = (radius**2 - arm**2 + d**2) / (2.0 * d)
        fixed = np.vstack([x, np.sqrt(np.maximum(radius**2 - x**2, 0.0))])
    else:
        radius = np.hypot(pitch[0], pitch[1])
        fixed = np.vstack([np.full(theta.size, follower.offset),
                           np.sqrt(np.maximum(radius**2 - follower.offset**2, 0.0))])
    turn = np.arctan2(fixed[1], fixed[0]) - np.arctan2(pitch[1], pitch[0])  # cam frame -> fixed frame
    surface = np.asarray(profile.surface, dtype=float)
    surface = surface[:, _pick(surface.shape[1], SURFACE_POINTS)]
    c, sn = np.cos(turn[frames]), np.sin(turn[frames])
    xs = c[:, None] * surface[0][None, :] - sn[:, None] * surface[1][None, :]   # frames x points
    ys = sn[:, None] * surface[0][None, :] + c[:, None] * surface[1][None, :]
    size = float(np.max(np.hypot(surface[0], surface[1])))
    stem = 0.8 * follower.base_radius
    points: dict[str, list[list[float]]] = {}
    names = [f"c{k}" for k in range(surface.shape[1])]
    for k, name in enumerate(names):
        points[f"cam.{name}"] = [list(xs[:, k]), list(ys[:, k])]
    if follower.contact == "flat":
        half = 0.5 * max(float(np.ptp(profile.contact_offset)) * 1.3, 0.4 * follower.base_radius)
        y = fixed[1][frames]
        points["follower.left"] = [list(np.full(frames.size, -half)), list(y)]
        points["follower.right"] = [list(np.full(frames.size, half)), list(y)]
        points["stem.face"] = [list(np.zeros(frames.size)), list(y)]
        points["stem.top"] = [list(np.zeros(frames.size)), list(y + stem)]
        bodies: list[dict[str, Any]] = [{"name": "follower", "shape": "link", "colour": "#d62728",
                                         "points": ["left", "right"], "angle": None}]
        path_x: float | None = 0.0
    elif oscillating:
        x, y = fixed[0][frames], fixed[1][frames]
        d = float(follower.pivot_distance)
        points["follower.centre"] = [list(x), list(y)]
        points["follower.pivot"] = [list(np.full(frames.size, d)), list(np.zeros(frames.size))]
        # the roller is drawn at a link's first point
        bodies = [{"name": "follower", "shape": "link", "colour": "#d62728", "points": ["centre", "pivot"],
                   "angle": None, "roller": float(follower.roller_radius) or None}]
        path_x = None
    else:
        x, y = fixed[0][frames], fixed[1][frames]
        points["follower.centre"] = [list(x), list(y)]
        points["follower.top"] = [list(x), list(y + stem)]
        bodies = [{"name": "follower", "shape": "link", "colour": "#d62728", "points": ["centre", "top"],
                   "angle": None, "roller": float(follower.roller_radius) or None}]
        path_x = float(follower.offset)
    if "stem.face" in points:
        bodies.append({"name": "stem", "shape": "link", "colour": "#d62728", "points": ["face", "top"],
                       "angle": None})
    bodies.insert(0, {"name": "cam", "shape": "polygon", "colour": "#1f77b4", "points": names, "angle": None,
                      "dots": False})
    every_x = np.concatenate([np.asarray(v[0], dtype=float) for v in points.values()])
    every_y = np.concatenate([np.asarray(v[1], dtype=float) for v in points.values()])
    extent = [float(min(every_x.min(), -size)), float(max(every_x.max(), size)),
              float(min(every_y.min(), -size)), float(every_y.max())]
    quantum = max(extent[1] - extent[0], extent[3] - extent[2]) * 1e-5
    rounded = {k: [[round(v / quantum) * quantum for v in axis] for axis in xy] for k, xy in points.items()}
    low, high = float(np.min(fixed[1])), float(np.max(fixed[1])) + stem
    guides = [] if path_x is None else [[path_x, low - 0.1 * size, path_x, high + 0.1 * size]]
    lift = ({"title": "Swing of the arm", "unit": "°", "y": _rounded(np.degrees(s[frames])), "zero": True}
            if oscillating else {"title": "Lift", "unit": "mm", "y": _rounded(1e3 * s[frames]), "zero": True})
    curves = [lift]
    forces = getattr(result, "forces", None)
    if forces is not None:
        curves.append({"title": "Contact force along the path", "unit": "N",
                       "y": _rounded(np.asarray(forces.contact, dtype=float)[frames]), "zero": True})
        curves.append({"title": "Camshaft torque", "unit": "N·m",
                       "y": _rounded(np.asarray(forces.torque, dtype=float)[frames]), "zero": True})
    return {
        "title": "",
        "angles": _rounded(np.degrees(theta[frames]), 6),
        "assembled": [True] * int(frames.size),
        "extent": extent,
        "bodies": bodies,
        "points": rounded,
        "traces": [],
        "masses": [],
        "ground": [{"name": "camshaft", "x": 0.0, "y": 0.0}]
        + ([{"name": "arm pivot", "x": float(follower.pivot_distance), "y": 0.0}] if oscillating else []),
        "guides": guides,
        "joints": [],
        "shaking": None,
        "curves": curves,
        "marks": [],
    }


def cam_view(result: Any) -> Markup | None:
    """The animated cam and follower of a cam run (None where it has no view)."""
    data = cam_scene(result)
    if data is None:
        return None
    motion = "swing" if result.model.follower.motion == "oscillating" else "lift"
    return view_html(data, caption=f"The cam turning and its follower at the computed {motion}: drag the slider or "
                                   f"press play; the cursors on the {motion}, contact force and camshaft torque "
                                   "follow the cam angle, and a click on a curve moves the cam there.")
