"""Benchmark: wall time and designs evaluated until a design within 0.1 % of the best known optimum is found, on
five design problems, by machdyn's optimiser and by scipy's and pymoo's optimisers used directly.

The problems (each a minimisation under Deb's rules, one cost per design: the objective where every constraint
holds, ``1e30 * (1 + total violation)`` where one does not — the cost machdyn's optimiser minimises,
:meth:`machdyn.studies.optimisation.search.Evaluator.scalar_cost`):

- ``four_bar_path``: a four-bar's coupler curve through five points (those of
  ``examples/synthesis_path_five_points.toml``, shifted by (60, 120) mm so that the crank pivot may stay at the
  origin): crank, coupler, rocker and ground lengths and the coupler point (u, v) free, the ground along x; the
  cost is the sum over the points of the squared distance to the nearest of 90 coupler-curve samples [m²], for a
  design that closes at every crank angle (else infeasible). Evaluated by machdyn's kinematics
  (:func:`machdyn.linkage.kinematics` of a population of four-bars).
- ``compactor``: ``examples/compactor_optimise.toml`` as shipped (seed 003: the force gain k1 k2 maximised over
  r, l, h and R under the plate-angle, transmission-angle and torque rules; 180 crank positions).
- ``cam_base_circle``: ``bench/problems/cam_base_circle.toml``: the press feeder cam's base circle, smallest with
  its largest pressure angle at most 30 deg (each design run through the cam's stages). Its optimum has a
  closed form, the run's ``cam.min_base_radius_pressure`` (Norton, *Design of Machinery*, 5th ed., eq 8.31):
  the long run is checked against it.
- ``inline_engine_phases``: ``examples/shaft_inline_four_phases_optimise.toml``: the inner crank phases of an
  in-line four minimising the primary couple with the primary force held under 1 N (each design run through
  the shaft line's stages). The optimum is zero (the 0-180-180-0 shaft): "within 0.1 %" is then within 0.1 %
  of the file's own design's couple.
- ``press_flywheel_motor``: ``bench/problems/press_flywheel_motor.toml``: the crank press of
  ``examples/crank_press_drive.toml`` with its flywheel and a motor chosen for it, the flywheel's design speed
  fluctuation and rim speed free: the lightest flywheel whose steady running under the motor keeps the
  simulated fluctuation at most 0.1 and the motor's duty load at most 1 (each design run through the file's
  stages: flywheel sizing, motor choice, periodic steady state).

The optimisers, each from ``--seeds`` seeds (min / median / max over the seeds that reach the target):

- ``machdyn``: machdyn's optimiser (:func:`machdyn.studies.optimisation.search.differential_evolution`: scipy's
  differential evolution, vectorised — one call of the evaluator per generation — then its batch polish), with
  the file's population and tolerance.
- ``scipy_de``: :func:`scipy.optimize.differential_evolution` with its defaults on the single-design cost (one
  design per call, what a user writes first); ``scipy_de_vectorized``: the same with ``vectorized=True`` on the
  population cost (machdyn's population evaluator behind it).
- ``scipy_cobyla``: :func:`scipy.optimize.minimize` (COBYLA, the constraints given as such) from a random start
  of each seed: the local method, for the problems with constraints and a smooth objective (cam, press,
  compactor).
- ``pymoo_ga``: pymoo's genetic algorithm (population 50) on the single-design cost (an ``ElementwiseProblem``)
  and ``pymoo_ga_vectorized`` on the population cost (a ``Problem``, whose ``_evaluate`` takes the population).

Where each design is run whole (cam, shaft line, press), the vectorised variants run the same runs as the
single-design ones and are left out.

A run stops as soon as a design within the target is evaluated, or at the problem's budget of designs (or
``--max-seconds``): a run that stops short is counted as not reaching it. A search that converges (by its own
rule) short of the target is started again from another seed, its designs and time counted on. The best known
optimum is that of a long run of machdyn's optimiser (population and generations stated in the output), or
better if any run of the benchmark finds better (said in the output). Ratios are each optimiser's median time
(and designs) over machdyn's. Usage: ``python bench/time_to_optimum.py [--seeds 5] [--quick] [--only PROBLEM]``.
The last line printed is one JSON object ``{"time_to_optimum": {...}}``.
"""

from __future__ import annotations

import argparse
import json
import math
import statistics
import sys
import time
import warnings
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))

