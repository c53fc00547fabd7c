"""Geared systems and hoists against printed textbook answers."""

from __future__ import annotations

import json

import pytest
from typer.testing import CliRunner

from machdyn.constants import STANDARD_GRAVITY
from machdyn.drivetrain.hoist import Drum, Shaft, acceleration, hoist, optimum_ratio


def test_khurmi_gupta_example_3_14_gear_ratio_for_the_largest_load_acceleration():
    """Khurmi & Gupta, *Theory of Machines* (14th ed.), ch. 3, example 3.14, p. 51: motor torque 100 N m, motor
    inertia 2 kg m^2, load inertia 32 kg m^2; printed: optimum ratio 4, load acceleration 6.25 rad/s^2, motor
    acceleration 25 rad/s^2 (exact values: tolerance rounding)."""
    g = optimum_ratio(2.0, 32.0)
    assert g == pytest.approx(4.0, rel=1e-12)
    train = (Shaft("motor", inertia=2.0), Shaft("load", "motor", g, 1.0, 32.0))
    alpha_motor = acceleration(train, 100.0)
    assert alpha_motor == pytest.approx(25.0, rel=1e-10)
    assert alpha_motor / g == pytest.approx(6.25, rel=1e-10)
    # and it is the optimum: the same train with a ratio 5 % either side accelerates the load less
    for other in (0.95 * g, 1.05 * g):
        near = (Shaft("motor", inertia=2.0), Shaft("load", "motor", other, 1.0, 32.0))
        assert acceleration(near, 100.0) / other < 6.25


# V. B. Bhandari, *Design of Machine Elements*, 3rd ed., Tata McGraw-Hill 2010, ch. 12 "Brakes": three examples
# whose brakes hold or stop a hoist or a vehicle, i.e. a train of shafts with a rope drum (or road wheels). The
# book's data and printed answers are those of the public FOSSEE Scilab Textbook Companion no. 764
# (FOSSEE/Scilab-TBC-Uploads, 764/CH12/EX12.n: data12_n.sci, result12_n.txt, six decimals); the book's pages were
# not available here. The book takes g = 9.81 m/s², passed to machdyn as such.
G_BOOK = 9.81


def test_bhandari_example_12_2_car_braked_as_a_branched_train():
    """Bhandari, 3rd ed., Example 12.2 (764/CH12/EX12.2): a 1000 kg car on four wheels of 0.5 kg m² and 0.35 m
    rolling radius, the engine's other parts 2.5 kg m² turning 5 times as fast as the wheels, braked at 0.5 g from
    100 km/h. Printed: energy absorbed by each brake 147234.819854 J, torque of each brake 655.167857 N m (the
    companion notes an error in the book's own printout and prints these). machdyn: the wheels' axle as the root
    shaft (4 × 0.5 kg m²) with the car as a drum of radius 0.35 m and no gravity (the road is level), the engine
    a child shaft of ratio 1/5; the torque to decelerate it at 0.5 g / R split over four brakes, and the kinetic
    energy ½ J_eq ω² over four. Tolerance one unit of the sixth decimal."""
    train = (Shaft("wheels", inertia=4 * 0.5, drums=(Drum(0.35, 1000.0),)),
             Shaft("engine", "wheels", ratio=1 / 5, inertia=2.5))
    res = hoist(train, -0.5 * G_BOOK / 0.35, gravity=0.0)
    assert -res.motor_torque / 4 == pytest.approx(655.167857, abs=1e-6)
    omega = 100 / 3.6 / 0.35
    assert 0.5 * res.equivalent_inertia * omega**2 / 4 == pytest.approx(147234.819854, abs=1e-6)


def test_bhandari_example_12_3_descending_load_stopped_by_the_drum_brake():
    """Bhandari, 3rd ed., Example 12.3 (764/CH12/EX12.3): 2500 kg descending at 1.5 m/s on a drum of 0.75 m
    radius (50 kg, radius of gyration 0.7 m) is stopped in 0.5 m. Printed: brake torque M_t = 22686 N m. The
    cage decelerates downwards at v²/(2 h) = 2.25 m/s², i.e. accelerates upwards: machdyn's torque at the drum
    for that upward acceleration (holding the weight and decelerating the masses) is the printed torque, exact
    in the data (tolerance 1e-9)."""
    train = (Shaft("drum", inertia=50 * 0.7**2, drums=(Drum(0.75, 2500.0, name="load"),)),)
    res = hoist(train, 1.5**2 / (2 * 0.5) / 0.75, gravity=G_BOOK)
    assert res.cage_acceleration["load"] == pytest.approx(2.25, rel=1e-12)
    assert res.motor_torque == pytest.approx(22686.0, rel=1e-9)


def test_bhandari_example_12_6_load_held_through_a_gear_and_its_lowering_speed():
    """Bhandari, 3rd ed., Example 12.6 (764/CH12/EX12.6): a 500 kg mass hangs from a cable drum of 150 mm radius
    geared 4 : 1 to a brake drum of 200 mm radius, μ = 0.2, p_max = 1 N/mm², pv limit 2 N/mm² m/s. Printed: brake
    shoe force P = 4598.4375 N; the mass can be lowered uniformly at 0.375 m/s. machdyn: the brake drum as the
    root shaft, the cable drum on a shaft of ratio 4; the torque that holds the load at the brake, T / (μ R_b),
    is the printed force; the cage moves at the shaft's speed ratio times the brake drum's speed at the pv limit,
    ω_b = (pv / p) / R_b."""
    train = (Shaft("brake drum"), Shaft("cable drum", "brake drum", ratio=4.0, drums=(Drum(0.15, 500.0),)))
    held = hoist(train, 0.0, gravity=G_BOOK)
    assert held.motor_torque / (0.2 * 0.200) == pytest.approx(4598.4375, abs=1e-6)
    omega_brake = (2.0 / 1.0) / 0.200
    assert omega_brake * held.speed_ratio["cable drum"] * 0.15 == pytest.approx(0.375, rel=1e-12)


BHANDARI_12_3 = """[meta]
name = "Bhandari, Design of Machine Elements, Example 12.3"

[hoist]
cage_acceleration = "2.25 m/s^2"   # the descending load decelerated from 1.5 m/s in 0.5 m
drum = "load"

[[hoist.shafts]]
name = "drum"
inertia = "24.5 kg*m^2"             # 50 kg at 0.7 m

[[hoist.shafts.drums]]
name = "load"
radius = "0.75 m"
cage = "2500 kg"
"""


def test_bhandari_example_12_3_through_a_problem_file_and_the_command_line(tmp_path):
    """Bhandari, 3rd ed., Example 12.3 as a ``[hoist]`` problem file run by ``machdyn run``: ``hoist.motor_torque``
    is the printed brake torque 22686 N m once the book's g = 9.81 m/s² is put in for the file's standard
    9.80665 m/s² (the weight's share m g R changes by m R Δg = 6.28 N m; the rest is exact: tolerance 1e-9)."""
    from machdyn.cli import app

    path = tmp_path / "bhandari_12_3.toml"
    path.write_text(BHANDARI_12_3)
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(out), "-q"])
    assert result.exit_code == 0, result.output
    scalars = {k: v["value"] for k, v in json.loads((out / "results.json").read_text())["scalars"].items()}
    book_weight = 2500.0 * 0.75 * (G_BOOK - STANDARD_GRAVITY)
    assert scalars["hoist.motor_torque"] + book_weight == pytest.approx(22686.0, rel=1e-9)
    assert scalars["hoist.load.rope_tension"] == pytest.approx(2500.0 * (STANDARD_GRAVITY + 2.25), rel=1e-9)  # N
