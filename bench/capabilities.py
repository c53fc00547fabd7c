"""Benchmark: designs per second of each capability's population form against its per-design path, in one run.

For each capability, N random designs are evaluated by the population form (NumPy arrays over the designs, one
call) and a subset of the same designs by the single-design functions one after the other; ``agreement`` is the
largest relative difference of the compared figure over that subset (0 = identical), ``designs_per_s`` and
``per_design_per_s`` the median over the repeats (min and max beside them).

- cams: the exact largest pressure angle, smallest convex radius of curvature of the pitch curve and smallest base
  circle of translating roller cams of one program shape with random base radius, roller, offset and lift
  (``machdyn.cams.population.analyse_population`` against ``profile`` + ``check_cam``); the agreement is the
  largest over the three figures;
- parts: the ``[parts]`` checks of random four-bars (a ball bearing, a pin, a link in fatigue), forces included:
  one kinetostatics of the population + ``parts_population`` against ``kinetostatics`` + ``size_parts`` per
  design; the figure is the largest utilisation;
- clutch: slip time and energy of random engagements (``engage_population`` against ``engage``);
- shaft_balance: two-plane corrections and the ISO 21940-11 grade of random shaft lines of four masses
  (``two_plane_population`` + ``grade_population`` against ``two_plane`` + the grade check per line); the
  figure is the mass of the correction in plane M;
- balance: ``[balance]`` counterweights of random four-bars (72 positions, one counterweight on the crank) through
  the optimiser's own evaluator (an ``[optimise]`` table on ``balance.rms_force_after``: the linkage's status, its
  kinetostatics and the table's population form ``machdyn.balancing.population.balance_population``) against
  ``least_squares_counterweights`` per design; the figure is the RMS shaking force after balancing;
- frame: ``[frame]`` (two mounts, two points, ``[frame.after]``, 6 orders) of random four-bars through the
  optimiser's evaluator (``frame.mean_acceleration_reduction``; the population form
  ``machdyn.vibration.population.frame_population``) against ``study_frame`` per design; the figure is the mean
  acceleration reduction;
- engine_orders: in-line fours with random crank phases, rods and masses (72 angles, 6 orders;
  ``engine_orders_population`` against ``engine_orders``); the figure is the largest primary couple;
- motor_duty: the S6 duty of random induction motors (``duty_population`` against ``motor_duty``); the figure is the
  load ratio;
- field_balance: two-plane influence-coefficient balances of random readings (``field_balance_population`` against
  ``field.two_plane``); the figure is the correction mass in the first plane;
- passage: the closed-form envelope of random damped passages through a resonance at 64 times
  (``passage_envelope_population`` against ``passage_envelope``); the figure is the largest envelope;
- linkage (reference): largest |driving torque| of random four-bars (the population evaluator of the studies
  against ``kinetostatics`` per design).

Beside the capabilities:

- ``per_design_workers``: the per-design path of the studies (:func:`machdyn.studies.per_design.evaluate_designs`,
  each design run whole through its file's stages) on the in-line four's shaft line, in this process and on 2
  worker processes (``--workers 2``), the pool started before the timing (as a study's later generations find
  it); ``overhead_per_design_s`` is the workers' busy time per design beyond a run in this process
  (2 x wall time on the workers / designs - wall time in this process / designs), the cost of sending a design
  and its results between the processes;
- ``linkage_1e6``: 10^6 four-bar designs (72 crank positions, the largest |driving torque| and the worst
  transmission angle) through the studies' evaluator in chunks of its memory budget, in a fresh process:
  designs/s and the process's peak resident memory.

Usage: ``python bench/capabilities.py [--quick] [--repeats N]``. The last line printed is one JSON object
``{"capabilities": {name: {"designs_per_s", "per_design_per_s", "agreement", ...}}, "per_design_workers": ...,
"linkage_1e6": ...}``.
"""

from __future__ import annotations

import argparse
import json
import math
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))


def _rate(fn, n, repeats):
    """(result, designs/s min, median, max) of ``fn`` evaluating n designs, over ``repeats`` runs."""
    rates = []
    out = None
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = fn()
        rates.append(n / (time.perf_counter() - t0))
    return out, min(rates), statistics.median(rates), max(rates)


def _agreement(many, one):
    many, one = np.asarray(many, dtype=float), np.asarray(one, dtype=float)
    return float(np.max(np.abs(many - one) / np.maximum(np.abs(one), 1e-300)))


