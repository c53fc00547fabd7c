"""The self-contained HTML report: input echoed, summary table, warnings, diagnostics and inline SVG plots.

The document needs no network and no JavaScript: the CSS is inline and every plot is an ``<svg>`` element
drawn by matplotlib's SVG backend on a plain :class:`~matplotlib.figure.Figure` (no pyplot, no GUI backend,
no global matplotlib state). All user text is escaped by the template engine.
"""

from __future__ import annotations

import datetime as _dt
import io
import itertools
import math
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

import jinja2
import matplotlib
import numpy as np
from markupsafe import Markup, escape

from .. import __version__
from ..linkage import model as _model
from . import plots
from .tables import _full_uniform_cycle, _slider_bodies, includes_end_point, joint_list, mechanism_of

_ENV = jinja2.Environment(
    loader=jinja2.PackageLoader("machdyn.report", "templates"),
    autoescape=jinja2.select_autoescape(enabled_extensions=("html", "j2"), default=True),
    trim_blocks=True,
    lstrip_blocks=True,
    undefined=jinja2.StrictUndefined,
)

#: matplotlib settings of the report figures (applied per figure via rc_context, never globally).
STYLE = {
    "svg.fonttype": "none",
    "svg.hashsalt": "machdyn",
    "font.family": "sans-serif",
    "font.sans-serif": ["DejaVu Sans"],
    "font.size": 9.0,
    "axes.titlesize": 10.0,
    "axes.labelsize": 9.0,
    "axes.edgecolor": "#444444",
    "axes.linewidth": 0.8,
    "axes.spines.top": False,
    "axes.spines.right": False,
    "xtick.labelsize": 8.0,
    "ytick.labelsize": 8.0,
    "legend.fontsize": 8.0,
    "figure.dpi": 96,
    "path.simplify": True,
    "path.simplify_threshold": 0.1,
}

_ids = itertools.count()


@dataclass(frozen=True)
class Figure:
    """One plot of the report: a title, a caption and the inline SVG markup."""

    key: str
    title: str
    caption: str
    svg: Markup


# ------------------------------------------------------------------------------------------- svg helpers


def figure_svg(fig: Any) -> Markup:
    """The figure as an inline ``<svg>`` element: XML prolog, DOCTYPE and metadata removed, every element id
    made unique in the document."""
    buf = io.StringIO()
    fig.savefig(buf, format="svg", metadata={"Date": None})
    text = buf.getvalue()
    start = text.find("<svg")
    text = text[start:]
    prefix = f"f{next(_ids)}-"
    text = re.sub(r'\bid="([^"]+)"', lambda m: f'id="{prefix}{m.group(1)}"', text)
    text = re.sub(r"url\(#([^)]+)\)", lambda m: f"url(#{prefix}{m.group(1)})", text)
    text = re.sub(r'href="#([^"]+)"', lambda m: f'href="#{prefix}{m.group(1)}"', text)
    text = re.sub(r"<metadata>.*?</metadata>\s*", "", text, count=1, flags=re.S)
    text = text.replace("<svg ", '<svg class="plot" role="img" ', 1)
    return Markup(text)


def _render(
    key: str,
    title: str,
    caption: str,
    size: tuple[float, float],
    draw,
    *,
    margins: tuple[float, float, float, float] = (0.75, 0.2, 0.5, 0.35),
    wspace: float | None = None,
    hspace: float | None = None,
) -> Figure:
    """Draw one report figure of ``size`` (width, height) [in] with ``margins`` (left, right, bottom, top)
    [in] around the axes grid and render it to SVG. A fixed layout keeps rendering fast (no layout engine,
    no tight bounding box)."""
    from matplotlib.figure import Figure as MplFigure

    width, height = size
    left, right, bottom, top = margins
    with matplotlib.rc_context(STYLE):
        fig = MplFigure(figsize=size)
        fig.subplots_adjust(
            left=left / width,
            right=1 - right / width,
            bottom=bottom / height,
            top=1 - top / height,
            wspace=wspace,
            hspace=hspace,
        )
        draw(fig)
        svg = figure_svg(fig)
    return Figure(key, title, caption, svg)


# -------------------------------------------------------------------------------------------- formatting


def format_value(value: Any) -> str:
    """A number to 4 significant digits (no exponent between 1e-3 and 1e6), lists joined, text as is."""
    if value is None:
        return "–"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int | np.integer):
        return str(int(value))
    if isinstance(value, float | np.floating):
        v = float(value)
        if math.isnan(v):
            return "n/a"
        if math.isinf(v):
            return "∞" if v > 0 else "−∞"
        if v == 0:
            return "0"
        if 1e-3 <= abs(v) < 1e6:
            digits = max(0, 3 - int(math.floor(math.log10(abs(v)))))
            text = f"{v:.{digits}f}"
            return text.rstrip("0").rstrip(".") if "." in text else text
        return f"{v:.4g}"
    if isinstance(value, np.ndarray):
        return format_value(value.tolist())
    if isinstance(value, list | tuple):
        return ", ".join(format_value(v) for v in value)
    return str(value)


