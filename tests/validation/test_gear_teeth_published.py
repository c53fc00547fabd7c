"""Spur gear teeth against published worked examples with printed answers: Lewis's bending stress with Barth's
velocity factor and the Hertz contact stress of the flanks (machdyn.drivetrain.gear_teeth).

R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., McGraw-Hill 2015, ch. 14,
Examples 14-1 (Lewis) and 14-3 (surface durability); the pages were not checked against a printed copy. The book
works in inch units; machdyn takes them in SI (1 in = 25.4 mm, 1 lbf = 4.448222 N, 1 psi = 6894.757 Pa), and its
Barth factor for cut or milled teeth, (6.1 + V)/6.1 with V in m/s, is the book's (1200 + V)/1200 with V in ft/min
to 4e-4 of V's share."""

from __future__ import annotations

import math

import pytest

from machdyn.drivetrain.gear_teeth import contact_stress, lewis_bending_stress, lewis_form_factor, velocity_factor

INCH, LBF, PSI = 0.0254, 4.4482216152605, 6894.757293168
# Example 14-1's stock pinion: 8 teeth/in, 1.5 in face, 16 teeth, 20° full depth, at 1200 rev/min
MODULE = INCH / 8
FACE = 1.5 * INCH
PINION_DIAMETER = 16 * MODULE
SPEED = math.pi * PINION_DIAMETER * 1200 / 60  # 628.3 ft/min


def test_shigley_example_14_1_lewis_rating_of_a_stock_pinion():
    """Shigley's MED, 10th ed., Example 14-1: AISI 1020 as rolled (S_y = 30 kpsi) with a design factor 3 allows
    σ = 10 kpsi. Printed: Y = 0.296 (Table 14-2), V = 628.3 ft/min, K_v = 1.52, W_t = 365 lbf, H = 6.95 hp.
    machdyn's form factor and velocity factor are the printed ones (to their printed digits), and its Lewis stress
    at the printed W_t is the allowed 10 kpsi within 0.4 % (the book rounds K_v to 1.52, +0.22 % in machdyn's
    exact 1.5233, and W_t to three digits, 0.14 %)."""
    assert lewis_form_factor(16) == pytest.approx(0.296, abs=5e-4)
    assert SPEED / 0.3048 * 60 == pytest.approx(628.3, abs=0.05)
    assert velocity_factor(SPEED, "cut") == pytest.approx(1.52, abs=0.005)
    sigma = lewis_bending_stress(365 * LBF, FACE, MODULE, 16, SPEED, "cut")
    assert sigma / PSI == pytest.approx(10_000, rel=4e-3)
    assert 365 * LBF * SPEED / 745.69987 == pytest.approx(6.95, abs=0.005)  # the printed power, W_t V


def test_shigley_example_14_3_contact_stress_of_a_steel_pinion_on_a_cast_iron_gear():
    """Shigley's MED, 10th ed., Example 14-3: the pinion of Example 14-1 meshes with a 50-tooth ASTM No. 50 cast
    iron gear under W_t = 382 lbf; C_p = 1817 √psi (Table 14-5 for steel on cast iron), K_v = 1.52, pitch radii of
    curvature r = d sin 20°/2 (0.342 in and 1.069 in). Printed: σ_C = −72.4 kpsi (a compression; machdyn reports
    the magnitude). Tolerance 0.2 %: half the last printed digit (0.07 %) and the book's rounding of K_v to 1.52
    (+0.11 % on σ_C, which goes with √K_v)."""
    sigma = contact_stress(382 * LBF, FACE, PINION_DIAMETER, 50 * MODULE, SPEED, manufacture="cut",
                           elastic=1817 * math.sqrt(PSI))
    assert sigma / PSI == pytest.approx(72_400, rel=2e-3)
    # the book's radii of curvature, printed to three decimals
    assert PINION_DIAMETER * math.sin(math.radians(20)) / 2 / INCH == pytest.approx(0.342, abs=5e-4)
    assert 50 * MODULE * math.sin(math.radians(20)) / 2 / INCH == pytest.approx(1.069, abs=5e-4)
