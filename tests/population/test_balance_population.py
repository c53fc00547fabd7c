"""The ``[balance]`` results of a population of linkage designs through the table's population form
(:mod:`machdyn.balancing.population`): the closed-form least-squares counterweights of every design at once equal,
design by design, a run of each design (the single-design path) to 1e-12, and the designs that cannot be balanced
(a floating counterweight of mass <= 0, a design that does not close) are flagged as the runs flag them."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.balancing.general import CounterweightSlot, least_squares_counterweights
from machdyn.balancing.population import least_squares_population
from machdyn.errors import AnalysisError
from machdyn.kinds import population_form
from machdyn.linkage import four_bar
from machdyn.reading import load_problem
from machdyn.runner import run_problem
from machdyn.studies.capability_population import population_results
from machdyn.studies.optimisation.study import setup

FILE = """
[mechanism]
type = "four_bar"
crank = {length = "40 mm", mass = "0.5 kg"}
coupler = {length = "120 mm", mass = "2 kg"}
rocker = {length = "80 mm", mass = "1 kg"}
ground = {length = "100 mm"}

[drive]
speed = "60 rad/s"
positions = 36

[balance]
method = "counterweights"
positions = 48

[[balance.counterweights]]
body = "crank"
radius = "50 mm"

[[balance.counterweights]]
body = "rocker"
radius = "40 mm"

[optimise]
population = 5
generations = 1
seed = 1

[[optimise.variables]]
parameter = "mechanism.coupler.mass"
lower = "0.5 kg"
upper = "3 kg"

[[optimise.variables]]
parameter = "mechanism.crank.length"
lower = "30 mm"
upper = "50 mm"

[[optimise.objectives]]
result = "balance.rms_force_after"
"""


def _close(a, b, scale=0.0):
    """a equals b to 1e-12 relative; of a figure balanced to zero, relative to ``scale`` (its value before): two
    counterweights balance a four-bar's force fully (Berkof & Lowen), leaving only round-off of either path."""
    return abs(a - b) <= 1e-12 * max(abs(b), scale)


def _scale(key, results):
    if key == "balance.com_travel_after":
        return 0.04  # the crank's length [m]: the travel of the centre of mass is at most of its size
    if key.endswith((".x", ".y")):
        return 0.05  # a counterweight's position: a vector of the slot's radius, one component may be 0
    return abs(results.get(key.replace("_after", "_before"), 0.0))


def test_the_optimiser_s_balance_equals_each_design_s_run():
    problem = load_problem(FILE)
    runs: list = []
    ev = setup(problem, problem.optimise, run_design=lambda design: runs.append(design) or {})
    x = np.column_stack([np.linspace(0.5, 3.0, 4), np.linspace(0.03, 0.05, 4)])
    results, _costs, _viol = ev(x)
    assert runs == []  # the population form gave every design's balance: none was run on its own
    pop = ev.space.population(x)
    for i in range(x.shape[0]):
        alone = run_problem(ev.space.problem_at(x[i]).model_copy(update={"optimise": None}))
        keys = [k for k in alone.results.values if k.startswith("balance.")]
        assert len(keys) == 18  # five figures before and after, the travel, the reduction, two counterweights
        every = population_results(problem, keys, pop.mechanism, pop.speed, pop.acceleration, x.shape[0])
        for key in keys:
            want = alone.results[key]
            assert _close(every[key][i], want, _scale(key, alone.results.values)), (key, i, every[key][i], want)
        assert results["balance.rms_force_after"][i] == every["balance.rms_force_after"][i]


