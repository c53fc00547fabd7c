"""Drawing a linkage: its bodies, joints, guides and ground at chosen crank positions, with the paths of its
points. Takes a matplotlib ``ax`` and returns it, like every plot of :mod:`machdyn.report.plots`."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from matplotlib.axes import Axes
from matplotlib.patches import Polygon, Rectangle

from ..linkage import model as _model
from .plotkit import PALETTE, _finish

_GROUND_COLOUR = "#555555"


def _rotate(x: Any, y: Any, angle: Any) -> tuple[np.ndarray, np.ndarray]:
    c, s = np.cos(angle), np.sin(angle)
    return c * x - s * y, s * x + c * y


def _pick(value: Any, design: int) -> float:
    arr = np.asarray(value, dtype=float)
    return float(arr.ravel()[design] if arr.ndim > 0 else arr)


def _series(values: Any, design: int, size: int) -> np.ndarray:
    """One design's series of ``size`` positions (scalars and constant results broadcast)."""
    arr = np.asarray(values, dtype=float)
    arr = arr[design] if arr.ndim == 2 else arr
    return np.broadcast_to(arr, (size,))


# -------------------------------------------------------------------------------------------- mechanism


def _pivot_symbol(ax: Axes, x: float, y: float, size: float) -> None:
    """A fixed pivot: a hatched triangle under a pin."""
    tri = Polygon(
        [(x, y), (x - 0.6 * size, y - size), (x + 0.6 * size, y - size)],
        closed=True,
        facecolor="#dddddd",
        edgecolor=_GROUND_COLOUR,
        linewidth=1.0,
        zorder=2,
    )
    ax.add_patch(tri)
    ax.plot(
        [x - 0.9 * size, x + 0.9 * size], [y - size, y - size], color=_GROUND_COLOUR, linewidth=1.2, zorder=2
    )
    for k in np.linspace(-0.8, 0.6, 5):
        ax.plot(
            [x + k * size, x + (k + 0.25) * size],
            [y - 1.35 * size, y - size],
            color=_GROUND_COLOUR,
            linewidth=0.7,
            zorder=2,
        )


