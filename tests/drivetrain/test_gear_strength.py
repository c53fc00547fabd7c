"""The books' force rating of spur teeth (machdyn.drivetrain.gear_strength): the wear strength against the Hertz
contact stress it stands for, the beam strength against Lewis's stress, Buckingham's dynamic load in its limits,
the stage check's effective load and failed checks, and bad input refused with the field named."""

from __future__ import annotations

import math

import numpy as np
import pytest
from pydantic import ValidationError

from machdyn.drivetrain import gear_strength as gs
from machdyn.drivetrain.gear_stage import GearTeethTable, check_teeth, gear_results
from machdyn.drivetrain.gear_teeth import contact_stress, elastic_coefficient, lewis_bending_stress
from machdyn.errors import InputError


@pytest.mark.parametrize("phi_deg, e_pinion, e_gear, zp, zg", [(20.0, 207e9, 207e9, 20, 60),
                                                              (14.5, 207e9, 100e9, 18, 45)])
def test_wear_strength_is_the_load_at_which_the_hertz_stress_reaches_the_endurance_limit(phi_deg, e_pinion,
                                                                                          e_gear, zp, zg):
    """Second method: Shigley's Hertz stress of the flanks (eq. 14-14, ν = 0.3, no velocity factor) under the wear
    strength S_w = b Q d_p K is σ_c again. The books' 1.4 is 4/(π (1 − 0.3²)) = 1.3992, so the two agree to
    0.06 % in load, 0.03 % in stress; tolerance 0.05 % on the stress."""
    phi, module, face, sigma_c = math.radians(phi_deg), 0.004, 0.040, 700e6
    k = gs.load_stress_factor(sigma_c, e_pinion, e_gear, phi)
    load = gs.wear_strength(face, module * zp, zp, zg, k)
    elastic = elastic_coefficient(e_pinion, 0.3, e_gear, 0.3)
    stress = contact_stress(load, face, module * zp, module * zg, 0.0, pressure_angle=phi, elastic=elastic)
    assert stress == pytest.approx(sigma_c, rel=5e-4)
    assert 4 / (math.pi * (1 - 0.09)) == pytest.approx(1.4, rel=6e-4)


def test_beam_strength_is_the_load_that_raises_the_lewis_stress_to_the_permissible_one():
    """S_b = m b σ_b Y inverts Lewis's σ = W_t/(F m Y) at standstill (K_v = 1) with Y of the same table."""
    from machdyn.drivetrain.gear_teeth import lewis_form_factor

    load = gs.beam_strength(0.005, 0.05, 120e6, lewis_form_factor(24))
    assert lewis_bending_stress(load, 0.05, 0.005, 24, 0.0) == pytest.approx(120e6, rel=1e-12)


def test_buckingham_increment_in_its_limits():
    """At standstill no increment; at great speed it tends to C e b + P_t (the force that closes the error);
    it grows with speed and with the error; with no error it still adds a share of P_t."""
    c, e, b, pt = gs.deformation_factor(207e9, 207e9), 25e-6, 0.05, 3000.0
    assert gs.buckingham_increment(pt, 0.0, b, c, e) == 0.0
    ceiling = c * e * b + pt
    assert gs.buckingham_increment(pt, 1e7, b, c, e) == pytest.approx(ceiling, rel=1e-4)
    speeds = np.linspace(0.5, 25, 20)
    values = [gs.buckingham_increment(pt, v, b, c, e) for v in speeds]
    assert np.all(np.diff(values) > 0) and values[-1] < ceiling
    assert gs.buckingham_increment(pt, 5.0, b, c, 2 * e) > gs.buckingham_increment(pt, 5.0, b, c, e)
    assert 0 < gs.buckingham_increment(pt, 5.0, b, c, 0.0) < pt


def test_deformation_and_hardness_factors():
    """C = k/(2/E) for steel on steel: k E/2; K from the hardness is 0.16 (BHN/100)² N/mm², which in the general K
    of 20° steel teeth is a surface endurance limit of 2.686 BHN N/mm²."""
    assert gs.deformation_factor(207e9, 207e9) == pytest.approx(0.107 * 207e9 / 2)
    assert gs.deformation_factor(207e9, 207e9, math.radians(14.5)) == pytest.approx(0.111 * 207e9 / 2)
    assert gs.deformation_factor(207e9, 207e9, math.radians(20), stub=True) == pytest.approx(0.115 * 207e9 / 2)
    bhn = 300.0
    equivalent = gs.load_stress_factor(2.686 * bhn * 1e6, 207e9, 207e9)
    assert gs.load_stress_factor_from_hardness(bhn) == pytest.approx(equivalent, rel=1e-3)


