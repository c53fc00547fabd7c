"""Single-objective search: :func:`scipy.optimize.differential_evolution` with ``vectorized=True``, so that
each generation — the whole population — is one call of the engine, then a local search from its best design
(:func:`polish`).

Constraints follow Deb's feasibility rules (K. Deb, *An efficient constraint handling method for genetic
algorithms*, Comput. Methods Appl. Mech. Engrg. 186 (2000) 311-338): differential evolution compares a trial
with its target only, so the cost of an infeasible design is ``INFEASIBLE * (1 + total violation)``, above
every feasible cost: a feasible design beats an infeasible one, two feasible ones compare by objective, two
infeasible ones by violation.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ...errors import MachdynError
from ...results.population import DEFAULT_MIN_TRANSMISSION_DEG
from ..evaluator import PopulationEvaluator
from ..exploration.execution import announce_estimate, current
from .constraints import CLOSES, violations
from .result import History, NoFeasibleDesign

#: Cost floor of infeasible designs; feasible objective values must stay far below it in magnitude.
INFEASIBLE = 1e30


@dataclass
class Evaluator:
    """Evaluates populations (N x V, SI) of a design space: results, objective costs, violations; keeps the
    count of designs evaluated, the least-violating design seen and each constraint's smallest violation."""

    space: Any
    objectives: tuple
    constraints: tuple
    phi: np.ndarray
    about: tuple = (0.0, 0.0)
    evaluations: int = 0
    least_violation: np.ndarray | None = None
    closest: tuple | None = None
    wanted: set = field(default_factory=set)
    #: the machine the mechanism is ([mechanism] machine), which decides the machine's own results
    machine: str | None = None
    #: the threshold [rad] of a degenerate design's poor transmission (the built-in constraint)
    min_transmission_angle: float = math.radians(DEFAULT_MIN_TRANSMISSION_DEG)
    #: capability results (no population group computes them): each design is run by ``run_design``
    per_design_keys: frozenset = frozenset()
    run_design: Any = None

    def __post_init__(self) -> None:
        self.wanted = {o.result for o in self.objectives} | {c.result for c in self.constraints}

    @property
    def per_design_wanted(self) -> set[str]:
        """The results asked for that only a run of each design gives."""
        return self.wanted & set(self.per_design_keys)

    def evaluator(self, speed: Any = 0.0, acceleration: Any = 0.0) -> PopulationEvaluator:
        """The studies' evaluator at the drive's ``speed`` and ``acceleration`` (one per design, or floats), on the
        compiled pass of the population evaluator (:mod:`machdyn.linkage.fused_population`); the designs' own runs
        on the worker processes the execution settings give (``--workers``)."""
        return PopulationEvaluator(self.phi, speed, acceleration, self.about, self.machine,
                                   self.min_transmission_angle, engine="fused", run_design=self.run_design,
                                   workers=current().workers or 1,
                                   problem=self.space.problem,
                                   varied=tuple(v.path for v in self.space.variables if v.path is not None)
                                   + tuple(f.path for f in self.space.formulas))

    def design_results(self, problems, keys) -> dict[str, np.ndarray]:
        """``keys`` of each design's run (:func:`~machdyn.studies.per_design.evaluate_designs`)."""
        problems = list(problems)
        return self.evaluator().per_design(problems, keys, len(problems))

    def __call__(self, population) -> tuple[dict, np.ndarray, np.ndarray]:
        """(results, costs N x K, violations N x (1 + C)) of a population: the capability results asked for by
        running each regular design through the file's stages."""
        x = np.atleast_2d(np.asarray(population, dtype=float))
        pop = self.space.population(x)
        evaluated = self.evaluator(pop.speed, pop.acceleration)(
            pop.mechanism, self.wanted - self.per_design_wanted, x.shape[0], self.per_design_wanted,
            lambda i: self.space.problem_at(x[i]), pop.buildable)
        results = {k: v for k, v in evaluated.items() if v.dtype.kind in "fb"}  # the text status left out
        costs = np.stack([o.cost(results) for o in self.objectives], axis=1)
        viol = violations(self.constraints, results, pop.buildable)
        viol[:, 0] += np.where(np.isfinite(costs).all(axis=1), 0.0, 1.0)
        self.evaluations += x.shape[0]
        self._track(x, results, viol)
        return results, costs, viol

    def _track(self, x, results, viol) -> None:
        low = viol.min(axis=0)
        self.least_violation = low if self.least_violation is None else np.minimum(self.least_violation, low)
        i = int(np.argmin(viol.sum(axis=1)))
        total = float(viol[i].sum())
        if self.closest is None or total < self.closest[0]:
            self.closest = (total, x[i].copy(), {k: float(np.asarray(v)[i]) for k, v in results.items()})

    def scalar_cost(self, population) -> np.ndarray:
        """Deb-rule cost of each design for a single objective."""
        _results, costs, viol = self(population)
        total = viol.sum(axis=1)
        return np.where(total > 0, INFEASIBLE * (1.0 + total), costs[:, 0])

    #: The built-in constraint every design meets first, as the infeasibility message names it.
    regular_rule = CLOSES

    def regular_reached(self, fraction: float) -> str:
        """How near the closest design came to the built-in constraint (the share of crank angles it closes at)."""
        return f"; the closest design closes at {100 * fraction:.0f} % of the angles" if math.isfinite(fraction) else ""

    def infeasible_message(self, show) -> str:
        """Why no design is feasible: every constraint with the smallest violation any design reached,
        tightest first, and the values of the design that came closest."""
        assert self.least_violation is not None and self.closest is not None
        labels = [self.regular_rule] + [c.describe(show(c)) for c in self.constraints]
        order = np.argsort(-self.least_violation, kind="stable")
        best = self.closest[2]
        lines = [f"No design within the bounds meets every constraint ({self.evaluations} designs evaluated). "
                 "Every constraint, tightest first, with the smallest relative violation any design reached and "
                 "the value of the design that came closest to meeting them all:"]
        for k in order:
            label = labels[k]
            reached = ""
            if k == 0:
                reached = self.regular_reached(best.get("assembled_fraction", math.nan))
            else:
                c = self.constraints[k - 1]
                value = best.get(c.result, math.nan)
                reached = f"; the closest design has {show(c)(value)}" if math.isfinite(value) else ""
            least = self.least_violation[k]
            said = (f"violated by at least {least:.3g}" if least > 0 else
                    "met by some designs, but not together with the others")
            lines.append(f"  {label}: {said}{reached}")
        if not np.any(self.least_violation > 0):
            lines.append("Each constraint alone is met somewhere within the bounds, but no design meets them all at "
                         "once: they conflict.")
        lines.append("Widen the variables' bounds or relax the tightest constraint.")
        return "\n".join(lines)


