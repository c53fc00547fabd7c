"""Mass substitution: each form reproduces what it claims (force, moment) and drops what it says it drops."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from machdyn.balancing.frame import frame_loads
from machdyn.balancing.substitution import (
    compare_substitute,
    complex_point_masses,
    complex_two_point,
    dynamic_two_point,
    static_two_point,
    substituted_model,
    two_point_masses,
)
from machdyn.errors import InputError
from machdyn.linkage import four_bar
from machdyn.machines import tamper

PHI = np.linspace(0.0, 2.0 * np.pi, 73)


def test_static_keeps_force_not_moment(engine):
    sub = static_two_point(engine.body("rod"), "A", "B")
    check = compare_substitute(engine, sub, PHI, speed=30.0, acceleration=5.0)
    assert check.force_error < 1e-10 * check.force_scale
    # rod: m a b = 2 * 0.06 * 0.14 = 0.0168 kg m^2 vs I = 0.012: the moment must differ
    assert sub.inertia_error == pytest.approx(2.0 * 0.06 * 0.14 - 0.012, rel=1e-12)
    assert check.moment_error > 1e-3 * check.moment_scale
    assert "inertia moment" in sub.drops


def test_dynamic_keeps_force_and_moment(engine):
    sub = dynamic_two_point(engine.body("rod"), "A")
    check = compare_substitute(engine, sub, PHI, speed=30.0, acceleration=5.0)
    assert check.force_error < 1e-10 * check.force_scale
    assert check.moment_error < 1e-10 * check.moment_scale
    assert sub.inertia_error == pytest.approx(0.0, abs=1e-15)
    assert sum(sub.masses) == pytest.approx(2.0)


def test_substituted_engine_models_reproduce_the_frame_loads(engine):
    real = frame_loads(engine, PHI, 30.0)
    static = frame_loads(substituted_model(engine, static_two_point(engine.body("rod"), "A", "B")), PHI, 30.0)
    dynamic = frame_loads(substituted_model(engine, dynamic_two_point(engine.body("rod"), "A")), PHI, 30.0)
    scale_f, scale_m = np.max(real.force), np.max(np.abs(real.moment))
    assert np.max(np.hypot(static.fx - real.fx, static.fy - real.fy)) < 1e-9 * scale_f
    assert np.max(np.abs(static.moment - real.moment)) > 1e-3 * scale_m  # static drops the inertia moment
    assert np.max(np.hypot(dynamic.fx - real.fx, dynamic.fy - real.fy)) < 1e-9 * scale_f
    assert np.max(np.abs(dynamic.moment - real.moment)) < 1e-9 * scale_m
    assert np.max(np.abs(dynamic.torque - real.torque)) < 1e-9 * np.max(np.abs(real.torque))


def test_complex_form_is_seed000_eq14_corrected_and_keeps_the_force(fourbar):
    coupler = fourbar.body("coupler")
    sub = complex_two_point(coupler, "A", "B")
    m_e, m_b = tamper.complex_mass_substitution(2.0, 0.35, 0.15, 0.04)
    assert sub.masses == pytest.approx((complex(m_e), complex(m_b)), rel=1e-14)
    assert sum(sub.masses) == pytest.approx(2.0)
    check = compare_substitute(fourbar, sub, PHI, speed=12.0)
    assert check.force_error < 1e-10 * check.force_scale
    assert check.moment_error is None and sub.inertia_error is None
    # the printed eq 14 breaks eq 11 (sum of masses) by 2 m (p + i q) / l
    printed = tamper.complex_mass_substitution_printed(2.0, 0.35, 0.15, 0.04)
    assert abs(sum(printed) - 2.0) == pytest.approx(abs(2 * 2.0 * complex(0.15, 0.04) / 0.35))
    with pytest.raises(InputError, match="no real point masses"):
        substituted_model(fourbar, sub)


def test_static_needs_the_centre_on_the_line(fourbar):
    with pytest.raises(InputError, match="off the line"):
        static_two_point(fourbar.body("coupler"), "A", "B")


def test_formula_functions_and_bad_input():
    assert two_point_masses(10.0, 0.3, 0.1) == pytest.approx((2.5, 7.5))
    assert sum(complex_point_masses(5.0, 1.0, 0.3, -0.2)) == pytest.approx(5.0)
    with pytest.raises(InputError, match="distance a"):
        two_point_masses(1.0, -0.1, 0.2)
    with pytest.raises(InputError, match="no point 'Z'"):
        dynamic_two_point(four_bar(1, 3, 3, 3).body("coupler"), "Z")


@settings(max_examples=25, deadline=None)
@given(p=st.floats(0.05, 0.3), q=st.floats(-0.05, 0.05), inertia=st.floats(1e-3, 0.05), speed=st.floats(1.0, 50.0))
def test_property_dynamic_substitute_is_exact_for_any_coupler(p, q, inertia, speed):
    mech = four_bar(0.1, 0.35, 0.3, 0.4, masses=(1.0, 2.0, 1.5), coms=(None, (p, q), None),
                    inertias=(None, inertia, None), gravity=(0.0, 0.0))
    sub = dynamic_two_point(mech.body("coupler"), "A")
    check = compare_substitute(mech, sub, PHI[::4], speed=speed, acceleration=3.0)
    assert check.force_error <= 1e-9 * max(check.force_scale, 1e-9)
    assert check.moment_error <= 1e-9 * max(check.moment_scale, 1e-9)