@pytest.mark.parametrize("call, words", [
    (lambda: gs.beam_strength(0.005, 0.0, 1e8, 0.3), "face width"),
    (lambda: gs.wear_strength(0.05, 0.1, 20, 60, -1.0), "load-stress factor"),
    (lambda: gs.buckingham_increment(-1.0, 5.0, 0.05, 1e10, 1e-5), "tangential load"),
    (lambda: gs.buckingham_increment(1e3, 5.0, 0.05, 1e10, math.nan), "tooth error"),
    (lambda: gs.deformation_factor(207e9, 207e9, math.radians(25)), "14.5° and 20°"),
    (lambda: gs.load_stress_factor_from_hardness(0.0), "Brinell"),
])
def test_bad_strength_input_is_refused(call, words):
    with pytest.raises(InputError, match=words):
        call()


BASE = {"module": "4 mm", "face_width": "40 mm", "pinion_teeth": 20}


@pytest.mark.parametrize("extra, words", [
    ({"method": "buckingham", "allowable_bending": "150 MPa"}, "tooth_error"),
    ({"method": "barth"}, "allowable_bending"),
    ({"bhn": 300, "surface_endurance": "600 MPa"}, "one of surface_endurance"),
    ({"method": "buckingham", "allowable_bending": "150 MPa", "tooth_error": "0.02 mm",
      "pressure_angle": "25 deg"}, "deformation_factor"),
])
def test_bad_teeth_tables_are_refused_with_the_key_named(extra, words):
    with pytest.raises(ValidationError, match=words):
        GearTeethTable(**BASE, **extra)


def test_every_mistake_of_a_teeth_table_is_named_at_once():
    with pytest.raises(ValidationError) as info:
        GearTeethTable(**BASE, method="buckingham", bhn=300, load_stress_factor="1 MPa")
    text = str(info.value)
    assert all(key in text for key in ("load_stress_factor", "allowable_bending", "tooth_error"))


def test_the_stage_rates_its_teeth_as_forces_and_fails_a_short_factor_of_safety():
    torques = np.array([[100.0, -240.0], [400.0, 960.0]])
    ratios = np.array([4.0, 1.0])
    teeth = GearTeethTable(**BASE, method="buckingham", allowable_bending="150 MPa", tooth_error="0.025 mm",
                           bhn=300, service_factor=1.25, safety_factor=1.5)
    check = check_teeth(0, teeth, 4.0, torques, ratios, 50.0)
    r = check.strength
    assert r is not None
    pt, v = 240.0 / 0.04, 50.0 * 4.0 * 0.04
    c = gs.deformation_factor(207e9, 207e9)
    assert r.effective_load == pytest.approx(1.25 * pt + gs.buckingham_increment(pt, v, 0.04, c, 25e-6))
    assert r.beam_strength == pytest.approx(0.004 * 0.04 * 150e6 * 0.322)
    assert r.wear_strength == pytest.approx(0.04 * 0.08 * 1.6 * 1.44e6)  # Q = 2·80/100
    assert check.utilisation == pytest.approx(max(1.5 / r.safety_bending, 1.5 / r.safety_wear))
    failures = check.failures()
    assert (r.safety_bending < 1.5) == any("beam strength" in f for f in failures)
    assert (r.safety_wear < 1.5) == any("wear strength" in f for f in failures)
    assert failures                                                  # 7.9 kN against 3.1 kN and 5.5 kN
    scalars, labels = gear_results((check,))
    for name in ("dynamic_load", "beam_strength", "wear_strength", "safety_bending", "safety_wear"):
        assert math.isfinite(scalars[f"drivetrain.stage_0.{name}"])
    assert labels["drivetrain.stage_0.wear_strength"].unit == "N"
    barth = check_teeth(0, teeth.model_copy(update={"method": "barth"}), 4.0, torques, ratios, 50.0)
    assert barth.strength is not None
    assert barth.strength.effective_load == pytest.approx(1.25 * pt * barth.velocity_factor)
    unloaded = check_teeth(0, teeth, 4.0, np.zeros_like(torques), ratios, 50.0)
    assert unloaded.strength is not None                             # the error alone loads the teeth at speed
    assert unloaded.strength.effective_load == pytest.approx(gs.buckingham_increment(0.0, v, 0.04, c, 25e-6))
    idle = check_teeth(0, teeth, 4.0, np.zeros_like(torques), ratios, 0.0)
    assert not idle.failures()
    assert all(math.isfinite(v) for v in gear_results((idle,))[0].values())
