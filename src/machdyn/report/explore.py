"""Report sections of the ``[sweep]`` table: a one-quantity sweep as before; an exploration's design space as
a scatter matrix of a bounded sample of the regular designs (at most 2,000 however many were explored),
coloured by the objective, with the best designs marked, and the table of the best designs."""

from __future__ import annotations

from typing import Any

import numpy as np
from markupsafe import escape

from ..results.labels import display_factor
from ..studies.exploration.run import Exploration
from .html import _render, format_value, pretty_unit
from .spaces import exploration_space
from .sweep import sections as one_quantity

#: At most this many quantities are drawn in the scatter matrix (the best-designs table lists them all).
MATRIX_QUANTITIES = 6


def sections(outcome: Any) -> list[tuple[str, str]]:
    """The report sections of a ``[sweep]`` outcome."""
    if not isinstance(outcome.results, Exploration):
        return one_quantity(outcome)
    done = outcome.results
    return [(f"Design space of {', '.join(done.plan.space.names)}", exploration_section(done))]


def _shown(done: Any, name: str, data: Any) -> tuple[np.ndarray, str]:
    """Values of a column in its display unit, and that unit."""
    quantity = next((q for q in done.plan.space.quantities if q.parameter == name), None)
    unit = done.units.get(name, ("", name))[0]
    display = quantity.display_unit if quantity is not None else unit
    return np.asarray(data, dtype=float) * display_factor(unit, display), display


def _short(path: str) -> str:
    """The last two parts of a key path, for an axis (``mechanism.crank.length`` -> ``crank.length``)."""
    return ".".join(path.split(".")[-2:])


def plot_design_space(fig: Any, done: Any) -> Any:
    """Scatter matrix of an exploration on ``fig``: each pair of quantities (below the diagonal) and the
    objective against each quantity (on the diagonal), the sampled regular designs coloured by the objective,
    the best designs ringed in red. Returns the axes grid."""
    names = list(done.plan.space.names[:MATRIX_QUANTITIES])
    goal = done.plan.objective
    sample = done.digest.sample_in_design_order()
    best = done.digest.best
    k = len(names)
    axes = np.atleast_2d(fig.subplots(k, k, squeeze=False))
    colour, goal_unit = _shown(done, goal, sample.get(goal, []))
    lo, hi = (float(np.min(colour)), float(np.max(colour))) if colour.size else (0.0, 1.0)
    points = None
    for i, y_name in enumerate(names):
        for j, x_name in enumerate(names):
            ax = axes[i, j]
            if j > i:
                ax.set_visible(False)
                continue
            x, x_unit = _shown(done, x_name, sample.get(x_name, []))
            bx, _ = _shown(done, x_name, best.get(x_name, []))
            if i == j:
                y, y_unit, by = colour, goal_unit, _shown(done, goal, best.get(goal, []))[0]
                y_label = f"{goal} [{pretty_unit(goal_unit)}]"
            else:
                y, y_unit = _shown(done, y_name, sample.get(y_name, []))
                by = _shown(done, y_name, best.get(y_name, []))[0]
                y_label = f"{_short(y_name)} [{pretty_unit(y_unit)}]"
            points = ax.scatter(x, y, c=colour, s=4, cmap="viridis", vmin=lo, vmax=hi, linewidths=0,
                                rasterized=True)  # thousands of markers: one embedded image per panel
            ax.scatter(bx, by, s=28, facecolors="none", edgecolors="#d62728", linewidths=1.0)
            if i == k - 1:
                ax.set_xlabel(f"{_short(x_name)} [{pretty_unit(x_unit)}]", fontsize=7)
            if j == 0:
                ax.set_ylabel(y_label, fontsize=7)
            if i == j:
                ax.set_title(f"{goal} [{pretty_unit(y_unit)}]", fontsize=7)
            ax.tick_params(labelsize=6)
    if points is not None:
        bar = fig.colorbar(points, ax=axes.ravel().tolist(), shrink=0.6, pad=0.02)
        bar.set_label(f"{goal} [{pretty_unit(goal_unit)}]", fontsize=8)
    return axes


def _resumed(done) -> str:
    """``"; this run computed 4 partition(s) and reused 2 from disk"`` when a run resumed, else empty."""
    if not getattr(done, "reused", 0):
        return ""
    return f"; this run computed {done.computed:,} partition(s) and reused {done.reused:,} from an earlier run"


def exploration_section(done: Any) -> str:
    """An HTML fragment for an exploration: what was explored, the scatter matrix and the best designs."""
    space, digest = done.plan.space, done.digest
    k = min(len(space.names), MATRIX_QUANTITIES)
    side = max(3.2, 1.9 * k + 1.2)
    figure = _render("explore", "Design space", "", (side + 1.0, side), lambda fig: plot_design_space(fig, done),
                     margins=(0.9, 1.3, 0.7, 0.3), wspace=0.35, hspace=0.35)
    how = {"grid": "a full grid", "lhs": f"Latin hypercubes (seed {space.seed})",
           "sobol": f"a scrambled Sobol' sequence (seed {space.seed})"}[space.method]
    intro = (f"<p>{digest.designs:,} designs drawn from {how} over {len(space.names)} quantities, in "
             f"{space.partitions:,} partition(s) of up to {space.partition:,} designs; {digest.regular:,} regular "
             f"(assemble everywhere and pass no dead position). Objective: lowest <code>{escape(done.plan.objective)}"
             f"</code>. Every design is in <code>{escape(str(done.store))}</code> (Parquet, SI units in the "
             f"schema){_resumed(done)}.</p><p>Shown: a uniform sample of "
             f"{len(digest.sample.get('design', [])):,} regular designs, "
             "coloured by the objective; the best designs ringed in red.</p>")
    if len(space.names) > MATRIX_QUANTITIES:
        intro += f"<p>The matrix shows the first {MATRIX_QUANTITIES} quantities; the table lists all.</p>"
    columns = ["design", *space.names, done.plan.objective]
    head = "".join(f"<th>{escape(c)} [{escape(pretty_unit(_shown(done, c, [])[1]))}]</th>" if c != "design"
                   else "<th>design</th>" for c in columns)
    rows = []
    for r in range(len(digest.best.get("design", []))):
        cells = [str(int(digest.best["design"][r]))]
        cells += [format_value(float(_shown(done, c, digest.best[c][r:r + 1])[0][0])) for c in columns[1:]]
        rows.append("<tr>" + "".join(f"<td>{escape(c)}</td>" for c in cells) + "</tr>")
    table = (f"<table class=\"figures\"><thead><tr>{head}</tr></thead><tbody>{''.join(rows)}</tbody></table>"
             if rows else "<p>No regular design.</p>")
    return (f"{intro}{exploration_space(done, _shown)}<figure class=\"plot\">{figure.svg}</figure>"
            f"<h3>Best designs</h3>{table}")