def _entry(n, n_single, fast, slow, agreement):
    return {"designs_per_s": fast[2], "designs_per_s_min_max": [fast[1], fast[3]], "population": n,
            "per_design_per_s": slow[2], "per_design_per_s_min_max": [slow[1], slow[3]],
            "per_design_designs": n_single, "speed_ratio": fast[2] / slow[2], "agreement": agreement}


def cams(n, n_single, repeats, rng):
    from machdyn.cams.checks import check_cam
    from machdyn.cams.followers import Follower
    from machdyn.cams.population import analyse_population
    from machdyn.cams.profile import profile
    from machdyn.cams.program import Segment, program

    def prog(lift):
        return program([Segment("rise", math.radians(120), lift, "cycloidal"), Segment("dwell", math.radians(60)),
                        Segment("return", math.radians(120), lift, "cycloidal"), Segment("dwell", math.radians(60))])

    theta = np.arange(360) * (2 * math.pi / 360)
    rb, rr = rng.uniform(0.03, 0.08, n), rng.uniform(0.005, 0.015, n)
    e, k = rng.uniform(-0.01, 0.01, n), rng.uniform(0.5, 1.5, n)
    base = prog(0.02)
    fast = _rate(lambda: analyse_population(base, theta, rb, rr, e, k), n, repeats)

    def single():
        return [check_cam(profile(prog(0.02 * k[i]), Follower("translating", "roller", rb[i], rr[i], e[i]), theta),
                          prog(0.02 * k[i])) for i in range(n_single)]

    slow = _rate(single, n_single, repeats)
    pop = fast[0]
    return _entry(n, n_single, fast, slow, max(
        _agreement(pop.max_pressure_angle[:n_single], [c.max_pressure_angle for c in slow[0]]),
        _agreement(pop.min_pitch_curvature_radius[:n_single], [c.min_pitch_radius for c in slow[0]]),
        _agreement(pop.min_base_radius_pressure[:n_single], [c.min_base_radius_pressure for c in slow[0]])))


def parts(n, n_single, repeats, rng):
    from machdyn.drivetrain.parts import BearingSpec, LinkSpec, PinSpec, size_parts
    from machdyn.drivetrain.parts_population import parts_population
    from machdyn.linkage import crank_angles, four_bar, kinetostatics
    from machdyn.studies.capability_population import population_forces

    specs = {"bearings": (BearingSpec("O", "ball", capacity=30e3, life=2e7),),
             "pins": (PinSpec("B", 0.012, 0.02, 2, allowable_shear=80e6),),
             "links": (LinkSpec("coupler", 4e-4, 2e-6, 150e6, 600e6),)}
    mech = four_bar(rng.uniform(0.03, 0.06, n), rng.uniform(0.13, 0.17, n), 0.12, 0.14, masses=(1.0, 3.0, 2.0))
    phi = crank_angles(72)

    def population():
        forces = population_forces(mech, phi, 60.0)  # the forces of every design, as the studies get them
        return parts_population(forces, **specs)["parts.utilisation.max"]

    fast = _rate(population, n, repeats)

    def single():
        return [max(c.utilisation for c in size_parts(kinetostatics(mech.take_designs(i), phi, 60.0),
                                                      **specs).checks) for i in range(n_single)]

    slow = _rate(single, n_single, repeats)
    return _entry(n, n_single, fast, slow, _agreement(fast[0][:n_single], slow[0]))


def clutch(n, n_single, repeats, rng):
    from machdyn.drivetrain.clutch import engage
    from machdyn.drivetrain.population import engage_population

    j1, j2, w1 = rng.uniform(0.5, 5.0, n), rng.uniform(0.1, 3.0, n), rng.uniform(50.0, 150.0, n)
    tc, t1, t2 = rng.uniform(100.0, 300.0, n), rng.uniform(-50.0, 50.0, n), rng.uniform(0.0, 80.0, n)
    fast = _rate(lambda: engage_population(j1, w1, j2, 0.0, tc, t1, t2), n, repeats)
    slow = _rate(lambda: [engage(j1[i], w1[i], j2[i], 0.0, tc[i], driving_torque=t1[i], load_torque=t2[i])
                          for i in range(n_single)], n_single, repeats)
    return _entry(n, n_single, fast, slow, max(
        _agreement(fast[0]["slip_time"][:n_single], [e.slip_time for e in slow[0]]),
        _agreement(fast[0]["dissipated"][:n_single], [e.dissipated for e in slow[0]])))


