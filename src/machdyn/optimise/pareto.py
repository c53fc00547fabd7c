"""Multi-objective search: a Pareto front by NSGA-II (K. Deb, A. Pratap, S. Agarwal, T. Meyarivan, *A fast
and elitist multiobjective genetic algorithm: NSGA-II*, IEEE Trans. Evol. Comput. 6 (2002) 182-197) as
implemented by pymoo (imported only here, when a front is asked for). Each generation is one call of the
engine; constraints use pymoo's constraint domination (the same feasibility rules as the single-objective
search)."""

from __future__ import annotations

import time

import numpy as np

from .result import History, NoFeasibleDesign
from .search import INFEASIBLE, Evaluator, _plain


def nsga2(evaluator: Evaluator, *, population: int, generations: int, seed: int | None, show=None):
    """The Pareto front of the evaluator's objectives: (front_x, front_costs, history, seconds).

    ``front_costs`` are the objectives' costs (results for minimised ones, negated for maximised ones)."""
    from pymoo.algorithms.moo.nsga2 import NSGA2
    from pymoo.core.callback import Callback
    from pymoo.core.problem import Problem
    from pymoo.optimize import minimize

    space = evaluator.space
    n_obj = len(evaluator.objectives)

    class _Design(Problem):
        def __init__(self):
            super().__init__(n_var=len(space.lower), n_obj=n_obj, n_ieq_constr=1, xl=space.lower, xu=space.upper)

        def _evaluate(self, x, out, *args, **kwargs):
            _results, costs, viol = evaluator(x)
            out["F"] = np.where(np.isfinite(costs), costs, INFEASIBLE)
            out["G"] = viol.sum(axis=1, keepdims=True)

    rows: dict[str, list] = {"evaluations": [], "best": [], "feasible": []}

    class _Record(Callback):
        def notify(self, algorithm):
            g = algorithm.pop.get("G")[:, 0]
            f = algorithm.pop.get("F")[:, 0]
            rows["evaluations"].append(evaluator.evaluations)
            ok = g <= 0
            rows["best"].append(float(f[ok].min()) if ok.any() else np.nan)
            rows["feasible"].append(float(ok.mean()))

    start = time.perf_counter()
    res = minimize(_Design(), NSGA2(pop_size=population), ("n_gen", generations), seed=seed,
                   callback=_Record(), verbose=False)
    seconds = time.perf_counter() - start
    if res.X is None or res.F is None:
        raise NoFeasibleDesign(evaluator.infeasible_message(show or _plain))
    front_x = np.atleast_2d(res.X)
    front_f = np.atleast_2d(res.F)
    order = np.argsort(front_f[:, 0])
    gens = np.arange(1, len(rows["best"]) + 1)
    history = History(gens, np.asarray(rows["evaluations"]), np.asarray(rows["best"]),
                      np.asarray(rows["feasible"]))
    return front_x[order], front_f[order], history, seconds
