"""The machine in time in the animated view: the frame, and the machine on it, moving as the run says.

A ``[transient]`` run holds the frame's rigid-body coordinates q(t) at its samples: on a planar frame (x, y, beta),
in space (u, vartheta) for a shaft line's frame. A frame point p moves by u(p, t) = P(p) q(t) (small motion;
:mod:`machdyn.vibration.frame`, :meth:`machdyn.shafts.frame6.Frame6.point_matrix`). The view plays the run back in
time: every drawn point — the frame's outline, the mounts' attachment points, the mechanism's joints at the crank
angle of that instant (the engine's kinematics) or a shaft line's cranks and pistons — is drawn at its place on
the frame at rest plus ``factor`` times its displacement, the factor stated in the caption (so that the largest
excursion is :data:`EXCURSION` of the drawing). A shaft line's frame in space is drawn projected on the plane
across the shaft (x, y), seen along the shaft's axis.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from markupsafe import Markup

from ..linkage import kinematics
from ..linkage import model as _model
from .animation import MAX_FRAMES, Curve, _rounded, view_html
from .plotkit import PALETTE

__all__ = ["EXCURSION", "FRAMES", "transient_scene", "transient_view"]

#: The largest drawn excursion of the frame, as a share of the drawing's size.
EXCURSION = 0.06
#: At most this many instants of the run are played back (evenly spaced in time).
FRAMES = MAX_FRAMES
RPM = 30.0 / np.pi


def _instants(t: np.ndarray) -> np.ndarray:
    if t.size <= FRAMES:
        return np.arange(t.size)
    return np.unique(np.linspace(0, t.size - 1, FRAMES).round().astype(int))


def _planar_parts(result: Any, idx: np.ndarray) -> tuple[dict[str, np.ndarray], list[dict[str, Any]]]:
    """Every mechanism's body points in frame coordinates at the chosen instants (frames x 2 each), and its
    bodies."""
    run = result.run
    points: dict[str, np.ndarray] = {}
    bodies: list[dict[str, Any]] = []
    for k, part in enumerate(run.model.parts):
        ex = part.exciter
        mech = ex.mechanism
        phi = np.mod(run.phi[k, idx], 2.0 * np.pi)
        kin = kinematics(mech, phi, 1.0, 0.0)
        a_mat, origin = ex.transform, np.asarray(ex.origin, dtype=float)
        sliders = {b2 for _n, kind, _b1, b2 in _model.joints(mech) if kind == "P"}
        prefix = f"{ex.name} " if run.model.cranks > 1 else ""
        for j, body in enumerate(mech.moving_bodies):
            motion = kin.body(body)
            ox, oy, ang = (np.broadcast_to(np.asarray(v, dtype=float), phi.shape) for v in
                           (motion.x, motion.y, motion.angle))
            names = []
            for pname, (lx, ly) in mech.body(body).points.items():
                u, v = float(np.ravel(lx)[0]), float(np.ravel(ly)[0])
                local = np.stack([ox + np.cos(ang) * u - np.sin(ang) * v, oy + np.sin(ang) * u + np.cos(ang) * v])
                points[f"{prefix}{body}.{pname}"] = (origin[:, None] + a_mat @ local).T
                names.append(pname)
            shape = "polygon" if len(names) >= 3 else "link"
            if body in sliders and len(names) < 2:
                shape = "polygon"  # drawn by its one point as a dot
            bodies.append({"name": f"{prefix}{body}", "shape": shape,
                           "colour": PALETTE[(k * 3 + j) % len(PALETTE)], "points": names, "angle": None})
    return points, bodies


def _shaft_parts(result: Any, idx: np.ndarray) -> tuple[dict[str, np.ndarray], list[dict[str, Any]], dict]:
    """A shaft line's cranks, rods and pistons and its rotating masses on the plane across the shaft (frames x 2
    each), their bodies, and each point's axial position z [m]."""
    run = result.run
    line = result.line
    xs, ys = result.shaft
    theta = run.phi[0, idx]
    centre = np.tile([xs, ys], (idx.size, 1))
    points: dict[str, np.ndarray] = {}
    bodies: list[dict[str, Any]] = []
    axial: dict[str, float] = {}
    for k, c in enumerate(line.cylinders):
        a = theta + c.phase
        pin = centre + c.crank * np.stack([np.cos(a), np.sin(a)], axis=1)
        phi = theta + c.phase - c.axis
        x = c.crank * np.cos(phi) + np.sqrt(c.rod ** 2 - (c.crank * np.sin(phi)) ** 2)
        piston = centre + x[:, None] * np.array([np.cos(c.axis), np.sin(c.axis)])
        for key, value in ((f"crank {c.name}.O", centre), (f"crank {c.name}.pin", pin),
                           (f"rod {c.name}.pin", pin), (f"rod {c.name}.piston", piston)):
            points[key] = value
            axial[key] = c.position
        bodies.append({"name": f"crank {c.name}", "shape": "link", "colour": PALETTE[(2 * k) % len(PALETTE)],
                       "points": ["O", "pin"], "angle": None})
        bodies.append({"name": f"rod {c.name}", "shape": "link", "colour": PALETTE[(2 * k + 1) % len(PALETTE)],
                       "points": ["pin", "piston"], "angle": None})
    for k, m in enumerate(line.masses):
        a = theta + m.angle
        at = centre + m.radius * np.stack([np.cos(a), np.sin(a)], axis=1)
        for key, value in ((f"mass {m.name}.O", centre), (f"mass {m.name}.at", at)):
            points[key] = value
            axial[key] = m.position
        bodies.append({"name": f"mass {m.name}", "shape": "link", "colour": PALETTE[(k + 5) % len(PALETTE)],
                       "points": ["O", "at"], "angle": None})
    return points, bodies, axial


