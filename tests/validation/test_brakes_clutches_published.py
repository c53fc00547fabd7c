"""Brakes and clutches from their geometry against published worked examples with printed answers."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from machdyn.drivetrain import brakes
from machdyn.drivetrain.clutch import engage

CASES = Path("/work/shared/validation/published-cases.json")


def _case(case_id: str) -> dict:
    if not CASES.exists():  # the shared file is a copy of the book's data; the inputs below repeat it
        return {}
    return {c["id"]: c for c in json.loads(CASES.read_text())}[case_id]


# Shigley's Example 16-2: r = 150 mm, b = 32 mm, f = 0.32, p_a = 1000 kPa, lining from θ1 = 0 to θ2 = 126°,
# hinge a = √(112² + 50²) = 123 mm from the centre, actuating force at c = 100 mm from the hinge.
R, B, F, A, C = 0.150, 0.032, 0.32, 0.123, 0.100
T1, T2 = 0.0, math.radians(126.0)


def test_shigley_example_16_2_internal_shoe_moments_and_actuating_force():
    """R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., §16-2, Example 16-2
    (page not checked against a printed copy): the right-hand (self-energising) shoe at p_a = 1000 kPa has
    M_f = 304 N·m and M_N = 790 N·m (printed to 3 digits: tolerance half a unit of the last digit, 0.5 N·m), so
    F = (M_N − M_f)/c = 4.86 kN (printed; the book divides the rounded moments: 0.2 % tolerance)."""
    m = brakes.shoe_moments(F, R, B, T1, T2, A)
    pa = 1.0e6
    assert m.friction * pa == pytest.approx(304.0, abs=0.5)
    assert m.normal * pa == pytest.approx(790.0, abs=0.5)
    force = (m.normal - m.friction) * pa / C
    assert force == pytest.approx(4.86e3, rel=2e-3)


def test_shigley_example_16_2_braking_torque_of_both_shoes():
    """Shigley's MED, 10th ed., §16-2, Example 16-2: the right-hand shoe brakes T_R = 366 N·m; the left-hand
    (de-energising) shoe under the same force brakes 162 N·m; the total is 528 N·m (printed to 3 digits). The
    force is the book's 4.86 kN; tolerance 0.3 % (the book's rounding of F and of the moments it divides), 0.5 %
    for the left shoe, which the book obtains from its rounded pressure (exact 162.6 N·m)."""
    both = brakes.internal_shoe_brake(F, 4.86e3, R, B, T1, T2, A, C, shoes=2)
    right = brakes.internal_shoe_brake(F, 4.86e3, R, B, T1, T2, A, C, shoes=1)
    assert right.max_pressure == pytest.approx(1.0e6, rel=3e-3)
    assert right.torque == pytest.approx(366.0, rel=3e-3)
    assert both.torque - right.torque == pytest.approx(162.0, rel=5e-3)
    assert both.torque == pytest.approx(528.0, rel=3e-3)


def test_khurmi_gupta_example_3_12_clutch_driven_side_acceleration():
    """Khurmi & Gupta, *Theory of Machines*, 14th ed., ch. 3, example 3.12, p. 47 (shared case PUB-DRV1): a
    150 N·m clutch joins a 1.176 kg·m² rotor at 750 rpm to a 0.128 kg·m² machine at rest; the machine reaches the
    printed common speed 70.8 rad/s after the printed 0.06 s. The driven side's acceleration α2 = T/J2 =
    1171.9 rad/s² (not printed) must carry it there: α2·t_s equals the printed common speed (0.1 %)."""
    case = _case("PUB-DRV1")
    j1, j2, torque = 1.176, 0.128, 150.0
    if case:
        assert case["inputs"]["I_machine"][0] == pytest.approx(j2)
        assert case["expected"]["common_speed"][0] == pytest.approx(70.8)
    e = engage(j1, 750 * math.pi / 30, j2, 0.0, torque)
    assert e.driven_acceleration == pytest.approx(torque / j2, rel=1e-12)
    assert e.driven_acceleration * e.slip_time == pytest.approx(70.8, rel=1e-3)
    assert e.slip_time == pytest.approx(0.06, abs=0.005)
