"""Fatigue criteria, Marin factors, notch sensitivity, multiaxial stresses and the S–N line: each closed form against
a second method (the failure locus met along the load line by root finding, principal stresses from the stress
tensor's eigenvalues, the S–N line read back), the limits that reduce to known cases, the link checks of
``[parts.links]``, and bad input refused."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.drivetrain import fatigue
from machdyn.drivetrain.parts import LinkSpec, link_fatigue_checks
from machdyn.errors import InputError

SE, SUT, SY = 180e6, 620e6, 470e6
POINTS = [(60e6, 120e6), (120e6, 40e6), (30e6, 300e6), (150e6, 5e6)]


@pytest.mark.parametrize("criterion", fatigue.CRITERIA)
@pytest.mark.parametrize("amplitude, mean", POINTS)
def test_the_safety_factor_is_where_the_load_line_meets_the_failure_locus(criterion, amplitude, mean):
    """Scale the stress (σ_a, σ_m) by n until it reaches the criterion's line S_a(σ_m): brentq on
    n σ_a − S_a(n σ_m) = 0, against the closed-form factors of Shigley's Tables 6-6 to 6-8."""
    n = fatigue.fatigue_safety(amplitude, mean, SE, SUT, SY, criterion).fatigue

    def gap(k):
        return k * amplitude - fatigue.failure_amplitude(k * mean, SE, SUT, SY, criterion)

    root = brentq(gap, 1e-6, min(SUT, SY) / mean * 0.999999 if criterion in ("soderberg", "asme_elliptic")
                  else SUT / mean * 0.999999, xtol=1e-14)
    assert n == pytest.approx(root, rel=1e-9)


def test_criteria_limits_and_order():
    # no mean: every criterion gives S_e/σ_a
    for c in fatigue.CRITERIA:
        assert fatigue.fatigue_safety(90e6, 0.0, SE, SUT, SY, c).fatigue == pytest.approx(SE / 90e6)
    # no amplitude: the line's end, S_ut or S_y
    assert fatigue.fatigue_safety(0.0, 100e6, SE, SUT, SY, "goodman").fatigue == pytest.approx(SUT / 100e6)
    assert fatigue.fatigue_safety(0.0, 100e6, SE, SUT, SY, "gerber").fatigue == pytest.approx(SUT / 100e6)
    assert fatigue.fatigue_safety(0.0, 100e6, SE, SUT, SY, "soderberg").fatigue == pytest.approx(SY / 100e6)
    assert fatigue.fatigue_safety(0.0, 100e6, SE, SUT, SY, "asme_elliptic").fatigue == pytest.approx(SY / 100e6)
    # a tensile mean: Soderberg is the most conservative, Gerber the least of the three lines through S_e
    n = {c: fatigue.fatigue_safety(80e6, 150e6, SE, SUT, SY, c).fatigue for c in fatigue.CRITERIA}
    assert n["soderberg"] < n["goodman"] < n["gerber"]
    # the existing Goodman function agrees
    from machdyn.drivetrain.strength import goodman_safety

    assert n["goodman"] == pytest.approx(goodman_safety(230e6, 70e6, SE, SUT), rel=1e-12)


def test_a_compressive_mean_is_judged_by_the_amplitude_and_langer_yields_on_the_peak():
    """Shigley's MED, 10th ed., §6-12: on the compressive side the fatigue line is σ_a = S_e and the yield line
    σ_a − σ_m = S_y."""
    for c in fatigue.CRITERIA:
        s = fatigue.fatigue_safety(100e6, -200e6, SE, SUT, SY, c)
        assert s.fatigue == pytest.approx(SE / 100e6)
        assert s.yielding == pytest.approx(SY / 300e6)
        assert s.governing == pytest.approx(min(SE / 100e6, SY / 300e6))


