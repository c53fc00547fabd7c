"""The exact flywheel of every design of a population (machdyn.dynamics.population_flywheel) against the single
run's energy-mass sizing (machdyn.dynamics.flywheel.size_flywheel on the equivalent machine), and the energy
curves of the fused population pass against machdyn.linkage.energy.

The population formula integrates the sampled reduced moment by the trapezoidal rule and searches the extremes
on the samples; the single run integrates cubic pieces through exact values and slopes on a fine grid. Their
difference is the sampling error: O(h^2) for smooth loads, O(h) near a load that switches on and off (the
compactor's pressing force, 220..260 deg), so it must fall as the crank step falls, and stays below 0.5 % at
1 deg steps for the compactor (measured 0.17 %).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from machdyn.dynamics.equivalent import equivalent_machine
from machdyn.dynamics.flywheel import size_flywheel
from machdyn.dynamics.population_flywheel import exact_flywheel_inertia
from machdyn.errors import InputError
from machdyn.linkage import crank_angles, energy, four_bar
from machdyn.linkage.engines import available

ROOT = Path(__file__).resolve().parents[2]


def _compactor():
    from machdyn.problem.build import build_mechanism
    from machdyn.reading import load_problem

    return build_mechanism(load_problem(ROOT / "examples" / "compactor_optimise.toml"))


def _population_flywheel(mech, positions, speed, delta):
    phi = crank_angles(positions)
    e = energy(mech, phi, speed)
    return exact_flywheel_inertia(phi, e.reduced_moment, e.reduced_inertia, speed, delta)


def test_population_flywheel_converges_to_the_single_run():
    mech = _compactor()
    exact = size_flywheel(equivalent_machine(mech, 720), 10.0, 0.05).exact
    errors = [abs(_population_flywheel(mech, m, 10.0, 0.05)[0] / exact[0] - 1.0) for m in (180, 360, 720)]
    assert errors[1] < 5e-3
    assert errors[2] < errors[1] < errors[0]


def test_population_flywheel_of_many_designs_equals_each_alone():
    # a four-bar population with a load: each design's flywheel is that of the design analysed alone
    cranks = np.array([0.03, 0.04, 0.05])
    mech = four_bar(cranks, 0.12, 0.08, 0.10, masses=(1.0, 2.0, 3.0))
    together = _population_flywheel(mech, 360, 20.0, 0.02)
    for i, crank in enumerate(cranks):
        alone = _population_flywheel(four_bar(float(crank), 0.12, 0.08, 0.10, masses=(1.0, 2.0, 3.0)), 360, 20.0,
                                     0.02)
        np.testing.assert_allclose(together[i], alone[0], rtol=1e-12)
        single = size_flywheel(equivalent_machine(four_bar(float(crank), 0.12, 0.08, 0.10, masses=(1.0, 2.0, 3.0)),
                                                  720), 20.0, 0.02).exact[0]
        assert abs(together[i] / single - 1.0) < 1e-3  # smooth curves: O(h^2) at 1 deg steps


def test_population_flywheel_rejects_bad_input():
    phi = crank_angles(36)
    with pytest.raises(InputError, match="delta"):
        exact_flywheel_inertia(phi, np.sin(phi), 1.0 + 0 * phi, 10.0, 1.5)
    with pytest.raises(InputError, match="mean speed"):
        exact_flywheel_inertia(phi, np.sin(phi), 1.0 + 0 * phi, -1.0, 0.1)


@pytest.mark.skipif(not available(), reason="the fused engine needs numba")
def test_fused_energy_curves_equal_the_energy_analysis():
    # J = 2 T / omega^2 and M = (dT/dt) / omega - driving torque (the power balance) from the fused pass equal
    # machdyn.linkage.energy's reduced inertia and reduced moment (computed from the load powers)
    from machdyn.linkage.fused_population import run_population

    mech = _compactor()
    phi = crank_angles(360)
    curves = run_population(mech, phi, 10.0, 0.0, designs=1, forces=True, energy=True).energy
    assert curves is not None
    e = energy(mech, phi, 10.0)
    np.testing.assert_allclose(curves[0][0], e.reduced_inertia, rtol=1e-12)
    scale = np.max(np.abs(e.reduced_moment))
    assert np.max(np.abs(curves[1][0] - e.reduced_moment)) <= 1e-11 * scale
