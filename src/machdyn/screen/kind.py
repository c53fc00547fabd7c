"""The ``[rotary_screen]`` kind: seed 002's grading screen from the paper's inputs, analysed by the engine,
with the paper's energy figures (as printed, by its formulas corrected, and exact) beside the engine's."""

from __future__ import annotations

from typing import Any

from ..errors import InputError
from ..pipeline import Outcome, ProblemKind, Step
from ..pipelines.linkage_run import analyse_linkage, check_assembly
from ..results.labels import Label
from ..results.linkage import LINKAGE_LABELS
from .figures import energy_figures
from .schema import RotaryScreenProblem

#: The engine's joints by the paper's names (seed 002, fig 2): A the crank centre, B crank-rod, C rod-slider.
PAPER_JOINTS = {"O": "A, the crank centre", "A": "B, crank to rod", "B": "C, rod to slider",
                "slider/ground": "of the slider on its guide"}

_COLUMNS = {"paper": "as printed", "formula": "paper's formula, corrected", "engine": "exact, engine"}

#: The figures shown in the summary (figure, column), in order.
SUMMARY_FIGURES = (
    ("T1max", "formula"), ("T1max", "paper"), ("T1max", "engine"), ("T2", "formula"), ("T2", "paper"),
    ("T3", "formula"), ("T3", "paper"), ("W_min", "formula"), ("W_min", "paper"), ("W_min", "engine"),
    ("W_max", "formula"), ("W_max", "paper"), ("W_max", "engine"), ("fluctuation_power", "formula"),
    ("fluctuation_power", "paper"), ("K", "formula"), ("P_r", "formula"), ("P_r", "paper"), ("P_r", "engine"),
    ("M_in_peak", "engine"), ("M_in_peak_spring", "engine"),
)


def build(problem: Any) -> tuple[Any, list[tuple[str, str]]]:
    if problem.drive.speed <= 0:
        speed = problem.drive.speed
        return None, [("drive.speed", f"must be > 0 rad/s for the rotary screen; got {speed:g} rad/s")]
    try:
        return problem.mechanism(), []
    except InputError as exc:
        return None, [("rotary_screen", str(exc))]


def analyse(problem: Any, mech: Any, step: Step) -> Outcome:
    linkage = analyse_linkage(problem, mech, step)
    step("energy figures")
    figures = energy_figures(problem.screen())
    values: dict[str, Any] = {}
    labels: dict[str, Label] = {}
    for key, f in figures.items():
        for col, words in _COLUMNS.items():
            if f[col] is not None:
                name = f"rotary_screen.{key}.{col}"
                values[name] = float(f[col])
                where = f", {f['source']}" if f.get("source") and col != "engine" else ""
                text = f["quantity"][:1].upper() + f["quantity"][1:]
                labels[name] = Label(f"{text}{where} ({words})", f["unit"])
    for joint, paper in PAPER_JOINTS.items():
        labels[f"joint.{joint}.max_force"] = Label(f"Joint {paper} (engine: {joint}), max force", "N")
    summary = tuple(f"rotary_screen.{k}.{c}" for k, c in SUMMARY_FIGURES if f"rotary_screen.{k}.{c}" in values)
    return Outcome(
        results=figures, scalars={**linkage.scalars, **values}, units=linkage.units, labels=labels,
        summary=(*summary, *linkage.summary), warnings=linkage.warnings, mechanism=mech, analysis=linkage.analysis,
    )


KIND = ProblemKind(
    name="rotary_screen",
    schema=RotaryScreenProblem,
    build=build,
    check=check_assembly,
    analyse=analyse,
    title=lambda problem: problem.meta.name,
    steps=("model", "analysis", "energy figures"),
    labels=LINKAGE_LABELS,
    report="machdyn.report.rotary_screen:sections",
)
