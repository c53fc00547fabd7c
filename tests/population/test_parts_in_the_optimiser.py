"""The optimiser reaches the ``[parts]`` results of a linkage file through the table's population form: for a
population of designs they equal, design by design, the runs of each design (the per-design path) to 1e-12."""

from __future__ import annotations

import numpy as np

from machdyn.kinds import population_form
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

[[loads.torques]]
body = "rocker"
torque = "-5 N*m"

[[parts.bearings]]
joint = "O"
kind = "ball"
capacity = "20 kN"
life = "20000 h"

[[parts.pins]]
joint = "B"
diameter = "10 mm"
length = "15 mm"
allowable_shear = "80 MPa"

[[parts.links]]
body = "coupler"
area = "200 mm^2"
section_modulus = "500 mm^3"
endurance_limit = "150 MPa"
ultimate_strength = "600 MPa"

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
result = "parts.utilisation.max"

[[optimise.constraints]]
result = "joint.B.max_force"
max = "5 kN"
"""


def test_the_parts_table_declares_its_population_form():
    assert population_form("parts") is not None and population_form("flywheel") is None


def test_the_optimiser_s_parts_results_equal_each_design_s_run():
    problem = load_problem(FILE)
    runs: list = []
    ev = setup(problem, problem.optimise, run_design=lambda design: runs.append(design) or {})
    x = np.column_stack([np.linspace(0.5, 3.0, 4), np.linspace(0.03, 0.05, 4)])
    results, _costs, _viol = ev(x)
    assert runs == []  # no design was run: the population form gave every design's parts
    pop = ev.space.population(x)
    for i in range(x.shape[0]):
        alone = run_problem(ev.space.problem_at(x[i]).model_copy(update={"optimise": None}))
        keys = [k for k in alone.results.values if k.startswith("parts.")]
        assert len(keys) == 4  # the bearing's life, the pin's shear, the link's safety factor, the largest use
        every = population_results(problem, keys, pop.mechanism, pop.speed, pop.acceleration, x.shape[0])
        for key in keys:
            assert abs(every[key][i] - alone.results[key]) <= 1e-12 * abs(alone.results[key]), (key, i)
        assert results["parts.utilisation.max"][i] == every["parts.utilisation.max"][i]


def test_a_parts_table_the_designs_change_and_a_flywheel_leave_the_parts_to_each_design_s_run():
    """Varied parts differ from design to design, and with a [flywheel] the parts take each design's real speed:
    no population form stands in for the runs then."""
    problem = load_problem(FILE)
    ev = setup(problem, problem.optimise)
    pop = ev.space.population(np.array([[1.0, 0.04], [2.0, 0.045]]))
    args = (["parts.utilisation.max"], pop.mechanism, pop.speed, pop.acceleration, 2)
    assert "parts.utilisation.max" in population_results(problem, *args)
    assert population_results(problem, *args, varied=("parts.pins.0.diameter",)) == {}
    with_flywheel = load_problem(FILE.replace("[optimise]", "[flywheel]\ndelta = 0.05\n\n[optimise]"))
    assert population_results(with_flywheel, *args) == {}


def test_a_sweep_s_parts_column_is_each_variant_s_run():
    """A [sweep] of the coupler's mass with the parts' largest utilisation as a column: computed at once by the
    population form, equal to each variant's own run."""
    from machdyn.studies.sweep.population import run_sweep

    text = FILE.split("[optimise]")[0] + (
        '[sweep]\nparameter = "mechanism.coupler.mass"\nvalues = ["0.5 kg", "2 kg", "3 kg"]\n'
        'columns = ["parts.utilisation.max"]\n')
    runs: list = []
    done = run_sweep(load_problem(text), run_design=lambda design: runs.append(design) or {})
    assert runs == []
    for i, mass in enumerate(("0.5 kg", "2 kg", "3 kg")):
        alone = run_problem(FILE.split("[optimise]")[0].replace('"2 kg"', f'"{mass}"', 1))
        want = alone.results["parts.utilisation.max"]
        assert abs(done.columns["parts.utilisation.max"][i] - want) <= 1e-12 * want