@pytest.mark.parametrize("call, words", [
    (lambda: fatigue.fatigue_safety(300e6, 330e6, SE, SUT, SY), "first cycle"),
    (lambda: fatigue.fatigue_safety(100e6, -600e6, SE, SUT, SY), "first cycle"),
    (lambda: fatigue.fatigue_safety(100e6, 100e6, 700e6, SUT, SY), "below the ultimate"),
    (lambda: fatigue.fatigue_safety(100e6, 100e6, SE, SUT, None, "soderberg"), "needs the yield strength"),
    (lambda: fatigue.fatigue_safety(-1.0, 100e6, SE, SUT, SY), ">= 0"),
    (lambda: fatigue.fatigue_safety(float("nan"), 100e6, SE, SUT, SY), ">= 0"),
    (lambda: fatigue.fatigue_safety(1e6, 1e6, SE, SUT, 700e6), "exceeds the ultimate"),
    (lambda: fatigue.size_factor(0.3), "2.79 to 254 mm"),
    (lambda: fatigue.temperature_factor(1000.0), "21 to 538"),
    (lambda: fatigue.reliability_factor(99.0), "fraction"),
    (lambda: fatigue.neuber_sensitivity(200e6, 0.003), "345 to 1724 MPa"),
    (lambda: fatigue.sn_line(600e6, 560e6, 0.9), "below f"),
    (lambda: fatigue.sn_line(600e6, 200e6, 0.9).cycles(600e6), "first cycle"),
])
def test_bad_fatigue_input_is_refused_with_a_clear_error(call, words):
    with pytest.raises(InputError, match=words):
        call()


def test_von_mises_equals_the_principal_stress_form():
    """σ' from the components against √(½ Σ (σi − σj)²) of the stress tensor's eigenvalues."""
    rng = np.random.default_rng(3)
    for _ in range(5):
        sx, sy, sz, txy, tyz, tzx = rng.normal(0.0, 100e6, 6)
        tensor = np.array([[sx, txy, tzx], [txy, sy, tyz], [tzx, tyz, sz]])
        s1, s2, s3 = np.linalg.eigvalsh(tensor)
        principal = math.sqrt(0.5 * ((s1 - s2) ** 2 + (s2 - s3) ** 2 + (s3 - s1) ** 2))
        assert fatigue.von_mises(sx, sy, txy, sz, tyz, tzx) == pytest.approx(principal, rel=1e-10)


def test_combined_loading_reduces_to_von_mises_of_bending_and_torsion():
    amp, mean = fatigue.combined_loading((50e6, 20e6), torsion=(30e6, 10e6), kf_bending=1.6, kf_torsion=1.3)
    assert amp == pytest.approx(fatigue.von_mises(1.6 * 50e6, txy=1.3 * 30e6), rel=1e-12)
    assert mean == pytest.approx(fatigue.von_mises(1.6 * 20e6, txy=1.3 * 10e6), rel=1e-12)
    # an axial amplitude counts 1/0.85 of a bending one (its load factor moved to the stress)
    axial_amp, _ = fatigue.combined_loading(axial=(85e6, 0.0))
    assert axial_amp == pytest.approx(100e6)
    # a compressive normal mean keeps its sign
    assert fatigue.combined_loading(axial=(0.0, -50e6))[1] == pytest.approx(-50e6)


def test_the_sn_line_passes_its_two_anchors_and_reads_back():
    """S_f(10³) = f S_ut, S_f(10⁶) = S_e (Shigley's MED, 10th ed., §6-7); N(S_f(N)) = N; the low-cycle line meets
    the S–N line at 10³ cycles and S_ut at one cycle."""
    line = fatigue.sn_line(700e6, 210e6)
    f = fatigue.fatigue_strength_fraction(700e6)
    assert line.strength(1e3) == pytest.approx(f * 700e6, rel=1e-12)
    assert line.strength(1e6) == pytest.approx(210e6, rel=1e-12)
    for n in (2e3, 4.5e4, 7e5, 10.0, 500.0):
        assert line.cycles(line.strength(n)) == pytest.approx(n, rel=1e-9)
    assert line.strength(1.0) == pytest.approx(700e6)
    assert line.cycles(209e6) == math.inf
    # f spans Shigley's Fig. 6-18 from 0.9 near 70 kpsi downwards
    assert fatigue.fatigue_strength_fraction(70 * fatigue.KPSI) == pytest.approx(0.9, abs=0.005)
    assert fatigue.fatigue_strength_fraction(60 * fatigue.KPSI) == 0.9


