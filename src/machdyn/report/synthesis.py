"""Report section of the ``[synthesis]`` kind: the best candidates drawn with their paths over the task's targets,
the population's ranking quantity against its kinematic error, and the ranked table."""

from __future__ import annotations

from html import escape
from typing import Any

import numpy as np

from ..synthesis.rank import QUANTITIES
from ..synthesis.task import shifted_error
from .html import _render, figures_html, format_value, rows_html
from .plotkit import PALETTE, _finish
from .slotted_lever import sections as slotted_sections

SHOWN = 4


def _draw_linkage(ax: Any, c: Any, phi: float, colour: str, label: str) -> None:
    a, b, _ = c.joints(np.array([phi]))
    a, b = complex(a[0]), complex(b[0])
    o2 = c.origin
    if c.kind == "slider_crank":
        xs = [o2, a, b]
        u = np.exp(1j * c.slide_angle)
        s0 = o2 + c.offset * 1j * u
        line = s0 + u * np.array([-0.2, 1.2]) * (abs(b - s0) + c.crank)
        ax.plot(line.real, line.imag, color="#bbbbbb", linewidth=0.8)
    else:
        xs = [o2, a, b, c.rocker_pivot]
        p = complex(c.point(np.array([phi]))[0])
        ax.fill([a.real, b.real, p.real], [a.imag, b.imag, p.imag], color=colour, alpha=0.15)
    ax.plot([z.real for z in xs], [z.imag for z in xs], "-o", color=colour, markersize=3, linewidth=1.6, label=label)
    ax.plot([o2.real] + ([c.rocker_pivot.real] if c.kind == "four_bar" else []),
            [o2.imag] + ([c.rocker_pivot.imag] if c.kind == "four_bar" else []), "^", color=colour, markersize=7)


def plot_candidates(ax: Any, result: Any) -> Any:
    """The best candidates in their first position, the coupler point's path over the working range (a full turn
    dotted) and the task's targets."""
    for k, c in enumerate(result.candidates[:SHOWN]):
        colour = PALETTE[k % len(PALETTE)]
        _draw_linkage(ax, c, float(c.angles[0]) if c.angles.size else 0.0, colour, f"#{k + 1}")
        if c.kind == "four_bar" and result.task in ("motion", "path"):
            whole = c.point(np.linspace(0, 2 * np.pi, 361))
            ax.plot(whole.real, whole.imag, ":", color=colour, linewidth=0.8)
            work = c.point(c.working_angles(181))
            ax.plot(work.real, work.imag, color=colour, linewidth=1.0)
    curve = result.curve
    if "points" in curve:
        p = curve["points"]
        ax.plot(p.real, p.imag, "kx", markersize=8, label="targets")
        if "angles" in curve:
            size = 0.15 * max(float(np.ptp(p.real)), float(np.ptp(p.imag)), 1e-9)
            for q, t in zip(p, curve["angles"], strict=True):
                ax.annotate("", (q.real + size * np.cos(t), q.imag + size * np.sin(t)), (q.real, q.imag),
                            arrowprops={"arrowstyle": "->", "color": "black"})
    if "swing" in curve:
        lo, hi = curve["swing"]
        t = np.linspace(float(lo), float(hi), 60)
        r = curve["rocker"]
        ax.plot(r * np.cos(t), r * np.sin(t), "k--", linewidth=1.2, label="required swing")
    if "stroke" in curve:
        ax.plot([0.0, curve["stroke"]], [0.0, 0.0], "k-", linewidth=3, alpha=0.4, label="required stroke")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    return _finish(ax, "Best candidates over the task")


def plot_function(ax: Any, result: Any) -> Any:
    """Function generation: the wanted output angle and each shown candidate's over the input range."""
    t2, t4 = result.curve["theta2"], result.curve["theta4"]
    ax.plot(np.degrees(t2 - t2[0]), np.degrees(t4 - t4[0]), "k-", linewidth=2.5, alpha=0.35, label="wanted")
    for k, c in enumerate(result.candidates[:SHOWN]):
        e = shifted_error(c, t2, t4)
        ax.plot(np.degrees(t2 - t2[0]), np.degrees(t4 - t4[0] + e), color=PALETTE[k % len(PALETTE)],
                label=f"#{k + 1}")
    ax.set_xlabel("input (crank) turn from the range's start [deg]")
    ax.set_ylabel("output (rocker) turn from the range's start [deg]")
    return _finish(ax, "Generated function")


