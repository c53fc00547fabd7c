"""The fused engine against the NumPy engine (the reference) on random assemblable mechanisms of every dyad
type: motion, joint reactions, driving torque, frame loads and sweep summaries agree to 1e-12 relative.

Both engines evaluate the same closed forms in the same order, so they differ by rounding only (a few units
in the last place of the largest term); each quantity is compared relative to its peak over the positions,
since a value that passes through zero has no relative precision of its own. The mechanisms come from the
generators of test_properties (four-bars, inverted slider-cranks, six-bars) plus a family with a PRP group and
an RRP group on a moving guide, each with random masses, a point mass, a spring, a point force and a body
torque. Few topologies, so that compilation stays a few seconds (cached on disk after).
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from machdyn.errors import InputError
from machdyn.linkage import (
    PRP,
    RRP,
    Body,
    Guide,
    Mechanism,
    PointForce,
    crank_angles,
    four_bar,
    kinematics,
    kinetostatics,
    sweep,
)
from machdyn.linkage.engines import available
from machdyn.linkage.motion import singular

from .test_properties import SETTINGS, base_mechanisms, good_angles, mechanisms

pytestmark = pytest.mark.skipif(not available(), reason="the fused engine needs numba")
RTOL = 1e-12


@st.composite
def guided(draw):
    """A crank-rocker four-bar carrying an RRP group whose guide is the rocker's axis (moving guide, Coriolis
    terms) and a PRP group between a ground line and the coupler's axis."""
    a = draw(st.floats(0.03, 0.05))
    base = four_bar(a, draw(st.floats(0.11, 0.13)), draw(st.floats(0.07, 0.09)), 0.10,
                    branch=draw(st.sampled_from([1, -1])))
    bodies = base.bodies + (
        Body("arm", {"E": (0.0, 0.0), "K": (draw(st.floats(0.11, 0.13)), 0.0)}),
        Body("runner", {"K": (0.0, 0.0)}),
        Body("cross", {"Q": (0.0, 0.0)}),
        Body("shoe", {"Q": (0.0, 0.0)}),
    )
    ground = dict(base.ground, E=(0.10, draw(st.floats(0.14, 0.16))), F=(0.0, draw(st.floats(0.25, 0.35))))
    dyads = base.dyads + (
        RRP("arm", "runner", "ground.E", "K", Guide("rocker.D", 0.0), branch=draw(st.sampled_from([1, -1]))),
        PRP("cross", "shoe", "Q", Guide("ground.F", draw(st.floats(-0.2, 0.2))), Guide("coupler.A", 0.0)),
    )
    return Mechanism("guided", ground, bodies, base.crank, dyads)


def any_family():
    # between them every dyad type, a chain of two RRR groups (six-bar) and guides fixed in moving bodies;
    # few topologies, since each costs one compilation the first time
    return st.one_of(base_mechanisms(kinds=("inverted", "six_bar")), guided())


def _finite_pairs(fused, reference, what):
    """Both as arrays, NaN at the same places (an indeterminate position: coincident pins), then the rest."""
    fused, reference = np.asarray(fused, dtype=float), np.asarray(reference, dtype=float)
    np.testing.assert_array_equal(np.isnan(fused), np.isnan(reference), err_msg=what)
    keep = ~np.isnan(reference)
    return fused[keep], reference[keep]


def _close_angle(fused, reference, what):
    # the same angle may come out as pi in one engine and -pi in the other: compare modulo a turn
    fused, reference = _finite_pairs(fused, reference, what)
    d = np.angle(np.exp(1j * (fused - reference)))
    assert d.size == 0 or np.max(np.abs(d)) <= RTOL * np.pi, what


def _close(fused, reference, what):
    fused, reference = _finite_pairs(fused, reference, what)
    if reference.size:
        scale = max(float(np.max(np.abs(reference))), 1e-300)
        assert np.max(np.abs(fused - reference)) <= RTOL * scale, what


@settings(**SETTINGS)
@given(mech=mechanisms(base=any_family()), speed=st.floats(0.5, 20.0), accel=st.floats(-50, 50))
def test_fused_kinetostatics_equals_numpy(mech, speed, accel):
    phi = good_angles(mech)
    ref = kinetostatics(mech, phi, speed, accel)
    got = kinetostatics(mech, phi, speed, accel, engine="fused")
    for name in mech.moving_bodies:
        a, b = got.kinematics.body(name), ref.kinematics.body(name)
        for field in ("x", "y", "vx", "vy", "ax", "ay", "omega", "alpha", "cos", "sin"):
            _close(getattr(a, field), getattr(b, field), f"{name}.{field}")
        _close_angle(a.angle, b.angle, f"{name}.angle")
    for body, slide in ref.kinematics.slides.items():
        for field in ("s", "v", "a"):
            _close(getattr(got.kinematics.slide(body), field), getattr(slide, field), f"slide {body}.{field}")
    for i, (ra, rb) in enumerate(zip(got.kinematics.dyad_reports, ref.kinematics.dyad_reports, strict=True)):
        _close(ra.det, np.broadcast_to(rb.det, np.shape(ra.det)), f"determinant of dyad {i + 1}")
    assert [j.name for j in got.joints] == [j.name for j in ref.joints]
    for j in ref.joints:
        a, b = got.joint(j.name), ref.joint(j.name)
        for field in ("fx", "fy", "normal", "couple"):
            if getattr(b, field) is None:
                assert getattr(a, field) is None
            else:
                _close(getattr(a, field), getattr(b, field), f"joint {j.name}.{field}")
    _close(got.driving_torque, ref.driving_torque, "driving torque")
    _close(got.shaking_moment((0.3, -0.2)), ref.shaking_moment((0.3, -0.2)), "shaking moment")
    for a, b in zip(got.frame_force, ref.frame_force, strict=True):
        _close(a, b, "frame force")


