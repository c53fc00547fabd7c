"""The ``[synthesis]`` problem kind: a task in, ranked candidate linkages out (summary, CSV, problem files).

Registered in :mod:`machdyn.kinds` as ``"synthesis": "machdyn.synthesis.kind:KIND"``. The run's results:
``synthesis.candidates`` and ``synthesis.defect_free`` (counts), the best candidate's dimensions
(``synthesis.best.<link>``) and quantities (``synthesis.best.<quantity>``); the series
``synthesis_candidates.csv`` lists every candidate ranked; ``best_<k>.toml`` are the best ``keep`` candidates the
engine can run over their range (no assembly defect, no dead position) as mechanism problem files. No candidate
free of defects is a failed design check (exit code 3).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import InputError
from ..pipeline import Outcome, ProblemKind, Step
from ..results.labels import Label
from .files import problem_text
from .rank import QUANTITIES, REDUCTION_OF
from .schema import SynthesisProblem, problems
from .slotted_task import outcome as slotted_outcome
from .task import synthesise

LABELS: dict[str, Label] = {
    "synthesis.candidates": Label("Candidates synthesised", over="count", better="higher"),
    "synthesis.defect_free": Label("Candidates free of defects", over="count", better="higher"),
    "synthesis.best.crank": Label("Best: crank length", "m", "mm", over="scalar", better="none"),
    "synthesis.best.coupler": Label("Best: coupler (rod) length", "m", "mm", over="scalar", better="none"),
    "synthesis.best.rocker": Label("Best: rocker length", "m", "mm", over="scalar", better="none"),
    "synthesis.best.ground": Label("Best: ground length", "m", "mm", over="scalar", better="none"),
    "synthesis.best.offset": Label("Best: slider offset", "m", "mm", over="scalar", better="none"),
    **{f"synthesis.best.{k}": Label(f"Best: {text[0].lower()}{text[1:]}", unit, over=REDUCTION_OF[k],
                                    better="higher" if larger else "lower")
       for k, (text, unit, larger) in QUANTITIES.items() if k != "error"},
}


def build(problem: Any) -> tuple[Any, list[tuple[str, str]]]:
    """No model before the synthesis: only the task's own rules are checked here."""
    return None, problems(problem.synthesis)


def check(problem: Any, _model: Any) -> list[str]:
    return []


def analyse(problem: Any, _model: Any, step: Step) -> Outcome:
    step("synthesis")
    spec = problem.synthesis
    if spec.task in ("slotted_lever", "whitworth"):
        return slotted_outcome(spec)
    try:
        result = synthesise(spec)
    except InputError as exc:  # a valid task without a linkage: a failed design, not bad input
        return Outcome(scalars={"synthesis.candidates": 0.0, "synthesis.defect_free": 0.0},
                       summary=("synthesis.candidates",), failed_checks=(str(exc),))
    best = result.best
    assert best is not None
    scalars: dict[str, Any] = {"synthesis.candidates": float(len(result.candidates)),
                               "synthesis.defect_free": float(result.defect_free)}
    for name, value in best.lengths().items():
        scalars[f"synthesis.best.{name}"] = float(value)
    for key in QUANTITIES:
        v = float(result.values[key][0])
        if np.isfinite(v):
            scalars[f"synthesis.best.{key}"] = v
    labels = {"synthesis.best.error": Label(
        "Best: largest output-angle error over the range" if spec.task == "function"
        else "Best: kinematic error at the positions",
        "m" if spec.task in ("motion", "path", "slider_quick_return") else "rad",
        "deg" if spec.task in ("function", "quick_return") else None)}
    if spec.task == "function":  # the best's Freudenstein constants and where its ranges were placed
        for name in ("K1", "K2", "K3"):
            scalars[f"synthesis.best.{name}"] = float(best.free[name])
            labels[f"synthesis.best.{name}"] = Label(f"Best: Freudenstein constant {name}")
        for name in ("input_shift", "output_shift"):
            scalars[f"synthesis.best.{name}"] = float(best.free.get(name, 0.0))
            labels[f"synthesis.best.{name}"] = Label(
                f"Best: {name.split('_')[0]} range turned from the file's by", "rad", "deg")
    summary = [k for k in ("synthesis.candidates", "synthesis.defect_free", "synthesis.best.crank",
                           "synthesis.best.coupler", "synthesis.best.rocker", "synthesis.best.ground",
                           "synthesis.best.offset", "synthesis.best.error", f"synthesis.best.{result.ranked_by}",
                           "synthesis.best.K1", "synthesis.best.K2", "synthesis.best.K3",
                           "synthesis.best.input_shift", "synthesis.best.output_shift",
                           "synthesis.best.min_transmission") if k in scalars]
    files = {}
    written = 0
    for k, (c, report) in enumerate(zip(result.candidates, result.reports, strict=True)):
        if written >= spec.ranking.keep:
            break
        # Only a linkage the engine can run over its range is written: it closes everywhere and passes no
        # dead position (a transmission angle of zero).
        if any(d.startswith("assembly") for d in report.defects) or not report.min_transmission > 1e-3:
            continue
        written += 1
        turns = report.full_turn and spec.full_turn
        files[f"best_{written}.toml"] = problem_text(
            c, result.drive, name=f"{problem.meta.name}: candidate {k + 1}",
            note=f"Rank {k + 1} of {len(result.candidates)} by {result.ranked_by}; defects: "
                 f"{'; '.join(report.defects) or 'none'}.", full_turn=turns)
    failed = () if result.defect_free else (
        f"none of the {len(result.candidates)} candidates is free of defects (the best has: "
        f"{'; '.join(result.reports[0].defects)})",)
    return Outcome(results=result, scalars=scalars, labels=labels, series={"synthesis_candidates": _series(result)},
                   files=files, summary=tuple(dict.fromkeys(summary)), failed_checks=failed)


def _series(result: Any) -> dict[str, tuple[Any, str]]:
    cands = result.candidates
    cols: dict[str, tuple[Any, str]] = {"rank": (np.arange(1, len(cands) + 1), "")}
    for name in ("crank", "coupler", "rocker", "ground", "offset"):
        cols[name] = (np.array([getattr(c, name) for c in cands], dtype=float), "m")
    cols["pivot_x"] = (np.array([c.origin.real for c in cands]), "m")
    cols["pivot_y"] = (np.array([c.origin.imag for c in cands]), "m")
    cols["ground_angle"] = (np.array([c.ground_angle for c in cands]), "rad")
    cols["branch"] = (np.array([c.branch for c in cands]), "")
    for key, (_, unit, _) in QUANTITIES.items():
        if key != "error":  # the larger of a distance and an angle: written as the two errors, each in its unit
            cols[key] = (np.asarray(result.values[key], dtype=float), unit)
    cols["position_error"] = (np.array([r.position_error for r in result.reports], dtype=float), "m")
    cols["angle_error"] = (np.array([r.angle_error for r in result.reports], dtype=float), "rad")
    cols["defect_count"] = (np.array([len(r.defects) for r in result.reports]), "")
    if result.task == "function":
        for name in ("K1", "K2", "K3"):
            cols[name] = (np.array([c.free.get(name, np.nan) for c in cands], dtype=float), "")
        for name in ("input_shift", "output_shift"):
            cols[name] = (np.array([c.free.get(name, 0.0) for c in cands], dtype=float), "rad")
    return cols


KIND = ProblemKind(
    name="synthesis",
    schema=SynthesisProblem,
    build=build,
    check=check,
    analyse=analyse,
    title=lambda problem: problem.meta.name,
    steps=("synthesis",),
    labels=LABELS,
    report="machdyn.report.synthesis:sections",
)
