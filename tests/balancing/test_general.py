"""General counterweights: the closed-form least squares against a brute-force optimiser, bounded objectives."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from machdyn.balancing.frame import cycle, frame_loads
from machdyn.balancing.general import (
    CounterweightSlot,
    Weights,
    force_model,
    least_squares_counterweights,
    optimise_counterweights,
    pivot_point,
)
from machdyn.errors import InputError


def test_force_model_is_linear_and_exact(fourbar):
    # F(x) = F0 + A x must equal the engine's shaking force with the counterweights attached
    phi = cycle(48)
    slots = [CounterweightSlot("crank", radius=0.05), CounterweightSlot("coupler")]
    lin = force_model(fourbar, slots, phi, 15.0)
    assert lin.unknowns == ("cw_crank.mu", "cw_crank.mv", "cw_coupler.m", "cw_coupler.mu", "cw_coupler.mv")
    from dataclasses import replace

    from machdyn.linkage import PointMass

    x = np.array([0.02, -0.01, 0.7, 0.05, -0.03])  # coupler: m = 0.7 kg at (0.05, -0.03)/0.7 from A
    mech = replace(fourbar, point_masses=(
        PointMass("c1", "crank", 1.0, (0.02, -0.01)),
        PointMass("c2", "coupler", 0.7, (0.05 / 0.7, -0.03 / 0.7)),
    ))
    loads = frame_loads(mech, phi, 15.0)
    assert np.allclose(lin.f0 + lin.matrix @ x, np.concatenate([loads.fx, loads.fy]), rtol=0, atol=1e-9)


def test_least_squares_matches_brute_force(engine):
    from scipy.optimize import brute

    phi = cycle(72)
    ls = least_squares_counterweights(engine, [CounterweightSlot("crank", radius=0.05)], phi, 40.0)
    cw = ls.counterweights[0]
    lin = force_model(engine, [CounterweightSlot("crank", radius=0.05)], phi, 40.0)

    def ms(first):
        r = lin.f0 + lin.matrix @ first
        return float(r @ r)

    # a brute-force grid + Nelder-Mead polish over the first moment (mu, mv) of the counterweight [kg m]
    best = brute(ms, ((-0.2, 0.0), (-0.05, 0.05)), Ns=41, full_output=False)
    assert cw.mass * np.asarray(cw.position) == pytest.approx(best, abs=1e-6)
    assert ls.after.rms_force <= np.sqrt(ms(best) / phi.size) * (1 + 1e-9)


def test_bounded_optimisation_respects_bounds_and_reports(fourbar):
    slots = [CounterweightSlot("crank", mass_bounds=(0, 1.0), radius_bounds=(0, 0.05)),
             CounterweightSlot("rocker", mass_bounds=(0, 1.0), radius_bounds=(0, 0.05))]
    result = optimise_counterweights(fourbar, slots, Weights(force=1.0, moment=0.5), cycle(36), 20.0)
    for p in result.counterweights:
        assert 0 <= p.mass <= 1.0 + 1e-12
        pivot = np.asarray(fourbar.body(p.body).points[pivot_point(fourbar, p.body)])
        assert np.hypot(*(np.asarray(p.position) - pivot)) <= 0.05 + 1e-12
    assert "converged" in result.notes[0]
    before = 1.0 + 0.5
    after = (result.after.rms_force / result.before.rms_force
             + 0.5 * result.after.rms_moment / result.before.rms_moment)
    assert after < before


def test_non_convergence_is_reported(fourbar):
    result = optimise_counterweights(fourbar, [CounterweightSlot("crank", radius_bounds=(0, 0.1))],
                                     Weights(force=1.0, torque=1.0, measure="peak"), cycle(24), 20.0,
                                     max_iterations=1)
    assert "did not converge" in result.notes[0]


def test_bad_input(fourbar):
    with pytest.raises(InputError, match="radius"):
        least_squares_counterweights(fourbar, [CounterweightSlot("crank")])
    with pytest.raises(InputError, match="weights"):
        optimise_counterweights(fourbar, [CounterweightSlot("crank")], Weights(force=0.0))
    with pytest.raises(InputError, match="measure"):
        optimise_counterweights(fourbar, [CounterweightSlot("crank")], Weights(measure="max"))
    with pytest.raises(InputError, match="mass_bounds"):
        optimise_counterweights(fourbar, [CounterweightSlot("crank", mass_bounds=(2.0, 1.0))])
    with pytest.raises(InputError, match="no body"):
        least_squares_counterweights(fourbar, [CounterweightSlot("flywheel", radius=0.1)])


@settings(max_examples=15, deadline=None)
@given(mx=st.floats(-0.05, 0.05), my=st.floats(-0.05, 0.05), speed=st.floats(1.0, 100.0))
def test_property_least_squares_residual_is_orthogonal_to_every_counterweight(mx, my, speed):
    # the normal equations: at the optimum no counterweight direction can lower the mean square force
    from dataclasses import replace

    from machdyn.linkage import PointMass, four_bar

    fourbar = four_bar(0.1, 0.35, 0.3, 0.4, masses=(1.0, 2.0, 1.5), coms=((0.05, 0.01), (0.15, 0.04), (0.12, -0.02)),
                       gravity=(0.0, 0.0))
    mech = replace(fourbar, point_masses=(PointMass("lump", "coupler", 0.5, (mx + 0.1, my)),))
    phi = cycle(36)
    slots = [CounterweightSlot("crank", radius=0.05)]  # one counterweight: a residual force is left
    result = least_squares_counterweights(mech, slots, phi, speed)
    assert result.after.rms_force > 1e-3 * result.before.rms_force
    lin = force_model(mech, slots, phi, speed)
    residual = np.concatenate([result.after.fx, result.after.fy])
    assert np.max(np.abs(lin.matrix.T @ residual)) <= 1e-9 * np.linalg.norm(lin.matrix) * np.linalg.norm(lin.f0)