def shaft_balance(n, n_single, repeats, rng):
    from machdyn.shafts.balance import Plane, equivalent_in_planes, two_plane
    from machdyn.shafts.grades import GradeCheck, allocate, permissible_unbalance
    from machdyn.shafts.population import grade_population, two_plane_population
    from machdyn.shafts.rotating import Mass

    shape = (n, 4)
    m, r = rng.uniform(0.1, 5.0, shape), rng.uniform(0.01, 0.2, shape)
    a, z = rng.uniform(0.0, 2 * np.pi, shape), rng.uniform(0.0, 1.0, shape)

    def population():
        done = two_plane_population(m, r, a, z, 0.0, 1.0, 0.1, 0.1)
        grade_population(6.3, 100.0, 300.0, 0.5, 0.0, 1.0, m, r, a, z)
        return done["M.mass"]

    fast = _rate(population, n, repeats)

    def single():
        out = []
        for i in range(n_single):
            masses = [Mass(f"m{j}", m[i, j], r[i, j], a[i, j], z[i, j]) for j in range(4)]
            done = two_plane(masses, Plane("L", 0.0, 0.1), Plane("M", 1.0, 0.1))
            u_per = permissible_unbalance(6.3, 100.0, 300.0)
            ua, ub = equivalent_in_planes(masses, 0.0, 1.0)
            GradeCheck(6.3, 100.0, 300.0, u_per, allocate(u_per, 0.5, 0.0, 1.0), (abs(ua), abs(ub)), ("A", "B"))
            out.append(done.corrections[1].mass)
        return out

    slow = _rate(single, n_single, repeats)
    return _entry(n, n_single, fast, slow, _agreement(fast[0][:n_single], slow[0]))


_FOUR_BAR = """
[mechanism]
type = "four_bar"
crank = {length = "40 mm", mass = "0.5 kg"}
coupler = {length = "120 mm", mass = "2 kg"}
rocker = {length = "80 mm", mass = "1 kg"}
ground = {length = "100 mm"}

[drive]
speed = "60 rad/s"
positions = 72
"""

_OPTIMISE = """
[optimise]
population = 5
generations = 1

[[optimise.variables]]
parameter = "mechanism.coupler.mass"
lower = "0.5 kg"
upper = "3 kg"

[[optimise.variables]]
parameter = "mechanism.crank.length"
lower = "30 mm"
upper = "50 mm"

[[optimise.objectives]]
result = "{objective}"
"""


def _in_the_optimiser(text, objective, n, repeats, rng):
    """(problem, designs x, the optimiser's evaluator, rate): the optimiser's own evaluator of ``text`` with an
    ``[optimise]`` table on ``objective``, timed on n random designs (coupler mass, crank length)."""
    from machdyn.reading import load_problem
    from machdyn.studies.optimisation.study import setup

    problem = load_problem(text + _OPTIMISE.format(objective=objective))
    ev = setup(problem, problem.optimise)
    x = np.column_stack([rng.uniform(0.5, 3.0, n), rng.uniform(0.03, 0.05, n)])
    ev(x[:8])  # compile the engine's kernels once
    return problem, x, ev, _rate(lambda: ev(x)[0], n, repeats)


def balance(n, n_single, repeats, rng):
    from machdyn.balancing.general import CounterweightSlot, least_squares_counterweights
    from machdyn.balancing.methods import slots

    text = _FOUR_BAR + """
[balance]
method = "counterweights"
positions = 72

[[balance.counterweights]]
body = "crank"
radius = "50 mm"
"""
    problem, x, ev, fast = _in_the_optimiser(text, "balance.rms_force_after", n, repeats, rng)
    mech = ev.space.population(x[:n_single]).mechanism
    phi = np.linspace(0.0, 2 * np.pi, 72, endpoint=False)
    assert all(isinstance(s, CounterweightSlot) for s in slots(problem.balance))
    slow = _rate(lambda: [least_squares_counterweights(mech.take_designs(i), slots(problem.balance), phi, 60.0)
                          for i in range(n_single)], n_single, repeats)
    return _entry(n, n_single, fast, slow, _agreement(fast[0]["balance.rms_force_after"][:n_single],
                                                      [b.after.rms_force for b in slow[0]]))


