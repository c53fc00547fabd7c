"""Report section of the slotted-lever quick returns: the ram's travel over a turn for the best designs (the
engine's kinematics) with the stroke and dead positions the task asked for, and the ranked table."""

from __future__ import annotations

from typing import Any

import numpy as np

from ..linkage import kinematics
from .html import _render, figures_html, format_value, rows_html
from .plotkit import PALETTE, _finish

SHOWN = 4


def plot_ram(ax: Any, result: Any) -> Any:
    """The ram's position over a turn of the crank for the best designs, from the engine's kinematics."""
    phi = np.linspace(0.0, 2.0 * np.pi, 361)
    for k, (d, m) in enumerate(zip(result.designs[:SHOWN], result.measured[:SHOWN], strict=False)):
        y = np.asarray(kinematics(d.mechanism(), phi, 1.0).point("ram.R").y, dtype=float)
        low = float(np.min(y))
        colour = PALETTE[k % len(PALETTE)]
        ax.plot(np.degrees(phi), 1e3 * (y - low), color=colour, label=f"#{k + 1}")
        for a in m.dead_angles:
            ax.axvline(np.degrees(a), color=colour, linewidth=0.6, linestyle=":")
    ax.axhline(1e3 * result.stroke, color="black", linewidth=1.0, linestyle="--", label="required stroke")
    ax.set_xlabel("crank angle [deg]")
    ax.set_ylabel("ram travel from its lowest place [mm]")
    return _finish(ax, "Ram travel over a turn")


def sections(result: Any) -> list[tuple[str, str]]:
    """The synthesis section of a slotted-lever task."""
    def draw(fig: Any) -> None:
        plot_ram(fig.subplots(1, 1), result)

    name = "crank and slotted lever" if result.task == "slotted_lever" else "Whitworth quick return"
    figures = [_render("synthesis", "Ram travel", "The ram's travel over one turn of the crank (engine "
                       "kinematics) for the best designs; dotted: the crank angles where the ram stops. The slow "
                       "stroke over the fast one is the time ratio.", (7.0, 4.0), draw)]
    head = ["#", "crank r [mm]", "centre distance d [mm]", "lever l [mm]", "rod [mm]", "time ratio (engine)",
            "stroke (engine) [mm]", "cutting peak / mean speed", "return peak / mean speed", "slot force / ram force"]
    rows = []
    for k, (d, m) in enumerate(zip(result.designs[:10], result.measured[:10], strict=False)):
        rows.append([str(k + 1), format_value(1e3 * d.crank), format_value(1e3 * d.centre_distance),
                     format_value(1e3 * d.lever), format_value(1e3 * d.rod), format_value(m.time_ratio),
                     format_value(1e3 * m.stroke), format_value(m.peak_over_mean_slow),
                     format_value(m.peak_over_mean_fast), format_value(m.slot_force_per_ram_force)])
    intro = (f"<p>{len(result.designs)} designs of a {name} for a time ratio of {format_value(result.time_ratio)} "
             f"and a stroke of {format_value(1e3 * result.stroke)} mm, synthesised in closed form and measured by "
             "the engine's kinematics. The ram's motion depends on the time ratio alone; the free scale sets the "
             "size and the forces: ranked by the largest force of the crank pin on the slot per newton resisting "
             "the ram in the cutting stroke.</p>")
    return [("Synthesis", intro + figures_html(figures) + rows_html(rows, head))]
