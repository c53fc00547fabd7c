"""Parts sizing against published worked examples with printed answers."""

from __future__ import annotations

import pytest

from machdyn.drivetrain.bearings import catalogue_rating, mean_effective_load, weibull_reliability
from machdyn.drivetrain.strength import goodman_safety


def test_shigley_problem_11_1_ball_bearing_rating_and_reliability():
    """Budynas & Nisbett, *Shigley's Mechanical Engineering Design*, 8th ed., instructor's solutions manual,
    problem 11-1: 30 000 h at 300 rpm (x_D = 540), F_D = 1.2 x 1.898 = 2.278 kN, R = 0.90 -> C10 = 18.59 kN;
    the chosen 02-30 mm bearing (C10 = 19.5 kN) has R = 0.919. Printed to 4 and 3 digits: tolerance half a unit
    of the last printed digit."""
    x_d = 30_000 * 300 * 60 / 1e6
    assert x_d == pytest.approx(540.0)
    assert catalogue_rating(1.898e3, x_d, 0.90, application_factor=1.2) / 1e3 == pytest.approx(18.59, abs=0.005)
    assert weibull_reliability(19.5e3, 1.898e3, x_d, application_factor=1.2) == pytest.approx(0.919, abs=0.0005)


def test_shigley_problem_11_3_roller_bearing_rating_and_reliability():
    """Shigley's MED, 8th ed., solutions manual, problem 11-3: straight roller bearing, x_D = 1440,
    F_D = 1.4 x 1650 lbf = 10.279 kN. The manual takes the Weibull denominator x0 + (theta - x0)(ln 1/0.9)^(1/b) =
    0.9935 as 1 and prints C10 = 91.1 kN: the exact denominator gives 0.2 % more, so 0.3 % tolerance. The
    chosen 03-55 mm bearing (C10 = 102 kN) has R = 0.942 (printed, 3 digits)."""
    assert catalogue_rating(10.279e3, 1440.0, 0.90, kind="roller") / 1e3 == pytest.approx(91.1, rel=3e-3)
    assert weibull_reliability(102e3, 10.279e3, 1440.0, kind="roller") == pytest.approx(0.942, abs=0.0005)


def test_mott_example_14_6_mean_effective_load():
    """R. L. Mott, *Machine Elements in Mechanical Design*, 4th ed., Example Problem 14-6 (p. 626): a 6308 ball
    bearing carries 650 lb for 30 min, 750 lb for 10 min and 250 lb for 20 min of each hour at 600 rpm;
    Fm = 597 lb (printed to the pound: tolerance 0.5 lb)."""
    assert mean_effective_load([650.0, 750.0, 250.0], [30.0, 10.0, 20.0]) == pytest.approx(597.0, abs=0.5)


def test_marks_calculations_goodman_safety_factor_on_a_proportional_load_line():
    """T. H. Brown, *Marks' Calculations for Machine Design*, McGraw-Hill 2005, ch. 7 (strength of machines),
    p. 298, step 17: sigma_a = 80.6 MPa, sigma_m = 202.3 MPa, Se = 229.1 MPa, Sut = 595 MPa on the modified
    Goodman line with the load line through the origin, printed as 229.1 / ((202.3)(0.385 + 0.398)) with the
    ratios rounded to 3 digits: tolerance 0.1 %."""
    printed = 229.1 / (202.3 * (0.385 + 0.398))
    sigma_max, sigma_min = 202.3e6 + 80.6e6, 202.3e6 - 80.6e6
    assert goodman_safety(sigma_max, sigma_min, 229.1e6, 595e6) == pytest.approx(printed, rel=1e-3)
