"""Report sections and plots of a design optimisation: the convergence history, the Pareto front, the best
design's variables and results, and the best design as a problem file."""

from __future__ import annotations

from typing import Any

import numpy as np
from markupsafe import escape

from ..results.labels import display_factor
from ..studies.optimisation.study import show_value
from .html import _render, figures_html, format_value, pretty_unit, rows_html
from .spaces import optimum_beside_nominal, pareto_space


def plot_convergence(result: Any, ax=None):
    """The best feasible objective per generation (the objective's own value, sign restored for a maximised
    one) and, on a second axis, the share of each generation that is feasible."""
    if ax is None:
        import matplotlib.pyplot as plt

        ax = plt.figure().add_subplot()
    h = result.history
    objective = result.objectives[0]
    best = -h.best if objective.sense == "maximise" else h.best
    ax.plot(h.generation, best, color="C0", marker=".", label="best feasible design")
    ax.set_xlabel("generation")
    unit = f" [{objective.unit}]" if objective.unit and objective.sense != "target" else ""
    what = "relative distance from target" if objective.sense == "target" else objective.result
    ax.set_ylabel(f"{what}{unit}")
    twin = ax.twinx()
    twin.plot(h.generation, 100 * np.asarray(h.feasible_share), color="C1", linestyle="--", label="feasible share")
    twin.set_ylabel("feasible designs [%]")
    twin.set_ylim(0, 105)
    ax.legend(loc="lower right")
    return ax


def plot_pareto(result: Any, ax=None, i: int = 0, j: int = 1):
    """Objectives i and j of the Pareto front's designs, the best design (best in the first objective)
    marked."""
    if ax is None:
        import matplotlib.pyplot as plt

        ax = plt.figure().add_subplot()
    f = result.front_f
    oi, oj = result.objectives[i], result.objectives[j]
    ax.plot(f[:, i], f[:, j], "o", color="C0", label="Pareto front")
    ax.plot(f[0, i], f[0, j], "*", color="C3", markersize=12, label="reported best design")
    ax.set_xlabel(f"{oi.result} [{oi.unit}]" if oi.unit else oi.result)
    ax.set_ylabel(f"{oj.result} [{oj.unit}]" if oj.unit else oj.result)
    ax.legend()
    return ax


def sections(outcome: Any) -> list[tuple[str, str]]:
    """The design-optimisation section of an ``[optimise]`` outcome."""
    result = outcome.results
    if result is None:
        text = "".join(f"<pre>{escape(m)}</pre>" for m in outcome.failed_checks)
        return [("Design optimisation", "<p>No feasible design was found.</p>" + text)]
    figures = [_render("optimise-history", "Convergence", "Best feasible objective per generation and the share "
                       "of feasible designs.", (7.0, 3.6), lambda fig: plot_convergence(result, fig.subplots()),
                       margins=(0.9, 0.9, 0.55, 0.3))]
    if result.front_f is not None and result.front_f.shape[1] >= 2:
        figures.append(_render("optimise-pareto", "Pareto front", "Designs no other design beats in both "
                               "objectives.", (6.0, 4.2), lambda fig: plot_pareto(result, fig.subplots()),
                               margins=(0.9, 0.2, 0.55, 0.3)))
    rows = []
    for name, lo, hi, x, unit, shown in zip(result.names, result.lower, result.upper, result.x, result.units,
                                            result.display_units, strict=True):
        factor = display_factor(unit, shown)  # in the unit the file gave the variable in
        rows.append([name, *(f"{format_value(v * factor)} {pretty_unit(shown)}".rstrip() for v in (lo, hi, x))])
    table = rows_html(rows, ["variable", "lower", "upper", "best design"])
    res_rows = []
    for o in result.objectives:
        res_rows.append([o.describe(), show_value(o.unit)(result.results.get(o.result, float("nan")))])
    for c in result.constraints:
        shown = show_value(c.unit)
        res_rows.append([c.describe(shown), shown(result.results.get(c.result, float("nan")))])
    results_table = rows_html(res_rows, ["objective / constraint", "best design"])
    status = (f"<p>{escape(result.method.replace('_', ' '))}: {result.evaluations} designs evaluated in "
              f"{format_value(result.seconds)} s ({format_value(result.designs_per_second)} designs/s); "
              f"{'converged' if result.converged else 'did not converge'} ({escape(result.message)}); the best "
              f"design, rebuilt from its own problem file, {'meets' if result.verified else 'breaks'} every "
              "constraint.</p>")
    best = f"<h3>The best design as a problem file</h3><pre>{escape(result.problem_text)}</pre>"
    moving = "".join(str(v) for v in (optimum_beside_nominal(result), pareto_space(result)) if v is not None)
    return [("Design optimisation", status + table + results_table + moving + figures_html(figures) + best)]
