"""Suggestions for a result name that is not one of a file's results: the nearest name (with the words users
write for a quantity mapped to the catalogue's own first, ``flywheel.weight`` -> ``flywheel.mass``), and a short
list of the results of the same family (``flywheel.*``) to choose from, never cut in the middle."""

from __future__ import annotations

import difflib
import re
from collections.abc import Sequence

#: Words for a quantity that the catalogue names otherwise: word -> the catalogue's word.
SYNONYMS = {
    "weight": "mass",
    "wt": "mass",
    "dia": "diameter",
    "moi": "inertia",
    "rpm": "speed",
    "velocity": "speed",
    "moment": "torque",
    "load": "force",
    "maximum": "max",
    "minimum": "min",
    "average": "mean",
    "avg": "mean",
}
#: The most names listed after an unknown one.
LISTED = 24


def _with_synonyms(name: str) -> str:
    return "".join(SYNONYMS.get(part, part) for part in re.split(r"([._])", name))


def nearest(name: str, names: Sequence[str]) -> str | None:
    """The result of ``names`` that ``name`` most likely means: ``name`` with its synonyms replaced if that is a
    result, else the closest by :func:`difflib.get_close_matches` (of the name with its synonyms replaced, then as
    written), None if none is close."""
    choices = list(names)
    swapped = _with_synonyms(name)
    if swapped in choices:
        return swapped
    for text in dict.fromkeys((swapped, name)):
        near = difflib.get_close_matches(text, choices, n=1, cutoff=0.6)
        if near:
            return near[0]
    return None


def did_you_mean_result(name: str, names: Sequence[str]) -> str:
    """``"; did you mean 'flywheel.mass'?"`` for the nearest result, else an empty string."""
    near = nearest(name, names)
    return f"; did you mean '{near}'?" if near else ""


def results_to_choose(name: str, names: Sequence[str]) -> str:
    """A short list of ``names`` for a message about ``name``: the results of its family (the names that share its
    first part, ``flywheel.``) whole, else the first :data:`LISTED`, saying how many more there are."""
    names = list(dict.fromkeys(names))
    parts = name.split(".")
    own: list[str] = []
    for end in range(len(parts) - 1, 0, -1):  # the longest family that has results: shaft.bearing., then shaft.
        family = ".".join(parts[:end]) + "."
        own = [n for n in names if n.startswith(family)]
        if own:
            break
    if own:
        shown = own[:LISTED]
        rest = len(names) - len(shown)
        more = f"; {rest} other results, see docs/results.md" if rest else ""
        return f"results of {family}*: {', '.join(shown)}{more}"
    shown = list(names[:LISTED])
    rest = len(names) - len(shown)
    more = f" and {rest} more, see docs/results.md" if rest else ""
    return f"results: {', '.join(shown)}{more}"
