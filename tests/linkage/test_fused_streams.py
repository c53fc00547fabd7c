"""The compiled kernels reduce their force summaries with the streaming forms of the shared reductions
(:data:`machdyn.linkage.reductions.STREAMS`): each stream equals its array form of ``REDUCTIONS``, in Python and
compiled, and the fused sweep's summaries equal the NumPy sweep's on random four-bars and slider-cranks."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.linkage import crank_angles, four_bar, kinematics, slider_crank, sweep
from machdyn.linkage.averages import time_weights
from machdyn.linkage.fused_source import SUMMARY_FIELDS, SUMMARY_REDUCTIONS
from machdyn.linkage.reductions import STREAMS, compiled_streams, reduce, streamed

pytest.importorskip("numba")

# Sums of a few hundred terms of mixed sign in another order than numpy's pairwise sum: rounding of order
# 1e-15 relative to the largest term, well inside 1e-12.
RTOL = 1e-12


def _varying_speed_kinematics(rng):
    phi = crank_angles(120)
    mech = four_bar(0.04, 0.12, 0.09, 0.11)
    return kinematics(mech, phi, speed=8.0 + 3.0 * np.sin(phi + rng.uniform(0, 6)))  # the time weights vary


@pytest.mark.parametrize("how", [h for h in STREAMS if h != "max_magnitude"])
def test_each_stream_equals_its_array_reduction_in_python_and_compiled(how):
    rng = np.random.default_rng(7)
    kin = _varying_speed_kinematics(rng)
    values = rng.normal(0.0, 50.0, kin.shape) + 20.0
    weights = time_weights(kin)
    want = float(reduce(values, how, kin))
    assert streamed(values, how, weights) == pytest.approx(want, rel=RTOL, abs=0)
    step, finish = compiled_streams()[f"RS_{how}"], compiled_streams()[f"RF_{how}"]
    acc = STREAMS[how].start
    for v, w in zip(values, weights, strict=True):
        acc = step(acc, float(v), float(w))
    assert finish(acc, float(weights.sum())) == pytest.approx(want, rel=RTOL, abs=0)


def test_the_magnitude_stream_is_the_largest_magnitude():
    rng = np.random.default_rng(3)
    fx, fy = rng.normal(size=(2, 200))
    got = streamed(fx * fx + fy * fy, "max_magnitude", np.ones(200))
    assert got == pytest.approx(float(reduce(np.hypot(fx, fy), "max")), rel=RTOL, abs=0)


def test_the_kernel_declares_every_summary_by_a_shared_stream():
    assert [f for f, _, _ in SUMMARY_REDUCTIONS] == list(SUMMARY_FIELDS[2:])
    assert {how for _, how, _ in SUMMARY_REDUCTIONS} <= set(STREAMS)


def _close(got, ref):
    for field in SUMMARY_FIELDS[2:]:
        a, b = np.asarray(getattr(got, field)), np.asarray(getattr(ref, field))
        assert np.array_equal(np.isnan(a), np.isnan(b)), field
        scale = np.nanmax(np.abs(b)) if np.any(~np.isnan(b)) else 1.0  # the mean power of a cycle may be ~0
        np.testing.assert_allclose(a, b, rtol=0, atol=RTOL * scale, equal_nan=True, err_msg=field)
    for name, values in ref.max_joint_force.items():
        np.testing.assert_allclose(got.max_joint_force[name], values, rtol=RTOL, equal_nan=True, err_msg=name)


@pytest.mark.parametrize("family", ["four_bar", "slider_crank"])
def test_fused_summaries_equal_numpy_on_random_designs(family):
    rng = np.random.default_rng(11 if family == "four_bar" else 12)
    n = 40
    if family == "four_bar":  # some designs cannot turn fully: NaN in both
        mech = four_bar(rng.uniform(0.02, 0.06, n), rng.uniform(0.08, 0.2, n), rng.uniform(0.06, 0.15, n),
                        rng.uniform(0.08, 0.16, n), ground_angle=0.2)
    else:
        mech = slider_crank(rng.uniform(0.02, 0.06, n), rng.uniform(0.1, 0.25, n), offset=rng.uniform(-0.02, 0.02, n))
    phi = crank_angles(90)
    speed = 10.0 + 4.0 * np.sin(phi)  # a varying crank speed: the time weights matter
    kw = dict(shaking_about=(0.03, -0.01))
    ref = sweep(mech, phi, speed, 3.0, engine="numpy", **kw)
    assert np.count_nonzero(ref.regular) >= n // 4  # enough regular designs to compare numbers, not NaNs
    _close(sweep(mech, phi, speed, 3.0, engine="fused", **kw), ref)