@pytest.mark.parametrize("slots", [
    [CounterweightSlot("crank", 0.05), CounterweightSlot("rocker", 0.04)],  # full force balance, closed form
    [CounterweightSlot("crank", 0.05), CounterweightSlot("coupler")],  # the coupler's at its bound m >= 0
    [CounterweightSlot("crank", 0.05), CounterweightSlot("coupler", mass_bounds=(-np.inf, np.inf))],  # m < 0
], ids=["closed-form", "bound-reached", "cannot-be-built"])
def test_random_designs_equal_the_single_function_and_are_flagged_as_it_flags_them(slots):
    """Random four-bars. On the floating coupler the force-optimal counterweight has a mass < 0: within its
    bounds the single function raises AnalysisError (it cannot be built) and the population marks the design
    invalid; with the default bound m >= 0 both take scipy's bounded least squares. One design does not close."""
    rng = np.random.default_rng(3)
    n = 12
    crank = rng.uniform(0.02, 0.05, n)
    crank[5] = 0.2  # longer than the ground allows: this four-bar does not close
    mech = four_bar(crank, rng.uniform(0.10, 0.15, n), 0.12, 0.10,
                    masses=(rng.uniform(0.2, 1.0, n), rng.uniform(0.5, 3.0, n), rng.uniform(0.05, 1.5, n)))
    phi = np.linspace(0.0, 2 * np.pi, 40, endpoint=False)
    done = least_squares_population(mech, slots, phi, 30.0)
    assert not done["valid"][5]
    for i in (i for i in range(n) if i != 5):
        try:
            alone = least_squares_counterweights(mech.take_designs(i), slots, phi, 30.0)
        except AnalysisError:
            assert not done["valid"][i]
            continue
        assert done["valid"][i]
        for key in ("rms_force", "peak_force", "rms_moment", "torque_fluctuation", "peak_joint_force"):
            before = getattr(alone.before, key)
            assert _close(done["before"][key][i], before), (key, i)
            assert _close(done["after"][key][i], getattr(alone.after, key), before), (key, i)
        for p in alone.counterweights:
            mass, x, y = done["placed"][p.name]
            assert _close(mass[i], p.mass, 1e-3) and _close(x[i], p.position[0], 0.05), (p.name, i)
            assert _close(y[i], p.position[1], 0.05), (p.name, i)
    assert done["valid"].sum() == (0 if slots[1].mass_bounds[0] < 0 else n - 1)


def test_only_the_closed_form_declares_a_population_form():
    problem = load_problem(FILE)
    assert population_form("balance") is not None
    ev = setup(problem, problem.optimise)
    pop = ev.space.population(np.array([[1.0, 0.04]]))
    args = (["balance.rms_force_after"], pop.mechanism, pop.speed, pop.acceleration, 1)
    assert "balance.rms_force_after" in population_results(problem, *args)
    robust = load_problem(FILE.replace('[[balance.counterweights]]\nbody = "rocker"', '[[balance.states]]\n'
                                       'name = "slow"\nspeed = "30 rad/s"\n\n[[balance.counterweights]]\n'
                                       'body = "rocker"'))
    assert population_results(robust, *args) == {}


@pytest.mark.parametrize("speed", [20.0, np.array([20.0, 45.0])])
def test_each_design_is_balanced_at_its_own_speed(speed):
    mech = four_bar(np.array([0.03, 0.04]), 0.12, 0.1, 0.1, masses=(0.5, 2.0, 1.0))
    slots = [CounterweightSlot("crank", 0.05), CounterweightSlot("rocker", 0.04)]
    phi = np.linspace(0.0, 2 * np.pi, 24, endpoint=False)
    done = least_squares_population(mech, slots, phi, speed if np.ndim(speed) == 0 else speed[:, None])
    for i in range(2):
        s = speed if np.ndim(speed) == 0 else speed[i]
        alone = least_squares_counterweights(mech.take_designs(i), slots, phi, s)
        assert _close(done["after"]["rms_force"][i], alone.after.rms_force, alone.before.rms_force)
        assert _close(done["before"]["peak_joint_force"][i], alone.before.peak_joint_force)


def test_a_population_in_chunks_gives_the_same_results(monkeypatch):
    """The form balances a population chunk by chunk (its memory bounded for any population): the results are
    those of one pass."""
    import machdyn.balancing.population as bp

    problem = load_problem(FILE)
    ev = setup(problem, problem.optimise)
    x = np.column_stack([np.linspace(0.5, 3.0, 5), np.linspace(0.03, 0.05, 5)])
    pop = ev.space.population(x)
    keys = ["balance.rms_force_after", "balance.cw_rocker.mass", "balance.peak_joint_force_before"]
    whole = population_results(problem, keys, pop.mechanism, pop.speed, pop.acceleration, 5)
    monkeypatch.setattr(bp, "CHUNK_POSITIONS", 2 * 48)  # two designs a chunk
    for key, value in population_results(problem, keys, pop.mechanism, pop.speed, pop.acceleration, 5).items():
        np.testing.assert_array_equal(value, whole[key])
