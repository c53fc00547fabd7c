"""Optimisation benchmark: designs evaluated per second on the seed 003 compactor problem.

The problem is the shipped example ``examples/compactor_optimise.toml`` reduced to three variables (crank radius
r, plate length l, pendulum length R; pivot height h fixed at 250 mm, so that every optimiser varies the same
link lengths): maximise the force gain k1*k2 guaranteed over the pressing window (seed 003 eq 1) with the
plate angle gamma <= 20 deg and the transmission angle >= 45 deg, over 360 crank positions per design.

Rows, each run ``--repeats`` times (min / median / max of designs per second):

- machdyn, vectorised: :func:`machdyn.studies.optimisation.optimise` (scipy differential evolution, ``vectorized=True``:
  each generation of ``--population`` designs is one engine call). Two cases: kinematics only (the same work
  as the peer) and with the full force analysis (the example's peak-torque constraint added).
- machdyn, vectorised, with the exact flywheel: the forces case plus, for every design of every generation,
  the exact (energy-mass) flywheel inertia for a coefficient of speed fluctuation of 0.05
  (:func:`machdyn.dynamics.population_flywheel.exact_flywheel_inertia` on the reduced inertia and moment
  curves of the fused population pass), kept below 1.5 kg*m^2 as one more constraint (scipy differential
  evolution, vectorised, the optimiser's settings).
- scipy's differential evolution alone, vectorised, on a trivial cost (the sum of the variables, no design
  evaluated): the rate the
  search's own bookkeeping allows (it draws the mutation's members for each design in Python), the ceiling of
  every vectorised row.
- machdyn, one design at a time: the same evaluator called design by design (what vectorisation buys).
- pylinkage: ``pylinkage.optimization.differential_evolution_optimization`` with the same population size,
  evaluating one design at a time: its compiled dyad solver steps the linkage through the 360 positions
  (``Linkage.step``) and the objective and constraints are computed from the loci with NumPy.

Every optimiser runs a fixed number of generations (no early stop), so the designs evaluated are counted, not
estimated. The script prints a table and, as its last line, one JSON object. Usage:
``python bench/optimise.py [--population 400] [--generations 10] [--repeats 3]``.
"""

from __future__ import annotations

import argparse
import json
import math
import statistics
import time
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
EXAMPLE = ROOT / "examples" / "compactor_optimise.toml"
H = 0.25  # m, the pivot height kept fixed
A_FROM_B = 0.10  # m, the particle's distance from B
WINDOW = (math.radians(220.0), math.radians(260.0))
GAMMA_MAX = math.radians(20.0)
MU_MIN = math.radians(45.0)
TARGET_RATIO = 50.0
TARGET_WITH_FORCES = 100_000.0  # designs/s, and 150 times the peer
TARGET_WITH_FORCES_RATIO = 150.0
TARGET_FLYWHEEL = 10_000.0  # designs/s with the exact flywheel in the loop
DELTA = 0.05  # coefficient of speed fluctuation of the flywheel line
FLYWHEEL_MAX = 1.5  # kg*m^2, the flywheel line's constraint
POSITIONS = 360  # crank positions per design, for every optimiser (the example searches at 180)


def machdyn_problem(forces: bool):
    """The compactor problem with three variables (and the torque constraint when ``forces``)."""
    from machdyn.reading import load_problem

    problem = load_problem(EXAMPLE)
    spec = problem.optimise
    variables = [v for v in spec.variables if v.name != "h"]
    derived = {"mechanism.ground.length": f"hypot(l, {H})", "mechanism.ground.angle": f"atan2({H}, l)",
               "mechanism.coupler_point[0]": f"l - {A_FROM_B}"}
    constraints = [c for c in spec.constraints if forces or c.result != "driving_torque.max_abs"]
    return problem, spec.model_copy(update={"variables": variables, "derived": derived, "positions": POSITIONS,
                                            "constraints": constraints, "tolerance": 1e-300})


def run_machdyn(population: int, generations: int, forces: bool) -> dict[str, Any]:
    from machdyn.studies.optimisation import optimise

    problem, spec = machdyn_problem(forces)
    spec = spec.model_copy(update={"population": population, "generations": generations})
    res = optimise(problem, spec)
    return {"designs": res.evaluations, "seconds": res.seconds, "best_gain": float(res.objective[0])}


