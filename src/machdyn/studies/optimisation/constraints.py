"""Constraints: a per-design result kept within ``min`` ... ``max``, and the built-in requirement that a
design is regular: it closes at every crank angle without passing or nearing a dead position or changing
branch, and keeps its transmission angle away from 0 and 180 deg (:mod:`machdyn.results.population`).

Violations are measured relative to the limit (``(limit - value) / |limit|``, or absolute for a zero limit),
so constraints in different units add up to one total; a feasible design has a total of zero.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ...errors import ProblemFileError
from ...problem.fields import FieldError, Unit, to_si
from ...results.catalogue import canonical
from .objectives import parse_objectives, unknown_result
from .schema import ConstraintSpec

#: The built-in constraint's name in messages.
CLOSES = "closes at every crank angle without a dead position"


@dataclass(frozen=True)
class Constraint:
    """``lower <= result <= upper`` (either bound may be None), SI."""

    result: str
    unit: str
    lower: float | None = None
    upper: float | None = None

    def violation(self, results: dict[str, np.ndarray]) -> np.ndarray:
        """Relative violation per design (0 where met, 1 where the result is undefined)."""
        r = np.asarray(results[self.result], dtype=float)
        v = np.zeros(r.shape)
        for limit, sign in ((self.lower, 1.0), (self.upper, -1.0)):
            if limit is not None:
                scale = abs(limit) if limit != 0.0 else 1.0
                v = v + np.maximum(0.0, sign * (limit - r)) / scale
        return np.where(np.isfinite(r), v, 1.0)

    def describe(self, show=None) -> str:
        show = show or (lambda v: f"{v:g} {self.unit}".rstrip())
        parts = []
        if self.lower is not None:
            parts.append(f">= {show(self.lower)}")
        if self.upper is not None:
            parts.append(f"<= {show(self.upper)}")
        return f"{self.result} {' and '.join(parts)}"


def parse_constraints(specs: list[ConstraintSpec], names: list[str], unit_of) -> tuple[Constraint, ...]:
    """Constraints from the table; unknown results, limits in the wrong unit and empty ranges reported
    together."""
    problems: list[tuple[str, str]] = []
    out = []
    for i, spec in enumerate(specs):
        where = f"optimise.constraints[{i}]"
        result = canonical(spec.result)
        if result not in names:
            problems.append((f"{where}.result", unknown_result(spec.result, names)))
            continue
        unit = unit_of(result)
        limits: dict[str, float | None] = {"min": None, "max": None}
        for key in ("min", "max"):
            raw = getattr(spec, key)
            if raw is None:
                continue
            try:
                limits[key] = to_si(raw, Unit(unit, "result"))
            except FieldError as exc:
                problems.append((f"{where}.{key}", f"{exc} (for {result}, in {unit or 'no unit'})"))
        lo, hi = limits["min"], limits["max"]
        if lo is not None and hi is not None and not hi >= lo:
            problems.append((f"{where}.max", f"must be >= min ({spec.min}); got {spec.max}"))
            continue
        out.append(Constraint(result, unit, lo, hi))
    if problems:
        raise ProblemFileError(problems)
    return tuple(out)


def parse_goals(spec: Any, names: list[str], unit_of, problems: list[tuple[str, str]]) -> tuple[tuple, tuple]:
    """(objectives, constraints) of an ``[optimise]`` table; raises one ProblemFileError with ``problems`` (the
    table's mistakes found before) and every mistake of its objectives and constraints."""
    problems = list(problems)
    objectives: tuple = ()
    constraints: tuple = ()
    try:
        objectives = parse_objectives(spec.objectives, names, unit_of)
    except ProblemFileError as exc:
        problems += exc.problems
    try:
        constraints = parse_constraints(spec.constraints, names, unit_of)
    except ProblemFileError as exc:
        problems += exc.problems
    if problems:
        raise ProblemFileError(problems)
    return objectives, constraints


def closing_violation(results: dict[str, np.ndarray], buildable: np.ndarray) -> np.ndarray:
    """Violation of the built-in constraint: the share of crank angles where the design cannot close, plus 1
    if it passes a dead position or cannot be built."""
    frac = np.asarray(results["assembled_fraction"], dtype=float)
    regular = np.asarray(results["regular"], dtype=bool)
    return (1.0 - frac) + np.where(regular & buildable, 0.0, 1.0)


def violations(constraints: tuple[Constraint, ...], results: dict[str, np.ndarray],
               buildable: np.ndarray) -> np.ndarray:
    """(N designs, 1 + C) violations: the built-in one first, then each constraint's."""
    cols = [closing_violation(results, buildable)] + [c.violation(results) for c in constraints]
    return np.stack(cols, axis=1)
