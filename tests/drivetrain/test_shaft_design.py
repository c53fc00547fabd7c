"""Shafts: the DE fatigue criteria against Shigley's closed forms and his Example 7-1, the influence coefficients
against the virtual work of the moment diagrams, the critical speeds' bounds (Rayleigh above, Dunkerley below the
exact lumped eigenvalue), a finely lumped shaft against the uniform shaft's closed form, and the shaft table."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.drivetrain import shaft_design as sd
from machdyn.drivetrain.shaft_check import ShaftTable, check_shaft
from machdyn.errors import InputError

KPSI = 6.894757293168361e6
INCH = 0.0254
LBF_IN = 0.1129848290276167


def test_de_goodman_and_de_asme_elliptic_are_shigleys_closed_forms():
    """Shigley's MED, 10th ed., eq. 7-7 (DE-Goodman) and the DE-ASME-elliptic form (eq. 7-11) written out, against
    the composition of the von Mises section stresses with the fatigue criteria."""
    d, ma, mm, ta, tm, kf, kfs = 0.035, 180.0, 40.0, 60.0, 250.0, 1.7, 1.4
    se, sut, sy = 210e6, 690e6, 520e6
    a = math.sqrt(4 * (kf * ma) ** 2 + 3 * (kfs * ta) ** 2)
    m = math.sqrt(4 * (kf * mm) ** 2 + 3 * (kfs * tm) ** 2)
    goodman = 1.0 / (16 / (math.pi * d**3) * (a / se + m / sut))
    asme = 1.0 / (16 / (math.pi * d**3) * math.sqrt(4 * (kf * ma / se) ** 2 + 3 * (kfs * ta / se) ** 2
                                                     + 4 * (kf * mm / sy) ** 2 + 3 * (kfs * tm / sy) ** 2))
    args = (d, (ma, mm), (ta, tm), se, sut, sy)
    assert sd.shaft_safety(*args, kf=kf, kfs=kfs).fatigue == pytest.approx(goodman, rel=1e-12)
    assert sd.shaft_safety(*args, kf=kf, kfs=kfs, criterion="asme_elliptic").fatigue == pytest.approx(asme, rel=1e-12)
    diameter = sd.de_goodman_diameter(2.5, (ma, mm), (ta, tm), se, sut, kf=kf, kfs=kfs)
    assert sd.shaft_safety(diameter, (ma, mm), (ta, tm), se, sut, kf=kf, kfs=kfs).fatigue == pytest.approx(2.5)


def test_shigley_example_7_1_de_goodman_and_yield_of_a_shaft_shoulder():
    """R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering Design*, 10th ed., §7-4, Example 7-1 (page
    not checked against a printed copy): d = 1.100 in at a machined shoulder, M_a = 1260 lbf·in, T_m = 1100 lbf·in,
    S_ut = 105 kpsi, S_y = 82 kpsi, with the book's K_f = 1.58, K_fs = 1.39 and S_e = 29.3 kpsi: DE-Goodman
    n = 1.62 and first-cycle yield n_y = 4.48 (printed to 3 digits; the book carries its rounded intermediate
    stresses: 0.5 %)."""
    d, ma, tm = 1.1 * INCH, 1260 * LBF_IN, 1100 * LBF_IN
    s = sd.shaft_safety(d, (ma, 0.0), (0.0, tm), 29.3 * KPSI, 105 * KPSI, 82 * KPSI, kf=1.58, kfs=1.39)
    assert s.fatigue == pytest.approx(1.62, rel=5e-3)
    assert s.yielding == pytest.approx(4.48, rel=5e-3)


def test_influence_coefficients_are_the_virtual_work_of_the_moment_diagrams():
    """δ(x, a) = ∫ m_x(s) m_a(s) ds / (E I), m the moment of a unit load on the simply supported span."""
    span, ei = 0.8, 2.5e4

    def moment(s, at):
        return (span - at) / span * s if s <= at else at / span * (span - s)

    for x, a in ((0.1, 0.5), (0.6, 0.2), (0.4, 0.4), (0.75, 0.05)):
        work = quad(lambda s, x=x, a=a: moment(s, x) * moment(s, a), 0.0, span, points=[x, a])[0] / ei
        assert sd.influence(span, ei, x, a) == pytest.approx(work, rel=1e-9)


def test_rayleigh_bounds_from_above_and_dunkerley_from_below():
    span, ei = 1.2, 8.0e4
    for masses, positions in (([20.0, 35.0], [0.3, 0.8]), ([10.0, 10.0, 40.0], [0.2, 0.6, 1.0])):
        rayleigh, dunkerley, exact = sd.critical_speeds(span, ei, masses, positions)
        assert dunkerley < exact < rayleigh
        assert rayleigh / exact < 1.01  # the static deflection curve is close to the first mode


def test_a_finely_lumped_shaft_has_the_uniform_shafts_critical_speed():
    """Shigley's MED, 10th ed., eq. 7-22 against the exact eigenvalue of 60 lumped slices (0.1 %)."""
    span, ei, per_length = 1.0, 5.0e4, 12.0
    n = 60
    positions = [(k + 0.5) * span / n for k in range(n)]
    _r, _d, exact = sd.critical_speeds(span, ei, [per_length * span / n] * n, positions)
    assert exact == pytest.approx(sd.uniform_shaft_speed(span, ei, per_length), rel=1e-3)