def run_machdyn_flywheel(population: int, generations: int) -> dict[str, Any]:
    from scipy.optimize import differential_evolution

    from machdyn.dynamics.population_flywheel import exact_flywheel_inertia
    from machdyn.linkage.fused_population import run_population
    from machdyn.studies.optimisation import setup
    from machdyn.studies.optimisation.search import INFEASIBLE

    problem, spec = machdyn_problem(True)
    ev = setup(problem, spec)
    bounds = list(zip(ev.space.lower, ev.space.upper, strict=True))

    def cost(xt):
        x = np.asarray(xt).T
        base = ev.scalar_cost(x)
        pop = ev.space.population(x)
        curves = run_population(pop.mechanism, ev.phi, pop.speed, pop.acceleration, designs=x.shape[0],
                                forces=True, energy=True).energy
        assert curves is not None
        flywheel = exact_flywheel_inertia(ev.phi, curves[1], curves[0], pop.speed, DELTA)
        over = np.maximum(np.nan_to_num(flywheel, nan=np.inf) - FLYWHEEL_MAX, 0.0) / FLYWHEEL_MAX
        return np.where(over > 0, np.maximum(base, INFEASIBLE) * (1.0 + np.minimum(over, 1e6)), base)

    start = time.perf_counter()
    res = differential_evolution(cost, bounds, maxiter=generations, popsize=math.ceil(population / 3), tol=0.0,
                                 atol=0.0, seed=1, polish=False, init="latinhypercube", vectorized=True,
                                 updating="deferred")
    seconds = time.perf_counter() - start
    return {"designs": ev.evaluations, "seconds": seconds, "best_gain": -float(res.fun)}


def run_search_alone(population: int, generations: int) -> dict[str, Any]:
    from scipy.optimize import differential_evolution

    _problem, spec = machdyn_problem(False)
    bounds = [(float(v.lower.split()[0]) / 1000, float(v.upper.split()[0]) / 1000) for v in spec.variables]
    counter = {"n": 0}

    def cost(xt):
        counter["n"] += np.shape(xt)[1]
        return np.asarray(xt).sum(axis=0)  # not constant: a constant population converges at once

    start = time.perf_counter()
    differential_evolution(cost, bounds, maxiter=generations, popsize=math.ceil(population / 3), tol=0.0, atol=0.0,
                           seed=1, polish=False, init="latinhypercube", vectorized=True, updating="deferred")
    return {"designs": counter["n"], "seconds": time.perf_counter() - start, "best_gain": math.nan}


def run_machdyn_one_at_a_time(population: int, generations: int) -> dict[str, Any]:
    from scipy.optimize import differential_evolution

    from machdyn.studies.optimisation import setup

    problem, spec = machdyn_problem(False)
    ev = setup(problem, spec)
    bounds = list(zip(ev.space.lower, ev.space.upper, strict=True))
    start = time.perf_counter()
    res = differential_evolution(lambda x: float(ev.scalar_cost(x[None, :])[0]), bounds, maxiter=generations,
                                 popsize=math.ceil(population / 3), tol=0.0, atol=0.0, seed=1, polish=False,
                                 init="latinhypercube")
    seconds = time.perf_counter() - start
    return {"designs": ev.evaluations, "seconds": seconds, "best_gain": -float(res.fun)}


def pylinkage_compactor():
    """The compactor in pylinkage: ground O and C = (l, h), crank O-A, the RRR dyad plate A-B / pendulum C-B
    (B starts below C, the seed's branch), one crank revolution = 360 steps."""
    from pylinkage.actuators import Crank
    from pylinkage.components import Ground
    from pylinkage.dyads import RRRDyad
    from pylinkage.simulation import Linkage

    step = 2 * math.pi / 360
    o = Ground(0.0, 0.0, name="O")
    c = Ground(0.5, H, name="C")
    crank = Crank(anchor=o, radius=0.03, angular_velocity=step, initial_angle=-step, name="crank")
    b = RRRDyad(crank.output, c, distance1=0.5, distance2=0.25, x=0.53, y=0.0, name="B")
    return Linkage([o, c, crank, b], name="compactor"), c


def compactor_score(loci: np.ndarray, l_plate: float) -> float:
    """Force gain k1*k2 (min over the window) penalised by the constraints' violations, from the loci
    (steps x joints x 2) of O, C, A, B: the same definitions as machdyn.studies.optimisation.evaluate."""
    a, b, c = loci[:, 2], loci[:, 3], loci[:, 1]
    phi = np.mod(np.arctan2(a[:, 1], a[:, 0]), 2 * math.pi)
    theta2 = np.arctan2(b[:, 1] - a[:, 1], b[:, 0] - a[:, 0])
    theta3 = np.arctan2(b[:, 1] - c[:, 1], b[:, 0] - c[:, 0])
    gamma = np.abs(np.mod(theta2 + math.pi, 2 * math.pi) - math.pi)
    mu = np.abs(np.mod(theta2 - theta3 + math.pi, 2 * math.pi) - math.pi)
    worst = np.minimum(mu, math.pi - mu).min()
    inside = (phi >= WINDOW[0]) & (phi <= WINDOW[1])
    k1 = (1.0 / np.abs(np.cos(theta2 - phi)))[inside].min()
    gain = k1 * l_plate / A_FROM_B
    violation = max(0.0, gamma.max() - GAMMA_MAX) / GAMMA_MAX + max(0.0, MU_MIN - worst) / MU_MIN
    return gain if violation == 0 else -1e6 * (1 + violation)


