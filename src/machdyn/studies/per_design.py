"""Results no population group computes — a capability's: the flywheel and its motor, the drive train, the parts,
a balance, the frame on its mounts, a cam on the crank shaft — for the designs of a population, by running each
design through the file's own stages (the run a ``machdyn run`` of that design makes, without the file's
``[sweep]`` and ``[optimise]``), and reading the result under its catalogue key.

This is general and exact — the optimiser sees what a run of the design reports — and as slow as one run per
design (a flywheel's steady state: milliseconds to a second): the vectorised groups of
:mod:`machdyn.results.population` stay the fast path for the linkage's own results. A design whose run fails (its
drive cannot carry it, its linkage does not close) gets NaN, which the optimiser counts as infeasible.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Mapping
from typing import Any

import numpy as np

from ..errors import MachdynError
from ..kinds import catalogue
from ..results.catalogue import find

#: The tables whose results are not a design's: the studies themselves.
STUDIES = ("sweep", "optimise")

#: Runs one design's problem through its stages and returns its results (SI) by key.
RunDesign = Callable[[Any], Mapping[str, Any]]


class KnownResults(list):
    """The results a study may name: the exact keys listed, and keys that a declared pattern matches
    (``shaft.engine.order2.couple``), as ``accepts(key)`` tells."""

    def __init__(self, names: Iterable[str], accepts: Callable[[str], bool]) -> None:
        super().__init__(names)
        self._accepts = accepts

    def __contains__(self, key: object) -> bool:
        return list.__contains__(self, key) or (isinstance(key, str) and self._accepts(key))


def capability_results(problem: Any) -> dict[str, str]:
    """{key: SI unit} of every numeric result the tables of ``problem`` declare (its kind's main table and every
    other table the file has, but for the studies): what a run of one of its designs reports. Keys made at run
    time (``balance.<part>.mass``) are declared as patterns; :func:`unit_of` resolves them."""
    present = {t for t in _tables(problem) if getattr(problem, t, None) is not None}
    return {q.key: q.unit for q in catalogue()
            if q.producer in present and q.kind == "number" and "<" not in q.key}


def unit_of(key: str, problem: Any) -> str | None:
    """The SI unit of a result ``key`` of ``problem`` declared by one of its tables (a pattern's too), or None if
    none declares it."""
    present = {t for t in _tables(problem) if getattr(problem, t, None) is not None}
    found = find(key, catalogue())
    if found is None or found[0].producer not in present or found[0].kind != "number":
        return None
    return found[0].unit


def _tables(problem: Any) -> list[str]:
    fields = getattr(type(problem), "model_fields", {})
    return [t for t in fields if t not in STUDIES]


def evaluate_designs(run_design: RunDesign, problems: Iterable[Any | None], keys: Iterable[str],
                     count: int) -> dict[str, np.ndarray]:
    """(count,) arrays of ``keys`` over the designs: ``problems`` yields each design's validated problem (None
    for a design that cannot be built), run by ``run_design``; NaN where a design's run fails or does not
    report the key."""
    wanted = list(keys)
    out = {k: np.full(count, math.nan) for k in wanted}
    for i, problem in enumerate(problems):
        if problem is None:
            continue
        try:
            values = run_design(problem)
        except (MachdynError, ArithmeticError, ValueError):  # a design the run refuses or cannot analyse
            continue
        for k in wanted:
            v = values.get(k)
            if v is not None and np.ndim(v) == 0 and math.isfinite(float(v)):
                out[k][i] = float(v)
    return out
