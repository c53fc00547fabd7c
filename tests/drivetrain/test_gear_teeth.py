"""Gear teeth: Lewis bending with Barth's velocity factor against Shigley's Example 14-1, the Hertz flank stress
against the contact of two cylinders computed from the half-width of the contact band, the stage check's choice of
the pinion's shaft, and bad teeth refused."""

from __future__ import annotations

import math

import numpy as np
import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.drivetrain import gear_teeth
from machdyn.drivetrain.gear_stage import GearTeethTable, check_teeth
from machdyn.errors import InputError

LBF, INCH, HP = 4.4482216152605, 0.0254, 745.6998715822702


def test_shigley_example_14_1_lewis_rating_of_a_stock_spur_gear():
    """R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., §14-1, Example 14-1 (page
    not checked against a printed copy): 8 teeth/in, 1.5 in face, 16 teeth, 20° full depth, AISI 1020 as rolled
    (S_y = 30 kpsi) with n_d = 3, 1200 rev/min, cut teeth: Y = 0.296, V = 628.3 ft/min, K_v = 1.52,
    W_t = 365 lbf, H = 6.95 hp (printed). The book rounds K_v to 1.52 (exact 1.5236): W_t is 364.3 lbf exactly,
    so 0.3 % tolerance."""
    module, face, teeth = INCH / 8, 1.5 * INCH, 16
    diameter = module * teeth
    speed = 1200 * math.pi / 30 * diameter / 2
    assert gear_teeth.lewis_form_factor(teeth) == 0.296
    assert speed / 0.00508 == pytest.approx(628.3, abs=0.05)  # ft/min
    assert gear_teeth.velocity_factor(speed, "cut") == pytest.approx(1.52, abs=0.005)
    allowed = 30e3 * 6894.757293168361 / 3
    load = allowed / gear_teeth.lewis_bending_stress(1.0, face, module, teeth, speed, "cut")
    assert load / LBF == pytest.approx(365.0, rel=3e-3)
    assert load * speed / HP == pytest.approx(6.95, rel=3e-3)


def test_contact_stress_is_the_hertz_pressure_of_two_cylinders():
    """Second method: two cylinders of diameters 2 r1, 2 r2 pressed by the normal force W = K_v W_t / cos φ over
    the length F: half-width b = √(2W/(πF) · ((1−ν1²)/E1 + (1−ν2²)/E2) / (1/d1 + 1/d2)), p_max = 2W/(π b F)
    (Shigley's MED, 10th ed., §3-19, eqs. 3-73 and 3-74)."""
    wt, face, d1, d2, v = 2500.0, 0.04, 0.08, 0.24, 4.0
    e1, nu1, e2, nu2 = 207e9, 0.3, 100e9, 0.21
    phi = math.radians(20.0)
    kv = gear_teeth.velocity_factor(v, "hobbed")
    normal = kv * wt / math.cos(phi)
    c1, c2 = 2 * (d1 * math.sin(phi) / 2), 2 * (d2 * math.sin(phi) / 2)
    b = math.sqrt(2 * normal / (math.pi * face) * ((1 - nu1**2) / e1 + (1 - nu2**2) / e2) / (1 / c1 + 1 / c2))
    p_max = 2 * normal / (math.pi * b * face)
    cp = gear_teeth.elastic_coefficient(e1, nu1, e2, nu2)
    assert gear_teeth.contact_stress(wt, face, d1, d2, v, elastic=cp) == pytest.approx(p_max, rel=1e-12)


def test_lewis_table_and_velocity_factors():
    assert [gear_teeth.lewis_form_factor(n) for n in (12, 50, 400, 1000)] == [0.245, 0.409, 0.480, 0.485]
    ys = [gear_teeth.lewis_form_factor(n) for n in range(12, 401)]
    assert all(b >= a for a, b in zip(ys, ys[1:], strict=False))
    for kind in gear_teeth.MANUFACTURE:
        assert gear_teeth.velocity_factor(0.0, kind) == 1.0
    # at 10 m/s the cast teeth suffer most, the ground ones least
    kv = {k: gear_teeth.velocity_factor(10.0, k) for k in gear_teeth.MANUFACTURE}
    assert kv["cast"] > kv["cut"] > kv["hobbed"] > kv["ground"] > 1.0


@pytest.mark.parametrize("call, words", [
    (lambda: gear_teeth.lewis_form_factor(10), "12 teeth"),
    (lambda: gear_teeth.velocity_factor(-1.0), ">= 0"),
    (lambda: gear_teeth.velocity_factor(1.0, "forged"), "cast, cut, hobbed, ground"),
    (lambda: gear_teeth.lewis_bending_stress(1e3, 0.0, 0.003, 20, 1.0), "face width"),
    (lambda: gear_teeth.elastic_coefficient(207e9, 0.5, 207e9, 0.3), "0 <= ν < 0.5"),
    (lambda: gear_teeth.contact_stress(1e3, 0.03, 0.06, 0.18, 1.0, pressure_angle=0.0), "pressure angle"),
])
def test_bad_gear_input_is_refused(call, words):
    with pytest.raises(InputError, match=words):
        call()


def test_the_stage_check_loads_the_pinion_with_its_shafts_peak_torque():
    teeth = GearTeethTable(module="4 mm", face_width="40 mm", pinion_teeth=20)
    torques = np.array([[10.0, -30.0], [100.0, -240.0], [400.0, 960.0]])  # shafts 0, 1, 2 over two positions
    ratios = np.array([12.0, 4.0, 1.0])
    reduction = check_teeth(1, teeth, 4.0, torques, ratios, 2.0)           # pinion on shaft 1
    assert reduction.tangential_load == pytest.approx(240.0 / 0.04)
    assert reduction.pitch_speed == pytest.approx(2.0 * 4.0 * 0.04)
    step_up = check_teeth(1, teeth, 0.25, torques, ratios, 2.0)            # pinion on shaft 2
    assert step_up.tangential_load == pytest.approx(960.0 / 0.04)
    assert step_up.gear_bending < step_up.pinion_bending                   # the larger wheel has the larger Y
    assert reduction.utilisation is None                                   # no allowable given
    rated = check_teeth(1, teeth.model_copy(update={"allowable_bending": 200e6, "allowable_contact": 900e6}),
                        4.0, torques, ratios, 2.0)
    assert rated.utilisation == pytest.approx(max(rated.pinion_bending / 200e6, rated.contact / 900e6))
    assert (rated.utilisation > 1) == bool(rated.failures())


def test_teeth_on_a_belt_stage_are_refused_by_check(tmp_path):
    from pathlib import Path

    example = Path(__file__).resolve().parents[2] / "examples" / "press_brake_clutch.toml"
    belt_end = 'inertia = "0.02 kg*m^2"          # large pulley and shaft (the flywheel itself comes from [flywheel])\n'
    text = example.read_text()
    assert belt_end in text
    text = text.replace(belt_end, belt_end + '[drivetrain.stages.teeth]\nmodule = "4 mm"\nface_width = "40 mm"\n'
                        'pinion_teeth = 20\n', 1)
    bad = tmp_path / "bad.toml"
    bad.write_text(text)
    result = CliRunner().invoke(app, ["check", str(bad)])
    assert result.exit_code == 2, result.output
    assert "drivetrain.stages[0]" in result.output and "teeth belong to a gear stage" in result.output
