"""The screw conveyor's report sections: design, power by method, checks, bending along a span, ranking.

Reads a :class:`~machdyn.conveyor.evaluate.ConveyorResult` only (SI) and shows it in the display units of
:data:`machdyn.conveyor.labels.LABELS`. Plots take an ``ax`` and return it.
"""

from __future__ import annotations

import math
from html import escape
from typing import Any

import numpy as np

from ..conveyor.labels import label_of
from ..results.labels import display_factor
from .html import figures_html, render_figure

_TABLE = 'style="border-collapse:collapse;margin:0.5em 0"'
_CELL = 'style="border:1px solid #bbb;padding:2px 8px;text-align:{align}"'


def _row(cells: list[str], *, head: bool = False, extra: str = "") -> str:
    tag = "th" if head else "td"
    out = [f"<{tag} {_CELL.format(align='left' if i == 0 else 'right')}>{c}</{tag}>" for i, c in enumerate(cells)]
    return f"<tr{extra}>" + "".join(out) + "</tr>"


def _fmt(value: float) -> str:
    return escape(f"{value:.4g}")


def _shown(key: str, value: float) -> tuple[str, float, str]:
    lab = label_of(key)
    unit = lab.shown_unit
    return lab.text, value * display_factor(lab.unit, unit), unit


def plot_power_by_method(result: Any, ax: Any = None) -> Any:
    """Bar chart of the shaft power [kW] of every method; the one that sizes the drive is dark."""
    if ax is None:
        from matplotlib.figure import Figure

        ax = Figure().add_subplot()
    keys = list(result.powers)
    values = [result.powers[k].shaft_power / 1000 for k in keys]
    colours = ["#1f4e79" if k == result.selected_method else "#9dc3e6" for k in keys]
    ax.bar(range(len(keys)), values, color=colours)
    ax.set_xticks(range(len(keys)), keys)
    ax.set_ylabel("shaft power [kW]")
    return ax


def plot_span_bending(result: Any, ax: Any = None) -> Any:
    """Bending moment [N·m], deflection [mm] and equivalent stress [MPa] along one span (three axes)."""
    b = result.bending
    if ax is None:
        from matplotlib.figure import Figure

        ax = Figure().subplots(3, 1, sharex=True)
    axes = np.atleast_1d(ax)
    series = [(np.abs(b.moment), "|M| [N·m]"), (b.deflection * 1000, "v [mm]"),
              (b.equivalent_stress / 1e6, "σ_eq [MPa]")]
    for a, (y, name) in zip(axes, series, strict=False):
        a.plot(b.x, y, color="#1f4e79")
        a.set_ylabel(name)
    axes[-1].set_xlabel("x along the span [m]")
    return ax


def plot_stress_along_screw(result: Any, ax: Any = None) -> Any:
    """Equivalent stress [MPa] along the whole screw, from the feed end to the drive."""
    b = result.bending
    if ax is None:
        from matplotlib.figure import Figure

        ax = Figure().add_subplot()
    ax.plot(b.screw_x, b.screw_stress / 1e6, color="#1f4e79")
    ax.set_xlabel("x from the feed end [m]")
    ax.set_ylabel("σ_eq [MPa]")
    return ax


def plot_ranking(result: Any, ax: Any = None, top: int = 10) -> Any:
    """The best feasible candidates of a design search by objective (lower is better)."""
    r = result.ranking
    if ax is None:
        from matplotlib.figure import Figure

        ax = Figure().add_subplot()
    rows = r.table(top)
    ax.barh(range(len(rows))[::-1], [row["objective"] for row in rows], color="#9dc3e6")
    ax.set_yticks(range(len(rows))[::-1], [row["name"] for row in rows])
    ax.set_xlabel(r.objective_label)
    return ax


def _figures(result: Any) -> str:
    figs = [render_figure("conveyor-power", "Power by method", "Shaft power of every method; the dark bar "
                          "sizes the drive.", (5.0, 2.6), lambda fig: plot_power_by_method(result, fig.add_subplot()))]
    if result.bending is not None:
        figs.append(render_figure(
            "conveyor-span", "Bending along one span",
            "The span between two hangers as a beam-column (lateral load and the whole axial force).",
            (5.0, 4.2), lambda fig: plot_span_bending(result, fig.subplots(3, 1, sharex=True)), hspace=0.35))
        figs.append(render_figure(
            "conveyor-screw-stress", "Equivalent stress along the screw",
            "Torque and axial force grow from the feed end to the drive; every span bends like the one above.",
            (5.0, 2.4), lambda fig: plot_stress_along_screw(result, fig.add_subplot())))
    if result.ranking is not None:
        figs.append(render_figure("conveyor-ranking", "Ranking of candidate designs",
                                  "The feasible candidates of least objective.", (5.0, 3.0),
                                  lambda fig: plot_ranking(result, fig.add_subplot()), margins=(2.2, 0.2, 0.5, 0.2)))
    return str(figures_html(figs))


