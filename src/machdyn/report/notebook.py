"""The HTML a Jupyter notebook shows for machdyn's objects (:class:`machdyn.notebook.ShownInNotebook`).

A run shows its summary table (values in their display units, each with its unit), its warnings and failed
checks, and every stage's report sections with their plots as inline SVG; one stage of it (``run.stage(name)``)
its own results and sections; :class:`~machdyn.results.Results` every key; :class:`~machdyn.results.Summary` its
rows; a study's or a capability's typed result (an optimisation, a sweep, an exploration, a flywheel, a balance
...) the report sections its capability draws from it. Nothing here computes: it reads the results and hands
them to the report's own sections, so a notebook shows what ``report.html`` shows.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import Any

from markupsafe import escape

from ..kinds import CAPABILITIES, capability
from ..pipeline import Outcome, import_object
from ..results import Results, Summary
from .html import format_value, pretty_unit

#: A little style of its own: a notebook does not load the report's stylesheet.
_STYLE = ("<style>.machdyn table.machdyn-summary td.value{text-align:right;font-variant-numeric:tabular-nums}"
          ".machdyn table.machdyn-summary th,.machdyn table.machdyn-summary td{padding:2px 8px}"
          ".machdyn svg.plot{max-width:100%;height:auto}.machdyn .warning{color:#a15c00}"
          ".machdyn .failed{color:#b00020}</style>")


def table_html(rows: Iterable[Sequence[Any]], *, key_column: bool = False) -> str:
    """A table of (quantity, value, unit) rows, or (key, quantity, value, unit) with ``key_column``: values as
    the report formats them, units in their own column."""
    head = ("key", "quantity", "value", "unit") if key_column else ("quantity", "value", "unit")
    body = []
    for row in rows:
        *text, value, unit = row
        cells = "".join(f"<td><code>{escape(t)}</code></td>" if key_column and i == 0 else f"<td>{escape(t)}</td>"
                        for i, t in enumerate(text))
        body.append(f'<tr>{cells}<td class="value">{escape(format_value(value))}</td>'
                    f"<td>{escape(pretty_unit(unit))}</td></tr>")
    thead = "".join(f"<th>{h}</th>" for h in head)
    return f'<table class="machdyn-summary"><thead><tr>{thead}</tr></thead><tbody>{"".join(body)}</tbody></table>'


def _results_rows(results: Results) -> list[tuple[str, str, Any, str]]:
    return [(key, *results.shown(key)) for key in results.values]


def _sections_html(sections: Iterable[tuple[str, str]]) -> str:
    return "".join(f"<section><h3>{escape(heading)}</h3>{html}</section>" for heading, html in sections)


def _notes_html(warnings: Iterable[str], failed: Iterable[str]) -> str:
    notes = [f'<li class="warning">{escape(w)}</li>' for w in warnings]
    notes += [f'<li class="failed">Design check failed: {escape(c)}</li>' for c in failed]
    return f"<ul>{''.join(notes)}</ul>" if notes else ""


def _page(title: str, body: str) -> str:
    return f'{_STYLE}<div class="machdyn"><h2>{escape(title)}</h2>{body}</div>'


def summary_html(summary: Summary) -> str:
    """The summary table of a run (values in their display units)."""
    rows = [(r.label, r.value, r.unit) for r in summary.rows]
    return _page(summary.title, table_html(rows))


def results_html(results: Results) -> str:
    """Every result with its key, label, value and unit (display units)."""
    return _page(f"Results ({len(results.values)})", table_html(_results_rows(results), key_column=True))


def run_html(run: Any) -> str:
    """A run (:class:`machdyn.runner.RunResult`): its summary, warnings and failed checks, and each stage's
    report sections with their plots."""
    rows = [(r.label, r.value, r.unit) for r in run.summary.rows]
    body = table_html(rows) + _notes_html(run.warnings, run.failed_checks)
    return _page(run.title, body + _sections_html(run.report_sections()))


def stage_html(stage: Any) -> str:
    """One stage of a run (:class:`machdyn.runner.StageResult`): its results and report sections."""
    body = table_html(_results_rows(stage.results), key_column=True)
    body += _notes_html(stage.outcome.warnings, stage.outcome.failed_checks)
    return _page(f"[{stage.name}]", body + _sections_html(stage.sections()))


def result_html(result: Any) -> str:
    """A capability's typed result alone (an optimisation, a sweep, a flywheel run ...): the report sections
    its capability draws from it (the capability whose declared ``result_type`` it is)."""
    for table in CAPABILITIES:
        cap = capability(table)
        if cap.result_type is not None and isinstance(result, cap.result_type) and cap.report is not None:
            sections = import_object(cap.report)(Outcome(results=result))
            return _page(f"[{table}]", _sections_html(sections))
    raise TypeError(f"No capability declares {type(result).__name__} as its result type.")


def html_of(obj: Any) -> str:
    """The notebook HTML of any object machdyn shows in Jupyter."""
    if isinstance(obj, Summary):
        return summary_html(obj)
    if isinstance(obj, Results):
        return results_html(obj)
    name = type(obj).__name__
    if name == "RunResult":
        return run_html(obj)
    if name == "StageResult":
        return stage_html(obj)
    return result_html(obj)