def pretty_unit(unit: str) -> str:
    """``"kg*m^2"`` -> ``"kg·m²"``: multiplication dots and superscript powers for display."""
    sup = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")
    text = re.sub(r"\^(-?\d+)", lambda m: m.group(1).translate(sup), unit)
    return text.replace("*", "·")


def _deg(angle: Any) -> str:
    return format_value(np.degrees(np.asarray(angle, dtype=float)).tolist()) + "°"


def _ranges(ranges: Iterable) -> str:
    items = [f"{format_value(np.degrees(a))}° – {format_value(np.degrees(b))}°" for a, b in ranges]
    return "; ".join(items) if items else "none"


def diagnostics_rows(diagnostics: Any, mechanism: Any = None) -> list[tuple[str, str]]:
    """(item, text) rows describing the mechanism's diagnostics: Grashof type, assembly, dead and limit
    positions, strokes, time ratio and transmission-angle extremes."""
    if diagnostics is None:
        return []
    rows: list[tuple[str, str]] = []
    g = getattr(diagnostics, "grashof", None)
    if g is not None:
        rows.append(("Grashof type", str(g)))
    non = getattr(diagnostics, "non_assembly_ranges", None)
    if non is not None:
        rows.append(("Crank ranges where it cannot assemble", _ranges(non)))
    dead = getattr(diagnostics, "dead_positions", None)
    if dead is not None:
        dead = list(dead)
        rows.append(("Dead (toggle) positions of the crank", _deg(dead) if dead else "none"))
    sliders = set(_slider_bodies(mechanism)) if mechanism is not None else set()
    limits = getattr(diagnostics, "limit_positions", None)
    if limits:
        by_body: dict[str, list[str]] = {}
        for item in limits:
            body = getattr(item, "body", "")
            angle = getattr(item, "crank_angle", item)
            value = getattr(item, "value", None)
            text = f"φ = {format_value(float(np.degrees(float(angle))))}°"
            if value is not None:
                if body in sliders:
                    text += f" (s = {format_value(float(value))} m)"
                else:
                    text += f" (θ = {format_value(float(np.degrees(float(value))))}°)"
            by_body.setdefault(body, []).append(text)
        for body, texts in by_body.items():
            rows.append((f"Limit positions of {body}" if body else "Limit positions", ", ".join(texts)))
    for body, stroke in (getattr(diagnostics, "strokes", None) or {}).items():
        if body in sliders:
            rows.append((f"Stroke of {body}", f"{format_value(np.asarray(stroke, dtype=float).tolist())} m"))
        else:
            rows.append((f"Swing of {body}", _deg(stroke)))
    tr = getattr(diagnostics, "time_ratio", None)
    if tr is not None:
        rows.append(("Time ratio (working / return stroke)", format_value(np.asarray(tr, float).tolist())))
    lo = getattr(diagnostics, "transmission_angle_min", None)
    hi = getattr(diagnostics, "transmission_angle_max", None)
    if lo is not None:
        rows.append(("Transmission angle, minimum", _deg(lo)))
    if hi is not None:
        rows.append(("Transmission angle, maximum", _deg(hi)))
    return rows


# ---------------------------------------------------------------------------------------------- figures


def _mechanism_height(mech: Any, kin: Any, *, axes_width: float, extra: float) -> float:
    """A figure height [in] that fits the mechanism's bounding box at equal axis scales, between 2.4 and
    4.8 in (long, flat mechanisms get a flat figure)."""
    xs, ys = [], []
    for body in mech.moving_bodies:
        for point in mech.body(body).points:
            p = kin.point(f"{body}.{point}")
            xs.append(np.ravel(p.x))
            ys.append(np.ravel(p.y))
    x, y = np.concatenate(xs), np.concatenate(ys)
    with np.errstate(all="ignore"):
        dx, dy = float(np.nanmax(x) - np.nanmin(x)), float(np.nanmax(y) - np.nanmin(y))
    if not (np.isfinite(dx) and np.isfinite(dy)) or dx <= 0:
        return 4.6
    pad = 0.15 * max(dx, dy)
    return float(np.clip(axes_width * (dy + pad) / (dx + pad) + extra, 2.4, 4.8))


def _output_bodies(mechanism: Any) -> list[str]:
    """The bodies whose motion is the mechanism's output: its sliders, else the last body placed."""
    sliders = _slider_bodies(mechanism)
    if sliders:
        return sliders
    return [mechanism.moving_bodies[-1]] if len(mechanism.moving_bodies) > 1 else []


