"""The report section of a design sweep: per-design summaries against the swept parameter, and a table."""

from __future__ import annotations

from typing import Any

import numpy as np
from markupsafe import escape

from . import plots
from .html import _render, format_value
from .spaces import sweep_space


def sections(outcome: Any) -> list[tuple[str, str]]:
    """The design-sweep section of a ``[sweep]`` outcome."""
    run = outcome.results
    plan = run.plan
    return [(f"Design sweep of {plan.parameter}",
             sweep_space(run) + sweep_section(plan.parameter, plan.display_unit, plan.values_display, run.result))]


def sweep_section(parameter: str, unit: str, values: Any, result: Any) -> str:
    """An HTML fragment for a design sweep: the per-design summaries plotted against the swept parameter and
    tabulated (the full table is also written as sweep.csv)."""
    panels = [
        ("Peak driving torque", "N·m", result.max_driving_torque),
        ("RMS driving torque", "N·m", result.rms_driving_torque),
        ("Peak shaking force", "N", result.max_shaking_force),
        ("Peak shaking moment", "N·m", result.max_shaking_moment),
    ]

    def draw(fig):
        axes = fig.subplots(2, 2)
        for ax, (name, u, data) in zip(axes.ravel(), panels, strict=True):
            plots.plot_sweep(ax, values, data, parameter=parameter, parameter_unit=unit, quantity=name, unit=u,
                       regular=result.regular)

    figure = _render("sweep", "Design sweep", "", (9.0, 6.4), draw, margins=(0.85, 0.25, 0.6, 0.4),
                     wspace=0.35, hspace=0.55)
    head = "".join(f"<th>{escape(h)}</th>" for h in
                   [f"{parameter} [{unit}]", "regular"] + [f"{n} [{u}]" for n, u, _ in panels])
    rows = []
    for i, v in enumerate(np.asarray(values, dtype=float)):
        cells = [format_value(float(v)), "yes" if result.regular[i] else "no"]
        cells += [format_value(float(data[i])) if np.isfinite(data[i]) else "–" for _, _, data in panels]
        rows.append("<tr>" + "".join(f"<td>{escape(c)}</td>" for c in cells) + "</tr>")
    shown = rows[:200]
    note = (f"<p>First 200 of {len(rows)} designs; all are in sweep.csv.</p>" if len(rows) > 200 else "")
    regular = int(np.sum(result.regular))
    intro = (f"<p>{len(rows)} variants of <code>{escape(parameter)}</code>, analysed together over the same crank "
             f"positions; {regular} regular (assemble everywhere and pass no dead position).</p>")
    return (f"{intro}<figure class=\"plot\">{figure.svg}</figure>{note}"
            f"<table class=\"figures\"><thead><tr>{head}</tr></thead><tbody>{''.join(shown)}</tbody></table>")
