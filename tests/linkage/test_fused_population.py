"""The fused population pass against the NumPy reference of the population evaluator: every status column, every
motion result (transmission angles, strokes, time ratios, inertial shaking force and moment, the compactor's
figures) and every force summary agree, on random mechanisms of every dyad type and on populations of designs
of which some do not close, pass a dead point or change branch.

Both paths compute the same closed forms; the fused pass reduces each design in one compiled loop, the
reference with whole-array NumPy operations. They differ by rounding only, so the results agree to 1e-12
relative (the status flags exactly). A transmission angle's extremes are taken at the extremes of its
argument (arccos and arcsin are monotonic), the plate's largest angle at its smallest cosine: the same values.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from machdyn.linkage import Mechanism, PointForce, crank_angles, four_bar
from machdyn.linkage.engines import available
from machdyn.results.catalogue import find
from machdyn.results.population import evaluate_population, result_names

from .test_fused import any_family
from .test_properties import SETTINGS, mechanisms

pytestmark = pytest.mark.skipif(not available(), reason="the fused engine needs numba")
RTOL = 1e-12
ROOT = Path(__file__).resolve().parents[2]


def _wanted(mech, machine=None) -> set[str]:
    """Every result of the status, motion and forces groups (the groups the fused pass computes)."""
    return {k for k in result_names(mech, machine) if (f := find(k)) is not None and f[0].group in ("motion",
                                                                                                       "forces")}


def _same(mech, phi, speed, accel, machine=None, about=(0.3, -0.2)) -> dict[str, np.ndarray]:
    wanted = _wanted(mech, machine)
    ref = evaluate_population(mech, phi, speed, accel, wanted, about=about, machine=machine, engine="numpy")
    got = evaluate_population(mech, phi, speed, accel, wanted, about=about, machine=machine, engine="fused")
    assert list(got) == list(ref)
    for key, b in ref.items():
        a = got[key]
        if b.dtype.kind != "f":
            np.testing.assert_array_equal(a, b, err_msg=key)
            continue
        np.testing.assert_array_equal(np.isnan(a), np.isnan(b), err_msg=key)
        ok = ~np.isnan(b)
        if key == "input_power.mean":
            # the mean power of a loss-free cycle is zero up to rounding: relative to the power scale
            scale = np.abs(ref["driving_torque.max_abs"][ok]) * np.max(np.abs(speed))
        else:
            scale = np.abs(b[ok])
        assert np.all(np.abs(a[ok] - b[ok]) <= RTOL * scale + 1e-300), key
    return ref


@settings(**SETTINGS)
@given(mech=mechanisms(base=any_family()), speed=st.floats(0.5, 20.0), accel=st.floats(-50, 50))
def test_fused_population_equals_numpy_for_one_design(mech, speed, accel):
    # every dyad type (RRR, RRP on a moving guide, RPR, PRP), masses, a point mass, a spring, loads
    _same(mech, crank_angles(90), speed, accel)


@settings(max_examples=15, deadline=None)
@given(n=st.integers(1, 40), full=st.booleans(), data=st.data())
def test_fused_population_equals_numpy_over_designs(n, full, data):
    # Arrays of four-bars: crank-rockers, double-rockers that do not close everywhere, designs near a dead
    # point, a speed per design; crank angles over a full turn (limit positions, time ratios) or over part.
    draw = data.draw
    lengths = [np.array(draw(st.lists(st.floats(lo, hi), min_size=n, max_size=n)))
               for lo, hi in ((0.2, 0.9), (0.5, 2.5), (0.5, 2.5), (0.8, 2.5))]
    phi = crank_angles(72) if full else np.linspace(0.2, 2.9, 40)
    speed = np.array(draw(st.lists(st.floats(1.0, 30.0), min_size=n, max_size=n)))
    mech = four_bar(*lengths, ground_angle=0.3, masses=(1.0, 2.0, 3.0))
    mech = Mechanism(mech.name, mech.ground, mech.bodies, mech.crank, mech.dyads,
                     forces=(PointForce("f", f"{mech.moving_bodies[-1]}.B", 10.0, -5.0, active=(0.5, 2.0)),))
    _same(mech, phi, speed, 2.0)


def test_fused_population_flags_designs_that_fail():
    # one four-bar (crank, coupler, rocker, ground) of each status, found by a random search of the reference
    designs = {"regular": (0.2297, 0.8324, 0.4477, 0.7166), "does not assemble": (0.5606, 0.7322, 0.4743, 1.3933),
               "dead point": (0.5, 1.0, 0.5, 1.0), "near dead point": (0.7043, 1.4563, 1.4752, 0.7337),
               "poor transmission": (0.8096, 1.1127, 1.3034, 0.5374)}
    mech = four_bar(*(np.array(v) for v in zip(*designs.values(), strict=True)), masses=(1.0, 2.0, 3.0))
    ref = _same(mech, crank_angles(180), 10.0, 0.0)
    assert list(ref["status"]) == list(designs)


def test_fused_population_equals_numpy_for_the_compactor():
    # the seed 003 compactor's population as the optimiser builds it, bounds widened so that some designs do
    # not close or break the transmission rule: the compactor's figures over its pressing window too
    from machdyn.reading import load_problem
    from machdyn.studies.optimisation.study import setup

    problem = load_problem(ROOT / "examples" / "compactor_optimise.toml")
    ev = setup(problem, problem.optimise)
    rng = np.random.default_rng(3)
    lower, upper = ev.space.lower, ev.space.upper
    x = lower + rng.random((60, lower.size)) * (upper - lower) * np.array([3.0, 1.0, 1.5, 1.0])
    pop = ev.space.population(x)
    ref = _same(pop.mechanism, crank_angles(360), pop.speed, pop.acceleration, machine="compactor")
    assert ref["regular"].any() and not ref["regular"].all()
    assert np.isfinite(ref["compactor.force_gain.min"][ref["regular"]]).all()
    assert math.isfinite(float(np.nanmax(ref["compactor.plate_angle.max"])))