def analysis_figures(
    analysis: Any,
    mechanism: Any = None,
    *,
    positions: int = 4,
    shaking_about: tuple[float, float] = (0.0, 0.0),
) -> list[Figure]:
    """The standard plots of an analysis, rendered to inline SVG (the shaking moment about
    ``shaking_about`` [m])."""
    mech = mechanism if mechanism is not None else mechanism_of(analysis)
    kin, forces, energy = analysis.kinematics, analysis.forces, analysis.energy
    designs = np.ndim(forces.driving_torque) == 2
    pick = 0 if designs else None
    out: list[Figure] = []
    note = " Design variant 0 of the sweep is shown." if designs else ""

    if mech is not None:
        out.append(
            _render(
                "mechanism",
                "Mechanism",
                f"The linkage at {positions} crank positions (first one solid, the others faded) with "
                f"the paths of its moving points (dotted).{note}",
                (7.4, _mechanism_height(mech, kin, axes_width=7.4 - 0.7 - 1.25, extra=0.85)),
                lambda fig: plots.plot_mechanism(fig.add_subplot(), mech, kin, positions, design=0),
                margins=(0.7, 1.25, 0.5, 0.35),
            )
        )
        outputs = _output_bodies(mech)
        if outputs:

            def draw_motion(fig):
                axes = fig.subplots(3, 1, sharex=True)
                for ax, quantity in zip(axes, ("displacement", "velocity", "acceleration"), strict=True):
                    for body in outputs:
                        plots.plot_point_motion(ax, kin, body, quantity, design=pick, title="")
                    if ax is not axes[-1]:
                        ax.set_xlabel("")
                axes[0].set_title(
                    f"Output motion: {', '.join(outputs)}", loc="left", fontweight="bold", fontsize="medium"
                )

            kinds = ["slide along its guide" if b in _slider_bodies(mech) else "rotation" for b in outputs]
            out.append(
                _render(
                    "motion",
                    "Output motion",
                    "Displacement, velocity and acceleration of the output "
                    + ", ".join(f"{b} ({k})" for b, k in zip(outputs, kinds, strict=True))
                    + f".{note}",
                    (7.4, 5.2),
                    draw_motion,
                    margins=(0.85, 0.25, 0.5, 0.35),
                    hspace=0.12,
                )
            )

    joints = [j[0] for j in joint_list(forces)]
    if mech is not None:
        order = [j[0] for j in _model.joints(mech)]
        joints.sort(key=lambda name: order.index(name) if name in order else len(order))
    ncols = min(4, max(1, len(joints)))
    nrows = math.ceil(len(joints) / ncols)

    def draw_joints(fig):
        for k, name in enumerate(joints):
            ax = fig.add_subplot(nrows, ncols, k + 1, projection="polar")
            plots.plot_joint_polar(ax, forces, name, design=pick, title="")
            ax.set_title(f"Joint {name}", loc="center", fontsize="medium", fontweight="bold", pad=14)

    out.append(
        _render(
            "joints",
            "Joint reactions",
            "Polar diagrams of the joint reactions: the tip of the force vector on the later body from "
            "the earlier body over one cycle (radius = magnitude in N, angle = direction in the global "
            f"frame); the dot marks the first crank position.{note}",
            (7.4, 2.3 * nrows),
            draw_joints,
            margins=(0.4, 0.4, 0.25, 0.5),
            wspace=0.65,
            hspace=0.6,
        )
    )

    out.append(
        _render(
            "torque",
            "Driving torque and power",
            f"Torque the motor must apply to the crank (left axis) and the input power (right axis).{note}",
            (7.4, 3.2),
            lambda fig: plots.plot_torque_power(fig.add_subplot(), forces, design=pick),
            margins=(0.8, 1.0, 0.5, 0.35),
        )
    )

    def draw_shaking(fig):
        ax1 = fig.add_subplot(1, 2, 1, projection="polar")
        plots.plot_shaking_force_polar(ax1, forces, design=pick)
        ax2 = fig.add_subplot(1, 2, 2)
        plots.plot_shaking_moment(ax2, forces, about=shaking_about, design=pick)

    out.append(
        _render(
            "shaking",
            "Shaking force and moment",
            "Left: the total force the moving mechanism exerts on the frame (polar locus). Right: the "
            f"shaking moment on the frame about ({shaking_about[0]:g}, {shaking_about[1]:g}) m, including "
            f"the motor's reaction torque.{note}",
            (7.4, 3.3),
            draw_shaking,
            margins=(0.35, 0.2, 0.5, 0.45),
            wspace=0.3,
        )
    )

    def draw_energy(fig):
        ax1, ax2 = fig.subplots(2, 1, sharex=True, height_ratios=(1.6, 1.0))
        plots.plot_energy(ax1, energy, kin.crank_angle, design=pick, legend=False)
        ax1.set_xlabel("")
        ax1.legend(
            fontsize="small", loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0, frameon=False
        )
        plots.plot_reduced_inertia(
            ax2, energy, kin.crank_angle, design=pick, title="Reduced moment of inertia at the crank"
        )

    out.append(
        _render(
            "energy",
            "Energy",
            "Top: kinetic energy of each body and in total, potential energy and the total mechanical "
            f"energy. Bottom: the moment of inertia of the whole mechanism reduced to the crank, 2T/ω².{note}",
            (7.4, 5.0),
            draw_energy,
            margins=(0.8, 1.75, 0.5, 0.35),
            hspace=0.3,
        )
    )

    harmonics = _torque_harmonics(forces, kin)
    if harmonics is not None:
        out.append(
            _render(
                "harmonics",
                "Harmonics of the driving torque",
                "Amplitudes of the Fourier series of the driving torque over the crank angle "
                "(order 0 is the mean).",
                (7.4, 2.7),
                lambda fig: plots.plot_harmonics(
                    fig.add_subplot(),
                    harmonics,
                    unit="N·m",
                    label="driving torque",
                    title="Harmonics of the driving torque",
                ),
            )
        )
    return out