@settings(max_examples=10, deadline=None)
@given(mech=mechanisms(base=base_mechanisms(kinds=("four_bar",)), loads=False), speed=st.floats(0.5, 20.0),
       accel=st.floats(-50, 50))
def test_fused_kinematics_equals_numpy(mech, speed, accel):
    # kinematics alone (the vectorised motion kernel), unassembled positions masked alike
    phi = crank_angles(180)
    ref = kinematics(mech, phi, speed, accel, on_fail="mask")
    got = kinematics(mech, phi, speed, accel, on_fail="mask", engine="fused")
    np.testing.assert_array_equal(got.assembled, ref.assembled)
    np.testing.assert_array_equal(singular(got.dyad_reports, phi.shape), singular(ref.dyad_reports, phi.shape))
    ok = ref.assembled & ~singular(ref.dyad_reports, phi.shape)  # dead positions: unbounded in both
    for name in mech.moving_bodies:
        for field in ("x", "y", "vx", "vy", "ax", "ay", "angle", "omega", "alpha"):
            a = np.broadcast_to(getattr(got.body(name), field), phi.shape)[ok]
            b = np.broadcast_to(getattr(ref.body(name), field), phi.shape)[ok]
            if b.size:
                (_close_angle if field == "angle" else _close)(a, b, f"{name}.{field}")


def _summaries_close(got, ref):
    np.testing.assert_array_equal(got.assembled, ref.assembled)
    np.testing.assert_array_equal(got.regular, ref.regular)
    for field in ("max_driving_torque", "rms_driving_torque", "max_shaking_force", "max_shaking_moment"):
        a, b = getattr(got, field), getattr(ref, field)
        np.testing.assert_array_equal(np.isnan(a), np.isnan(b))
        ok = ~np.isnan(b)
        np.testing.assert_allclose(a[ok], b[ok], rtol=RTOL, atol=0, err_msg=field)
    # The mean input power of a loss-free cycle is zero up to rounding: compared relative to the power scale
    scale = np.nan_to_num(ref.max_driving_torque) * 20.0
    ok = ~np.isnan(ref.mean_input_power)
    assert np.all(np.abs(got.mean_input_power - ref.mean_input_power)[ok] <= 1e-12 * scale[ok] + 1e-300)
    for name, values in ref.max_joint_force.items():
        ok = ~np.isnan(values)
        np.testing.assert_allclose(got.max_joint_force[name][ok], values[ok], rtol=RTOL, atol=0, err_msg=name)


@settings(**SETTINGS)
@given(mech=mechanisms(base=st.one_of(base_mechanisms(kinds=("inverted",)), guided())), speed=st.floats(0.5, 20.0))
def test_fused_sweep_equals_numpy_for_one_design(mech, speed):
    # Crank angles over a revolution, assembled or not: designs that fail somewhere are flagged in both. Two
    # families between them hold every dyad type (the summaries' code is common to all).
    phi = crank_angles(90)
    _summaries_close(sweep(mech, phi, speed, engine="fused"), sweep(mech, phi, speed, engine="numpy"))


@settings(max_examples=15, deadline=None)
@given(n=st.integers(1, 40), data=st.data())
def test_fused_sweep_equals_numpy_over_designs(n, data):
    # Arrays of designs, some of which cannot assemble, a speed per design, and a varying crank speed law.
    draw = data.draw
    lengths = [np.array(draw(st.lists(st.floats(lo, hi), min_size=n, max_size=n)))
               for lo, hi in ((0.2, 0.6), (0.5, 2.5), (0.5, 2.5), (0.8, 2.5))]
    phi = crank_angles(72)
    speed = np.array(draw(st.lists(st.floats(1.0, 30.0), min_size=n, max_size=n)))
    for mech, w in ((four_bar(*lengths, ground_angle=0.3), speed),
                    (four_bar(*lengths, ground_angle=0.3), 5.0 + np.sin(phi))):
        mech = Mechanism(mech.name, mech.ground, mech.bodies, mech.crank, mech.dyads,
                         forces=(PointForce("f", f"{mech.moving_bodies[-1]}.B", 10.0, -5.0, active=(0.5, 2.0)),))
        chunk = 9 * phi.size  # several chunks, and progress reported after each
        seen: list[tuple[int, int]] = []
        got = sweep(mech, phi, w, 2.0, engine="fused", chunk_positions=chunk,
                    progress=lambda done, total, seen=seen: seen.append((done, total)))
        _summaries_close(got, sweep(mech, phi, w, 2.0, engine="numpy", chunk_positions=chunk))
        assert seen[-1] == (n, n)


def test_auto_engine_and_errors():
    mech = four_bar(0.04, 0.12, 0.08, 0.10)
    phi = crank_angles(36)
    with pytest.raises(InputError, match="engine"):
        sweep(mech, phi, engine="gpu")
    with pytest.raises(InputError, match="1-D"):
        kinematics(mech, 0.3, engine="fused")
    # a load that depends on design and crank angle at once cannot be compiled: 'fused' refuses, 'auto' does
    # the work with NumPy
    both = PointForce("f", "rocker.B", lambda p: np.outer(np.ones(3), p), 0.0)
    many = four_bar(np.array([0.04, 0.041, 0.042]), 0.12, 0.08, 0.10)
    many = Mechanism(many.name, many.ground, many.bodies, many.crank, many.dyads, forces=(both,))
    with pytest.raises(InputError, match="cannot compile"):
        sweep(many, phi, engine="fused")
    assert sweep(many, phi, engine="auto").regular.all()