def frame(n, n_single, repeats, rng):
    from machdyn.linkage import analyse
    from machdyn.vibration.study import study_frame

    text = _FOUR_BAR + """
[frame]
mass = "300 kg"
inertia = "40 kg*m^2"
com = ["0 mm", "50 mm"]
mechanism_origin = ["200 mm", "100 mm"]
orders = 6
direction = "90 deg"
band = ["1 Hz", "1000 Hz"]

[[frame.mounts]]
type = "tyre"
name = "front"
position = ["500 mm", "-300 mm"]
vertical_stiffness = "400 kN/m"
horizontal_stiffness = "250 kN/m"
vertical_damping = "1.5 kN*s/m"
horizontal_damping = "0.8 kN*s/m"

[[frame.mounts]]
type = "spring"
name = "rear"
position = ["-500 mm", "-300 mm"]
direction = "90 deg"
stiffness = "400 kN/m"
damping = "1.5 kN*s/m"

[frame.points]
centre = ["0 mm", "0 mm"]
front = ["400 mm", "100 mm"]

[frame.after]
[[frame.after.counterweights]]
body = "crank"
mass = "0.3 kg"
radius = "40 mm"
angle = "180 deg"
"""
    problem, x, ev, fast = _in_the_optimiser(text, "frame.mean_acceleration_reduction", n, repeats, rng)
    mech = ev.space.population(x[:n_single]).mechanism
    phi = np.linspace(0.0, 2 * np.pi, 72, endpoint=False)

    def single():
        out = []
        for i in range(n_single):
            one = mech.take_designs(i)
            study = study_frame(problem.frame, one, analyse(one, phi, 60.0, diagnostics=False))
            out.append(study.acceleration.mean_reduction / 100.0)  # the study's percent; the key is a fraction
        return out

    slow = _rate(single, n_single, repeats)
    return _entry(n, n_single, fast, slow, _agreement(fast[0]["frame.mean_acceleration_reduction"][:n_single],
                                                      slow[0]))


def engine_orders(n, n_single, repeats, rng):
    from machdyn.shafts.engine_population import engine_orders_population
    from machdyn.shafts.reciprocating import Cylinder
    from machdyn.shafts.reciprocating import engine_orders as one_engine

    shape = (n, 4)  # in-line fours with random crank phases, masses and rods, 72 angles, 6 orders
    cyl = {"position": np.arange(4) * 0.1, "phase": rng.uniform(0.0, 2 * np.pi, shape), "axis": np.pi / 2,
           "crank": 0.05, "rod": rng.uniform(0.15, 0.25, shape), "reciprocating_mass": rng.uniform(0.5, 2.0, shape),
           "rotating_mass": 0.8}
    fast = _rate(lambda: engine_orders_population(cyl, 300.0, 72, 6, 0.15)["primary_couple"], n, repeats)

    def single():
        out = []
        for i in range(n_single):
            cylinders = [Cylinder(f"c{j}", 0.1 * j, cyl["phase"][i, j], np.pi / 2, 0.05, cyl["rod"][i, j],
                                  cyl["reciprocating_mass"][i, j], 0.8) for j in range(4)]
            out.append(one_engine(cylinders, 300.0, 72, 6, 0.15, include_rotating=True).primary_couple)
        return out

    slow = _rate(single, n_single, repeats)
    return _entry(n, n_single, fast, slow, _agreement(fast[0][:n_single], slow[0]))


def motor_duty(n, n_single, repeats, rng):
    from machdyn.dynamics.drives import InductionMotor
    from machdyn.dynamics.duty import motor_duty as one_duty
    from machdyn.dynamics.population_duty import duty_population

    power, slip = rng.uniform(1e3, 30e3, n), rng.uniform(0.02, 0.06, n)
    ratio, eff = rng.uniform(5.0, 30.0, n), rng.uniform(0.8, 1.0, n)
    rated = power / (50 * np.pi * (1 - slip)) * ratio * eff  # the rated torque at the crank
    load = rated * rng.uniform(0.3, 1.6, n)
    fast = _rate(lambda: duty_population(load, rated, "S6", 0.4, 10.0)["load_ratio"], n, repeats)

    def single():
        return [one_duty(InductionMotor(power[i], 50 * np.pi * (1 - slip[i]), 50 * np.pi, 2.5, ratio[i], eff[i]),
                         load[i], "S6", 0.4, 10.0).load_ratio for i in range(n_single)]

    slow = _rate(single, n_single, repeats)
    return _entry(n, n_single, fast, slow, _agreement(fast[0][:n_single], slow[0]))


