"""The animated mechanism of the report: the run's own motion and forces, played back in the browser.

Nothing is solved in the browser. The scene is the analysis itself, sampled: the global position of every body
point at every computed crank angle, the reaction of every joint, the inertial shaking force (−Σ m·a_G) and
the shaking moment, and a few curves against the crank angle. A small script (``templates/view.js``, no
library, no network) draws it as SVG in world coordinates (metres, y up) so that a drawn joint sits exactly
where ``motion.csv`` puts it; a slider, play/pause and a speed choice move it, a cursor on each curve follows
the slider and a click on a curve moves the slider there.

The scene is JSON inside a ``<script type="application/json">`` element, numbers rounded to a resolution well
below a pixel (1e-5 of the drawing's extent for coordinates, 5 significant digits for forces and curves), and
at most :data:`MAX_FRAMES` positions, so that a report stays small enough to mail.
"""

from __future__ import annotations

import itertools
import json
import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from importlib import resources
from typing import Any

import numpy as np
from markupsafe import Markup, escape

from ..linkage import inertial_force
from ..linkage import model as _model
from ..linkage.reductions import worst_of
from .plotkit import PALETTE

#: At most this many crank positions are played back (a longer run is sampled evenly).
MAX_FRAMES = 720

_ids = itertools.count()


@dataclass(frozen=True)
class Curve:
    """A curve against the crank angle shown under the animation: its title, unit and one value per position."""

    title: str
    unit: str
    values: Any
    #: draw the curve's axis from zero (forces, torques); False for a quantity that lives far from it (a speed)
    from_zero: bool = True


def _rounded(values: Any, digits: int = 5, *, relative: bool = True) -> list[float | None]:
    """Values rounded to ``digits`` significant digits, non-finite as None: of the largest value (a curve's
    resolution) when ``relative``, else of each value (a table's columns, whose designs differ by decades)."""
    arr = np.asarray(values, dtype=float).ravel()
    finite = arr[np.isfinite(arr)]
    scale = float(np.max(np.abs(finite))) if finite.size else 0.0
    if relative and scale > 0:
        quantum = 10.0 ** (math.floor(math.log10(scale)) - digits + 1)
        arr = np.round(arr / quantum) * quantum
    return [float(f"{v:.{digits + 2}g}") if math.isfinite(v) else None for v in arr]


def _at(values: Any, design: int, frames: np.ndarray, size: int) -> np.ndarray:
    """One design's series at the chosen frames (scalars and constant results broadcast)."""
    arr = np.asarray(values, dtype=float)
    arr = arr[design] if arr.ndim == 2 else arr
    return np.broadcast_to(arr, (size,))[frames]


def _pick(value: Any, design: int) -> float:
    arr = np.asarray(value, dtype=float)
    return float(arr.ravel()[design] if arr.ndim > 0 else arr)


def _frames(size: int, limit: int) -> np.ndarray:
    if size <= limit:
        return np.arange(size)
    return np.unique(np.linspace(0, size - 1, limit).round().astype(int))


def _marks(diagnostics: Any, kin: Any, design: int) -> list[dict[str, Any]]:
    """Crank angles [deg] worth a mark on the slider's track: dead and limit positions, the worst transmission
    angle."""
    marks: list[dict[str, Any]] = []
    if diagnostics is None:
        return marks
    for d in getattr(diagnostics, "dead_positions", None) or []:
        marks.append({"angle": float(np.degrees(float(d))), "kind": "dead", "label": "dead position"})
    for item in getattr(diagnostics, "limit_positions", None) or []:
        body = getattr(item, "body", "")
        marks.append({"angle": float(np.degrees(float(item.crank_angle))), "kind": "limit",
                      "label": f"limit position of {body}"})
    phi = np.asarray(kin.crank_angle, dtype=float).ravel()
    worst: tuple[float, float] | None = None
    for rep in getattr(kin, "dyad_reports", ()) or ():
        try:
            mu = np.asarray(rep.transmission() if callable(rep.transmission) else rep.transmission, float)
        except (AttributeError, TypeError, ValueError):
            continue
        mu = mu[design] if mu.ndim == 2 else np.broadcast_to(mu, phi.shape)
        badness = np.where(np.isfinite(mu), worst_of(mu, mu), np.inf)
        i = int(np.argmin(badness))
        if np.isfinite(badness[i]) and (worst is None or badness[i] < worst[1]):
            worst = (float(phi[i]), float(mu[i]))
    if worst is not None:
        marks.append({"angle": float(np.degrees(worst[0])), "kind": "transmission",
                      "label": f"worst transmission angle {np.degrees(worst[1]):.1f}°"})
    return marks


