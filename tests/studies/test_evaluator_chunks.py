"""A population larger than the evaluator's memory budget is evaluated chunk of designs by chunk: the results
equal the unchunked call's, design for design, and the working memory (traced by tracemalloc, beyond the
population's own model and results) stays under the budget while the unchunked call's does not."""

from __future__ import annotations

import tracemalloc

import numpy as np
import pytest

from machdyn.linkage import crank_angles, four_bar
from machdyn.studies import PopulationEvaluator

KEYS = ("driving_torque.max_abs", "transmission_angle.min", "frame_force.max", "stroke.rocker")
BUDGET = 2 * 2**20  # bytes
DESIGNS = 1500


@pytest.fixture(scope="module")
def population():
    rng = np.random.default_rng(7)
    # Some designs do not close (a crank near the coupler's and rocker's reach): they must be flagged alike.
    return four_bar(rng.uniform(0.03, 0.09, DESIGNS), rng.uniform(0.11, 0.17, DESIGNS), 0.12, 0.14,
                    masses=(1.0, 3.0, 2.0))


def _evaluate(evaluator, mech):
    tracemalloc.start()
    try:
        before = tracemalloc.get_traced_memory()[0]
        tracemalloc.reset_peak()
        out = evaluator(mech, KEYS, DESIGNS)
        peak = tracemalloc.get_traced_memory()[1] - before
    finally:
        tracemalloc.stop()
    results = sum(v.nbytes for v in out.values())
    return out, peak - results


@pytest.mark.parametrize("engine", ["numpy", "auto"])
def test_chunks_give_the_unchunked_results_within_the_memory_budget(population, engine):
    phi = crank_angles(36)
    speed = np.linspace(8.0, 12.0, DESIGNS)  # one drive speed per design: sliced with its designs
    chunked = PopulationEvaluator(phi, speed, engine=engine, memory_budget=BUDGET)
    whole = PopulationEvaluator(phi, speed, engine=engine, memory_budget=2**40)
    assert 5 <= DESIGNS // chunked.chunk() and whole.chunk() >= DESIGNS
    warm = PopulationEvaluator(phi, 10.0, engine=engine)
    warm(population.take_designs(slice(0, 2)), KEYS, 2)  # compiled (and its caches filled) before tracing
    got, working = _evaluate(chunked, population)
    want, working_whole = _evaluate(whole, population)
    assert set(got) == set(want)
    for key, value in want.items():
        if value.dtype.kind == "f":
            np.testing.assert_array_equal(got[key], value, err_msg=key)  # NaN where the other has NaN
        else:
            assert (got[key] == value).all(), key
    assert 0 < got["regular"].sum() < DESIGNS  # both regular and degenerate designs in the population
    assert working < BUDGET, f"chunked working memory {working / 2**20:.2f} MiB"
    if engine == "numpy":  # the NumPy path holds designs x positions: the budget is what bounds it
        assert working_whole > BUDGET