def field_balance(n, n_single, repeats, rng):
    from machdyn.shafts.field import TrialRun, reading, two_plane
    from machdyn.shafts.field_population import field_balance_population

    coefficients = rng.normal(size=(n, 2, 2)) + 1j * rng.normal(size=(n, 2, 2))
    v0 = np.einsum("nij,nj->ni", coefficients, rng.normal(size=(n, 2)) + 1j * rng.normal(size=(n, 2)))
    mass, angle = rng.uniform(0.05, 0.5, (n, 2)), rng.uniform(0, 2 * np.pi, (n, 2))
    runs = v0[:, None, :] + np.swapaxes(coefficients, 1, 2) * (mass * np.exp(1j * angle))[..., None]
    fast = _rate(lambda: field_balance_population(v0, runs, mass, angle), n, repeats)

    def single():
        out = []
        for i in range(n_single):
            trials = [TrialRun(k, mass[i, k], angle[i, k], tuple(reading(complex(v)) for v in runs[i, k]))
                      for k in range(2)]
            try:
                out.append(two_plane([reading(complex(v)) for v in v0[i]], trials).correction_mass[0])
            except ValueError:  # refused (a set whose trial runs act alike): NaN, as the population flags it
                out.append(np.nan)
        return out

    slow = _rate(single, n_single, repeats)
    both = np.isfinite(np.asarray(slow[0]))
    return _entry(n, n_single, fast, slow, _agreement(fast[0]["mass"][:n_single, 0][both],
                                                      np.asarray(slow[0])[both]))


def passage(n, n_single, repeats, rng):
    from machdyn.transient.closed_forms import passage_envelope
    from machdyn.transient.population import passage_envelope_population

    w, alpha, zeta = rng.uniform(20.0, 200.0, n), rng.uniform(0.5, 50.0, n), rng.uniform(0.0, 0.05, n)
    s = np.linspace(-2.0, 6.0, 64)  # the envelope at 64 times around each resonance
    fast = _rate(lambda: passage_envelope_population(s, w, alpha, zeta)[0].max(axis=1), n, repeats)
    slow = _rate(lambda: [float(np.max(passage_envelope(s, w[i], alpha[i], zeta[i]))) for i in range(n_single)],
                 n_single, repeats)
    return _entry(n, n_single, fast, slow, _agreement(fast[0][:n_single], slow[0]))


def linkage(n, n_single, repeats, rng):
    from machdyn.linkage import crank_angles, four_bar, kinetostatics
    from machdyn.studies import PopulationEvaluator

    mech = four_bar(rng.uniform(0.03, 0.06, n), rng.uniform(0.13, 0.17, n), 0.12, 0.14, masses=(1.0, 3.0, 2.0))
    phi = crank_angles(72)
    evaluator = PopulationEvaluator(phi, 60.0)
    key = "driving_torque.max_abs"
    evaluator.vectorised(mech, [key])  # compile once
    fast = _rate(lambda: evaluator.vectorised(mech, [key])[key], n, repeats)
    slow = _rate(lambda: [float(np.max(np.abs(kinetostatics(mech.take_designs(i), phi, 60.0).driving_torque)))
                          for i in range(n_single)], n_single, repeats)
    return _entry(n, n_single, fast, slow, _agreement(fast[0][:n_single], slow[0]))


def per_design_workers(n: int, repeats: int) -> dict:
    from machdyn.problem.paths import design_problem
    from machdyn.reading import load_problem
    from machdyn.runner import design_results
    from machdyn.studies.per_design import evaluate_designs

    problem = load_problem(ROOT / "examples" / "shaft_inline_four_phases_optimise.toml")
    designs = [design_problem(problem, {"cylinders[1].phase": float(p)}) for p in np.linspace(0.0, 6.0, n)]
    keys = ("shaft.engine.primary_couple",)
    evaluate_designs(design_results, designs[:4], keys, 4, workers=2)  # the pool started, as a study keeps it
    here = _rate(lambda: evaluate_designs(design_results, designs, keys, n), n, repeats)
    there = _rate(lambda: evaluate_designs(design_results, designs, keys, n, workers=2), n, repeats)
    same = bool(np.array_equal(here[0][keys[0]], there[0][keys[0]], equal_nan=True))
    return {"designs": n, "in_process_per_s": here[2], "in_process_min_max": [here[1], here[3]],
            "workers": 2, "workers_per_s": there[2], "workers_min_max": [there[1], there[3]],
            "overhead_per_design_s": 2.0 / there[2] - 1.0 / here[2], "same_results": same}


