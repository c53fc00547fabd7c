"""The screw conveyor as a problem kind, in the shape of every kind: schema, build, check, analysis.

The registry's line ``"screw_conveyor": "machdyn.conveyor.kind:KIND"`` gives the loader the schema
(:class:`~machdyn.conveyor.schema.ConveyorFile`, validated with every other mistake of the file at once) and
``build`` (the frozen SI :class:`~machdyn.conveyor.model.ConveyorProblem` of a valid file, or the problems of
its rules across fields). ``check(problem)`` -> warnings, after every validation ``run`` relies on;
``run(problem, step)`` -> :class:`~machdyn.pipeline.Outcome` with SI scalars, labels, summary keys, warnings and
failed checks; the report module :mod:`machdyn.report.conveyor` draws them. ``validate(data, source)`` is the
loader's validation of a parsed file, returning the :class:`ConveyorProblem`.
"""

from __future__ import annotations

from typing import Any

from ..errors import InputError, ProblemFileError
from ..pipeline import Outcome, ProblemKind
from .evaluate import evaluate
from .labels import LABELS, SUMMARY, label_of
from .model import ConveyorProblem
from .schema import ConveyorFile, build, validate

__all__ = ["check", "run", "validate"]


def _analyse(problem: ConveyorProblem) -> Any:
    try:
        return evaluate(problem)
    except InputError as exc:
        raise ProblemFileError([("screw_conveyor", str(exc))], problem.source) from None


def check(problem: ConveyorProblem) -> list[str]:
    """Every validation a run relies on (the same analysis as :func:`run`); returns the warnings.

    Raises :class:`~machdyn.errors.ProblemFileError` naming the input when the problem cannot be analysed.
    """
    return list(_analyse(problem).warnings)


def run(problem: ConveyorProblem, step: Any = None) -> Any:
    """Analyse the conveyor and return the stage's :class:`~machdyn.pipeline.Outcome` (SI scalars)."""
    if step is not None:
        step("design")
    result = _analyse(problem)
    scalars = dict(result.scalars)
    labels = {k: label_of(k) for k in scalars}
    series = {}
    if result.bending is not None:
        b = result.bending
        series["conveyor_span"] = {"x": (b.x, "m"), "moment": (b.moment, "N*m"), "deflection": (b.deflection, "m"),
                                   "equivalent_stress": (b.equivalent_stress, "Pa")}
        series["conveyor_screw_stress"] = {"x": (b.screw_x, "m"), "equivalent_stress": (b.screw_stress, "Pa")}
    if result.ranking is not None:
        series["conveyor_candidates"] = result.ranking.series()
    return Outcome(results=result, scalars=scalars, labels=labels, series=series,
                   summary=tuple(k for k in SUMMARY if k in scalars), warnings=result.warnings,
                   failed_checks=result.failed_checks)


def _title(spec: ConveyorFile) -> str:
    return spec.meta.name


def _kind() -> Any:
    return ProblemKind(
        name="screw_conveyor", schema=ConveyorFile, build=build,
        check=lambda _spec, problem: check(problem), analyse=lambda _spec, problem, step: run(problem, step),
        title=_title, steps=("design",), labels=LABELS, report="machdyn.report.conveyor:sections",
    )


#: The entry of the registry of problem kinds: ``"screw_conveyor": "machdyn.conveyor.kind:KIND"``.
KIND = _kind()