def test_marin_endurance_limit_is_the_product_of_its_factors():
    m = fatigue.marin_endurance_limit(800e6, finish="hot_rolled", diameter=0.06, load="bending",
                                      temperature=400.0, reliability=0.95, miscellaneous=0.9)
    product = m.surface * m.size * m.load * m.temperature * m.reliability * m.miscellaneous * m.specimen
    assert m.endurance_limit == pytest.approx(product, rel=1e-12)
    assert m.specimen == pytest.approx(400e6)
    assert fatigue.specimen_endurance_limit(2000e6) == pytest.approx(700e6)
    assert m.size == pytest.approx(1.51 * 60.0**-0.157)  # the 51-254 mm branch
    # the two branches of the size factor nearly meet at 51 mm
    assert fatigue.size_factor(0.051) == pytest.approx(fatigue.size_factor(0.05101), rel=0.01)


def _fibres(amplitude, mean):
    t = np.linspace(0.0, 2 * np.pi, 73)
    top = mean + amplitude * np.sin(t)
    return top, 0.2 * top


def test_a_link_is_checked_by_its_criterion_langer_and_its_damage():
    link = LinkSpec("rod", 1e-3, 1e-5, SE, SUT, 1.5, "gerber", SY, 1.4, 1e6)
    checks, point = link_fatigue_checks(link, *_fibres(150e6, 100e6))
    by_name = {c.quantity: c for c in checks}
    expected = fatigue.fatigue_safety(1.4 * 150e6, 1.4 * 100e6, SE, SUT, SY, "gerber")
    assert by_name["fatigue safety factor (Gerber)"].value == pytest.approx(expected.fatigue, rel=1e-9)
    assert by_name["yield safety factor (Langer)"].value == pytest.approx(expected.yielding, rel=1e-9)
    line = fatigue.sn_line(SUT, SE)
    cycles = line.cycles(fatigue.reversed_equivalent(1.4 * 150e6, 1.4 * 100e6, SUT))
    assert by_name["fatigue damage over the required cycles"].value == pytest.approx(1e6 / cycles, rel=1e-9)
    assert point.amplitude == pytest.approx(210e6, rel=1e-9)


def test_a_link_stressed_past_its_ultimate_strength_is_a_failed_check_not_a_nan():
    link = LinkSpec("rod", 1e-3, 1e-5, SE, SUT)
    checks, _ = link_fatigue_checks(link, *_fibres(400e6, 300e6))
    assert [c.quantity for c in checks] == ["peak stress"]
    assert not checks[0].passed and math.isfinite(checks[0].utilisation)


EXAMPLE_LINK = ('''endurance_limit = "150 MPa"      # Se of the forged rod, Marin factors applied
ultimate_strength = "600 MPa"
min_safety = 2.0''')


@pytest.mark.parametrize("new, path, words", [
    ('endurance_limit = "150 MPa"\nultimate_strength = "600 MPa"\ncriterion = "soderberg"', "parts.links[0]",
     "needs yield_strength"),
    ('endurance_limit = "150 MPa"\nultimate_strength = "600 MPa"\n[parts.links.marin]\nfinish = "ground"',
     "parts.links[0]", "not both"),
    ('ultimate_strength = "600 MPa"\n[parts.links.marin]\ndiameter = "300 mm"', "parts.links[0].marin",
     "2.79 to 254 mm"),
])
def test_bad_link_fatigue_tables_are_named_by_check(tmp_path, new, path, words):
    from pathlib import Path

    example = Path(__file__).resolve().parents[2] / "examples" / "crank_press_drive.toml"
    text = example.read_text()
    assert EXAMPLE_LINK in text
    bad = tmp_path / "bad.toml"
    bad.write_text(text.replace(EXAMPLE_LINK, new))
    result = CliRunner().invoke(app, ["check", str(bad)])
    assert result.exit_code == 2, result.output
    assert path in result.output and words in result.output, result.output