def _torque_harmonics(forces: Any, kin: Any):
    if not _full_uniform_cycle(kin.crank_angle):
        return None
    torque = np.asarray(forces.driving_torque, dtype=float)
    torque = torque[0] if torque.ndim == 2 else torque
    if not np.all(np.isfinite(torque)):
        return None
    from ..linkage.harmonics import harmonics

    phi = np.asarray(kin.crank_angle, dtype=float).ravel()
    if includes_end_point(phi):
        phi, torque = phi[:-1], torque[:-1]
    orders = min(10, phi.size // 2 - 1)
    return harmonics(torque, phi, orders=orders) if orders >= 1 else None


# ---------------------------------------------------------------------------------------------- document


def render_report(
    *,
    title: str,
    problem_text: str,
    summary_rows: Sequence[tuple[str, Any, str]],
    warnings: Sequence[str],
    analysis: Any = None,
    mechanism: Any = None,
    extra_html_sections: Sequence[str | tuple[str, str]] = (),
    positions: int = 4,
    shaking_about: tuple[float, float] = (0.0, 0.0),
) -> str:
    """One self-contained HTML document.

    title : the report's heading.
    problem_text : the input (problem file) echoed verbatim in a ``<pre>`` block.
    summary_rows : (quantity, value, unit) rows of the summary table; values are formatted to 4 significant
        digits (lists are joined).
    warnings : messages listed in the warnings section (the analysis diagnostics' own warnings are appended,
        duplicates dropped).
    analysis : an :func:`machdyn.linkage.analyse` result; adds the diagnostics table and the plots.
    mechanism : the mechanism drawn (taken from the analysis if omitted).
    extra_html_sections : HTML fragments inserted as sections after the summary, as a string (trusted HTML
        produced by machdyn) or a (heading, html) pair.
    positions : the number of crank positions at which the mechanism is drawn.
    shaking_about : the point [m] about which the shaking moment is plotted.
    """
    mech = mechanism if mechanism is not None else (mechanism_of(analysis) if analysis is not None else None)
    all_warnings = [str(w) for w in warnings]
    diagnostics = getattr(analysis, "diagnostics", None) if analysis is not None else None
    for w in getattr(diagnostics, "warnings", None) or []:
        if str(w) not in all_warnings:
            all_warnings.append(str(w))
    figures = (
        analysis_figures(analysis, mech, positions=positions, shaking_about=tuple(shaking_about))
        if analysis is not None
        else []
    )
    extras = []
    for i, section in enumerate(extra_html_sections):
        if isinstance(section, tuple):
            heading, body = section
        else:
            heading, body = None, section
        extras.append({"id": f"extra-{i + 1}", "heading": heading, "html": Markup(body)})
    rows = [(str(q), format_value(v), pretty_unit(str(u or ""))) for q, v, u in summary_rows]
    template = _ENV.get_template("report.html.j2")
    return template.render(
        title=title,
        problem_text=problem_text,
        summary_rows=rows,
        warnings=all_warnings,
        diagnostics=diagnostics_rows(diagnostics, mech),
        figures=figures,
        extras=extras,
        mechanism_name=getattr(mech, "name", None),
        version=__version__,
        generated=_dt.datetime.now().astimezone().strftime("%Y-%m-%d %H:%M %Z").strip(),
    )


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