INFEASIBLE = 1e30
TOLERANCE = 1e-3  # within 0.1 % of the best known optimum


class Reached(Exception):
    """Raised inside an optimiser's cost call to stop it: the target is reached or the budget spent."""


@dataclass
class Tracker:
    """Counts the designs an optimiser evaluates and the time, and stops it at the target or the budget."""

    target: float
    budget: int
    max_seconds: float
    evaluations: int = 0
    best: float = math.inf
    reached: tuple[float, int] | None = None
    start: float = field(default_factory=time.perf_counter)

    def record(self, costs: np.ndarray) -> None:
        costs = np.atleast_1d(np.asarray(costs, dtype=float))
        feasible = costs[costs < INFEASIBLE]
        for k, c in enumerate(costs):  # the design at which the target is first met, in the order evaluated
            if c < INFEASIBLE and c <= self.target and self.reached is None:
                self.reached = (time.perf_counter() - self.start, self.evaluations + k + 1)
        self.evaluations += costs.size
        if feasible.size:
            self.best = min(self.best, float(feasible.min()))
        if self.reached is not None or self.evaluations >= self.budget or \
                time.perf_counter() - self.start > self.max_seconds:
            raise Reached


@dataclass
class Problem:
    """A benchmark problem: bounds, its population and single-design costs, constraints for COBYLA, and the
    machdyn evaluator its optimiser runs on."""

    name: str
    lower: np.ndarray
    upper: np.ndarray
    evaluator: Any  # machdyn's: space, scalar_cost(X), __call__(X) -> (results, costs, violations)
    population: int
    tolerance: float
    budget: int
    scale: float = 0.0  # the size "0.1 %" is of, where the optimum is zero
    smooth: bool = True
    note: str = ""
    by_runs: bool = False  # each design run whole: the single-design and population costs are the same runs
    long_run: tuple[int, int] = (0, 400)  # the long run's population (0: 4 x the problem's) and generations
    closed_form: Any = None  # () -> the optimum by a closed form, where one is known

    def costs(self, x: np.ndarray) -> np.ndarray:
        return np.asarray(self.evaluator.scalar_cost(np.atleast_2d(x)), dtype=float)

    def cost(self, x: np.ndarray) -> float:  # one design, as a user's objective function would
        return float(self.costs(np.asarray(x, dtype=float)[None, :])[0])


# ----------------------------------------------------------------------------------------------------- problems


def _from_file(path: Path, budget: int, *, scale_from_start: bool = False, smooth: bool = True) -> Problem:
    from machdyn.reading import load_problem
    from machdyn.runner import design_results
    from machdyn.studies.optimisation import setup
    from machdyn.studies.optimisation.variables import current_values

    problem = load_problem(path)
    spec = problem.optimise
    ev = setup(problem, spec, design_results)
    name = path.stem.replace("_optimise", "")
    out = Problem(name, np.asarray(ev.space.lower, float), np.asarray(ev.space.upper, float), ev, spec.population,
                  spec.tolerance, budget, smooth=smooth, by_runs=getattr(problem, "mechanism", None) is None)
    if scale_from_start:
        start = current_values(ev.space)
        out.scale = abs(out.cost(np.asarray(start, dtype=float)))
    return out