def conveyor_html_section(result: Any, *, figures: bool = True) -> str:
    """HTML fragment: design, power by method, checks, ranking (if any) and the plots."""
    p = result.problem
    parts = [f'<section class="machdyn-conveyor"><h2>Screw conveyor: {escape(p.name)}</h2>']
    if p.description:
        parts.append(f"<p>{escape(p.description)}</p>")
    parts.append(f"<p>Material: {escape(p.material_name)}; drive sized by <b>{escape(result.selected_method)}"
                 f"</b>. Overall: <b>{'all checks pass' if result.passed else 'CHECKS FAIL'}</b>.</p>")
    section = ("the annulus around the pipe, π/4·(D² − d_o²), as in CEMA 350" if p.capacity_section == "annulus"
               else "the whole circle, π/4·D², as in seed 004 (eq 2.83)")
    flight = ("its pitch's share F_a·S/L of the axial force on the material's section (eq 2.92)"
              if p.flight_load == "per_pitch" else "the whole axial force on one turn's whole face (eq 2.56)")
    parts.append(f"<p>Capacity over {escape(section)}; each flight turn loaded by {escape(flight)}.</p>")
    parts.append(f"<h3>Design</h3><table {_TABLE}>")
    parts.append(_row(["Quantity", "Value", "Unit"], head=True))
    for key, value in result.scalars.items():
        if key.startswith(("check_", "power_")):
            continue
        text, shown, unit = _shown(key, value)
        parts.append(_row([escape(text), _fmt(shown), escape(unit)]))
    parts.append("</table>")
    parts.append(f"<h3>Power by method</h3><table {_TABLE}>")
    parts.append(_row(["Method", "Shaft power [kW]", "Motor power at drive efficiency [kW]", "Parts [kW]", "Note"],
                      head=True))
    for key, res in result.powers.items():
        parts_txt = "; ".join(f"{escape(k)} {v / 1000:.4g}" for k, v in res.parts.items())
        mark = ' style="font-weight:bold"' if key == result.selected_method else ""
        parts.append(_row([escape(res.label), _fmt(res.shaft_power / 1000),
                           _fmt(res.shaft_power / p.drive_efficiency / 1000), parts_txt, escape(res.note)], extra=mark))
    parts.append("</table>")
    parts.append(f"<h3>Checks</h3><table {_TABLE}>")
    parts.append(_row(["Check", "Value", "Limit", "Unit", "Utilisation", "Result", "Basis"], head=True))
    for c in result.checks:
        value, limit, unit = c.shown()
        verdict = ('<span style="color:#060">pass</span>' if c.passed
                   else '<span style="color:#b00;font-weight:bold">FAIL</span>')
        parts.append(_row([escape(c.name), _fmt(value), _fmt(limit), escape(unit), f"{c.utilisation:.0%}", verdict,
                           escape(c.source)]))
    parts.append("</table>")
    if result.ranking is not None:
        r = result.ranking
        parts.append(f"<h3>Design search</h3><p>{r.feasible} of {r.candidates} candidates meet the duty and every "
                     f"check; ranked by {escape(r.objective_label)}.</p><table {_TABLE}>")
        parts.append(_row(["Rank", "D [mm]", "S/D", "n [rpm]", "filling", "power [kW]", "screw mass [kg]",
                           escape(r.objective_label)], head=True))
        for i, row in enumerate(r.table(10), 1):
            rpm = row["speed"] * 30 / math.pi  # shown in rpm, kept in rad/s
            parts.append(_row([str(i), _fmt(row["diameter"] * 1000), _fmt(row["pitch_ratio"]), _fmt(rpm),
                               _fmt(row["filling"]), _fmt(row["power"] / 1000), _fmt(row["screw_mass"]),
                               _fmt(row["objective"])]))
        parts.append("</table>")
    if result.warnings:
        parts.append("<h3>Warnings</h3><ul>" + "".join(f"<li>{escape(w)}</li>" for w in result.warnings) + "</ul>")
    if figures:
        parts.append(_figures(result))
    parts.append("</section>")
    return "\n".join(parts)


def sections(outcome: Any) -> list[tuple[str, str]]:
    """The screw conveyor's report section of a run's outcome."""
    result = outcome.results
    result = getattr(result, "result", result)  # the wrapper of the first releases holds the result
    return [("Screw conveyor", conveyor_html_section(result))]
