"""Report sections and plots of ``[balance]``: shaking-force polar diagrams before and after on one plot, the
partial-balance trade-off curve, the before/after table and the per-state table of a robust balance."""

from __future__ import annotations

from types import SimpleNamespace
from typing import Any

import numpy as np
from markupsafe import escape

from ..balancing.robust import RobustResult
from .animation import scene, view_html
from .html import _render, figures_html, format_value, rows_html
from .plots import PALETTE, _finish

__all__ = ["plot_polar_before_after", "plot_before_after", "plot_tradeoff", "plot_state_reductions", "sections"]


def plot_polar_before_after(ax: Any, before: Any, after: Any, *, title: str | None = "Shaking force [N]") -> Any:
    """The locus of the shaking-force vector over the cycle before and after balancing on one polar plot
    (radius = magnitude [N], angle = direction in the global frame); dots mark the first crank position."""
    for loads, label, colour in ((before, "before", PALETTE[1]), (after, "after", PALETTE[0])):
        theta, r = np.arctan2(loads.fy, loads.fx), np.hypot(loads.fx, loads.fy)
        ax.plot(theta, r, color=colour, linewidth=1.5, label=label)
        ax.plot(theta[:1], r[:1], marker="o", color=colour, markersize=4, linestyle="none")
    ax.set_rlabel_position(112.5)
    ax.set_thetagrids(range(0, 360, 45), ["0°", "", "90°", "", "180°", "", "270°", ""])
    ax.set_ylim(bottom=0)
    ax.grid(True, alpha=0.4, linewidth=0.6)
    return _finish(ax, title)


def plot_before_after(ax: Any, before: Any, after: Any, quantity: str = "torque", *, title: str | None = None) -> Any:
    """A cycle quantity of two :class:`~machdyn.balancing.frame.FrameLoads` against the crank angle [deg]:
    ``quantity`` 'torque' (driving torque [N*m]) or 'moment' (shaking moment about the crank pivot [N*m])."""
    names = {"torque": "Driving torque [N·m]", "moment": "Shaking moment [N·m]"}
    for loads, label, colour in ((before, "before", PALETTE[1]), (after, "after", PALETTE[0])):
        ax.plot(np.degrees(loads.crank_angle), getattr(loads, quantity), color=colour, label=label)
    ax.set_xlabel("crank angle [deg]")
    ax.set_xlim(0, 360)
    ax.set_xticks(range(0, 361, 90))
    ax.axhline(0.0, color="#888888", linewidth=0.6)
    ax.grid(True, alpha=0.35, linewidth=0.6)
    return _finish(ax, title if title is not None else names[quantity])


def plot_tradeoff(ax: Any, curve: Any, *, chosen: float | None = None, title: str | None = None) -> Any:
    """Peak shaking force along and across the stroke and the peak resultant against the balanced fraction of
    the reciprocating mass; a dashed line marks the chosen fraction."""
    ax.plot(curve.fraction, curve.peak_along, color=PALETTE[0], label="peak along the stroke")
    ax.plot(curve.fraction, curve.peak_across, color=PALETTE[1], label="peak across the stroke")
    ax.plot(curve.fraction, curve.peak_total, color=PALETTE[2], label="peak resultant")
    if chosen is not None:
        ax.axvline(chosen, color="#888888", linestyle="--", linewidth=0.8)
    ax.set_xlabel("balanced fraction of the reciprocating mass [-]")
    ax.set_ylabel("shaking force [N]")
    ax.set_ylim(bottom=0)
    ax.grid(True, alpha=0.35, linewidth=0.6)
    return _finish(ax, title if title is not None else "Partial balance trade-off")


def plot_state_reductions(ax: Any, rows: Any, *, reference: float | None = None, title: str | None = None) -> Any:
    """RMS shaking force before and after per operating state (bars) and, if given, a published reduction as a
    reference line on the reductions (right axis)."""
    x = np.arange(len(rows))
    ax.bar(x - 0.2, [r.rms_before for r in rows], 0.4, color=PALETTE[1], label="before")
    ax.bar(x + 0.2, [r.rms_after for r in rows], 0.4, color=PALETTE[0], label="after")
    ax.set_xticks(x, [r.state for r in rows], rotation=70, ha="right", fontsize="x-small")
    ax.set_ylabel("RMS shaking force [N]")
    if reference is not None:
        twin = ax.twinx()
        twin.plot(x, [100 * r.reduction for r in rows], "o", color=PALETTE[2], markersize=3, label="reduction")
        twin.axhline(100 * reference, color=PALETTE[2], linestyle="--", linewidth=0.8)
        twin.set_ylabel("reduction [%]")
    return _finish(ax, title if title is not None else "Shaking force per operating state")


def sections(outcome: Any) -> list[tuple[str, str]]:
    """The balancing section of a ``[balance]`` outcome."""
    done = outcome.results
    r = done.result
    if isinstance(r, RobustResult):
        return [("Balance over operating states", _robust_html(done))]
    parts = [_motion_before_after(r.before, r.after, r.model), _polar_and_tradeoff(done), _cost_figure(r),
             _table_html(r)]
    if r.notes:
        parts.append("<p>" + "<br>".join(escape(n) for n in r.notes) + "</p>")
    return [(f"Balance ({done.method.replace('_', ' ')})", "".join(parts))]


