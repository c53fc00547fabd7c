"""Spur gear teeth against published worked examples with printed answers: Lewis's bending stress with Barth's
velocity factor and the Hertz contact stress of the flanks (machdyn.drivetrain.gear_teeth).

R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., McGraw-Hill 2015, ch. 14,
Examples 14-1 (Lewis) and 14-3 (surface durability); the pages were not checked against a printed copy. The book
works in inch units; machdyn takes them in SI (1 in = 25.4 mm, 1 lbf = 4.448222 N, 1 psi = 6894.757 Pa), and its
Barth factor for cut or milled teeth, (6.1 + V)/6.1 with V in m/s, is the book's (1200 + V)/1200 with V in ft/min
to 4e-4 of V's share."""

from __future__ import annotations

import json
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


@pytest.mark.parametrize("wheel, size_factor, printed", [("pinion", 1.043, 70_360), ("gear", 1.052, 70_660)])
def test_shigley_example_14_4_contact_stress_of_pinion_and_gear(wheel, size_factor, printed):
    """Shigley's MED, 10th ed., Example 14-4 (AGMA rating of a 17-tooth pinion on a 52-tooth gear, 10 teeth/in,
    1.5 in face, 4 hp at 1800 rev/min, steel on steel; page not checked against a printed copy; the printed
    figures as transcribed): d_P = 1.7 in, d_G = 5.2 in, W_t = 164.8 lbf, K_o = 1, K_v = 1.377 (AGMA, Q_v = 6),
    K_s = 1.043 (pinion) and 1.052 (gear), K_m = 1.22, C_f = 1, I = 0.121, C_p = 2300 √psi. Printed:
    σ_c = 70 360 psi (pinion) and 70 660 psi (gear). AGMA's eq. 14-16 with I = cos φ sin φ/2 · m_G/(m_G + 1) is
    the Hertz stress of eq. 14-14, so machdyn's contact stress at standstill (no Barth factor) under the book's
    factored load W_t K_o K_v K_s K_m C_f is the printed stress; tolerance 0.1 % for the book's four-digit W_t and
    the printed factors (machdyn is 0.04 % low)."""
    load = 164.8 * 1.377 * size_factor * 1.22 * LBF
    sigma = contact_stress(load, FACE, 1.7 * INCH, 5.2 * INCH, 0.0, elastic=2300 * math.sqrt(PSI))
    assert sigma / PSI == pytest.approx(printed, rel=1e-3)
    geometry = math.cos(math.radians(20)) * math.sin(math.radians(20)) / 2 * (52 / 17) / (52 / 17 + 1)
    assert geometry == pytest.approx(0.121, abs=5e-4)  # the printed I


# T. H. Wentzell, *Machine Design*, Cengage Learning (Indian edition) 2007, ch. 12 "Spur gear design and
# selection", and U. C. Jindal, *Machine Design*, 1st ed., Dorling Kindersley (India) 2010, ch. 25 "Gears": the
# books' data and printed answers are read from the public FOSSEE Python Textbook Companions of the books
# (Machine_Design_by_T._H._Wentzell,_P._E/Chapter12.ipynb and Machine_Design_by_U.C._Jindal/Ch25_2.ipynb, which give
# the pages). Wentzell's dynamic load is Barth's (600 + V)/600 · W_t with V in ft/min, machdyn's cast-tooth factor
# (3.05 + V)/3.05 with V in m/s: 600 ft/min is 3.048 m/s, so machdyn's factor is up to 0.05 % smaller.
FPM = 0.3048 / 60  # 1 ft/min in m/s