def plot_population(ax: Any, result: Any) -> Any:
    """The ranking quantity against the kinematic error of every candidate (filled: free of defects)."""
    label, unit, _ = QUANTITIES[result.ranked_by]
    v = np.asarray(result.values[result.ranked_by], dtype=float)
    e = np.asarray(result.values["error"], dtype=float)
    shown = np.degrees(v) if unit == "rad" else v
    ok = np.array([r.ok for r in result.reports])
    floor = max(float(np.nanmax(np.where(np.isfinite(e), e, np.nan), initial=0.0)) * 1e-6, 1e-16)
    ee = np.maximum(np.where(np.isfinite(e), e, np.nan), floor)
    ax.scatter(ee[~ok], shown[~ok], s=12, facecolors="none", edgecolors="#999999", label="with defects")
    ax.scatter(ee[ok], shown[ok], s=14, color=PALETTE[0], label="free of defects")
    ax.scatter(ee[:1], shown[:1], s=60, marker="*", color=PALETTE[1], label="best", zorder=3)
    finite = ee[np.isfinite(ee)]
    if finite.size and finite.max() > 100.0 * finite.min():
        ax.set_xscale("log")
    positive = shown[np.isfinite(shown) & (shown > 0)]
    if positive.size and positive.max() > 100.0 * np.median(positive):
        ax.set_yscale("log")
    ax.set_xlabel("kinematic error at the positions")
    ax.set_ylabel(f"{label.lower()} [{'deg' if unit == 'rad' else unit}]")
    return _finish(ax, "The population")


def sections(outcome: Any) -> list[tuple[str, str]]:
    """The synthesis section: figures and the ranked table."""
    result = outcome.results
    if result is None:  # the task gave no linkage at all: say why
        why = "; ".join(outcome.failed_checks) or "no candidate"
        return [("Synthesis", f"<p>No linkage was found: {escape(why)}</p>")]
    if result.task in ("slotted_lever", "whitworth"):
        return slotted_sections(result)
    first = plot_function if result.task == "function" else plot_candidates

    def draw(fig: Any) -> None:
        ax1, ax2 = fig.subplots(1, 2)
        first(ax1, result)
        plot_population(ax2, result)

    figures = [_render("synthesis", "Candidates", "Left: the best candidates (triangles: ground pivots) with the "
                       "coupler point's path (solid over the working range, dotted a full turn) over the task's "
                       "targets. Right: every candidate's ranking quantity against its kinematic error.",
                       (10.0, 4.4), draw, margins=(0.75, 0.3, 0.6, 0.45), wspace=0.35)]
    function = result.task == "function"
    head = ["#", "method", "links [mm]", "crank pivot", f"{QUANTITIES[result.ranked_by][0]}", "worst μ [deg]",
            "error [deg]" if function or result.task == "quick_return" else "error [m]", "defects"]
    if function:
        head[3:3] = ["K1, K2, K3", "ranges turned by [deg]"]
    rows = []
    for k, (c, r) in enumerate(zip(result.candidates[:10], result.reports[:10], strict=False)):
        v = result.values[result.ranked_by][k]
        unit = QUANTITIES[result.ranked_by][1]
        links = ", ".join(f"{name} {format_value(1e3 * value)}" for name, value in c.lengths().items())
        rows.append([str(k + 1), c.method, links,
                     f"({format_value(1e3 * c.origin.real)}, {format_value(1e3 * c.origin.imag)}) mm",
                     f"{format_value(np.degrees(v) if unit == 'rad' else v)} {'deg' if unit == 'rad' else unit}",
                     format_value(np.degrees(result.values['min_transmission'][k])),
                     format_value(np.degrees(result.values["error"][k]) if head[-2] == "error [deg]"
                                  else result.values["error"][k]), "; ".join(r.defects) or "none"])
        if function:
            rows[-1][3:3] = [", ".join(format_value(c.free[n]) for n in ("K1", "K2", "K3")),
                             f"{format_value(np.degrees(c.free.get('input_shift', 0.0)))}, "
                             f"{format_value(np.degrees(c.free.get('output_shift', 0.0)))}"]
    intro = (f"<p>{len(result.candidates)} candidates of the task '{result.task}', {result.defect_free} free of "
             f"defects, ranked by {QUANTITIES[result.ranked_by][0].lower()} (defect-free first) at "
             f"{format_value(result.drive.speed * 30 / np.pi)} rpm. The best are written as problem files "
             "(best_1.toml ...) that run on their own.</p>")
    return [("Synthesis", intro + figures_html(figures) + rows_html(rows, head))]