def _motion_before_after(before: Any, after: Any, model: Any, state: str = "") -> str:
    """The machine before and after balancing, moving side by side on one slider (empty when the frame loads
    do not keep their analysis)."""
    if before.forces is None or after.forces is None:
        return ""
    scenes = {}
    for name, loads, mech in (("unbalanced", before, None), ("balanced", after, model)):
        played = SimpleNamespace(kinematics=loads.forces.kinematics, forces=loads.forces, energy=None,
                                 diagnostics=None)
        scenes[name] = scene(played, mech, about=(0.0, 0.0), title=f"{name.capitalize()} machine")
    where = f" in operating state '{state}'" if state else ""
    return str(view_html(scenes, caption=(
        f"The machine before and after balancing{where}, on one slider (gravity left out, as in the balance; "
        "grey discs: the balancing masses). Red: the inertial shaking force on the frame, both machines on one "
        "scale; the curves below share the crank angle.")))


def _polar_and_tradeoff(done: Any) -> str:
    r = done.result
    curve = done.tradeoff

    def draw(fig):
        if curve is None:
            plot_polar_before_after(fig.add_subplot(1, 1, 1, projection="polar"), r.before, r.after)
        else:
            plot_polar_before_after(fig.add_subplot(1, 2, 1, projection="polar"), r.before, r.after)
            plot_tradeoff(fig.add_subplot(1, 2, 2), curve, chosen=done.fraction)

    size = (4.6, 4.0) if curve is None else (9.6, 4.0)
    caption = ("Shaking-force polar diagram before and after balancing (dots: first crank position)"
               + ("; right: the trade-off of partial balance (balance_tradeoff.csv)." if curve else "."))
    figure = _render("balance", "Shaking force before and after", caption, size, draw,
                     margins=(0.6, 0.3, 0.7, 0.45), wspace=0.35)
    return figures_html([figure])


def _cost_figure(r: Any) -> str:
    def draw(fig):
        plot_before_after(fig.add_subplot(1, 2, 1), r.before, r.after, "torque")
        plot_before_after(fig.add_subplot(1, 2, 2), r.before, r.after, "moment")

    caption = "What balancing changes elsewhere: the driving torque and the shaking moment over the cycle."
    figure = _render("balance-cost", "Driving torque and shaking moment before and after", caption, (9.6, 3.4),
                     draw, margins=(0.7, 0.3, 0.6, 0.4), wspace=0.3)
    return figures_html([figure])


def _table_html(result: Any) -> str:
    rows = []
    for row in result.table.rows:
        change = "–" if not np.isfinite(row.change) else f"{100 * row.change:+.1f} %"
        rows.append((row.quantity, f"{format_value(row.before)} {row.unit}", f"{format_value(row.after)} {row.unit}",
                     change))
    return rows_html(rows, ("quantity", "before", "after", "change"))


def _robust_html(done: Any) -> str:
    r = done.result
    ref = done.reference_reduction

    def draw(fig):
        plot_state_reductions(fig.add_subplot(1, 1, 1), r.rows, reference=ref)

    caption = "RMS shaking force of each state before and after; dots: the reduction, dashed: the published one."
    figure = _render("balance-states", "Shaking force per state", caption, (9.6, 4.4), draw,
                     margins=(0.8, 0.8, 1.6, 0.4))
    head = ["state", "RMS before [N]", "RMS after [N]", "peak before [N]", "peak after [N]", "reduction"]
    if ref is not None:
        head.append("published reduction")
    rows = []
    for row in r.rows:
        cells = [row.state, format_value(row.rms_before), format_value(row.rms_after), format_value(row.peak_before),
                 format_value(row.peak_after), f"{100 * row.reduction:.1f} %"]
        if ref is not None:
            cells.append(f"{100 * ref:.0f} %")
        rows.append(cells)
    values = "; ".join(
        f"{name} {mass:.4g} kg" + ("" if pos is None else f" at ({1e3 * pos[0]:.4g}, {1e3 * pos[1]:.4g}) mm")
        for name, (mass, pos) in r.placed.items()
    )
    source = f" Published reduction: {escape(done.reference_source)}." if done.reference_source else ""
    intro = (f"<p>One set of balancing masses for {len(r.rows)} operating states, minimising the "
             f"{'sum' if r.mode == 'sum' else 'worst'} of their mean square shaking forces: {escape(values)} "
             "(positions in the body frame; on the crank, in the frame of the shaft). "
             f"Mean reduction {100 * r.mean_reduction:.1f} %.{source}</p>")
    notes = "<p>" + "<br>".join(escape(n) for n in r.notes) + "</p>"
    motion = _motion_before_after(r.before[0], r.after[0], r.models[0], r.rows[0].state)
    return f"{intro}{motion}{figures_html([figure])}{rows_html(rows, head)}{notes}"
