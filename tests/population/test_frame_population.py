"""The frame on its mounts for a population (:mod:`machdyn.vibration.population`): the stacked modes of random
frames equal :func:`machdyn.vibration.modes.modes` of each, the stacked response equals
:func:`machdyn.vibration.response.steady_state`, and the ``[frame]`` results the optimiser takes from the table's
population form equal a run of each design, to 1e-12; frames the mounts do not hold, orders on an undamped mode
and designs that do not close are flagged as the single path flags them."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.errors import InputError
from machdyn.kinds import population_form
from machdyn.reading import load_problem
from machdyn.runner import run_problem
from machdyn.studies.capability_population import population_results
from machdyn.studies.optimisation.study import setup
from machdyn.vibration.frame import Frame, Mount
from machdyn.vibration.modes import check_supported, modes
from machdyn.vibration.population import (
    frame_matrices,
    modes_population,
    response_population,
    supported,
)
from machdyn.vibration.response import harmonic_loads, steady_state

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

[frame]
mass = "300 kg"
inertia = "40 kg*m^2"
com = ["0 mm", "50 mm"]
mechanism_origin = ["200 mm", "100 mm"]
mechanism_angle = "10 deg"
orders = 5
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
label = "after"

[[frame.after.counterweights]]
body = "crank"
mass = "0.3 kg"
radius = "40 mm"
angle = "180 deg"

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
result = "frame.mean_acceleration_reduction"
"""


def _random_frames(rng, n):
    mass, inertia = rng.uniform(50.0, 500.0, n), rng.uniform(5.0, 80.0, n)
    com = rng.uniform(-0.2, 0.2, (n, 2))
    positions = rng.uniform(-1.0, 1.0, (n, 3, 2))
    directions = rng.uniform(0.0, np.pi, (n, 3))
    stiffness, damping = rng.uniform(1e4, 1e6, (n, 3)), rng.uniform(0.0, 2e3, (n, 3))
    frames = [Frame(mass[i], inertia[i], tuple(Mount(f"m{j}", tuple(positions[i, j]), directions[i, j],
                                                     stiffness[i, j], damping[i, j]) for j in range(3)),
                    com=tuple(com[i])) for i in range(n)]
    return frames, frame_matrices(mass, inertia, com, positions, directions, stiffness, damping)


def test_stacked_modes_equal_each_frame_s_modes_and_unsupported_frames_are_flagged():
    rng = np.random.default_rng(7)
    frames, (m, k, c) = _random_frames(rng, 40)
    # two mounts on one line through the same point: the frame turns freely about it
    frames[3] = Frame(100.0, 10.0, (Mount("a", (0.0, 0.0), 0.0, 1e5), Mount("b", (0.0, 0.0), np.pi / 2, 1e5),
                                    Mount("c", (0.0, 0.0), np.pi / 2, 1e5)))
    m[3], k[3], c[3] = frames[3].mass_matrix(), frames[3].stiffness_matrix(), frames[3].damping_matrix()
    size = np.array([max(1.0, *(np.hypot(*mt.position) for mt in f.mounts)) for f in frames])
    held = supported(k, size)
    found = modes_population(m, k, c)
    for i, frame in enumerate(frames):
        try:
            check_supported(frame)
        except InputError:
            assert not held[i]
            continue
        assert held[i]
        np.testing.assert_allclose(m[i], frame.mass_matrix(), rtol=1e-15)
        np.testing.assert_allclose(k[i], frame.stiffness_matrix(), rtol=1e-12, atol=1e-12 * np.abs(k[i]).max())
        one = modes(frame)
        # omega^2 to 1e-12 of the largest: what any backward-stable symmetric eigensolver guarantees (each eigenvalue
        # within eps * |A| of the exact one; Golub & Van Loan, Matrix Computations, 4th ed., sec. 8.1.2, Weyl)
        w2, w2_one = found["angular_frequencies"][i] ** 2, one.angular_frequencies**2
        assert np.all(np.abs(w2 - w2_one) <= 1e-12 * w2_one.max()), i
        np.testing.assert_allclose(found["damping_ratios"][i], one.damping_ratios, rtol=1e-10,
                                   atol=1e-12 * one.damping_ratios.max())
        # shapes to 1e-12 of the largest entry of each (a mode's shape is fixed only up to its scale)
        scale = np.abs(one.shapes).max(axis=0)
        assert np.all(np.abs(found["shapes"][i] - one.shapes) <= 1e-10 * scale), i
    assert held.sum() == len(frames) - 1


