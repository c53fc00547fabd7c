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

    rows: dict[str, list] = {"evaluations": [], "best": [], "feasible": [], "fronts": []}

    class _Record(Callback):
        def notify(self, algorithm):
            g = algorithm.pop.get("G")[:, 0]
            f = algorithm.pop.get("F")[:, 0]
            rows["evaluations"].append(evaluator.evaluations)
            ok = g <= 0
            rows["best"].append(float(f[ok].min()) if ok.any() else np.nan)
            rows["feasible"].append(float(ok.mean()))
            opt = algorithm.opt
            feasible = opt.get("G")[:, 0] <= 0 if opt is not None and len(opt) else np.zeros(0, dtype=bool)
            rows["fronts"].append(np.asarray(opt.get("F"))[feasible] if feasible.any() else np.zeros((0, n_obj)))

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
                      np.asarray(rows["feasible"]), hypervolumes(rows["fronts"]))
    return front_x[order], front_f[order], history, seconds


def hypervolumes(fronts: list[np.ndarray]) -> np.ndarray:
    """The hypervolume of each generation's feasible front (Zitzler & Thiele, *Multiobjective evolutionary
    algorithms: a comparative case study and the strength Pareto approach*, IEEE Trans. Evol. Comput. 3 (1999)
    257-271), in the objective space normalised over every generation (0 at the best value any front reached, 1
    at the worst) against the reference point 1.1 in each objective; NaN before the first feasible front.
    One normalisation for all generations, so the values compare across generations."""
    from pymoo.indicators.hv import HV

    found = [f for f in fronts if len(f)]
    out = np.full(len(fronts), np.nan)
    if not found:
        return out
    stacked = np.vstack(found)
    low, high = stacked.min(axis=0), stacked.max(axis=0)
    scale = np.where(high > low, high - low, 1.0)
    indicator = HV(ref_point=np.full(stacked.shape[1], 1.1))
    for i, f in enumerate(fronts):
        if len(f):
            out[i] = float(indicator((f - low) / scale))
    return out


def hypervolume_converged(hv: np.ndarray, tolerance: float, window: int) -> tuple[bool, str]:
    """The stated stopping criterion of the front: the hypervolume (:func:`hypervolumes`) grew by at most
    ``tolerance`` (relative) over the last ``window`` generations — stagnation of the hypervolume, the usual
    convergence test of a multi-objective evolutionary search (Wagner, Trautmann & Naujoks, *OCD: online
    convergence detection for evolutionary multi-objective algorithms based on statistical testing*, EMO 2009,
    LNCS 5467, 198-215, whose simplest form this is). Returns (converged, the reason in words)."""
    values = np.asarray(hv, dtype=float)
    if values.size <= window or not np.isfinite(values[-window - 1]):
        return False, (f"the hypervolume of the front needs more than {window} generations with a feasible front "
                       f"to judge convergence; {int(np.isfinite(values).sum())} had one")
    last, before = float(values[-1]), float(values[-window - 1])
    growth = (last - before) / max(abs(before), 1e-300)
    if growth <= tolerance:
        return True, (f"the hypervolume of the front grew by {100 * growth:.3g} % over the last {window} "
                      f"generations (criterion: at most {100 * tolerance:.3g} %)")
    return False, (f"the hypervolume of the front still grew by {100 * growth:.3g} % over the last {window} "
                   f"generations (criterion: at most {100 * tolerance:.3g} %)")


def spacing(front: np.ndarray) -> float:
    """Schott's spacing of a front (J. R. Schott, *Fault tolerant design using single and multicriteria genetic
    algorithm optimization*, MS thesis, MIT, 1995): the standard deviation of each member's L1 distance to its
    nearest neighbour, in the objective space normalised to the front's own extent (0: evenly spread; NaN for
    fewer than 3 members)."""
    f = np.asarray(front, dtype=float)
    if f.shape[0] < 3:
        return float("nan")
    low, high = f.min(axis=0), f.max(axis=0)
    g = (f - low) / np.where(high > low, high - low, 1.0)
    d = np.abs(g[:, None, :] - g[None, :, :]).sum(axis=2)
    np.fill_diagonal(d, np.inf)
    return float(np.std(d.min(axis=1), ddof=1))
