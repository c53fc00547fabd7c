"""The screw-conveyor report section: three HTML tables (design, power by method, checks).

Reads a :class:`~machdyn.conveyor.problem.ConveyorResult` only; self-contained (inline styles, no
external resources).
"""

from __future__ import annotations

from html import escape
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # pragma: no cover
    from .problem import ConveyorResult

_TABLE = 'style="border-collapse:collapse;margin:0.5em 0"'
_CELL = 'style="border:1px solid #bbb;padding:2px 8px;text-align:{align}"'


def _row(cells: list[str], *, head: bool = False, extra: str = "") -> str:
    tag = "th" if head else "td"
    out = []
    for i, cell in enumerate(cells):
        align = "left" if i == 0 else "right"
        out.append(f"<{tag} {_CELL.format(align=align)}>{cell}</{tag}>")
    return f"<tr{extra}>" + "".join(out) + "</tr>"


def _fmt(value: float) -> str:
    return escape(f"{value:.4g}")


def conveyor_html_section(result: ConveyorResult) -> str:
    """HTML fragment with the design table, the power-by-method table and the checks table."""
    p = result.problem
    parts = [f'<section class="machdyn-conveyor"><h2>Screw conveyor: {escape(p.name)}</h2>']
    if p.description:
        parts.append(f"<p>{escape(p.description)}</p>")
    parts.append(f"<p>Material: {escape(p.material_name)}; drive sized by <b>{escape(result.selected_method)}"
                 f"</b>. Overall: <b>{'all checks pass' if result.passed else 'CHECKS FAIL'}</b>.</p>")

    parts.append(f"<h3>Design</h3><table {_TABLE}>")
    parts.append(_row(["Quantity", "Value", "Unit"], head=True))
    for q in result.quantities:
        parts.append(_row([escape(q.label), _fmt(q.value), escape(q.unit)]))
    parts.append("</table>")

    parts.append(f"<h3>Power by method</h3><table {_TABLE}>")
    parts.append(_row(["Method", "Shaft power [kW]", "Motor power at drive efficiency [kW]", "Parts [kW]",
                       "Note"], head=True))
    for key, res in result.powers.items():
        parts_txt = "; ".join(f"{escape(k)} {v / 1000:.4g}" for k, v in res.parts.items())
        mark = ' style="font-weight:bold"' if key == result.selected_method else ""
        parts.append(_row([escape(res.label), _fmt(res.shaft_power / 1000),
                           _fmt(res.shaft_power / p.drive_efficiency / 1000), parts_txt, escape(res.note)],
                          extra=mark))
    parts.append("</table>")

    parts.append(f"<h3>Checks</h3><table {_TABLE}>")
    parts.append(_row(["Check", "Value", "Limit", "Unit", "Utilisation", "Result", "Basis"], head=True))
    for c in result.checks:
        verdict = ('<span style="color:#060">pass</span>' if c.passed
                   else '<span style="color:#b00;font-weight:bold">FAIL</span>')
        parts.append(_row([escape(c.name), _fmt(c.value), _fmt(c.limit), escape(c.unit),
                           f"{c.utilisation:.0%}", verdict, escape(c.source)]))
    parts.append("</table>")
    if result.warnings:
        parts.append("<h3>Warnings</h3><ul>" + "".join(f"<li>{escape(w)}</li>" for w in result.warnings)
                     + "</ul>")
    parts.append("</section>")
    return "\n".join(parts)


def sections(outcome) -> list[tuple[str, str]]:
    """The screw conveyor's report section of a run's outcome."""
    return [("Screw conveyor", conveyor_html_section(outcome.results))]