def test_the_shaft_check_loads_the_wheel_seat_with_its_force_and_torque():
    table = ShaftTable(shaft=1, diameter="40 mm", span="400 mm", wheel_at="100 mm", wheel_radius="50 mm",
                       masses=["20 kg"], mass_at=["100 mm"], ultimate_strength="700 MPa",
                       endurance_limit="200 MPa", notch_factor=1.6, shear_notch_factor=1.3)
    torque = np.array([50.0, 250.0, 150.0])
    c = check_shaft(table, torque, 30.0)
    force = 1.064 * 250.0 / 0.05
    assert c.moment == pytest.approx(force * 0.1 * 0.3 / 0.4)
    assert (c.torque_amplitude, c.torque_mean) == (100.0, 150.0)
    expected = sd.shaft_safety(0.04, (c.moment, 0.0), (100.0, 150.0), 200e6, 700e6, kf=1.6, kfs=1.3)
    assert c.fatigue_safety == pytest.approx(expected.fatigue)
    assert c.utilisation == pytest.approx(max(1.5 / min(c.fatigue_safety, c.yield_safety),
                                              30.0 * 1.25 / c.critical_dunkerley))
    ei = 207e9 * math.pi * 0.04**4 / 64
    assert c.deflection == pytest.approx(force * 0.1**2 * 0.3**2 / (3 * ei * 0.4))
    # far too thin: the first cycle breaks it, a failed check with a finite factor
    thin = check_shaft(table.model_copy(update={"diameter": 0.008}), torque, 30.0)
    assert thin.fatigue_safety < 1.0 and thin.failures()


@pytest.mark.parametrize("call, words", [
    (lambda: sd.section_stresses(0.0, (1.0, 0.0), (0.0, 0.0)), "diameter"),
    (lambda: sd.influence(1.0, 1.0, 1.2, 0.5), "between its bearings"),
    (lambda: sd.critical_speeds(1.0, 1.0, [1.0, -2.0], [0.2, 0.5]), "masses > 0"),
])
def test_bad_shaft_input_is_refused(call, words):
    with pytest.raises(InputError, match=words):
        call()


def test_a_wheel_outside_the_bearings_is_refused_by_check(tmp_path):
    from pathlib import Path

    example = Path(__file__).resolve().parents[2] / "examples" / "press_brake_clutch.toml"
    text = example.read_text()
    assert 'wheel_at = "90 mm"' in text
    bad = tmp_path / "bad.toml"
    bad.write_text(text.replace('wheel_at = "90 mm"', 'wheel_at = "400 mm"'))
    result = CliRunner().invoke(app, ["check", str(bad)])
    assert result.exit_code == 2, result.output
    assert "drivetrain.shafts[0]" in result.output and "between the bearings" in result.output
