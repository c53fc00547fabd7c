"""The ``[screw_conveyor]`` kind: a screw conveyor designed from its duty, its power by every method and its
verification checks (seed 004, ISO 7119, CEMA 350)."""

from __future__ import annotations

import warnings as _warnings
from typing import Any

from ..pipeline import Outcome, ProblemKind, Step
from ..results.labels import Label


def _validate(data: dict[str, Any], source: str | None) -> Any:
    from ..conveyor.problem import load_conveyor_problem

    return load_conveyor_problem(data, source=source)


def analyse(problem: Any, _model: Any, step: Step) -> Outcome:
    from ..conveyor.problem import run_conveyor

    step("design")
    with _warnings.catch_warnings():
        _warnings.simplefilter("ignore")
        result = run_conveyor(problem)
    scalars = result.scalars()
    labels = {q.key: Label(q.label, q.unit) for q in result.quantities}
    for key, entry in scalars.items():
        labels.setdefault(key, Label(key.replace("_", " "), entry["unit"]))
    failed = tuple(f"{c.name}: {c.value:.4g} > {c.limit:.4g} {c.unit}" for c in result.checks if not c.passed)
    said = [w for w in result.warnings if not any(c.name in w for c in result.checks if not c.passed)]
    return Outcome(
        results=result, scalars={k: v["value"] for k, v in scalars.items()}, labels=labels,
        summary=tuple(scalars), warnings=tuple(said), failed_checks=failed,
    )


def _problem_type() -> type:
    from ..conveyor.problem import ConveyorProblem

    return ConveyorProblem


KIND = ProblemKind(
    name="screw_conveyor",
    schema=None,
    build=lambda problem: (None, []),
    check=lambda problem, model: [],
    analyse=analyse,
    title=lambda problem: problem.name,
    steps=("design",),
    report="machdyn.conveyor.report:sections",
    validate=_validate,
    dump=repr,
    problem_type=_problem_type,
)
