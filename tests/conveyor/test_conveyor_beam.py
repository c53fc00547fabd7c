"""The screw as a beam on two supports (seed 004, eqs 2.39-2.45) solved with solve_bvp, against closed forms."""

import math

import numpy as np
import pytest

from machdyn.conveyor.beam import (
    beam_column,
    equivalent_stress_along,
    harmonic_amplitudes,
    harmonic_load,
    moment_one_term,
    one_term_error,
    uniform_load_deflection,
    uniform_load_moment,
)
from machdyn.errors import InputError

EJ = 210e9 * math.pi * (0.1**4 - 0.076**4) / 64  # the seed example's pipe, 100 x 12 mm


def test_uniform_load_matches_the_simply_supported_closed_form_to_1e_9():
    """Closed form: Timoshenko & Gere, simply supported beam, uniform load. Tolerance 1e-9 of the peak: the
    collocation of solve_bvp is exact for the polynomial solution up to the solver's tolerance 1e-10."""
    q, span = 250.0, 3.0
    s = beam_column(span, EJ, lambda x: q + 0 * x)
    v_ref = uniform_load_deflection(s.x, q, span, EJ)
    m_ref = uniform_load_moment(s.x, q, span)
    assert np.max(np.abs(s.deflection - v_ref)) <= 1e-9 * np.max(np.abs(v_ref))
    assert np.max(np.abs(s.moment - m_ref)) <= 1e-9 * np.max(np.abs(m_ref))
    assert np.max(s.deflection) == pytest.approx(5 * q * span**4 / (384 * EJ), rel=1e-9)


def test_equilibrium_moment_curvature_and_shear():
    """Physics: M'' = w (equilibrium) and the end shears carry the load (reactions = q·l/2)."""
    q, span = 100.0, 2.0
    s = beam_column(span, EJ, lambda x: q + 0 * x)
    d2m = np.gradient(np.gradient(s.moment, s.x), s.x)
    assert np.allclose(d2m[5:-5], q, rtol=1e-6)
    assert -s.shear[0] == pytest.approx(q * span / 2, rel=1e-8)


def test_one_term_2_45_is_exact_without_axial_force_on_whole_pitches():
    """Seed 004, eq 2.45: with N = 0 and l = 4 pitches the exact moment is (B/a − A/a²)(1 − cos ax)."""
    pitch = 0.16
    a_amp, b_amp = harmonic_amplitudes(20e3, 0.1, 0.05, math.tan(math.radians(20)), pitch)
    s = beam_column(4 * pitch, EJ, harmonic_load(a_amp, b_amp, pitch), nodes=401)
    ref = moment_one_term(s.x, a_amp, b_amp, pitch)
    assert np.max(np.abs(s.moment - ref)) <= 1e-8 * np.max(np.abs(ref))


@pytest.mark.parametrize("pitches", [3.25, 4.5, 7.8])
def test_one_term_error_off_whole_pitches_is_the_end_term(pitches):
    """Off whole pitches the exact moment is 2.45 minus C(1 − cos al)·x/l; the estimate bounds the error."""
    pitch = 0.2
    a_amp, b_amp = harmonic_amplitudes(10e3, 0.1, 0.05, 0.4, pitch)
    span = pitches * pitch
    s = beam_column(span, EJ, harmonic_load(a_amp, b_amp, pitch), nodes=401)
    ref = moment_one_term(s.x, a_amp, b_amp, pitch)
    a = 2 * math.pi / pitch
    c = b_amp / a - a_amp / a**2
    exact = ref - c * (1 - math.cos(a * span)) * s.x / span
    assert np.max(np.abs(s.moment - exact)) <= 1e-8 * abs(c)
    err = np.max(np.abs(s.moment - ref)) / np.max(np.abs(ref))
    assert err == pytest.approx(one_term_error(span, pitch, 0.0, EJ), rel=1e-3)  # grid sampling of the peak


def test_axial_compression_amplifies_the_moment_beyond_2_45():
    """With compression N the beam-column moment exceeds 2.45, by less than N/(N_cr − N); where N/N_cr <= 1 % the
    one-term form is within 1.5 % (the range where the paper's approximation holds)."""
    pitch, span = 0.3, 3.0  # 10 whole pitches
    a_amp, b_amp = harmonic_amplitudes(20e3, 0.1, 0.05, 0.36, pitch)
    euler = math.pi**2 * EJ / span**2

    load = harmonic_load(a_amp, b_amp, pitch)
    errors = []
    for ratio in (0.001, 0.01, 0.1, 0.3):
        s = beam_column(span, EJ, load, axial_start=ratio * euler, axial_end=ratio * euler, nodes=301, tol=1e-7)
        ref = moment_one_term(s.x, a_amp, b_amp, pitch)
        errors.append(np.max(np.abs(s.moment - ref)) / np.max(np.abs(ref)))
    assert errors == sorted(errors)
    assert errors[1] <= 0.015
    # the estimate N/(N_cr − N) (the first mode's amplification) bounds the computed growth
    for ratio, err in zip((0.001, 0.01, 0.1, 0.3), errors, strict=True):
        assert err <= one_term_error(span, pitch, ratio * euler, EJ)


def test_compression_at_or_beyond_euler_is_refused():
    with pytest.raises(InputError, match="Euler load"):
        beam_column(3.0, EJ, lambda x: 1 + 0 * x, axial_start=math.pi**2 * EJ / 9.0)


def test_equivalent_stress_along_reduces_to_torsion_and_bending():
    d_o, d_i = 0.1, 0.076
    jp = math.pi * (d_o**4 - d_i**4) / 32
    assert float(equivalent_stress_along(0.0, 0.0, 100.0, d_o, d_i)) == pytest.approx(2 * 100 * 0.05 / jp)
    assert float(equivalent_stress_along(-200.0, 0.0, 0.0, d_o, d_i)) == pytest.approx(200 * 0.05 / (jp / 2))


def test_stress_along_the_screw_grows_to_the_drive_and_stays_below_the_span_bound(base_problem):
    """Torque and axial force grow from the feed end to the drive: the stress along the screw is largest in the
    last span, and never above the span analysed with the whole F_a and T (the conservative bound)."""
    from machdyn.conveyor import evaluate, validate

    result = evaluate(validate(base_problem))
    b = result.bending
    assert b.screw_x[0] == 0 and b.screw_x[-1] == pytest.approx(21.0)
    last = b.screw_x >= 21.0 - 3.0
    assert np.argmax(b.screw_stress) in np.flatnonzero(last)
    assert result.scalars["screw_stress_max"] <= result.scalars["span_stress_max"] * (1 + 1e-12)
    # at the drive, x = L: the moment vanishes at the support, so only torsion and the axial force remain
    d_o, d_i = 0.1, 0.088
    assert b.screw_stress[-1] == pytest.approx(
        float(equivalent_stress_along(0.0, result.scalars["axial_force"], result.torque, d_o, d_i)), rel=1e-6)
