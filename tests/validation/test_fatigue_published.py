"""Fatigue: Marin factors, notch sensitivity and the Goodman sizing of a bar against published worked examples with
printed answers. The Shigley examples are those of the 10th edition's §6-9 and §6-10 (the same examples, with
the same numbers, stand in the 9th edition); their page numbers were not checked against a printed copy."""

from __future__ import annotations

import math

import pytest
from scipy.optimize import brentq

from machdyn.drivetrain import fatigue

KPSI = fatigue.KPSI


def test_shigley_example_6_3_surface_factor_of_a_machined_steel():
    """R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., §6-9, Example 6-3: a
    machined steel of S_ut = 520 MPa has k_a = 4.51 (520)^−0.265 = 0.860 (printed to 3 digits: ±0.0005)."""
    assert fatigue.surface_factor(520e6, "machined") == pytest.approx(0.860, abs=5e-4)


def test_shigley_example_6_4_size_factor_rotating_and_not():
    """Shigley's MED, 10th ed., §6-9, Example 6-4: a 32 mm shaft in bending, k_b = (32/7.62)^−0.107 = 0.858
    rotating; not rotating, d_e = 0.370 d = 11.84 mm and k_b = 0.954 (printed to 3 digits: ±0.0005)."""
    assert fatigue.size_factor(0.032) == pytest.approx(0.858, abs=5e-4)
    assert 0.370 * 32 == pytest.approx(11.84)
    assert fatigue.size_factor(0.370 * 0.032) == pytest.approx(0.954, abs=5e-4)


def test_shigley_example_6_5_temperature_factor_at_450_F():
    """Shigley's MED, 10th ed., §6-9, Example 6-5 (a): a 1035 steel at 450 °F, k_d = 1.007 by eq. 6-27, and with
    the tested (S_e')_70° = 39.0 kpsi, S_e = 39.3 kpsi (printed to 3 and 3 digits: half a unit of the last)."""
    kelvin = (450.0 - 32.0) * 5.0 / 9.0 + 273.15
    kd = fatigue.temperature_factor(kelvin)
    assert kd == pytest.approx(1.007, abs=5e-4)
    assert kd * 39.0 == pytest.approx(39.3, abs=0.05)


def test_shigley_table_6_5_reliability_factors():
    """Shigley's MED, 10th ed., §6-9, Table 6-5: k_e = 1 − 0.08 z_a for 50 % to 99.9999 % (printed to 3 digits;
    the table rounds z_a to 3 decimals, so ±0.001)."""
    printed = {0.5: 1.000, 0.9: 0.897, 0.95: 0.868, 0.99: 0.814, 0.999: 0.753, 0.9999: 0.702, 0.99999: 0.659,
               0.999999: 0.620}
    for reliability, ke in printed.items():
        assert fatigue.reliability_factor(reliability) == pytest.approx(ke, abs=1e-3), reliability


def test_shigley_example_6_6_fatigue_notch_factor_by_neuber():
    """Shigley's MED, 10th ed., §6-10, Example 6-6 (b): a steel shaft of S_ut = 690 MPa (100 kpsi) with a 3 mm
    shoulder fillet (K_t = 1.65 from Fig. A-15-9): √a = 0.0622 √in by eq. 6-35a and K_f = 1.55 (printed to 3
    digits: ±0.005)."""
    s = 690e6 / KPSI
    root_a = 0.246 - 3.08e-3 * s + 1.51e-5 * s**2 - 2.67e-8 * s**3
    assert root_a == pytest.approx(0.0622, abs=2e-4)
    kf = fatigue.fatigue_notch_factor(1.65, fatigue.neuber_sensitivity(690e6, 0.003))
    assert kf == pytest.approx(1.55, abs=5e-3)


def test_wentzell_example_5_3_goodman_sizing_of_a_cantilever_bar():
    """T. H. Wentzell, *Machine Design*, example 5.3, p. 97 (shared case PUB-DRV16): a round cantilever carrying
    1000 lb at 12 in, repeated 0 → max; S_u = 90 ksi, S_n' = 34 ksi, C_size = 0.85, C_surface = C_type = 1,
    design factor 1.6 on the modified Goodman line. The diameter whose Goodman factor is 1.6, found by root
    finding on :func:`fatigue_safety`: printed 1.65 in (exact 1.6473 in; 0.3 % tolerance, the case's)."""
    load, arm = 4448.221617233438, 0.3048
    ultimate, endurance = 620528130.0, 0.85 * 234421738.0
    moment = load * arm

    def factor(d):
        peak = 32.0 * moment / (math.pi * d**3)
        return fatigue.fatigue_safety(peak / 2, peak / 2, endurance, ultimate).fatigue - 1.6

    diameter = brentq(factor, 0.035, 0.1, xtol=1e-12)  # from a peak of 322 MPa (below S_u) upwards
    assert diameter == pytest.approx(0.04191, rel=3e-3)
    assert diameter / 0.0254 == pytest.approx(1.6473, rel=2e-4)


def test_marks_calculations_goodman_factor_by_the_criteria_module():
    """T. H. Brown, *Marks' Calculations for Machine Design*, McGraw-Hill 2005, ch. 7, p. 298, step 17:
    σ_a = 80.6 MPa, σ_m = 202.3 MPa, S_e = 229.1 MPa, S_ut = 595 MPa on the modified Goodman line, printed as
    229.1/((202.3)(0.385 + 0.398)) with the ratios rounded to 3 digits: tolerance 0.1 %."""
    printed = 229.1 / (202.3 * (0.385 + 0.398))
    assert fatigue.fatigue_safety(80.6e6, 202.3e6, 229.1e6, 595e6).fatigue == pytest.approx(printed, rel=1e-3)
