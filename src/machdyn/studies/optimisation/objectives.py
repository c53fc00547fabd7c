"""Objectives: a per-design result to minimise, maximise or bring to a target value.

Any result of :func:`machdyn.studies.optimisation.evaluate.result_names` may be named, by its catalogue key or an old
name of :data:`machdyn.results.catalogue.ALIASES`; a name that is none of them is
refused with a did-you-mean. Every objective is turned into a value to *minimise*: the result itself
(minimise), its negative (maximise) or its distance from the target, relative to the target when that is not
zero (target).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...errors import ProblemFileError
from ...problem.fields import FieldError, Unit, to_si
from ...results.catalogue import Quantity, against, better_of, canonical
from ...results.names import did_you_mean_result, results_to_choose
from .schema import ObjectiveSpec

SENSES = {"minimise": "minimise", "minimize": "minimise", "maximise": "maximise", "maximize": "maximise"}


@dataclass(frozen=True)
class Objective:
    """``result`` [its SI ``unit``] to ``sense`` ('minimise', 'maximise' or 'target'); ``target`` in SI."""

    result: str
    sense: str
    unit: str
    target: float | None = None

    def cost(self, results: dict[str, np.ndarray]) -> np.ndarray:
        """The value to minimise for each design (NaN where the result is NaN)."""
        r = np.asarray(results[self.result], dtype=float)
        if self.sense == "maximise":
            return -r
        if self.sense == "target":
            assert self.target is not None
            scale = abs(self.target) if self.target != 0.0 else 1.0
            return np.abs(r - self.target) / scale
        return r

    def describe(self) -> str:
        if self.sense == "target":
            return f"bring {self.result} to {self.target:g} {self.unit}".rstrip()
        return f"{self.sense} {self.result}"


def direction_advice(specs: list[ObjectiveSpec], entries: tuple[Quantity, ...]) -> list[str]:
    """A warning for each objective whose sense works against its result's declared better direction (the
    catalogue ``entries``, :func:`machdyn.kinds.catalogue`): minimising a result of which more is better, or
    maximising one of which less is. The objective is kept as written: a designer may mean it (the worst case)."""
    out = []
    for i, spec in enumerate(specs):
        if spec.target is not None:
            continue
        key = canonical(spec.result)
        sense = SENSES[spec.sense]
        better = better_of(key, entries)
        if against(sense, better):
            other = "maximise" if sense == "minimise" else "minimise"
            out.append(f"optimise.objectives[{i}]: sense = \"{sense}\" on {key}, whose better direction is "
                       f"{better} (docs/results.md): the search looks for the design that is worst by it; write "
                       f"sense = \"{other}\" if the best was meant.")
    return out


def unknown_result(name: str, names: list[str]) -> str:
    """The message for a result name that is not one of ``names``."""
    why = ""
    if name.startswith("compactor.") and not any(n.startswith("compactor.") for n in names):
        why = ("; the compactor results need [mechanism] machine = \"compactor\" (a four-bar whose coupler point "
               "is the point of the plate where the material is pressed)")
    return (f"'{name}' names no result of this file{why}{did_you_mean_result(name, names)} "
            f"({results_to_choose(name, names)})")


def parse_objectives(specs: list[ObjectiveSpec], names: list[str], unit_of) -> tuple[Objective, ...]:
    """Objectives from the table; unknown results and targets in the wrong unit are reported together.

    ``unit_of(result)`` gives the result's SI unit."""
    problems: list[tuple[str, str]] = []
    out = []
    for i, spec in enumerate(specs):
        where = f"optimise.objectives[{i}]"
        result = canonical(spec.result)
        if result not in names:
            problems.append((f"{where}.result", unknown_result(spec.result, names)))
            continue
        unit = unit_of(result)
        if spec.target is None:
            out.append(Objective(result, SENSES[spec.sense], unit))
            continue
        if "sense" in spec.model_fields_set:
            problems.append((f"{where}.sense", "give either sense or target, not both"))
            continue
        try:
            target = to_si(spec.target, Unit(unit, "result"))
        except FieldError as exc:
            problems.append((f"{where}.target", f"{exc} (for {result}, in {unit or 'no unit'})"))
            continue
        out.append(Objective(result, "target", unit, target))
    if problems:
        raise ProblemFileError(problems)
    return tuple(out)