def scene(analysis: Any, mechanism: Any = None, *, design: int = 0, about: tuple[float, float] = (0.0, 0.0),
          curves: Sequence[Curve] = (), max_frames: int = MAX_FRAMES, title: str = "") -> dict[str, Any]:
    """The animation's data for one design of a linkage analysis.

    Parameters
    ----------
    analysis : the result of :func:`machdyn.linkage.analyse` (kinematics, forces, diagnostics).
    mechanism : its model (taken from the analysis when None).
    design : which design of a stacked analysis.
    about : point [m] the shaking moment is taken about.
    curves : extra curves against the crank angle (the driving torque, the inertial shaking force and the
        kinetic energy are always shown).
    max_frames : the most positions kept.
    title : a heading shown above the view.

    Returns
    -------
    dict
        JSON-ready: crank angles [deg], body points [m], point masses (counterweights) [m, kg], ground pivots
        and guides [m], joint reactions [N],
        shaking force [N] and moment [N·m], curves and marks.
    """
    kin = analysis.kinematics
    mech = mechanism if mechanism is not None else kin.mechanism
    phi = np.asarray(kin.crank_angle, dtype=float).ravel()
    size = phi.size
    frames = _frames(size, max_frames)
    assembled = np.asarray(getattr(kin, "assembled", np.ones(size, bool)), dtype=bool)
    assembled = np.broadcast_to(assembled[design] if assembled.ndim == 2 else assembled, (size,))

    coords: dict[str, tuple[np.ndarray, np.ndarray]] = {}
    bodies = []
    sliders = {b2 for _n, kind, _b1, b2 in _model.joints(mech) if kind == "P"}
    for k, body in enumerate(mech.moving_bodies):
        motion = kin.body(body)
        ox, oy, ang = (_at(v, design, frames, size) for v in (motion.x, motion.y, motion.angle))
        names = []
        for pname, (lx, ly) in mech.body(body).points.items():
            u, v = _pick(lx, design), _pick(ly, design)
            c, s = np.cos(ang), np.sin(ang)
            coords[f"{body}.{pname}"] = (ox + c * u - s * v, oy + s * u + c * v)
            names.append(pname)
        shape = "slider" if body in sliders else ("polygon" if len(names) >= 3 else "link")
        bodies.append({"name": body, "shape": shape, "colour": PALETTE[k % len(PALETTE)], "points": names,
                       "angle": _rounded(np.degrees(ang), 6) if shape == "slider" else None})

    xs = [c[0] for c in coords.values()] + [np.atleast_1d(_pick(g[0], design)) for g in mech.ground.values()]
    ys = [c[1] for c in coords.values()] + [np.atleast_1d(_pick(g[1], design)) for g in mech.ground.values()]
    all_x, all_y = np.concatenate(xs), np.concatenate(ys)
    all_x, all_y = all_x[np.isfinite(all_x)], all_y[np.isfinite(all_y)]
    extent = [float(all_x.min()), float(all_x.max()), float(all_y.min()), float(all_y.max())]
    span = max(extent[1] - extent[0], extent[3] - extent[2], 1e-9)
    quantum = span * 1e-5

    def world(values: np.ndarray) -> list[float | None]:
        return [round(float(v) / quantum) * quantum if np.isfinite(v) else None for v in values]

    points = {key: [world(x), world(y)] for key, (x, y) in coords.items()}
    crank = mech.crank.body
    traces: list[str] = []
    for key, (x, y) in coords.items():
        if key.startswith(f"{crank}.") or not np.all(np.isfinite(x)):
            continue
        if np.nanmax(np.hypot(x - np.nanmean(x), y - np.nanmean(y))) < 1e-6 * span:
            continue
        if any(np.allclose(x, coords[t][0]) and np.allclose(y, coords[t][1]) for t in traces):
            continue
        traces.append(key)

    masses = []
    total = sum(abs(_pick(pm.mass, design)) for pm in mech.point_masses) or 1.0
    for pm in mech.point_masses:
        if pm.body == _model.GROUND:
            continue
        motion = kin.body(pm.body)
        ox, oy, ang = (_at(v, design, frames, size) for v in (motion.x, motion.y, motion.angle))
        u, v = (_pick(c, design) for c in pm.position)
        c, s = np.cos(ang), np.sin(ang)
        mass = _pick(pm.mass, design)
        masses.append({"name": pm.name, "mass": mass, "size": float(np.sqrt(abs(mass) / total)),
                       "at": [world(ox + c * u - s * v), world(oy + s * u + c * v)]})

    ground = [{"name": name, "x": _pick(gx, design), "y": _pick(gy, design)}
              for name, (gx, gy) in mech.ground.items()]
    guides = []
    for d in mech.dyads:
        for g, slider in d.drawing().guides:
            gbody, gpoint = _model.split_ref(g.point)
            if gbody != _model.GROUND:
                continue
            gx, gy = (_pick(v, design) for v in mech.ground[gpoint])
            ga = _pick(g.angle, design)
            sx, sy = coords[f"{slider}.{next(iter(mech.body(slider).points))}"]
            along = (sx - gx) * np.cos(ga) + (sy - gy) * np.sin(ga)
            lo, hi = float(np.nanmin(along)) - 0.08 * span, float(np.nanmax(along)) + 0.08 * span
            guides.append([gx + lo * np.cos(ga), gy + lo * np.sin(ga), gx + hi * np.cos(ga), gy + hi * np.sin(ga)])

    forces = getattr(analysis, "forces", None)
    joints = []
    shaking = None
    plots: list[Curve] = []
    if forces is not None:
        for name, _kind, _b1, b2 in _model.joints(mech):
            pname = name.split(":")[0]
            at = f"{b2}.{pname}" if f"{b2}.{pname}" in coords else f"{b2}.{next(iter(mech.body(b2).points))}"
            r = forces.joint(name)
            joints.append({"name": name, "at": at, "fx": _rounded(_at(r.fx, design, frames, size)),
                           "fy": _rounded(_at(r.fy, design, frames, size))})
        ix, iy = inertial_force(kin)
        moment = forces.shaking_moment(about=tuple(about))
        shaking = {"at": [float(about[0]), float(about[1])], "fx": _rounded(_at(ix, design, frames, size)),
                   "fy": _rounded(_at(iy, design, frames, size)),
                   "moment": _rounded(_at(moment, design, frames, size))}
        plots.append(Curve("Driving torque", "N·m", forces.driving_torque))
        plots.append(Curve("Inertial shaking force |−Σ m·a_G|", "N", np.hypot(ix, iy)))
    energy = getattr(analysis, "energy", None)
    if energy is not None:
        plots.append(Curve("Kinetic energy", "J", energy.kinetic_total))
    plots += list(curves)
    shown = [{"title": c.title, "unit": c.unit, "y": _rounded(_at(c.values, design, frames, size)),
              "zero": c.from_zero} for c in plots]
    return {
        "title": title,
        "angles": _rounded(np.degrees(phi[frames]), 6),
        "assembled": [bool(a) for a in assembled[frames]],
        "extent": extent,
        "bodies": bodies,
        "points": points,
        "traces": traces,
        "masses": masses,
        "ground": ground,
        "guides": guides,
        "joints": joints,
        "shaking": shaking,
        "curves": shown,
        "marks": _marks(getattr(analysis, "diagnostics", None), kin, design),
    }


