"""``[optimise]`` for a kind with no linkage population — a shaft line, a cam: each design is written out and run
through the file's own stages (:mod:`machdyn.studies.per_design`), and the objectives and constraints read its
results by their catalogue keys (``shaft.engine.primary_couple``, ``cam.pressure_angle.max`` ...). The search is
the linkage optimiser's (scipy's differential evolution, NSGA-II for several objectives) with the same Deb rules,
history and verification; only the evaluation differs, one run per design instead of one engine call per
population. A kind that declares a population form (:mod:`machdyn.studies.kind_population`) evaluates every
population at once instead, when its form gives every result named for the variables' paths.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ...errors import ProblemFileError
from ..kind_population import AT_ONCE, KindPopulation, kind_population_form, tell
from ..per_design import KnownResults, RunDesign, capability_results, evaluate_designs, unit_of
from .constraints import parse_goals, violations
from .schema import OptimiseSpec
from .search import Evaluator
from .variables import search_space


@dataclass
class RunEvaluator(Evaluator):
    """An :class:`~machdyn.studies.optimisation.search.Evaluator` whose designs are each run whole by ``run_design``,
    or evaluated all at once by the kind's population form (``at_once``)."""

    at_once: KindPopulation | None = None
    #: what evaluates the designs, for the user (the population form, or why each design is run whole)
    note: str = ""
    largest: int = 0

    def __call__(self, population) -> tuple[dict, np.ndarray, np.ndarray]:
        x = np.atleast_2d(np.asarray(population, dtype=float))
        results = self._at_once(x)
        if results is not None:
            built = np.all([np.isfinite(v) for v in results.values()], axis=0) if results else np.ones(len(x), bool)
        else:
            problems: list[Any] = []
            for row in x:
                try:
                    problems.append(self.space.problem_at(row))
                except ProblemFileError:  # a design whose values break a field's rule: not buildable
                    problems.append(None)
            results = self.design_results(problems, self.wanted)
            built = np.array([p is not None for p in problems])
        ran = np.all([np.isfinite(v) for v in results.values()], axis=0) if results else built
        results["regular"] = built & ran
        results["assembled_fraction"] = results["regular"].astype(float)  # a design that runs is whole
        costs = np.stack([o.cost(results) for o in self.objectives], axis=1)
        viol = violations(self.constraints, results, results["regular"])
        viol[:, 0] += np.where(np.isfinite(costs).all(axis=1), 0.0, 1.0)
        self.evaluations += x.shape[0]
        self._track(x, results, viol)
        return results, costs, viol

    def _at_once(self, x: np.ndarray) -> dict[str, np.ndarray] | None:
        """The results of the population by the kind's form (designs that break a field's rule NaN), else None."""
        if self.at_once is None:
            return None
        values = self.space.values(x)
        found = self.at_once(values)
        if found is None:
            return None
        broken, _reasons = self.space._broken(values) if values else (np.zeros(len(x), bool), [])
        if len(x) > self.largest:  # the note names the largest population evaluated in one pass
            if not self.largest:
                tell(AT_ONCE.format(count=len(x), kind=self.at_once.kind))
            self.largest = len(x)
            self.note = AT_ONCE.format(count=len(x), kind=self.at_once.kind)
        return {k: np.where(broken, np.nan, v) for k, v in found.items()}

    @property
    def per_design_wanted(self) -> set[str]:
        return set(self.wanted)

    #: A design run whole has no crank angles to close at: it is built and its run reports the results named.
    regular_rule = "builds and runs, reporting every result named"

    def regular_reached(self, fraction: float) -> str:
        if not math.isfinite(fraction):
            return ""
        return "; the closest design ran" if fraction > 0 else "; no design evaluated ran"


def setup_by_runs(problem: Any, spec: OptimiseSpec, run_design: RunDesign | None) -> RunEvaluator:
    """The evaluator of a problem of a kind without a linkage population; every mistake of the table at once.
    The results it may name are those the file's kind and tables declare in the catalogue."""
    problems: list[tuple[str, str]] = []
    space = None
    try:
        space = search_space(problem, spec)
    except ProblemFileError as exc:
        problems += exc.problems
    declared = capability_results(problem)
    names = KnownResults(sorted(declared), lambda key: unit_of(key, problem) is not None)

    def unit(key: str) -> str:
        found = unit_of(key, problem)
        return found if found is not None else ""

    objectives, constraints = parse_goals(spec, names, unit, problems)
    wanted = frozenset(o.result for o in objectives) | frozenset(c.result for c in constraints)
    at_once, why = None, ""
    if space is not None and not problems:
        at_once, why = kind_population_form(problem, sorted(wanted), space.values(space.lower[None, :]))
    return RunEvaluator(space, objectives, constraints, np.zeros(0), per_design_keys=wanted, run_design=run_design,
                        at_once=at_once, note=why)


def verify_by_runs(problem: Any, ev: RunEvaluator) -> tuple[dict[str, float], bool]:
    """The results of the best design run alone, and whether it meets every constraint."""
    res = evaluate_designs(ev.run_design, [problem], ev.wanted, 1) if ev.run_design is not None else {}
    ok = np.array([all(np.isfinite(v[0]) for v in res.values())])
    viol = violations(ev.constraints, {**res, "regular": ok, "assembled_fraction": ok.astype(float)}, ok)
    return {k: float(v[0]) for k, v in res.items()}, bool(np.all(viol <= 1e-9))
