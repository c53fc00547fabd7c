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
from .animation import assets as view_assets

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


def render_figure(
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
    with matplotlib.rc_context(STYLE):  # type: ignore[arg-type]  # keys checked by matplotlib at run time
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


_render = render_figure  # the name the report modules use


def figures_html(figures: Sequence[Figure]) -> str:
    """Report figures as HTML: each a ``<figure>`` with its title, inline SVG and caption."""
    return "".join(
        f'<figure id="fig-{escape(f.key)}"><h3>{escape(f.title)}</h3>{f.svg}'
        f"<figcaption>{escape(f.caption)}</figcaption></figure>"
        for f in figures
    )


def rows_html(rows: Iterable[Sequence[Any]], head: Sequence[str] = ()) -> str:
    """A table of text cells (escaped); ``head`` the column headings (none: a table of row headings)."""
    thead = "<thead><tr>" + "".join(f"<th>{escape(h)}</th>" for h in head) + "</tr></thead>" if head else ""
    body = []
    for row in rows:
        cells = [format_value(c) if not isinstance(c, str) else c for c in row]
        if head:
            body.append("<tr>" + "".join(f"<td>{escape(c)}</td>" for c in cells) + "</tr>")
        else:
            body.append(f'<tr><th scope="row">{escape(cells[0])}</th>'
                        + "".join(f"<td>{escape(c)}</td>" for c in cells[1:]) + "</tr>")
    return f'<table class="summary">{thead}<tbody>{"".join(body)}</tbody></table>'


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


# ---------------------------------------------------------------------------------------------- document


def render_report(
    *,
    title: str,
    problem_text: str,
    summary_rows: Sequence[tuple[str, Any, str]],
    warnings: Sequence[str],
    sections: Sequence[tuple[str, str]] = (),
    subtitle: str | None = None,
    watch_stamp: str | None = None,
) -> str:
    """One self-contained HTML document.

    title : the report's heading; ``subtitle`` a line under it.
    problem_text : the input (problem file) echoed verbatim in a ``<pre>`` block.
    summary_rows : (quantity, value, unit) rows of the summary table; values are formatted to 4 significant
        digits (lists are joined).
    warnings : messages listed in the warnings section.
    sections : (heading, html) pairs, each a section after the warnings with a link in the navigation; the html
        is trusted markup produced by machdyn's report modules. A section holding an interactive view
        (``<div class="mdview">``, :mod:`.animation`) brings the view's inline style and script, once.
    watch_stamp : set by ``machdyn watch``: the page re-loads itself when ``report.stamp.js`` beside it carries
        another stamp (a new run).
    """
    used: set[str] = set()
    extras = []
    for heading, body in sections:
        slug = re.sub(r"[^a-z0-9]+", "-", heading.lower()).strip("-") or "section"
        key, n = slug, 2
        while key in used or key in ("summary", "warnings", "input"):
            key, n = f"{slug}-{n}", n + 1
        used.add(key)
        extras.append({"id": key, "heading": heading, "html": Markup(body)})
    rows = [(str(q), format_value(v), pretty_unit(str(u or ""))) for q, v, u in summary_rows]
    template = _ENV.get_template("report.html.j2")
    interactive = any('class="mdview"' in str(section["html"]) for section in extras)
    return template.render(
        view_assets=view_assets() if interactive else None,
        watch_stamp=watch_stamp,
        title=title,
        problem_text=problem_text,
        summary_rows=rows,
        warnings=[str(w) for w in warnings],
        extras=extras,
        subtitle=subtitle,
        version=__version__,
        generated=_dt.datetime.now().astimezone().strftime("%Y-%m-%d %H:%M %Z").strip(),
    )