def _asset(name: str) -> str:
    return resources.files("machdyn.report").joinpath("templates", name).read_text(encoding="utf-8")


def assets() -> Markup:
    """The view's style and script, once per report (inline: the report needs no network)."""
    return Markup(f"<style>{_asset('view.css')}</style>\n<script>{_asset('view.js')}</script>")


def _json(data: Any) -> str:
    # Inside <script> only "</" could end the element early; escape it (and the HTML comment opener).
    text = json.dumps(data, separators=(",", ":"), allow_nan=False)
    return text.replace("</", "<\\/").replace("<!--", "<\\!--")


def view_html(scenes: Mapping[str, dict[str, Any]] | dict[str, Any], *, caption: str = "") -> Markup:
    """The markup of one animated view; several scenes (``{"unbalanced": s1, "balanced": s2}``) play side by
    side on one slider."""
    if "angles" in scenes:
        scenes = {"": scenes}
    view_id = f"mdv{next(_ids)}"
    body = _json({"scenes": scenes})
    text = escape(caption)
    return Markup(
        f'<div class="mdview" id="{view_id}" data-view="mechanism">'
        f'<script type="application/json" class="mdview-data">{body}</script>'
        f'<noscript>The animated view needs JavaScript; the static plots below show the same results.</noscript>'
        f'</div><p class="caption">{text}</p>'
    )