def test_wentzell_example_12_4_dynamic_load_and_lewis_check_of_a_pinion():
    """Wentzell, *Machine Design*, ch. 12, Example 12.4, p. 262: the 20-tooth, 8 teeth/in, 1 in wide steel pinion
    of Examples 12.1–12.3 (S_n = 47.5 kpsi, allowable load F_s = S_n b Y/P_d = 1900 lbf with the book's Y = 0.320)
    carries W_t = 146 lbf at V = 1129 ft/min. Printed: the dynamic load F_d = (600 + V) W_t/600 = 420.72 lbf, and
    with a safety factor 2 an acceptable design (F_s/2 = 950 lbf > F_d). machdyn's velocity factor times W_t is the
    printed F_d within 0.05 % (the SI constant); its Lewis stress uses Shigley's Y = 0.322 for 20 teeth, so its
    utilisation σ/(S_n/2) = 0.4399 is the book's F_d/(F_s/2) = 0.4429 times 0.320/0.322: tolerance 0.1 % on that
    product, and the design is acceptable."""
    speed = 1129 * FPM
    assert velocity_factor(speed, "cast") * 146 == pytest.approx(420.72, rel=5e-4)
    sigma = lewis_bending_stress(146 * LBF, 1 * INCH, INCH / 8, 20, speed, "cast")
    utilisation = sigma / (47_500 * PSI / 2)
    assert utilisation < 1
    assert utilisation == pytest.approx(420.72 / 950 * 0.320 / lewis_form_factor(20), rel=1e-3)


def test_wentzell_example_12_6_dynamic_force_on_a_48_tooth_pinion():
    """Wentzell, *Machine Design*, ch. 12, Example 12.6, p. 266: a 48-tooth, 12 teeth/in pinion at 900 rpm
    transmits 2 hp. Printed: V = 942.48 ft/min, W_t = 70.03 lbf, the dynamic force F_d = 180.03 lbf. machdyn's
    pitch speed of the pinion, the tangential load from the power, and its velocity factor times W_t: to half a
    unit of the last printed digit, F_d within 0.05 % (the SI constant). (The book then sizes the face width with
    its own Lewis Y = 0.344 for these teeth, a table other than the 20° full-depth one machdyn carries, so that
    step is not compared.)"""
    diameter = 48 / 12 * INCH
    speed = math.pi * diameter * 900 / 60
    assert speed / FPM == pytest.approx(942.48, abs=0.005)
    load = 2 * 745.69987 / speed / LBF
    assert load == pytest.approx(70.03, abs=0.005)
    assert velocity_factor(speed, "cast") * 70.03 == pytest.approx(180.03, rel=5e-4)


def test_jindal_example_25_3_lewis_beam_strength_and_power_rating():
    """Jindal, *Machine Design*, ch. 25, Example 25-3, p. 670: a 30-tooth pinion of module 5 mm, face 60 mm, at
    1000 rpm drives 75 teeth; σ_b = σ_ut/3 = 150 MPa, service factor 1.5 and safety factor 2. Printed: the beam
    strength S_b = m b σ_b Y = 16110 N (the book's Y = 0.358), and the power 11.657 kW at which
    S_b C_v/(C_s n) is the tangential load, with C_v = 3/(3 + v), v = 7.854 m/s.

    machdyn's Lewis stress at S_b and standstill (K_v = 1) is σ_b within 0.3 % (its Y = 0.359 from Shigley's
    table). Its power rating — the load at which its stress, service and safety factors applied, is σ_b — is
    11.83 kW: the book's velocity factor is Barth's with 3 m/s where machdyn (Shigley, cast teeth) has 3.05 m/s,
    1.2 % apart at this speed, and its Y 0.28 % smaller; with those two ratios the printed 11.657 kW is met to
    half a unit of its last digit."""
    beam = lewis_bending_stress(16110.0, 0.060, 0.005, 30, 0.0, "cast")
    assert beam == pytest.approx(150e6, rel=3e-3)
    speed = math.pi * 0.150 * 1000 / 60
    allowed = 150e6 / (1.5 * 2)
    load = allowed / lewis_bending_stress(1.0, 0.060, 0.005, 30, speed, "cast")
    power = load * speed / 1e3
    assert power == pytest.approx(11.657, rel=0.016)
    book_kv = (3 + speed) / 3
    assert power * 0.358 / lewis_form_factor(30) * velocity_factor(speed, "cast") / book_kv == pytest.approx(
        11.657, abs=5e-4)


