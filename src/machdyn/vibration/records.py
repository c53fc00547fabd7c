"""The ``[signals]`` problem kind: vibration records judged on their own, without a machine.

A test engineer with accelerometer or velocity records and no model of the machine writes a file with
``[signals]`` (and optionally ``[meta]``): the records are band-limited, integrated to velocity, their RMS,
peak, crest factor and spectra computed and judged by ISO 10816-1 / ISO 20816-1 zones or ISO 2372 classes
(:mod:`machdyn.vibration.signals`, :mod:`machdyn.vibration.severity`); two records give the reduction in %.
``signals.speed`` (the machine's running speed) adds order spectra and a warning when the band leaves out an
order of it. In a machine's file ``[signals]`` is a capability (:mod:`machdyn.vibration.stage`) instead; the
loader tells the two apart (:func:`machdyn.reading.kind_of`).
"""

from __future__ import annotations

from typing import Any

from pydantic import PrivateAttr, ValidationError

from ..errors import InputError, ProblemFileError
from ..pipeline import Outcome, ProblemKind, Step
from ..problem.errors import problems_from
from ..problem.loader import top_level_problems
from ..problem.schema import Meta, Spec
from .stage import check_signals, signal_outcome
from .study import study_signals
from .tables import SignalsTable

__all__ = ["KIND", "SignalsProblem", "validate"]


class SignalsProblem(Spec):
    """A file of vibration records alone: ``[meta]`` and ``[signals]``; ``source`` is the file's path, against
    whose folder the records' relative paths are read (None: the working folder)."""

    meta: Meta = Meta()
    signals: SignalsTable
    _source: str | None = PrivateAttr(None)

    @property
    def source(self) -> str | None:
        return self._source


def _problems(problem: SignalsProblem) -> list[tuple[str, str]]:
    return check_signals(problem, problem.signals, problem.source)


def validate(data: dict[str, Any], source: str | None = None) -> SignalsProblem:
    """The validated problem of a parsed ``[signals]`` file, its records read and checked against the band;
    raises one :class:`~machdyn.errors.ProblemFileError` with every mistake."""
    allowed = tuple(SignalsProblem.model_fields)
    problems = top_level_problems(data, allowed)
    try:
        problem = SignalsProblem.model_validate({k: v for k, v in data.items() if k in allowed})
    except ValidationError as exc:
        raise ProblemFileError(problems + problems_from(exc, SignalsProblem), source) from None
    problem._source = source
    problems += _problems(problem)
    if problems:
        raise ProblemFileError(problems, source)
    return problem


def _study(problem: SignalsProblem) -> Any:
    try:
        return study_signals(problem.signals, source=problem.source)
    except InputError as exc:
        where, _, message = str(exc).partition(": ")
        raise ProblemFileError([(where, message)], problem.source) from None


def check(problem: SignalsProblem, _model: Any = None) -> list[str]:
    """Every validation a run relies on (the records analysed as a run analyses them); returns the warnings."""
    return list(_study(problem).warnings)


def analyse(problem: SignalsProblem, _model: Any, step: Step) -> Outcome:
    """The records judged: the outcome of :func:`machdyn.vibration.stage.signal_outcome`."""
    step("measured signals")
    return signal_outcome(_study(problem))


def _build(problem: SignalsProblem) -> tuple[Any, list[tuple[str, str]]]:
    return problem.signals, _problems(problem)


#: The entry of the registry of problem kinds: ``"signals": "machdyn.vibration.records:KIND"``.
KIND = ProblemKind(
    name="signals", schema=SignalsProblem, build=_build, check=check, analyse=analyse,
    title=lambda problem: problem.meta.name if problem.meta.name != "problem" else "Vibration records",
    steps=("measured signals",), report="machdyn.report.vibration:signal_sections", validate=validate,
)