def design_space_html(table: Mapping[str, Iterable[Any]], units: Mapping[str, str], *, x: str, y: str,
                      status: Iterable[str] | None = None, highlight: Mapping[str, int] | None = None,
                      scenes: Mapping[int, dict[str, Any]] | None = None, front: Iterable[int] | None = None,
                      caption: str = "") -> Markup:
    """An interactive scatter of a design space: hover shows a design's variables and results, a click opens
    it (its numbers, and its animation where ``scenes`` holds one for that design).

    Parameters
    ----------
    table : column -> one value per design (variables and results, SI).
    units : column -> unit shown.
    x, y : the columns plotted (the reader can choose others from the table).
    status : per design, e.g. "regular" or why it is not; only regular designs set the axes' scale.
    highlight : label -> design index marked on the plot ("optimum", "nominal").
    scenes : design index -> :func:`scene`, for the designs that can be played back.
    front : indices of a Pareto front, joined by a line.
    """
    columns = {name: _rounded(values, 6, relative=False) for name, values in table.items()}
    size = len(next(iter(columns.values()))) if columns else 0
    data = {
        "columns": columns, "units": dict(units), "x": x, "y": y, "size": size,
        "status": list(status) if status is not None else ["regular"] * size,
        "highlight": dict(highlight or {}), "front": list(front or []),
        "scenes": {str(k): v for k, v in (scenes or {}).items()},
    }
    view_id = f"mdv{next(_ids)}"
    return Markup(
        f'<div class="mdview" id="{view_id}" data-view="space">'
        f'<script type="application/json" class="mdview-data">{_json(data)}</script>'
        f'<noscript>The interactive design space needs JavaScript.</noscript>'
        f'</div><p class="caption">{escape(caption)}</p>'
    )


def outcome_view(outcome: Any, curves: Sequence[Curve] = ()) -> Markup | None:
    """The animated view of a linkage kind's outcome (None when it has no linkage analysis)."""
    analysis = getattr(outcome, "analysis", None)
    if analysis is None or getattr(analysis, "kinematics", None) is None:
        return None
    about = (float(outcome.scalars.get("shaking_moment.about_x", 0.0)),
             float(outcome.scalars.get("shaking_moment.about_y", 0.0)))
    data = scene(analysis, outcome.mechanism, about=about, curves=curves)
    return view_html(data, caption=(
        "The mechanism as computed: drag the slider or press play. Arrows: the reaction at each joint (force on "
        "the later body) and the inertial shaking force on the frame, scaled to the largest over the cycle. A "
        "click on a curve moves the crank there; marks on the track: dead and limit positions, the worst "
        "transmission angle."))