@dataclass
class PathEvaluator:
    """The four-bar path problem's costs for a population, by machdyn's kinematics of all its designs at once."""

    points: np.ndarray
    lower: np.ndarray
    upper: np.ndarray
    positions: int = 90
    evaluations: int = 0

    @property
    def space(self) -> Any:
        return self

    def scalar_cost(self, x: np.ndarray) -> np.ndarray:
        from machdyn.linkage import crank_angles, four_bar, kinematics

        x = np.atleast_2d(np.asarray(x, dtype=float))
        self.evaluations += x.shape[0]
        crank, coupler, rocker, ground, u, v = x.T
        mech = four_bar(crank, coupler, rocker, ground, coupler_point=(u, v), branch=1)
        with np.errstate(all="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)  # a design that never closes: an all-NaN row
            kin = kinematics(mech, crank_angles(self.positions), 1.0, on_fail="mask")
            p = kin.point("coupler.P")
            px, py = np.broadcast_to(p.x, (x.shape[0], self.positions)), np.broadcast_to(p.y, (x.shape[0],
                                                                                               self.positions))
            closes = np.all(np.isfinite(px), axis=1)
            d2 = (px[:, :, None] - self.points[:, 0]) ** 2 + (py[:, :, None] - self.points[:, 1]) ** 2
            error = np.nanmin(d2, axis=1).sum(axis=1)
        return np.where(closes & np.isfinite(error), error, INFEASIBLE * 2.0)

    def __call__(self, x: np.ndarray) -> tuple[dict, np.ndarray, np.ndarray]:
        costs = self.scalar_cost(x)
        viol = np.where(costs < INFEASIBLE, 0.0, 1.0)[:, None]
        return {}, np.where(costs < INFEASIBLE, costs, np.nan)[:, None], viol

    def infeasible_message(self, _show: Any) -> str:
        return "no design of the four-bar closes at every crank angle"


def four_bar_path(budget: int) -> Problem:
    points = np.array([[0, 0], [30, 40], [80, 60], [130, 50], [160, 20]], dtype=float) / 1000 + [0.06, 0.12]
    lower = np.array([0.02, 0.05, 0.05, 0.05, -0.2, -0.2])
    upper = np.array([0.12, 0.40, 0.40, 0.40, 0.3, 0.3])
    ev = PathEvaluator(points, lower, upper)
    return Problem("four_bar_path", lower, upper, ev, 60, 1e-6, budget, smooth=False,
                   note="cost: sum of squared distances [m^2] of the five points to the coupler curve")


def _long(problem: Problem, population: int, generations: int) -> Problem:
    """``problem`` with a long run of ``population`` x ``generations`` (each design run whole is slow)."""
    problem.long_run = (population, generations)
    return problem


def _cam(path: Path, budget: int) -> Problem:
    """The cam problem, with its closed-form optimum: the smallest base radius meeting the pressure-angle limit,
    as a run of the file reports it (independent of the base radius the file gives)."""
    from machdyn.reading import load_problem
    from machdyn.runner import design_results

    out = _from_file(path, budget)
    out.closed_form = lambda: float(design_results(load_problem(path))["cam.min_base_radius_pressure"])
    return out


def problems(quick: bool) -> dict[str, Any]:
    """name -> a function making the problem (budget of designs per run: full, quick)."""
    bench = ROOT / "bench" / "problems"
    scale = 0.25 if quick else 1.0
    return {
        "four_bar_path": lambda: four_bar_path(int(200_000 * scale)),
        "compactor": lambda: _from_file(ROOT / "examples" / "compactor_optimise.toml", int(60_000 * scale)),
        "cam_base_circle": lambda: _long(_cam(bench / "cam_base_circle.toml", int(600 * scale)), 10, 40),
        "inline_engine_phases": lambda: _long(_from_file(ROOT / "examples" / "shaft_inline_four_phases_optimise.toml",
                                                         int(3_000 * scale), scale_from_start=True, smooth=False),
                                              24, 60),
        "press_flywheel_motor": lambda: _long(_from_file(bench / "press_flywheel_motor.toml", int(400 * scale)),
                                              12, 25),
    }


# --------------------------------------------------------------------------------------------------- optimisers


class _Tracked:
    """machdyn's evaluator with its population costs recorded by a tracker."""

    def __init__(self, inner: Any, tracker: Tracker) -> None:
        self._inner, self._tracker = inner, tracker

    def scalar_cost(self, x: np.ndarray) -> np.ndarray:
        costs = np.asarray(self._inner.scalar_cost(x), dtype=float)
        self._tracker.record(costs)
        return costs

    def __getattr__(self, name: str) -> Any:
        return getattr(self._inner, name)


def run_machdyn(problem: Problem, seed: int, tracker: Tracker, generations: int = 100_000) -> None:
    from machdyn.studies.optimisation.search import differential_evolution

    differential_evolution(_Tracked(problem.evaluator, tracker), population=problem.population,
                           generations=generations, tolerance=problem.tolerance, seed=seed)


def _bounds(problem: Problem) -> list[tuple[float, float]]:
    return list(zip(problem.lower, problem.upper, strict=True))


def run_scipy_de(problem: Problem, seed: int, tracker: Tracker) -> None:
    from scipy.optimize import differential_evolution

    def cost(x):
        c = problem.cost(x)
        tracker.record(np.array([c]))
        return c

    differential_evolution(cost, _bounds(problem), seed=seed, maxiter=100_000, polish=False)


def run_scipy_de_vectorized(problem: Problem, seed: int, tracker: Tracker) -> None:
    from scipy.optimize import differential_evolution

    def cost(xt):
        c = problem.costs(np.asarray(xt).T)
        tracker.record(c)
        return c

    differential_evolution(cost, _bounds(problem), seed=seed, maxiter=100_000, polish=False, vectorized=True,
                           updating="deferred")


def run_scipy_cobyla(problem: Problem, seed: int, tracker: Tracker) -> None:
    from scipy.optimize import minimize

    cache: dict[bytes, tuple[float, float]] = {}

    def evaluated(x):  # objective and total violation of one design, evaluated once for both calls
        x = np.clip(np.asarray(x, dtype=float), problem.lower, problem.upper)  # COBYLA's bounds are not strict
        key = x.tobytes()
        if key not in cache:
            _res, costs, viol = problem.evaluator(x[None, :])
            total = float(viol.sum())
            objective = float(costs[0, 0])
            cache[key] = (objective if math.isfinite(objective) else 1e6, total)
            tracker.record(np.array([objective if total <= 0 and math.isfinite(objective)
                                     else INFEASIBLE * (1 + total)]))
        return cache[key]

    span = problem.upper - problem.lower
    x0 = problem.lower + np.random.default_rng(seed).uniform(0.0, 1.0, span.size) * span
    constraints = [{"type": "ineq", "fun": lambda x: -evaluated(x)[1]}]
    while True:  # restarts from new random starts until the target or the budget stops it
        minimize(lambda x: evaluated(x)[0], x0, method="COBYLA", constraints=constraints, bounds=_bounds(problem),
                 options={"maxiter": 10_000, "rhobeg": 0.1 * float(span.min())})
        x0 = problem.lower + np.random.default_rng(seed + 7919 * tracker.evaluations).uniform(0, 1, span.size) * span


def _pymoo_problem(problem: Problem, tracker: Tracker, vectorized: bool) -> Any:
    from pymoo.core.problem import ElementwiseProblem
    from pymoo.core.problem import Problem as PymooProblem

    dims = problem.lower.size
    if vectorized:
        class Population(PymooProblem):
            def _evaluate(self, x, out, *args, **kwargs):
                c = problem.costs(x)
                tracker.record(c)
                out["F"] = c

        return Population(n_var=dims, n_obj=1, xl=problem.lower, xu=problem.upper)

    class One(ElementwiseProblem):
        def _evaluate(self, x, out, *args, **kwargs):
            c = problem.cost(x)
            tracker.record(np.array([c]))
            out["F"] = c

    return One(n_var=dims, n_obj=1, xl=problem.lower, xu=problem.upper)


def _run_pymoo(problem: Problem, seed: int, tracker: Tracker, vectorized: bool) -> None:
    from pymoo.algorithms.soo.nonconvex.ga import GA
    from pymoo.optimize import minimize

    minimize(_pymoo_problem(problem, tracker, vectorized), GA(pop_size=50), ("n_evals", problem.budget + 100),
             seed=seed, verbose=False)


def run_pymoo_ga(problem: Problem, seed: int, tracker: Tracker) -> None:
    _run_pymoo(problem, seed, tracker, False)


def run_pymoo_ga_vectorized(problem: Problem, seed: int, tracker: Tracker) -> None:
    _run_pymoo(problem, seed, tracker, True)


OPTIMISERS = {"machdyn": run_machdyn, "scipy_de": run_scipy_de, "scipy_de_vectorized": run_scipy_de_vectorized,
              "scipy_cobyla": run_scipy_cobyla, "pymoo_ga": run_pymoo_ga,
              "pymoo_ga_vectorized": run_pymoo_ga_vectorized}


# -------------------------------------------------------------------------------------------------- the runs


def best_known(problem: Problem, quick: bool) -> dict[str, Any]:
    """A long run of machdyn's optimiser, with no early stop: the problem's long-run population and generations
    (a quarter of the generations with ``--quick``)."""
    population = problem.long_run[0] or problem.population * 4
    generations = max(problem.long_run[1] // (4 if quick else 1), 10)
    tracker = Tracker(-math.inf, 10**12, math.inf)
    t0 = time.perf_counter()
    from machdyn.studies.optimisation.result import NoFeasibleDesign
    from machdyn.studies.optimisation.search import differential_evolution

    try:
        differential_evolution(_Tracked(problem.evaluator, tracker), population=population, generations=generations,
                               tolerance=1e-12, seed=12345)
    except Reached:
        pass
    except NoFeasibleDesign:
        if generations >= problem.long_run[1]:
            raise
        # a shortened (--quick) run found no feasible design: the full long run is the reference then
        generations = problem.long_run[1]
        try:
            differential_evolution(_Tracked(problem.evaluator, tracker), population=population,
                                   generations=generations, tolerance=1e-12, seed=12345)
        except Reached:
            pass
    return {"value": tracker.best, "population": population, "generations": generations,
            "designs": tracker.evaluations, "seconds": time.perf_counter() - t0}


def _spread(values: list[float]) -> dict[str, float] | None:
    if not values:
        return None
    return {"min": min(values), "median": statistics.median(values), "max": max(values)}


def bench_problem(make: Any, seeds: int, quick: bool, max_seconds: float, only: list[str] | None) -> dict[str, Any]:
    problem = make()
    known = best_known(problem, quick)
    runs: dict[str, list[tuple[float, int] | None]] = {}
    found = known["value"]
    for name, optimiser in OPTIMISERS.items():
        if only and name not in only:
            continue
        if name == "scipy_cobyla" and not problem.smooth:
            continue
        if name.endswith("_vectorized") and problem.by_runs:
            continue  # the same runs of each design as the single-design cost
        runs[name] = []
        for seed in range(seeds):
            target = known["value"] + TOLERANCE * max(abs(known["value"]), problem.scale)
            tracker = Tracker(target, problem.budget, max_seconds)
            try:
                for restart in range(10**6):  # a search that converges short of the target starts again
                    optimiser(problem, seed + 1000 * restart, tracker)
            except Reached:
                pass
            runs[name].append(tracker.reached)
            found = min(found, tracker.best)
    out: dict[str, Any] = {"best_known": known, "target_tolerance": TOLERANCE, "budget_designs": problem.budget,
                           "evaluated": "each design run whole" if problem.by_runs else "population evaluator"}
    if problem.closed_form is not None:
        out["closed_form_optimum"] = problem.closed_form()
    if problem.scale:
        out["tolerance_of"] = problem.scale
    if problem.note:
        out["note"] = problem.note
    if found < known["value"]:
        out["better_found_by_a_run"] = found
    base = runs.get("machdyn")
    base_t = _spread([r[0] for r in base if r]) if base else None
    base_n = _spread([float(r[1]) for r in base if r]) if base else None
    for name, reached in runs.items():
        t = _spread([r[0] for r in reached if r])
        n = _spread([float(r[1]) for r in reached if r])
        entry: dict[str, Any] = {"reached": sum(r is not None for r in reached), "seeds": len(reached),
                                 "seconds": t, "designs": n}
        if t and base_t:
            entry["time_ratio_to_machdyn"] = t["median"] / base_t["median"]
            entry["designs_ratio_to_machdyn"] = n["median"] / base_n["median"] if n and base_n else None
        out[name] = entry
        shown = f"{t['median']:9.3g} s ({t['min']:.3g}..{t['max']:.3g})" if t else "    never"
        ratio = f"x{entry.get('time_ratio_to_machdyn', math.nan):8.3g}" if t and base_t else ""
        print(f"  {name:22s} reached {entry['reached']}/{entry['seeds']}  {shown}  "  # noqa: T201
              f"{n['median'] if n else math.nan:10.0f} designs  {ratio}", flush=True)
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--seeds", type=int, default=5)
    ap.add_argument("--quick", action="store_true", help="smaller budgets and a shorter long run")
    ap.add_argument("--only", action="append", help="a problem (repeatable)")
    ap.add_argument("--optimiser", action="append", help="an optimiser (repeatable)")
    ap.add_argument("--max-seconds", type=float, default=20.0, help="wall time allowed to one run")
    args = ap.parse_args()
    found: dict[str, Any] = {}
    t0 = time.perf_counter()
    for name, make in problems(args.quick).items():
        if args.only and name not in args.only:
            continue
        print(name, flush=True)  # noqa: T201
        found[name] = bench_problem(make, args.seeds, args.quick, args.max_seconds, args.optimiser)
        print(f"  best known {found[name]['best_known']['value']:.10g}", flush=True)  # noqa: T201
        print(json.dumps({"problem": name, **found[name]}), flush=True)  # noqa: T201 - kept if a later one stops
    print(json.dumps({"time_to_optimum": found, "seeds": args.seeds, "quick": args.quick,  # noqa: T201
                      "runtime_s": time.perf_counter() - t0}))


if __name__ == "__main__":
    main()