def _displacement(result: Any, at: np.ndarray, z: float | None, idx: np.ndarray) -> np.ndarray:
    """(frames x 2) displacement [m], in the plane drawn, of the frame point at ``at`` (x, y) — one point, or one
    per instant (frames x 2) — at the chosen instants (at axial position ``z`` on a frame in space): P(p) q."""
    q = result.run.q[:, idx]
    px, py = (np.asarray(at, dtype=float).T[i] for i in (0, 1))
    if z is None:
        x, y, b = q
        return np.stack([x - b * py, y + b * px], axis=1)
    ux, uy, _uz, rx, ry, rz = q
    # u + vartheta x p, its x and y components
    return np.stack([ux + ry * z - rz * py, uy + rz * px - rx * z], axis=1)


def transient_scene(result: Any, factor: float | None = None) -> tuple[dict[str, Any], float] | None:
    """The animated view's scene of a ``[transient]`` run on a frame and the exaggeration of the frame's motion
    (by default the one that makes the largest excursion :data:`EXCURSION` of the drawing); None on a rigid
    frame. ``result``: a :class:`~machdyn.transient.stage.TransientRun` or a shaft line's
    :class:`~machdyn.transient.shaft_stage.ShaftTransientRun` (which carries ``line`` and ``shaft``)."""
    run = result.run
    if run.q.shape[0] == 0:
        return None
    spatial = run.q.shape[0] == 6
    idx = _instants(run.t)
    frame = run.model.frame
    mounts: list[tuple[Any, np.ndarray, float | None, np.ndarray]]
    axial: dict[str, float]
    if spatial:
        parts, bodies, axial = _shaft_parts(result, idx)
        depth = float(frame.com[2])
        mounts = [(m, np.asarray(m.position[:2], dtype=float), float(m.position[2]),
                   np.asarray(m.direction[:2], dtype=float)) for m in frame.mounts]
        extra = [np.asarray(p[:2], dtype=float) for p in (result.point, frame.com)]
    else:
        parts, bodies = _planar_parts(result, idx)
        axial, depth = {}, 0.0
        mounts = [(m, np.asarray(m.position, dtype=float), None,
                   np.array([np.cos(m.direction), np.sin(m.direction)])) for m in frame.mounts]
        extra = [np.asarray(result.point, dtype=float)]
    every = np.concatenate([np.concatenate(list(parts.values())) if parts else np.zeros((0, 2)),
                            np.array([p for _m, p, _z, _n in mounts] + extra)])
    lo, hi = every.min(axis=0), every.max(axis=0)
    pad = 0.08 * max(float(np.max(hi - lo)), 1e-9)
    corners = [np.array(c) for c in ((lo[0] - pad, lo[1] - pad), (hi[0] + pad, lo[1] - pad),
                                     (hi[0] + pad, hi[1] + pad), (lo[0] - pad, hi[1] + pad))]
    span = float(max(hi[0] - lo[0], hi[1] - lo[1]) + 2 * pad)
    z_of = None if not spatial else depth
    outline = [_displacement(result, c, z_of, idx) for c in corners]
    mount_moves = [_displacement(result, p, z, idx) for _m, p, z, _n in mounts]
    largest = max(float(np.max(np.hypot(u[:, 0], u[:, 1]))) for u in outline + mount_moves)
    if factor is None:
        factor = EXCURSION * span / largest if largest > 0 else 1.0
    decimals = int(-np.floor(np.log10(span * 1e-5)))  # well below a pixel, and short in the report's JSON

    def world(xy: np.ndarray) -> list[list[float]]:
        return [np.round(xy[:, 0], decimals).tolist(), np.round(xy[:, 1], decimals).tolist()]

    points: dict[str, list[list[float]]] = {}
    for key, xy in parts.items():  # the machine rides on the frame: each of its points moves with it
        points[key] = world(xy + factor * _displacement(result, xy, axial.get(key, z_of), idx))
    drawn_bodies = [{"name": "frame", "shape": "frame", "colour": "#7f7f7f", "points": ["c1", "c2", "c3", "c4"],
                     "angle": None}]
    for i, c in enumerate(corners):
        points[f"frame.c{i + 1}"] = world(c + factor * outline[i])
    ground = []
    for (m, p, _z, n), move in zip(mounts, mount_moves, strict=True):
        length = float(np.hypot(*n))
        if length < 1e-9:  # a mount along the shaft's axis shows no line in this plane
            continue
        anchor = p - 0.12 * span * n / length
        name = f"mount {m.name}"
        drawn_bodies.append({"name": name, "shape": "link", "colour": "#8c564b", "points": ["anchor", "at"],
                             "angle": None})
        points[f"{name}.anchor"] = world(np.tile(anchor, (idx.size, 1)))
        points[f"{name}.at"] = world(p + factor * move)
        ground.append({"name": name, "x": float(anchor[0]), "y": float(anchor[1])})
    xs = np.concatenate([np.asarray(v[0], dtype=float) for v in points.values()])
    ys = np.concatenate([np.asarray(v[1], dtype=float) for v in points.values()])
    u = run.point_displacement(result.point)
    amp = np.sqrt(np.sum(u * u, axis=0))
    curves = [Curve("Speed", "rpm", run.omega[0, idx] * RPM, from_zero=False),
              Curve(f"Displacement at {result.point_name}", "mm", amp[idx] * 1e3),
              Curve("Largest mount force", "N", np.max(np.abs(run.mount_force[:, idx]), axis=0))]
    shown = [{"title": c.title, "unit": c.unit, "y": _rounded(c.values), "zero": c.from_zero} for c in curves]
    data = {
        "title": "", "angles": _rounded(run.t[idx], 6), "axis": {"name": "time", "symbol": "t", "unit": "s"},
        "assembled": [True] * idx.size, "extent": [float(xs.min()), float(xs.max()), float(ys.min()), float(ys.max())],
        "bodies": drawn_bodies + bodies, "points": points, "traces": [], "masses": [], "ground": ground,
        "guides": [], "joints": [], "shaking": None, "curves": shown, "marks": [],
        "scale": float(factor), "plane": "x-y, along the shaft's axis" if spatial else "x-y",
    }
    return data, float(factor)


def transient_view(result: Any) -> Markup | None:
    """The run played back in time, the frame's motion exaggerated by a stated factor; None on a rigid frame."""
    made = transient_scene(result)
    if made is None:
        return None
    data, factor = made
    seen = ("the frame in space projected on the plane across the shaft, seen along its axis; " if
            data["plane"] != "x-y" else "")
    return view_html(data, caption=(
        f"The run played back in time: {seen}the grey outline is the frame and the machine on it, their motion on "
        f"the mounts drawn {factor:.3g} times larger than it is (scale factor {factor:.3g}); brown lines are the "
        "mounts. Drag the slider or press play; the curves are the speed, the displacement at the watched point "
        "and the largest mount force over the run."))