def plot_mechanism(
    ax: Axes,
    mechanism: _model.Mechanism,
    kinematics: Any,
    positions: Sequence[float] | int = 4,
    *,
    design: int = 0,
    paths: bool = True,
    title: str | None = "Mechanism",
) -> Axes:
    """Draw the linkage at a few crank positions: the first position in full colour, the others faded.

    ``positions`` is either a number of evenly spaced positions over the computed range or a sequence of
    crank angles [rad] (the nearest computed position is drawn). With ``paths`` the trajectory of every
    moving point that is not on the crank is drawn dotted. Axes are equal, in metres.
    """
    phi = np.asarray(kinematics.crank_angle, dtype=float).ravel()
    assembled = np.asarray(getattr(kinematics, "assembled", np.ones(phi.shape, bool)), dtype=bool)
    assembled = assembled[design] if assembled.ndim == 2 else assembled
    ok = np.flatnonzero(assembled) if assembled.any() else np.arange(phi.size)
    if isinstance(positions, int | np.integer):
        count = max(1, int(positions))
        picks = ok[np.linspace(0, ok.size, count, endpoint=False).astype(int)]
    else:
        picks = np.array(
            [ok[np.argmin(np.abs(np.angle(np.exp(1j * (phi[ok] - p)))))] for p in positions], int
        )

    # global coordinates of every body point at every position
    coords: dict[str, dict[str, tuple[np.ndarray, np.ndarray]]] = {}
    for body in mechanism.moving_bodies:
        motion = kinematics.body(body)
        ox, oy, ang = (_series(v, design, phi.size) for v in (motion.x, motion.y, motion.angle))
        pts = {}
        for pname, (lx, ly) in mechanism.body(body).points.items():
            rx, ry = _rotate(_pick(lx, design), _pick(ly, design), ang)
            pts[pname] = (ox + rx, oy + ry)
        coords[body] = pts

    all_x = np.concatenate(
        [p[0] for pts in coords.values() for p in pts.values()]
        + [np.atleast_1d(_pick(g[0], design)) for g in mechanism.ground.values()]
    )
    all_y = np.concatenate(
        [p[1] for pts in coords.values() for p in pts.values()]
        + [np.atleast_1d(_pick(g[1], design)) for g in mechanism.ground.values()]
    )
    extent = float(
        np.nanmax(np.ptp(np.vstack([all_x[np.isfinite(all_x)], all_y[np.isfinite(all_y)]]), axis=1))
    )
    extent = extent if extent > 0 else 1.0
    size = 0.04 * extent

    joint_list = _model.joints(mechanism)
    sliders = {b2 for _n, kind, _b1, b2 in joint_list if kind == "P"}

    # guides fixed in the ground
    for d in mechanism.dyads:
        for g, slider in d.drawing().guides:
            gbody, gpoint = _model.split_ref(g.point)
            if gbody != _model.GROUND:
                continue
            gx, gy = (float(_pick(v, design)) for v in mechanism.ground[gpoint])
            ga = _pick(g.angle, design)
            ux, uy = np.cos(ga), np.sin(ga)
            sx, sy = coords[slider][next(iter(mechanism.body(slider).points))]
            along = (sx - gx) * ux + (sy - gy) * uy
            lo, hi = np.nanmin(along) - 2.5 * size, np.nanmax(along) + 2.5 * size
            ax.plot(
                [gx + lo * ux, gx + hi * ux],
                [gy + lo * uy, gy + hi * uy],
                color=_GROUND_COLOUR,
                linewidth=1.0,
                linestyle=(0, (6, 3)),
                zorder=1,
            )
            nx, ny = -uy, ux
            for t in np.linspace(lo, hi, 12):
                bx, by = gx + t * ux - 0.9 * size * nx, gy + t * uy - 0.9 * size * ny
                ax.plot(
                    [bx, bx - 0.4 * size * (ux + nx)],
                    [by, by - 0.4 * size * (uy + ny)],
                    color=_GROUND_COLOUR,
                    linewidth=0.6,
                    zorder=1,
                )

    # point paths
    if paths:
        crank = mechanism.crank.body
        drawn: list[tuple[np.ndarray, np.ndarray]] = []
        for body, pts in coords.items():
            for x, y in pts.values():
                if body == crank or any(
                    np.allclose(x, px, equal_nan=True) and np.allclose(y, py, equal_nan=True)
                    for px, py in drawn
                ):
                    continue
                if np.nanmax(np.hypot(x - np.nanmean(x), y - np.nanmean(y))) < 1e-9 * extent:
                    continue
                drawn.append((x, y))
                ax.plot(x, y, color="#999999", linewidth=0.8, linestyle=":", zorder=1)
        # crank circle
        for x, y in coords[crank].values():
            if np.nanmax(np.hypot(x - np.nanmean(x), y - np.nanmean(y))) > 1e-9 * extent:
                ax.plot(x, y, color="#bbbbbb", linewidth=0.6, linestyle=":", zorder=1)

    # ground pivots (revolute joints with the frame)
    for name, kind, b1, _b2 in joint_list:
        if kind == "R" and b1 == _model.GROUND and name in mechanism.ground:
            gx, gy = (float(_pick(v, design)) for v in mechanism.ground[name])
            _pivot_symbol(ax, gx, gy, size)
            ax.annotate(
                name,
                (gx, gy),
                xytext=(-10, -4),
                textcoords="offset points",
                ha="right",
                va="top",
                fontsize="small",
                color=_GROUND_COLOUR,
            )

    # the bodies at each picked position
    for order, idx in enumerate(picks):
        main = order == 0
        alpha = 1.0 if main else 0.28
        for k, body in enumerate(mechanism.moving_bodies):
            colour = PALETTE[k % len(PALETTE)]
            pts = coords[body]
            xs = np.array([p[0][idx] for p in pts.values()])
            ys = np.array([p[1][idx] for p in pts.values()])
            if body in sliders:
                ang = _series(kinematics.body(body).angle, design, phi.size)[idx]
                w, h = 2.4 * size, 1.4 * size
                cx, cy = xs[0], ys[0]
                dx, dy = _rotate(-w / 2, -h / 2, ang)
                ax.add_patch(
                    Rectangle(
                        (cx + dx, cy + dy),
                        w,
                        h,
                        angle=float(np.degrees(ang)),
                        rotation_point="xy",
                        facecolor=colour,
                        edgecolor="#222222",
                        alpha=0.55 * alpha,
                        linewidth=1.0,
                        zorder=3,
                    )
                )
            elif len(xs) >= 3:
                order_pts = np.argsort(np.arctan2(ys - ys.mean(), xs - xs.mean()))
                ax.add_patch(
                    Polygon(
                        np.column_stack([xs[order_pts], ys[order_pts]]),
                        closed=True,
                        facecolor=colour,
                        edgecolor=colour,
                        alpha=0.35 if main else 0.3,
                        fill=main,
                        linewidth=2.5 if main else 1.2,
                        zorder=3,
                    )
                )
            else:
                ax.plot(
                    xs,
                    ys,
                    color=colour,
                    linewidth=3.2 if main else 2.0,
                    alpha=alpha,
                    solid_capstyle="round",
                    zorder=3,
                    label=body if main else None,
                )
            ax.plot(
                xs,
                ys,
                linestyle="none",
                marker="o",
                markersize=5 if main else 3.5,
                markerfacecolor="white",
                markeredgecolor="#222222",
                alpha=alpha,
                zorder=4,
                label=None,
            )
            if len(xs) >= 3 or body in sliders:
                ax.plot([], [], color=colour, linewidth=3.2, label=body if main else None)
        if main:
            labelled: set[str] = set()
            for body in mechanism.moving_bodies:
                for pname, (x, y) in coords[body].items():
                    if pname in labelled or pname in mechanism.ground:
                        continue
                    labelled.add(pname)
                    ax.annotate(
                        pname,
                        (x[idx], y[idx]),
                        xytext=(5, 5),
                        textcoords="offset points",
                        fontsize="small",
                        color="#222222",
                        zorder=5,
                    )
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.grid(True, alpha=0.3, linewidth=0.6)
    shown = ", ".join(f"{np.degrees(phi[i]):.0f}°" for i in picks)
    full = title if title is None else f"{title} at φ = {shown}"
    _finish(ax, full, legend=False)
    ax.legend(
        fontsize="small", loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0, frameon=False
    )
    return ax


# ------------------------------------------------------------------------------------------------- motion