def linkage_million(n: int) -> dict:
    """In a fresh process: the studies' evaluator on ``n`` four-bar designs; designs/s and peak RSS."""
    code = f"""
import json, resource, sys, time
import numpy as np
sys.path.insert(0, {str(ROOT / "src")!r})
from machdyn.linkage import crank_angles, four_bar
from machdyn.studies import PopulationEvaluator
rng = np.random.default_rng(1)
n = {n}
evaluator = PopulationEvaluator(crank_angles(72), 60.0, engine="fused")
keys = ["driving_torque.max_abs", "transmission_angle.min"]
evaluator(four_bar(0.04, 0.15, 0.12, 0.14, masses=(1.0, 3.0, 2.0)), keys, 1)  # compiled before the timing
before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
mech = four_bar(rng.uniform(0.03, 0.06, n), rng.uniform(0.13, 0.17, n), 0.12, 0.14, masses=(1.0, 3.0, 2.0))
t0 = time.perf_counter()
out = evaluator(mech, keys, n)
seconds = time.perf_counter() - t0
print(json.dumps({{"designs": n, "designs_per_s": n / seconds, "seconds": seconds, "chunk": evaluator.chunk(),
                  "memory_budget_mb": evaluator.memory_budget / 2**20, "rss_before_mb": before,
                  "peak_rss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
                  "regular": int(out["regular"].sum())}}))
"""
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return json.loads(done.stdout.strip().splitlines()[-1])


#: capability -> (function, population size, per-design designs), full run and --quick.
CASES = {"cams": (cams, 20_000, 20, 2_000, 5), "parts": (parts, 5_000, 100, 500, 20),
         "clutch": (clutch, 200_000, 5_000, 20_000, 500), "shaft_balance": (shaft_balance, 100_000, 500, 10_000, 50),
         "balance": (balance, 20_000, 50, 2_000, 10), "frame": (frame, 20_000, 50, 2_000, 10),
         "engine_orders": (engine_orders, 50_000, 200, 5_000, 20),
         "motor_duty": (motor_duty, 1_000_000, 2_000, 100_000, 200),
         "field_balance": (field_balance, 200_000, 1_000, 20_000, 100),
         "passage": (passage, 100_000, 1_000, 10_000, 100),
         "linkage": (linkage, 20_000, 100, 2_000, 20)}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--repeats", type=int, default=None)
    args = ap.parse_args()
    repeats = args.repeats or (3 if args.quick else 5)
    found = {}
    for name, (fn, n, n_single, n_quick, n_single_quick) in CASES.items():
        rng = np.random.default_rng(1)
        found[name] = fn(n_quick if args.quick else n, n_single_quick if args.quick else n_single, repeats, rng)
        e = found[name]
        print(f"{name:14s} {e['designs_per_s']:12.4g} designs/s  per design {e['per_design_per_s']:10.4g}/s  "  # noqa: T201
              f"x{e['speed_ratio']:.4g}  agreement {e['agreement']:.2g}", flush=True)
    workers = per_design_workers(40 if args.quick else 200, repeats)
    print(f"per design     {workers['in_process_per_s']:10.4g}/s here, {workers['workers_per_s']:10.4g}/s on 2 "  # noqa: T201
          f"workers, overhead {workers['overhead_per_design_s'] * 1e3:.3g} ms per design", flush=True)
    million = linkage_million(100_000 if args.quick else 1_000_000)
    print(f"linkage 1e6    {million['designs_per_s']:12.4g} designs/s  peak RSS {million['peak_rss_mb']:.0f} MB "  # noqa: T201
          f"(chunks of {million['chunk']})", flush=True)
    print(json.dumps({"capabilities": found, "per_design_workers": workers, "linkage_1e6": million}))  # noqa: T201


if __name__ == "__main__":
    main()
