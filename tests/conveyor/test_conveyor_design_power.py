"""Unit tests of the design and power formulas (physics relations, not only numbers)."""

import math
import re

import pytest

from machdyn.conveyor import design, power, tables
from machdyn.errors import InputError


def test_diameter_for_duty_inverts_capacity_at_the_speed_limit():
    d = design.diameter_for_duty(0.01, 1.0, 60, 0.3, 0.9)
    n = design.speed_limit(d, 60)
    capacity = design.volume_capacity(d, d, angular_speed=n, filling=0.3, inclination_factor=0.9)
    assert capacity == pytest.approx(0.01, rel=1e-12)


def test_design_meets_duty_and_standard_size():
    des = design.design_screw(mass_flow=2.0, bulk_density=1200, filling=0.4, speed_coefficient=45,
                              pitch_ratio=0.8, inclination_factor=0.8)
    assert des.diameter in tables.standard_diameters()
    assert des.diameter >= des.diameter_required
    assert des.capacity_mass >= des.mass_flow
    assert des.speed == pytest.approx(des.speed_limit)
    assert des.filling_actual <= des.filling


def test_filling_above_one_is_rejected_with_value_and_limit():
    with pytest.raises(InputError, match=re.escape("The filling coefficient must be <= 1; got 1.3.")):
        design.design_screw(mass_flow=2.0, bulk_density=1200, filling=1.3, speed_coefficient=45,
                            pitch_ratio=0.8, inclination_factor=0.8)


def test_throughput_beyond_largest_standard_size():
    with pytest.raises(InputError, match=r"The throughput 3\.6e\+04 t/h .* exceeds the capacity of the largest "
                                         r"standard screw \(1250 mm at 40\.2 rpm\)"):
        design.design_screw(mass_flow=1e4, bulk_density=1200, filling=0.4, speed_coefficient=45,
                            pitch_ratio=0.8, inclination_factor=0.8)


def test_next_standard_diameter():
    assert design.next_standard_diameter(0.16496) == pytest.approx(0.2)
    assert design.next_standard_diameter(0.2) == pytest.approx(0.2)
    with pytest.raises(InputError, match=re.escape("The required screw diameter 1300 mm exceeds the largest "
                                                   "standard size 1250 mm.")):
        design.next_standard_diameter(1.3)


def test_iso7119_parts_in_si():
    r = power.power_iso7119(mass_flow=10 / 3.6, length=20, inclination=math.radians(10), diameter=0.3,
                            progress_resistance=2.5)
    # P_H = I_m L lambda / 367 kW with I_m = 10 t/h (367 = 3600/g)
    assert r.progress == pytest.approx(1000 * 10 * 20 * 2.5 * power.G / 3600, rel=1e-12)
    assert r.no_load == pytest.approx(1000 * 0.3 * 20 / 20, rel=1e-12)
    assert r.inclination == pytest.approx(1000 * 10 * 20 * math.sin(math.radians(10)) * power.G / 3600)
    assert r.total == pytest.approx(r.progress + r.no_load + r.inclination)


def test_iso7119_range_is_enforced():
    with pytest.raises(InputError, match=re.escape("ISO 7119 applies to inclinations up to 20 deg; got 25 deg.")):
        power.power_iso7119(1.0, 10, math.radians(25), 0.2, 2.5)


def test_textbook_forms_differ_only_by_g():
    p360 = power.power_textbook_360(2.0, 21, 3.65, 2.5)
    p367 = power.power_textbook_367(2.0, 21, 3.65, 2.5)
    assert p360 / p367 == pytest.approx(10 / power.G, rel=1e-12)


def test_cema_units_and_overload():
    # HPf = L N Fd Fb / 1e6 in ft and rpm (the speed given in rad/s: 50 rpm)
    assert power.cema_friction_hp(100 * 0.3048, 50 * math.pi / 30, 55, 1.7) == pytest.approx(100 * 50 * 55 * 1.7 / 1e6)
    # HPm = C L W Ff Fm Fp / 1e6, C ft^3/h, W lb/ft^3
    c_ft3h, w = 1000.0, 50.0
    vol = c_ft3h * 0.3048**3 / 3600
    rho = w * 0.45359237 / 0.3048**3
    assert power.cema_material_hp(vol, rho, 100 * 0.3048, 1.0, 1.4) == pytest.approx(1000 * 100 * 50 * 1.4 / 1e6)
    assert tables.cema_overload_factor(0.1) == 3.0
    assert tables.cema_overload_factor(0.2) == pytest.approx(3.0)
    assert tables.cema_overload_factor(5.2) == pytest.approx(1.0)
    assert tables.cema_overload_factor(10) == 1.0
    # straight line on log scale: the geometric mean sits half way
    assert tables.cema_overload_factor(math.sqrt(0.2 * 5.2)) == pytest.approx(2.0)


def test_cema_total_applies_overload_and_efficiency():
    r = power.power_cema(volume_flow=0.01, bulk_density=800, length=10, speed=2 * math.pi, diameter_factor=55,
                         hanger_bearing_factor=1.7, material_factor=1.0, efficiency=0.9)
    assert r.total_hp == pytest.approx((r.friction_hp + r.material_hp) * r.overload_factor / 0.9)
    with pytest.raises(InputError, match=re.escape("The drive efficiency must be in (0, 1]; got 1.2.")):
        power.power_cema(volume_flow=0.01, bulk_density=800, length=10, speed=2 * math.pi, diameter_factor=55,
                         hanger_bearing_factor=1.7, material_factor=1.0, efficiency=1.2)


def test_table_lookups_name_the_value_and_suggest():
    assert tables.cema_diameter_factor(12 * 0.0254) == pytest.approx(55.0)
    assert tables.cema_diameter_factor(0.2) == pytest.approx(18 + 13 * (0.2 / 0.0254 - 6) / 3)
    assert tables.cema_hanger_bearing_factor("bronze") == 1.7
    with pytest.raises(InputError, match=re.escape("got 'bronz'. Did you mean 'bronze'?")):
        tables.cema_hanger_bearing_factor("bronz")
    with pytest.raises(InputError, match=re.escape("The flight type 'cut_and_folded' has no value for loading_15")):
        tables.cema_flight_factor("cut_and_folded", 0.1)
    assert tables.inclination_factor(math.radians(10)) == pytest.approx(0.8)
    assert tables.inclination_factor(math.radians(12.5)) == pytest.approx(0.75)


def test_motor_selection_next_iec_rating():
    """The conveyor's drive is chosen from the one IEC 60072-1 table by the shared selection."""
    from machdyn.dynamics.motors import smallest_rating

    assert smallest_rating(1276.0) == 1500.0
    assert smallest_rating(1500.0) == 1500.0
    assert math.isnan(smallest_rating(250e3))


