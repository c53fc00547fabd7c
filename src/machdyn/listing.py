"""The catalogue written out: the keys a run reports (``machdyn results FILE``) and the tables of
docs/results.md, both from the declarations of the catalogue (:func:`machdyn.kinds.catalogue`) and nothing else.

docs/results.md keeps its prose; the tables between its ``<!-- catalogue: NAME -->`` and
``<!-- end catalogue -->`` marks are generated here. Regenerate them with::

    python -m machdyn.listing docs/results.md

and ``tests/docs/test_results_doc.py`` fails when the file is stale.
"""

from __future__ import annotations

import re
import sys
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path

from .kinds import catalogue
from .linkage.reductions import REDUCTIONS
from .results.catalogue import BETTER, COMPACTOR, GROUPS, MECHANISM, STATUS, Quantity, find
from .results.labels import Label


@dataclass(frozen=True)
class Listed:
    """One key of a run: its ``key``, its ``unit`` (the SI unit of results.json, with the unit the summary shows
    it in where that differs: ``rad (deg)``), its ``meaning`` (the label), the ``better`` direction ("lower",
    "higher", "target", "true" for a yes/no check, "" for none) and its ``reduction`` over the crank positions (a
    name of :data:`machdyn.linkage.reductions.REDUCTIONS`, "" for a key the catalogue does not know)."""

    key: str
    unit: str
    meaning: str
    better: str
    reduction: str = ""


def _quantity(key: str) -> Quantity | None:
    found = find(key, catalogue())
    if found is not None:
        return found[0]
    for carrier in ("sweep.best.", "sweep.lowest_", "optimise.best.", "sweep."):
        if key.startswith(carrier):
            inner = find(key[len(carrier):], catalogue())
            if inner is not None:
                return inner[0]
    return None


def listed(labels: Mapping[str, Label]) -> list[Listed]:
    """The keys of a run's results (``RunResult.results.labels``) with unit, meaning and better direction."""
    out = []
    for key, lab in labels.items():
        quantity = _quantity(key)
        better = quantity.better if quantity is not None and quantity.better != "none" else ""
        reduction = quantity.over_positions if quantity is not None else ""
        unit = lab.unit if lab.shown_unit == lab.unit else f"{lab.unit or '–'} ({lab.shown_unit})"
        out.append(Listed(key, unit, lab.text, better, reduction))
    return out


# ------------------------------------------------------------------------------------------------ the docs


def _cell(text: str) -> str:
    return text.replace("|", "\\|")


def _group(q: Quantity) -> str:
    if q.group:
        return q.group
    return f"– ({q.why})" if q.why else "–"


def mechanism_table(entries: Iterable[Quantity] = MECHANISM + COMPACTOR) -> str:
    """The markdown table of the quantities of a mechanism: key, SI unit, meaning, series, reduction, better
    direction and population group."""
    lines = ["| key | SI unit | meaning | series | over the crank positions | better | population group |",
             "|---|---|---|---|---|---|---|"]
    for q in entries:
        lines.append(f"| `{q.key}` | {q.unit or '–'} | {_cell(q.text)} | {f'`{q.series}`' if q.series else '–'} "
                     f"| {REDUCTIONS[q.over_positions].text} | {_better(q)} | {_cell(_group(q))} |")
    return "\n".join(lines)


def _better(q: Quantity) -> str:
    return q.better


def status_table() -> str:
    """The markdown table of the checks of each design of a population."""
    lines = ["| column | the design... |", "|---|---|"]
    lines += [f"| `{q.key}` | {_cell(q.text)} |" for q in STATUS]
    return "\n".join(lines)


def reductions_table() -> str:
    """The markdown table of the reductions (:data:`machdyn.linkage.reductions.REDUCTIONS`)."""
    lines = ["| reduction | meaning |", "|---|---|"]
    lines += [f"| `{name}` | {r.text} |" for name, r in REDUCTIONS.items()]
    return "\n".join(lines)


def capability_table() -> str:
    """The markdown table of every other declared result: the problem kinds' and the capabilities'."""
    own = {q.key for q in MECHANISM + COMPACTOR + STATUS}
    lines = ["| key | SI unit | meaning | over the crank positions | better | produced by |",
             "|---|---|---|---|---|---|"]
    for q in catalogue():
        if q.key in own:
            continue
        lines.append(f"| `{q.key}` | {q.unit or '–'} | {_cell(q.text)} | `{q.over_positions}` | {_better(q)} "
                     f"| `{q.producer}` |")
    return "\n".join(lines)


def better_table() -> str:
    """The markdown table of the better directions (:data:`machdyn.results.catalogue.BETTER`)."""
    lines = ["| better | meaning |", "|---|---|"]
    lines += [f"| `{name}` | {text} |" for name, text in BETTER.items()]
    return "\n".join(lines)


def groups_table() -> str:
    lines = ["| group | how it is computed for many designs |", "|---|---|"]
    lines += [f"| `{name}` | {text} |" for name, text in GROUPS.items()]
    return "\n".join(lines)


#: The generated tables of docs/results.md by the name in their marks.
TABLES = {
    "mechanism": mechanism_table,
    "status": status_table,
    "reductions": reductions_table,
    "better": better_table,
    "groups": groups_table,
    "capabilities": capability_table,
}
_MARKS = re.compile(r"(<!-- catalogue: (\w+) -->\n)(.*?)(<!-- end catalogue -->)", re.S)


def regenerated(text: str) -> str:
    """``text`` (docs/results.md) with every generated table written anew from the catalogue."""
    return _MARKS.sub(lambda m: f"{m.group(1)}\n{TABLES[m.group(2)]()}\n\n{m.group(4)}", text)


def main(argv: list[str] | None = None) -> int:
    """Regenerate the tables of the markdown files named on the command line, in place."""
    for name in argv if argv is not None else sys.argv[1:]:
        path = Path(name)
        path.write_text(regenerated(path.read_text(encoding="utf-8")), encoding="utf-8")
    return 0


if __name__ == "__main__":  # pragma: no cover - python -m machdyn.listing docs/results.md
    raise SystemExit(main())
