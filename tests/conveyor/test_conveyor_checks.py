"""Unit tests of the load and check formulas."""

import math
import re

import pytest

from machdyn.conveyor import checks as ck
from machdyn.errors import InputError


def test_axial_force_is_torque_over_lead_for_a_frictionless_screw():
    # with f -> 0, F_a = T/(R tan alpha) = 2 pi T / S: the work T*2pi per turn equals F_a * S
    t, s, r = 100.0, 0.16, 0.07
    alpha = ck.helix_angle(s, r)
    assert ck.axial_force(t, r, alpha, 1e-12) == pytest.approx(2 * math.pi * t / s, rel=1e-9)
    assert ck.axial_force(t, r, alpha, 0.5) < 2 * math.pi * t / s


def test_axial_force_rejects_self_locking_geometry():
    with pytest.raises(InputError, match="The helix angle plus the friction angle must be < 90 deg"):
        ck.axial_force(100.0, 0.07, math.radians(50), 1.0)


def test_torque_from_power():
    assert ck.torque_from_power(1000.0, angular_speed=1.0) == pytest.approx(1000.0)  # 1 kW at 1 rad/s
    with pytest.raises(InputError, match=re.escape("The screw speed must be > 0 rad/s; got 0 rad/s.")):
        ck.torque_from_power(1000.0, angular_speed=0.0)


def test_tube_section_and_twist():
    jp = ck.polar_moment_tube(0.1, 0.088)
    assert jp == pytest.approx(math.pi / 32 * (0.1**4 - 0.088**4))
    # uniform torque: twist of the whole length is half that of the full torque at one end
    t, length, g = 100.0, 21.0, 8e10
    assert ck.torsion_angle_distributed(t / length, length, g, jp) == pytest.approx(t * length / (g * jp) / 2)
    assert ck.shear_stress_tube(t, 0.1, 0.088) == pytest.approx(t * 0.05 / jp)
    with pytest.raises(InputError, match="The pipe needs outer diameter > inner diameter >= 0"):
        ck.polar_moment_tube(0.05, 0.06)


def test_seed_polar_moment_overestimates_the_exact_tube():
    assert ck.polar_moment_seed(0.2, 0.5) / ck.polar_moment_tube(0.2, 0.1) == pytest.approx(1.5e-4 / 1.4726e-4,
                                                                                            rel=1e-4)


def test_span_formulas():
    q, l_span, e, i = 200.0, 3.0, 2.1e11, 2e-6
    assert ck.span_bending_moment(q, l_span) == pytest.approx(225.0)
    assert ck.span_deflection(q, l_span, e, i) == pytest.approx(5 * 200 * 81 / (384 * 2.1e11 * 2e-6))


def test_base_bolts_symmetric_case():
    # with no lever and a -> 0 the moment still acts; with b -> 0 and a given, cos(theta) = 1 and forces add
    f = ck.base_bolt_max_force(400.0, 0.0, 0.0, 0.2, 0.0)
    f_z = 100.0
    f_m = (0.1 * 400.0) / (4 * 0.1)
    assert f == pytest.approx(f_z + f_m)
    d3 = ck.bolt_minor_diameter_required(f, 120e6)
    assert d3 == pytest.approx(math.sqrt(1.3 * 4 * 2 * f / (0.2 * math.pi * 120e6)))


def test_check_object():
    c = ck.Check("x", 5.0, 10.0, "MPa")
    assert c.passed and c.utilisation == 0.5
    assert not ck.Check("x", 11.0, 10.0, "MPa").passed


def test_check_functions_named_in_the_docs_are_exported():
    """Every function docs/conveyor.md names as exported from machdyn.conveyor is there and callable."""
    from pathlib import Path

    import machdyn.conveyor as conveyor

    doc = (Path(__file__).resolve().parents[2] / "docs" / "conveyor.md").read_text(encoding="utf-8")
    start = doc.index("The check functions are exported from `machdyn.conveyor`")
    names = re.findall(r"`([a-z_]+)`", doc[start:doc.index("\n\n", start)])
    assert {"axial_force", "helix_angle", "lateral_load", "torque_from_power"} <= set(names)
    for name in names:
        assert callable(getattr(conveyor, name)), name
        assert name in conveyor.__all__
