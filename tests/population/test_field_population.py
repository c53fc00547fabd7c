"""Field balancing of many sets of readings at once (:mod:`machdyn.shafts.field_population`) equals
:func:`machdyn.shafts.field.two_plane` of each set to 1e-12, and the sets it refuses (a trial run that hardly moved
the readings, trial runs that act alike, a trial mass not > 0) are flagged."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.errors import InputError
from machdyn.shafts.field import TrialRun, reading, two_plane
from machdyn.shafts.field_population import field_balance_population


@pytest.mark.parametrize("removed", [(True, True), (False, True)])
def test_random_readings_equal_each_two_plane_balance_and_refused_sets_are_flagged(removed):
    rng = np.random.default_rng(9)
    n_sets = 40
    coefficients = rng.normal(size=(n_sets, 2, 2)) + 1j * rng.normal(size=(n_sets, 2, 2))
    coefficients[3, :, 1] = coefficients[3, :, 0] * (1 + 1e-3)  # both trial runs act alike: near singular
    unbalance = rng.normal(size=(n_sets, 2)) + 1j * rng.normal(size=(n_sets, 2))
    v0 = np.einsum("nij,nj->ni", coefficients, unbalance)
    mass, angle = rng.uniform(0.05, 0.5, (n_sets, 2)), rng.uniform(0, 2 * np.pi, (n_sets, 2))
    mass[5, 0] = 1e-6  # a trial mass too small to move the readings
    mass[6, 1] = -0.1
    w = mass * np.exp(1j * angle)
    runs = np.empty((n_sets, 2, 2), dtype=complex)
    state = v0.copy()
    for k in range(2):
        runs[:, k] = state + coefficients[:, :, k] * w[:, k, None]
        if not removed[k]:
            state = runs[:, k]
    done = field_balance_population(v0, runs, mass, angle, removed)
    refused = 0
    for i in range(n_sets):
        trials = [TrialRun(k, mass[i, k], angle[i, k], tuple(reading(complex(v)) for v in runs[i, k]), removed[k])
                  for k in range(2)]
        try:
            one = two_plane([reading(complex(v)) for v in v0[i]], trials)
        except InputError:
            assert not done["valid"][i], i
            refused += 1
            continue
        assert done["valid"][i], i
        for k in range(2):
            assert abs(done["mass"][i, k] - one.correction_mass[k]) <= 1e-12 * one.correction_mass[k], (i, k)
            assert abs(done["angle"][i, k] - one.correction_angle[k]) <= 1e-12 * 2 * np.pi, (i, k)
    assert refused >= 3  # the near-singular set, the small and the negative trial mass
