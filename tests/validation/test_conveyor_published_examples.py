"""Published worked examples of the screw-conveyor power methods, reproduced by machdyn.

Source A: M. P. Alexandrov, *Materials Handling Equipment* (Mir Publishers), screw conveyors, as worked in the
calculation sheet "Book-II Chapter 5, Conveying Systems, 2_5_conveying_3nr1: Screw Conveyor" (published on
Scribd as "Mathcad 2-5 conveying 3n", document 361554071). Inputs: D = 300 mm, pitch 300 mm, n = 20 rpm,
bulk density 1.25 t/m^3, filling 0.8, C = 1 (horizontal), L = 5 m, friction factor C1 = 4 (cement, gypsum,
clay, ash, lime), lift H = 0.3 m. Printed results: cross-section F = 0.057 m^2, material speed v = 0.1 m/s,
Q = 25.447 t/h, N_HS = C1·Q·L/367 = 1.387 kW (horizontal), N_gs = Q·(C1·L + H)/367 = 1.408 kW (with lift).
All values were read from the sheet's text, not from a chart.

The same example is the ISO 7119 material-progress and inclination terms: P_H = I_m·L·λ/367 and
P_st = I_m·H/367 with λ = C1; the sheet has no no-load term P_N = D·L/20, so only P_H and P_st are compared
with it, and P_N is checked against its definition.

Tolerance: half a unit of the last printed digit (abs), as for the seed paper. machdyn uses 3600/g = 367.10
where the sheet divides by the rounded 367; the powers are therefore compared after rescaling machdyn's value
to the sheet's divisor (factor (3600/g)/367 = 1.00027), and machdyn's own value is checked to stay within
that 0.03 % of the sheet.
"""

import math

import pytest

from machdyn.conveyor import design, power

SHEET = (3600 / power.G) / 367  # the sheet's rounded divisor
D, PITCH, N, RHO, PHI, C, L, LAM, H = 0.300, 0.300, 20.0, 1250.0, 0.8, 1.0, 5.0, 4.0, 0.3


def _mass_flow():
    return design.volume_capacity(D, PITCH, N, PHI, C) * RHO  # kg/s


def test_alexandrov_capacity():
    """Q = F·v·ρ·3600 = 25.447 t/h (tol abs 0.0005 t/h); F = 0.057 m^2, v = 0.1 m/s."""
    assert math.pi / 4 * D**2 * PHI * C == pytest.approx(0.057, abs=0.0005)
    assert PITCH * N / 60 == pytest.approx(0.1, abs=0.0005)
    assert _mass_flow() * 3.6 == pytest.approx(25.447, abs=0.0005)


def test_alexandrov_textbook_power_horizontal_and_inclined():
    """N_HS = 1.387 kW (horizontal) and N_gs = 1.408 kW (H = 0.3 m) by Q(C1·L + H)/367 (tol abs 0.0005 kW)."""
    m = _mass_flow()
    horizontal = power.power_textbook_367(m, L, 0.0, LAM) / 1000
    inclined = power.power_textbook_367(m, L, H, LAM) / 1000
    assert horizontal * SHEET == pytest.approx(1.387, abs=0.0005)
    assert inclined * SHEET == pytest.approx(1.408, abs=0.0005)
    assert horizontal == pytest.approx(1.387, rel=3e-4 + 0.0005 / 1.387)
    assert inclined == pytest.approx(1.408, rel=3e-4 + 0.0005 / 1.408)


def test_alexandrov_example_as_iso7119_terms():
    """ISO 7119 P_H and P_st for the same duty: P_H = 1.387 kW, P_H + P_st = 1.408 kW (tol abs 0.0005 kW).

    The inclination is the one that gives the sheet's lift: sin β = H/L. P_N = D·L/20 = 0.075 kW is the
    no-load term the sheet does not include.
    """
    m = _mass_flow()
    beta = math.asin(H / L)
    r = power.power_iso7119(m, L, beta, D, LAM)
    assert r.progress / 1000 * SHEET == pytest.approx(1.387, abs=0.0005)
    assert (r.progress + r.inclination) / 1000 * SHEET == pytest.approx(1.408, abs=0.0005)
    assert r.no_load / 1000 == pytest.approx(0.3 * 5 / 20, rel=1e-12)
    assert r.total == pytest.approx(r.progress + r.inclination + r.no_load)