def test_the_stacked_response_equals_each_frame_s_steady_state():
    rng = np.random.default_rng(8)
    frames, (m, k, c) = _random_frames(rng, 12)
    w = rng.uniform(5.0, 200.0, 12)
    q = rng.normal(size=(12, 1, 3)) + 1j * rng.normal(size=(12, 1, 3))
    done = response_population(m, k, c, w[:, None], q)
    for i, frame in enumerate(frames):
        one = steady_state(frame, harmonic_loads(w[i], *q[i, 0]))
        np.testing.assert_allclose(done["coordinates"][i], one.coordinates, rtol=1e-11)
        assert done["valid"][i]
    # an undamped frame driven at its own natural frequency: refused by the single path, flagged here
    still = Frame(100.0, 1.0, (Mount("v", (0, 0), np.pi / 2, 1e5), Mount("h", (0, 0), 0.0, 1e5),
                               Mount("t", (1, 0), np.pi / 2, 1e5), Mount("t2", (-1, 0), np.pi / 2, 1e5)))
    wn = modes(still).angular_frequencies[0]
    with pytest.raises(InputError):
        steady_state(still, harmonic_loads(wn, 1.0))
    refused = response_population(still.mass_matrix(), still.stiffness_matrix(), still.damping_matrix(),
                                  np.array([wn]), np.ones((1, 1, 3)))
    assert not refused["valid"][0]


def test_the_optimiser_s_frame_results_equal_each_design_s_run():
    problem = load_problem(FILE)
    assert population_form("frame") is not None
    runs: list = []
    ev = setup(problem, problem.optimise, run_design=lambda design: runs.append(design) or {})
    x = np.column_stack([np.linspace(0.5, 3.0, 4), np.linspace(0.03, 0.05, 4)])
    x[2, 1] = 0.2  # a crank longer than the ground allows: it does not close
    results, _costs, _viol = ev(x)
    assert runs == []  # the population form gave every design's frame: none was run on its own
    pop = ev.space.population(x)
    keys = None
    for i in (0, 1, 3):
        alone = run_problem(ev.space.problem_at(x[i]).model_copy(update={"optimise": None}))
        keys = [k for k in alone.results.values if k.startswith("frame.")]
        # 3 modes x 2, 2 points x 3 figures x 2 variants, 3 mounts x 2, 2 reductions and their mean
        assert len(keys) == 6 + 12 + 6 + 3
        every = population_results(problem, keys, pop.mechanism, pop.speed, pop.acceleration, x.shape[0])
        for key in keys:
            want = alone.results[key]
            assert abs(every[key][i] - want) <= 1e-12 * abs(want), (key, i, every[key][i], want)
        assert results["frame.mean_acceleration_reduction"][i] == every["frame.mean_acceleration_reduction"][i]
    every = population_results(problem, keys, pop.mechanism, pop.speed, pop.acceleration, x.shape[0])
    assert all(np.isnan(every[k][2]) for k in keys if not k.startswith("frame.mode_"))


def test_a_population_in_chunks_gives_the_same_results(monkeypatch):
    """The form works through a population chunk by chunk (its memory bounded for any population): the results
    are those of one pass."""
    import machdyn.vibration.population as vp

    problem = load_problem(FILE)
    ev = setup(problem, problem.optimise)
    x = np.column_stack([np.linspace(0.5, 3.0, 5), np.linspace(0.03, 0.05, 5)])
    pop = ev.space.population(x)
    keys = ["frame.mean_acceleration_reduction", "frame.rms_velocity.after.front", "frame.zone.before.centre"]
    whole = population_results(problem, keys, pop.mechanism, pop.speed, pop.acceleration, 5)
    monkeypatch.setattr(vp, "CHUNK_POSITIONS", 2 * 36)  # two designs a chunk
    for key, value in population_results(problem, keys, pop.mechanism, pop.speed, pop.acceleration, 5).items():
        np.testing.assert_array_equal(value, whole[key])
