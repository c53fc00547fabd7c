"""Interactive design spaces of the report: a one-quantity sweep, an exploration and an optimisation.

Each is a scatter the reader can re-plot against any column, hover for a design's numbers and click to open a
design — its numbers and, for the designs the stage analysed for playback (:mod:`machdyn.studies.views`),
its animation. After an optimisation the optimum plays beside the nominal design on one slider.
Only regular designs set the scatter's scale, so that a design near a dead position with enormous forces does
not squash the others into a corner.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import numpy as np
from markupsafe import Markup

from ..results.catalogue import label
from ..results.labels import display_factor
from .animation import design_space_html, scene, view_html


def _scene(view: Any) -> dict[str, Any]:
    return scene(view.analysis, view.mechanism, about=view.about)


def _rows_of(views: Iterable[Any], designs: Any) -> dict[int, dict[str, Any]]:
    """Scenes keyed by the row of the design in the scatter's table."""
    where = {int(d): row for row, d in enumerate(np.asarray(designs).ravel())}
    return {where[v.design]: _scene(v) for v in views if v.design in where}


def sweep_space(done: Any) -> Markup:
    """The interactive scatter of a one-quantity ``[sweep]`` (:class:`machdyn.studies.sweep.population.SweepRun`): every
    per-design column of the catalogue, in its display unit, against the swept value."""
    plan = done.plan
    values = np.asarray(plan.values_display, dtype=float)
    table: dict[str, Any] = {"design": np.arange(values.size), plan.parameter: values}
    units = {plan.parameter: plan.display_unit}
    for key, data in done.columns.items():
        arr = np.asarray(data)
        if arr.dtype.kind not in "fiu" or key in ("assembled", "regular") or arr.shape != values.shape:
            continue
        lab = label(key, done.units.get(key))
        shown = lab.shown_unit if lab is not None else done.units.get(key, "")
        table[key] = arr.astype(float) * display_factor(done.units.get(key, ""), shown)
        units[key] = shown
    status_column = done.columns.get("status")
    regular = np.asarray(done.columns["regular"], dtype=bool)
    status = [("regular" if r else "not regular") if status_column is None else str(status_column[i])
              for i, r in enumerate(regular)]
    y = "driving_torque.max_abs" if "driving_torque.max_abs" in table else next(iter(units))
    return design_space_html(table, units, x=plan.parameter, y=y, status=status,
                             scenes=_rows_of(done.views, table["design"]),
                             highlight={v.label: v.design for v in done.views[:1]},
                             caption="Each dot is a variant of the sweep: hover for its numbers, click to open it. "
                                     "Designs with a moving picture: " + ", ".join(v.label for v in done.views)
                                     + ". Axes: choose any column.")


def exploration_space(done: Any, shown: Any) -> Markup:
    """The interactive scatter of an exploration: a uniform sample of its regular designs and its best designs,
    in display units (``shown(done, column, values) -> (values, unit)``)."""
    digest, plan = done.digest, done.plan
    sample, best = digest.sample_in_design_order(), digest.best
    columns = [c for c in ("design", *plan.space.names, plan.objective)]
    columns += [c for c in best if c not in columns and np.asarray(best[c]).dtype.kind in "fiu"
                and c not in ("assembled", "regular")]  # numbers only: the status flags go into ``status``
    seen = set()
    rows: dict[str, list[float]] = {c: [] for c in columns}
    status: list[str] = []
    for part in (best, sample):
        for r in range(len(part.get("design", []))):
            d = int(part["design"][r])
            if d in seen:
                continue
            seen.add(d)
            for c in columns:
                rows[c].append(float(part[c][r]) if c in part else float("nan"))
            status.append(str(part["status"][r]) if "status" in part else "regular")
    table: dict[str, Any] = {}
    units: dict[str, str] = {}
    for c in columns:
        if c == "design":
            table[c] = np.asarray(rows[c])
            continue
        table[c], units[c] = shown(done, c, rows[c])
    views = [v for v in done.views if v.design >= 0]
    highlight = {"best": 0} if rows["design"] else {}
    nominal = next((v for v in done.views if v.design < 0), None)
    caption = ("The regular designs of a uniform sample and the best designs: hover for a design's numbers, click "
               "to open it; the best designs also play their motion. Axes: choose any column.")
    space = design_space_html(table, units, x=plan.space.names[0], y=plan.objective, highlight=highlight, status=status,
                              scenes=_rows_of(views, table["design"]), caption=caption)
    if nominal is None or not views:
        return space
    side = view_html({"nominal": _scene(nominal), "best design": _scene(views[0])},
                     caption="The nominal design and the best design of the exploration, on one crank slider and "
                             "to one scale.")
    return Markup(space + side)


def optimum_beside_nominal(result: Any) -> Markup | None:
    """The optimum and the nominal design playing side by side on one slider, to one scale (None when either
    could not be analysed)."""
    views = {v.label: v for v in getattr(result, "views", ())}
    if "nominal" not in views or "optimum" not in views:
        return None
    return view_html({"nominal": _scene(views["nominal"]), "optimum": _scene(views["optimum"])},
                     caption="The nominal design (the file as written) and the optimum, on one crank slider and to "
                             "one scale: drag the slider or press play.")


def pareto_space(result: Any) -> Markup | None:
    """The Pareto front of a multi-objective optimisation as an interactive scatter (None for one objective)."""
    if result.front_f is None or result.front_x is None or result.front_f.shape[1] < 2:
        return None
    table: dict[str, Any] = {"design": np.arange(len(result.front_f))}
    units: dict[str, str] = {}
    for i, (name, unit, shown_unit) in enumerate(zip(result.names, result.units, result.display_units, strict=True)):
        table[name] = result.front_x[:, i] * display_factor(unit, shown_unit)
        units[name] = shown_unit
    for j, o in enumerate(result.objectives):
        table[o.result] = result.front_f[:, j]
        units[o.result] = "" if o.sense == "target" else o.unit
    order = [o.result for o in result.objectives]
    optimum = next((v for v in result.views if v.label == "optimum"), None)
    return design_space_html(table, units, x=order[0], y=order[1], front=range(len(result.front_f)),
                             highlight={"reported best": 0},
                             scenes={0: _scene(optimum)} if optimum is not None else None,
                             caption="The Pareto front: designs no other design beats in every objective. Hover "
                                     "for a design's variables and objectives; the reported best design (best in "
                                     "the first objective) plays its motion.")