#: Passes a polish may make (each one batch of POINTS designs per variable, evaluated in one call; a run of each
#: design for a cam or a shaft line); about seven reach the 1e-7 bracket.
POLISH_EVALUATIONS = 40

#: Designs along each variable in one pass of the polish, and the factor its bracket shrinks by between passes
#: (the new bracket, ±h/SHRINK, spans the old spacing 2h/(POINTS-1) on either side of the best design).
POINTS, SHRINK = 17, 8.0

#: The half-width of the polish's first bracket along each variable, as a share of the variable's range.
WINDOW = 0.05

#: A best design counts as better than the file's own only if its cost is lower by more than this (relative):
#: below it the two agree to the rounding of the analysis.
IMPROVEMENT = 1e-9


def polish(evaluator: Evaluator, x, cost: float) -> tuple[np.ndarray, float]:
    """A local search from the best design ``x`` (Deb-rule ``cost``) of the evolution, within the bounds, that
    evaluates whole batches of designs at once: a compass (pattern) search on the variables scaled to [0, 1] — each
    pass tries :data:`POINTS` designs spaced along every variable through the best one, over ±h, and moves to the
    best of them; h shrinks by :data:`SHRINK` when the best design lies inside the bracket and the bracket moves
    on (h kept) when it lies on its edge — from h = :data:`WINDOW` of the range down to 1e-7, at most
    :data:`POLISH_EVALUATIONS` passes (Hooke & Jeeves, "Direct search solution of numerical and statistical
    problems", J. ACM 8 (1961) 212–229; Kolda, Lewis & Torczon, SIAM Review 45 (2003) 385–482, compass search).
    Differential evolution closes in on an optimum only as fast as its population shrinks, so with a short budget
    it may stop near the start it was given (the file's own design); the search walks the last stretch, to the
    boundary of an active constraint from its feasible side. A pass is one call of the vectorised evaluator, so
    the polish costs a few population evaluations, not hundreds of single designs. Returns the better of ``x``
    and the best design the search evaluated, with its cost."""
    lower, upper = np.asarray(evaluator.space.lower, float), np.asarray(evaluator.space.upper, float)
    span = np.where(upper > lower, upper - lower, 1.0)
    best_cost, best_u = float(cost), (np.asarray(x, dtype=float) - lower) / span
    dims = best_u.size
    offsets = np.linspace(-1.0, 1.0, POINTS)
    h = WINDOW
    for _ in range(POLISH_EVALUATIONS):
        if h < 1e-7:
            break
        trial = np.repeat(best_u[None, :], dims * POINTS, axis=0)
        for d in range(dims):
            trial[d * POINTS:(d + 1) * POINTS, d] = best_u[d] + h * offsets
        trial = np.clip(trial, 0.0, 1.0)
        costs = np.asarray(evaluator.scalar_cost(lower + trial * span), dtype=float)
        k = int(np.argmin(costs))
        moved = costs[k] < best_cost
        if moved:
            best_cost, best_u = float(costs[k]), trial[k].copy()
        on_edge = moved and k % POINTS in (0, POINTS - 1) and 0.0 < best_u[k // POINTS] < 1.0
        if not on_edge:
            h /= SHRINK
    return lower + best_u * span, best_cost


def differential_evolution(evaluator: Evaluator, *, population: int, generations: int, tolerance: float,
                           seed: int | None, x0=None, show=None):
    """Run scipy's differential evolution on ``evaluator``, then :func:`polish` its best design; returns (x,
    converged, message, history, seconds, improved): ``improved`` True when the best design's cost is lower than
    the start's ``x0`` (the file's own design; by more than :data:`IMPROVEMENT`, relative), False when it is
    not, None without a start.

    Raises :class:`NoFeasibleDesign` when no design evaluated meets the constraints."""
    from scipy.optimize import differential_evolution as scipy_de

    space = evaluator.space
    bounds = list(zip(space.lower, space.upper, strict=True))
    dims = len(bounds)
    multiplier = max(1, math.ceil(population / dims))
    history: dict[str, list] = {"evaluations": [], "best": [], "feasible": []}

    def func(xt):  # scipy hands the population as (V, S)
        first = not history["feasible"]
        began = time.perf_counter()
        costs = evaluator.scalar_cost(np.asarray(xt).T)
        history["feasible"].append(float(np.mean(costs < INFEASIBLE)))
        if first:  # the first generation's time, times the generations: the estimate of the whole search
            per = time.perf_counter() - began
            announce_estimate(per * (generations + 1), f"an optimisation of {generations:,} generations of "
                              f"{np.asarray(xt).shape[1]:,} designs ({per:.2g} s per generation)")
        return costs

    def callback(intermediate_result):
        fun = float(intermediate_result.fun)
        history["evaluations"].append(evaluator.evaluations)
        history["best"].append(fun if fun < INFEASIBLE else math.nan)

    if x0 is not None:
        x0 = _inside(np.asarray(x0, dtype=float), np.asarray(space.lower, float), np.asarray(space.upper, float))
    start = time.perf_counter()
    try:
        res = scipy_de(
            func, bounds, maxiter=generations, popsize=multiplier, tol=tolerance, seed=seed, polish=False,
            vectorized=True, updating="deferred", callback=callback, init="latinhypercube", x0=x0,
        )
    except RuntimeError as exc:  # scipy wraps what the evaluator raised (no design buildable): say that instead
        if isinstance(exc.__cause__, MachdynError):
            raise exc.__cause__ from None
        raise
    if not float(res.fun) < INFEASIBLE:
        raise NoFeasibleDesign(evaluator.infeasible_message(show or _plain))
    x, cost = polish(evaluator, res.x, float(res.fun))
    improved = None
    if x0 is not None:
        start_cost = float(evaluator.scalar_cost(np.asarray(x0, dtype=float)[None, :])[0])
        improved = bool(cost < start_cost - IMPROVEMENT * max(abs(start_cost), abs(cost)))
    seconds = time.perf_counter() - start
    if history["evaluations"]:  # the last generation's row counts the local search's designs and its best
        history["evaluations"][-1] = evaluator.evaluations
        last = history["best"][-1]
        history["best"][-1] = cost if not last <= cost else last
    gens = np.arange(1, len(history["best"]) + 1)
    feasible_share = np.asarray(history["feasible"][1:len(gens) + 1] or [math.nan] * len(gens), dtype=float)
    if feasible_share.size < gens.size:
        feasible_share = np.pad(feasible_share, (0, gens.size - feasible_share.size), constant_values=np.nan)
    hist = History(gens, np.asarray(history["evaluations"]), np.asarray(history["best"]), feasible_share)
    converged = bool(res.success)
    message = str(res.message)
    return np.asarray(x, dtype=float), converged, message, hist, seconds, improved


def _inside(x0: np.ndarray, lower: np.ndarray, upper: np.ndarray) -> np.ndarray:
    """``x0`` moved by a few units in the last place where a start on a bound would fall a rounding outside
    [0, 1] in scipy's own scaling, ``(x - (lo + hi) / 2) / |hi - lo| + 0.5``, which refuses it."""
    x = np.clip(x0, lower, upper)
    for _ in range(8):
        scaled = (x - 0.5 * (lower + upper)) / np.abs(upper - lower) + 0.5
        low, high = scaled < 0.0, scaled > 1.0
        if not (low.any() or high.any()):
            break
        x = np.where(low, np.nextafter(x, upper), np.where(high, np.nextafter(x, lower), x))
    return x


def _plain(constraint):
    return lambda v: f"{v:g} {constraint.unit}".rstrip()