SHIGLEY_TEETH = """[drivetrain.stages.teeth]
module = "3.175 mm"
face_width = "38.1 mm"
pinion_teeth = 16
manufacture = "cut"
allowable_bending = "68.94757 MPa"

"""


SARKAR_BRAKE = """[drivetrain.brake.geometry]
kind = "differential_band"
friction = 0.25
force = "180 N"
drum_radius = "450 mm"
lever = "700 mm"
slack_arm = "100 mm"
tight_arm = "30 mm"
blocks = 12
block_angle = "16 deg"

"""


def test_shigley_example_14_1_and_sarkar_band_and_block_brake_through_a_problem_file_and_the_command_line(tmp_path):
    """Shigley's MED, 10th ed., Example 14-1 (above) as the gear stage of a problem file run by ``machdyn run``:
    the shipped press with the book's stock pinion (16 teeth, 8 teeth/in = 3.175 mm module, 1.5 in face, cut
    teeth) on its pinion shaft, the belt and the gear ratios changed (1.25 and 30: the same 37.5 overall) so that
    the pinion turns at the book's 1200 rpm. The run's pitch speed is the printed 628.3 ft/min, and its bending
    stress per newton of its tangential load is the book's: 10 kpsi at the printed rating W_t = 365 lbf
    (tolerance 0.4 %, as in the direct test: the book rounds K_v and W_t); the allowable is the book's 10 kpsi.

    The same run's brake is B. K. Sarkar's band-and-block brake (*Theory of Machines*, Tata McGraw-Hill 2002,
    ch. 10, illustration 10, p. 275; tests/validation/test_brakes_clutches_published.py): 12 blocks of 16°, no
    wrap angle needed; ``brake.torque`` is the printed 2481.63 N·m within the book's rounding (0.05 %)."""
    from pathlib import Path

    from typer.testing import CliRunner

    from machdyn.cli import app

    example = Path(__file__).resolve().parents[2] / "examples" / "press_brake_clutch.toml"
    text = example.read_text()
    text = text[: text.index("[flywheel]")] + text[text.index("[drivetrain]"): text.index("[drivetrain.single_stroke]")]
    for old, new in (("ratio = 4.6875", "ratio = 1.25"), ("ratio = 8.0 ", "ratio = 30.0 "),
                     ('wheel_radius = "50 mm"', 'wheel_radius = "25.4 mm"')):
        assert text.count(old) == 1
        text = text.replace(old, new)
    for header, table in (("[drivetrain.stages.teeth]", SHIGLEY_TEETH), ("[drivetrain.brake.geometry]", SARKAR_BRAKE)):
        start = text.index(header)
        text = text[:start] + table + text[text.index("\n\n", start) + 2:]
    path = tmp_path / "shigley.toml"
    path.write_text(text)
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(out), "-q"])
    assert result.exit_code in (0, 3), result.output
    reported = json.loads((out / "results.json").read_text())["scalars"]
    stage = "drivetrain.stage_1."
    units = {name: reported[stage + name]["unit"] for name in ("pitch_speed", "tangential_load",
                                                               "pinion_bending_stress")}
    assert units == {"pitch_speed": "m/s", "tangential_load": "N", "pinion_bending_stress": "Pa"}  # SI
    scalars = {k: v["value"] for k, v in reported.items()}
    assert scalars[stage + "pitch_speed"] / 0.3048 * 60 == pytest.approx(628.3, abs=0.05)
    per_newton = scalars[stage + "pinion_bending_stress"] / scalars[stage + "tangential_load"]
    assert per_newton == pytest.approx(10_000 * PSI / (365 * LBF), rel=4e-3)
    assert scalars[stage + "utilisation"] >= scalars[stage + "pinion_bending_stress"] / (10_000 * PSI) * (1 - 1e-6)
    assert scalars["brake.torque"] == pytest.approx(2481.63, rel=5e-4)
