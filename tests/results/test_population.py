"""The population evaluator, design by design."""

from __future__ import annotations

import numpy as np


def test_a_massless_design_does_not_zero_the_inertial_force_of_the_others():
    """The inertial shaking force -sum m a is computed per design: a massless (statics) design among massive ones
    has none, the others keep theirs, and the NumPy and compiled paths agree."""
    from machdyn.linkage import builders, crank_angles
    from machdyn.results.population import evaluate_population

    mass = np.array([0.0, 0.5])
    mech = builders.four_bar(0.04, 0.12, 0.08, np.array([0.1, 0.1]), masses=(mass, mass, mass), linear_density=0.0)
    alone = builders.four_bar(0.04, 0.12, 0.08, 0.1, masses=(0.5, 0.5, 0.5), linear_density=0.0)
    key = "inertial_shaking_force.max"
    expected = evaluate_population(alone, crank_angles(72), 20.0, 0.0, [key], engine="numpy")[key]
    assert expected[0] > 1.0
    for engine in ("numpy", "fused"):
        got = evaluate_population(mech, crank_angles(72), 20.0, 0.0, [key], engine=engine)[key]
        np.testing.assert_allclose(got, [0.0, expected[0]], rtol=1e-12, atol=0.0)
