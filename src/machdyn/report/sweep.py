"""The report section of a design sweep: per-design results against the swept parameter, and a table."""

from __future__ import annotations

from typing import Any

import numpy as np
from markupsafe import escape

from ..results.catalogue import label
from ..results.labels import display_factor
from ..studies.sweep.runs import column_label
from . import plots
from .html import _render, format_value, pretty_unit
from .spaces import sweep_space

#: The per-design results plotted and tabulated (catalogue keys); the full table is sweep.csv.
PANELS = ("driving_torque.max_abs", "driving_torque.rms", "frame_force.max", "inertial_shaking_force.max",
          "shaking_moment.max_abs", "transmission_angle.worst")


def sections(outcome: Any) -> list[tuple[str, str]]:
    """The design-sweep section of a ``[sweep]`` outcome."""
    run = outcome.results
    plan = run.plan
    asked = getattr(run, "asked", None)
    if asked is not None:  # a cam's or a shaft line's sweep, each variant run whole: its columns
        count = int(np.sum(np.asarray(run.columns["regular"], dtype=bool)))
        intro = (f"<p>{plan.values_display.size} variants of <code>{escape(plan.parameter)}</code>, each run whole "
                 f"through the file's stages; {count} built, ran and reported every column (the status of the "
                 "others is in the table).</p>")
        shown = tuple(k for k in asked if k != plan.parameter)
        return [(f"Design sweep of {plan.parameter}",
                 sweep_section(plan.parameter, plan.display_unit, plan.values_display, run.columns, run.units,
                               panels=shown, intro=intro))]
    return [(f"Design sweep of {plan.parameter}",
             # str(): Markup + str would escape the plots and the table that follow the scatter
             str(sweep_space(run)) + sweep_section(plan.parameter, plan.display_unit, plan.values_display, run.columns,
                                              run.units))]


def _panel(key: str, columns: dict, units: dict) -> tuple[str, str, np.ndarray]:
    """(label, display unit, values in it) of a per-design result."""
    lab = label(key, units.get(key))
    if lab is None and units.get(key) is not None:  # a result a kind's or a capability's table declares
        lab = column_label(key, units[key])
    text = lab.text if lab is not None else key
    unit = lab.shown_unit if lab is not None else units.get(key, "")
    factor = display_factor(units.get(key, ""), unit)
    return text, pretty_unit(unit), np.asarray(columns[key], dtype=float) * factor


def sweep_section(parameter: str, unit: str, values: Any, columns: dict, units: dict, *,
                  panels: tuple[str, ...] = PANELS, intro: str | None = None) -> str:
    """An HTML fragment for a design sweep: the per-design results ``panels`` (catalogue keys) plotted against
    the swept parameter and tabulated (the full table is also written as sweep.csv). Only regular designs are
    drawn, so the axes scale to them; the others are marked on the axis and their status is in the table.
    ``intro`` replaces the linkage sweep's opening paragraph."""
    regular = np.asarray(columns["regular"], dtype=bool)
    drawn = [_panel(k, columns, units) for k in panels if k in columns]

    def draw(fig):
        rows = (len(drawn) + 1) // 2
        axes = np.atleast_1d(fig.subplots(rows, 2)).ravel()
        for ax, (name, u, data) in zip(axes, drawn, strict=False):
            plots.plot_sweep(ax, values, data, parameter=parameter, parameter_unit=unit, quantity=name, unit=u,
                             regular=regular)
        for ax in axes[len(drawn):]:
            ax.set_visible(False)

    plot = ""
    if drawn:
        figure = _render("sweep", "Design sweep", "", (9.0, 3.2 * ((len(drawn) + 1) // 2)), draw,
                         margins=(0.85, 0.25, 0.6, 0.4), wspace=0.35, hspace=0.55)
        plot = f"<figure class=\"plot\">{figure.svg}</figure>"
    head = "".join(f"<th>{escape(h)}</th>" for h in
                   [f"{parameter} [{unit}]", "status"] + [f"{n} [{u}]" for n, u, _ in drawn])
    rows = []
    for i, v in enumerate(np.asarray(values, dtype=float)):
        cells = [format_value(float(v)), str(columns["status"][i])]
        cells += [format_value(float(data[i])) if np.isfinite(data[i]) else "–" for _, _, data in drawn]
        rows.append("<tr>" + "".join(f"<td>{escape(c)}</td>" for c in cells) + "</tr>")
    shown = rows[:200]
    note = (f"<p>First 200 of {len(rows)} designs; all are in sweep.csv.</p>" if len(rows) > 200 else "")
    intro = intro or (f"<p>{len(rows)} variants of <code>{escape(parameter)}</code>, analysed together over the "
                      f"same crank positions; {int(regular.sum())} regular (assemble everywhere, pass no dead point "
                      "and keep clear of one, change no branch, transmit force at an angle above the threshold).</p>")
    return (f"{intro}{plot}{note}"
            f"<table class=\"figures\"><thead><tr>{head}</tr></thead><tbody>{''.join(shown)}</tbody></table>")
