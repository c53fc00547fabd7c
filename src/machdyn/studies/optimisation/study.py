"""Design optimisation of a problem: :func:`optimise` ties the variables, the objectives and constraints, the
search and the verification of the best design together."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ...errors import ProblemFileError
from ...problem.build import build_mechanism, crank_angles, harmonics_of
from ...problem.dumper import dump_problem
from ...results.labels import display_factor
from ...results.population import DEFAULT_MIN_TRANSMISSION_DEG
from ..per_design import RunDesign, capability_results
from .by_runs import RunEvaluator, setup_by_runs, verify_by_runs
from .constraints import parse_goals, violations
from .evaluate import evaluate, result_names, result_unit
from .pareto import hypervolume_converged, nsga2
from .result import OptimiseResult
from .schema import OptimiseSpec
from .search import Evaluator, differential_evolution
from .variables import current_values, search_space

#: A verified design may break a constraint by this much (relative): the population and the single-design
#: evaluations of one design agree to rounding, not bit for bit.
VERIFY_TOLERANCE = 1e-9


#: The relative growth of the front's hypervolume over the last generations below which NSGA-II has converged.
FRONT_TOLERANCE = 1e-3


def _window(generations: int) -> int:
    """Generations over which the hypervolume must stagnate: a tenth of the run, at least 5 and at most 50."""
    return int(min(50, max(5, generations // 10)))


def show_value(unit: str):
    """Format an SI value for a message: angles in degrees, others in their SI unit."""
    if unit == "rad":
        return lambda v: f"{math.degrees(v):.4g} deg"
    return lambda v: f"{v:.4g} {unit}".rstrip()


def setup(problem: Any, spec: OptimiseSpec, run_design: RunDesign | None = None) -> Evaluator:
    """The :class:`~machdyn.studies.optimisation.search.Evaluator` of a problem and its ``[optimise]`` table; every
    mistake of the table is reported at once (:class:`~machdyn.errors.ProblemFileError`). Objectives and
    constraints may name the linkage's results (computed for the whole population at once) and the results of
    the file's capability tables (``flywheel.mass``, ``parts...``: each design run by ``run_design``, see
    :mod:`machdyn.studies.per_design`)."""
    if getattr(problem, "mechanism", None) is None:  # a shaft line, a cam: every design run whole
        return setup_by_runs(problem, spec, run_design)
    problems: list[tuple[str, str]] = []
    space = None
    try:
        space = search_space(problem, spec)
    except ProblemFileError as exc:
        problems += exc.problems
    mech = build_mechanism(problem)
    machine = getattr(problem.mechanism, "machine", None)
    linkage_names = result_names(mech, machine, harmonics_of(problem))
    per_design = {k: u for k, u in capability_results(problem).items() if k not in set(linkage_names)}
    names = linkage_names + sorted(per_design)

    def unit_of(key):
        if key in per_design:
            return per_design[key]
        return result_unit(key, mech)

    objectives, constraints = parse_goals(spec, names, unit_of, problems)
    if spec.positions is not None:
        # The drive's own crank range, sampled at the search's number of positions.
        problem = problem.model_copy(update={"drive": problem.drive.model_copy(update={"positions": spec.positions})})
    phi = crank_angles(problem)
    lowest = spec.min_transmission_angle
    return Evaluator(space, objectives, constraints, phi, tuple(problem.output.shaking_moment_about),
                     machine=machine, min_transmission_angle=(
                         float(lowest) if lowest is not None else math.radians(DEFAULT_MIN_TRANSMISSION_DEG)),
                     per_design_keys=frozenset(per_design), run_design=run_design)


def _show(constraint):
    return show_value(constraint.unit)


def optimise(problem: Any, spec: OptimiseSpec, run_design: RunDesign | None = None) -> OptimiseResult:
    """Optimise ``problem`` (a validated linkage problem) as ``spec`` (its ``[optimise]`` table) says.

    One objective: differential evolution (:mod:`machdyn.studies.optimisation.search`); several: the Pareto front by
    NSGA-II (:mod:`machdyn.studies.optimisation.pareto`), whose member best in the first objective is reported as the
    best design. Raises :class:`~machdyn.studies.optimisation.result.NoFeasibleDesign` listing the tightest constraints
    when no design meets them all. A search that stops without converging is reported in ``converged``,
    ``message`` and ``warnings``.
    """
    ev = setup(problem, spec, run_design)
    space = ev.space
    warnings: list[str] = []
    front_x = front_f = None
    improved: bool | None = None
    if len(ev.objectives) == 1:
        start = current_values(space)
        x, converged, message, history, seconds, improved = differential_evolution(
            ev, population=spec.population, generations=spec.generations, tolerance=spec.tolerance,
            seed=spec.seed, x0=start, show=_show,
        )
        method = "differential_evolution"
        if improved is False:
            assert start is not None
            given = ", ".join(f"{v.name} = {value * display_factor(v.unit, v.display_unit):.6g} {v.display_unit}"
                              .rstrip() for v, value in zip(space.variables, start, strict=True))
            warnings.append(
                f"The search found no design better than the one the file gives ({given}): that design may be "
                "the optimum within the bounds, or the search too short to find a better one (raise "
                "optimise.generations or optimise.population, or widen the bounds)."
            )
    else:
        front_x, front_f, history, seconds = nsga2(ev, population=spec.population, generations=spec.generations,
                                                   seed=spec.seed, show=_show)
        x = front_x[0]
        method = "nsga2"
        assert history.hypervolume is not None
        converged, why = hypervolume_converged(history.hypervolume, FRONT_TOLERANCE, _window(spec.generations))
        message = f"NSGA-II ran {spec.generations} generations, {len(front_x)} designs on the front; {why}"
    note = getattr(ev, "note", "")
    if note:  # a kind's designs: evaluated by its population form, or each run whole (and why)
        message = f"{message}; {note}"
        if not note.startswith("population form"):
            warnings.append(f"The designs were {note.replace('each design run whole', 'each run whole')}.")
    if not converged:
        warnings.append(
            f"The search did not converge within {spec.generations} generations ({message}); the best design "
            "found is reported but may not be the optimum: raise optimise.generations or optimise.population."
        )
    best_problem = space.problem_at(x)
    results, verified = verify(best_problem, ev)
    if not verified:
        warnings.append("The best design, rebuilt from its problem file, does not meet every constraint.")
    objective = np.array([results.get(o.result, math.nan) for o in ev.objectives])
    if front_f is not None:
        signs = np.array([-1.0 if o.sense == "maximise" else 1.0 for o in ev.objectives])
        front_f = front_f * signs  # back from costs to the results themselves (targets stay distances)
    return OptimiseResult(
        method=method, names=tuple(space.names), units=tuple(v.unit for v in space.variables),
        display_units=tuple(v.display_unit for v in space.variables), lower=space.lower, upper=space.upper,
        x=x, results=results, objectives=ev.objectives, constraints=ev.constraints, objective=objective,
        converged=converged, message=message, evaluations=ev.evaluations, seconds=seconds, verified=verified,
        history=history, problem=best_problem, problem_text=dump_problem(best_problem),
        front_x=front_x, front_f=front_f, warnings=tuple(warnings), improved=improved,
    )


def verify(problem: Any, ev: Evaluator) -> tuple[dict[str, float], bool]:
    """The results of one design built alone from its validated problem, and whether it meets every
    constraint (and closes at every crank angle)."""
    if isinstance(ev, RunEvaluator):
        return verify_by_runs(problem, ev)
    mech = build_mechanism(problem)
    wanted = set(result_names(mech, ev.machine, harmonics_of(problem))) & (ev.wanted | _all_cheap(mech, ev.machine))
    res = evaluate(mech, ev.phi, problem.drive.speed, problem.drive.acceleration, wanted, ev.about,
                   machine=ev.machine, min_transmission_angle=ev.min_transmission_angle)
    if ev.per_design_wanted:
        res |= ev.design_results([problem], ev.per_design_wanted)
    viol = violations(ev.constraints, res, np.array([True]))
    results = {k: float(np.asarray(v)[0]) for k, v in res.items()}
    return results, bool(np.all(viol <= VERIFY_TOLERANCE))


def _all_cheap(mech, machine=None) -> set[str]:
    """The kinematic results, reported for the best design whether asked for or not."""
    return {k for k in result_names(mech, machine) if k.startswith(("stroke.", "transmission_angle", "time_ratio",
                                                            "compactor."))}
