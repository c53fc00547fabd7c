"""The report sections of the rotary screen: the seed 002 energy figures (paper, formula, engine), then the
linkage's diagnostics and plots."""

from __future__ import annotations

from typing import Any

from . import mechanism
from .html import rows_html


def sections(outcome: Any) -> list[tuple[str, str]]:
    figures = outcome.results
    rows = [(k, f["quantity"], f["paper"], f["formula"], f["engine"], f["unit"], f["source"], f["note"])
            for k, f in figures.items()]
    table = rows_html(rows, ("figure", "quantity", "paper", "formula", "engine", "unit", "source", "note"))
    table = table.replace('class="summary"', 'class="figures"', 1)
    return [("Energy figures of seed 002: paper, formula, engine", table), *mechanism.sections(outcome)]