def run_pylinkage(population: int, generations: int) -> dict[str, Any]:
    from pylinkage.exceptions import UnbuildableError
    from pylinkage.optimization import differential_evolution_optimization

    linkage, pivot = pylinkage_compactor()
    counter = {"n": 0}

    def fitness(linkage, params, init_pos):
        counter["n"] += 1
        r, l_plate, big_r = params
        linkage.set_coords(init_pos)
        linkage.set_constraints([r, l_plate, big_r])
        pivot.set_coord(l_plate, H)
        try:
            loci = np.array(list(linkage.step(iterations=360)), dtype=float)
        except UnbuildableError:
            return -1e12
        if not np.all(np.isfinite(loci)):
            return -1e12
        return compactor_score(loci, l_plate)

    problem, spec = machdyn_problem(False)
    lower = [float(v.lower.split()[0]) / 1000 for v in spec.variables]
    upper = [float(v.upper.split()[0]) / 1000 for v in spec.variables]
    start = time.perf_counter()
    ens = differential_evolution_optimization(fitness, linkage, bounds=(lower, upper), order_relation=max,
                                              maxiter=generations, popsize=math.ceil(population / 3), tol=0.0,
                                              atol=0.0, seed=1, polish=False, verbose=False,
                                              init="latinhypercube")
    seconds = time.perf_counter() - start
    return {"designs": counter["n"], "seconds": seconds, "best_gain": float(ens.scores["score"][0])}


def rates(runs: list[dict[str, Any]]) -> dict[str, float]:
    r = [x["designs"] / x["seconds"] for x in runs]
    return {"min": min(r), "median": statistics.median(r), "max": max(r), "designs": runs[0]["designs"],
            "best_gain": runs[0]["best_gain"]}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--population", type=int, default=400)
    parser.add_argument("--generations", type=int, default=10)
    parser.add_argument("--peer-generations", type=int, default=2)
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    p, g, pg = args.population, args.generations, args.peer_generations
    # warm-up: imports, and each row's compiled kernels (from numba's cache, or compiled once)
    run_machdyn(p, 1, False)
    run_machdyn(p, 1, True)
    run_machdyn_flywheel(p, 1)
    table = {
        "machdyn_vectorised_kinematics": rates([run_machdyn(p, g, False) for _ in range(args.repeats)]),
        "machdyn_vectorised_with_forces": rates([run_machdyn(p, g, True) for _ in range(args.repeats)]),
        "machdyn_vectorised_with_flywheel": rates([run_machdyn_flywheel(p, g) for _ in range(args.repeats)]),
        "scipy_de_alone_trivial_cost": rates([run_search_alone(p, g) for _ in range(args.repeats)]),
        "machdyn_one_at_a_time": rates([run_machdyn_one_at_a_time(p, pg) for _ in range(args.repeats)]),
        "pylinkage_de_one_at_a_time": rates([run_pylinkage(p, pg) for _ in range(args.repeats)]),
    }
    peer = table["pylinkage_de_one_at_a_time"]["median"]
    print(f"Compactor optimisation, population {p}, {POSITIONS} crank positions per design; designs per second")
    print(f"{'optimiser':34s} {'designs':>8s} {'min':>10s} {'median':>10s} {'max':>10s} {'vs pylinkage':>13s}")
    for name, row in table.items():
        print(f"{name:34s} {row['designs']:8d} {row['min']:10.0f} {row['median']:10.0f} {row['max']:10.0f} "
              f"{row['median'] / peer:12.1f}x")
    ratio = table["machdyn_vectorised_kinematics"]["median"] / peer
    summary = {
        "population": p, "generations": g, "peer_generations": pg, "repeats": args.repeats, "rows": table,
        "ratio_vs_pylinkage_median": ratio,
        "ratio_with_forces_vs_pylinkage_median": table["machdyn_vectorised_with_forces"]["median"] / peer,
        "target_ratio": TARGET_RATIO, "target_met": ratio >= TARGET_RATIO,
        "target_with_forces": TARGET_WITH_FORCES, "target_with_forces_ratio": TARGET_WITH_FORCES_RATIO,
        "target_with_forces_met": table["machdyn_vectorised_with_forces"]["median"] >= TARGET_WITH_FORCES
        and table["machdyn_vectorised_with_forces"]["median"] / peer >= TARGET_WITH_FORCES_RATIO,
        "target_flywheel": TARGET_FLYWHEEL,
        "target_flywheel_met": table["machdyn_vectorised_with_flywheel"]["median"] >= TARGET_FLYWHEEL,
    }
    print(json.dumps(summary))


if __name__ == "__main__":
    main()
