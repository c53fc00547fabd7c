"""Problem files: every example and every mechanism type loads, builds, and survives dump -> load unchanged."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from machdyn.problem import build_mechanism, crank_angles, dump_problem
from machdyn.problem.dumper import format_quantity_exact
from machdyn.problem.fields import Unit
from machdyn.problem.schema import LinkageProblem
from machdyn.reading import load_problem
from machdyn.screen.schema import RotaryScreenProblem

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))
LINKAGE_EXAMPLES = [p for p in EXAMPLES if tomllib.loads(p.read_text()).keys() & {"mechanism", "rotary_screen"}]

DRIVE = '\n[drive]\nspeed = "300 rpm"\npositions = 72\n'

MECHANISMS = {
    "slider_crank": """
[mechanism]
type = "slider_crank"
offset = "5 mm"
slide_angle = "10 deg"
branch = -1
crank = {length = "40 mm", mass = "0.5 kg", inertia = "2e-4 kg*m^2", com = ["20 mm", "0 mm"]}
rod = {length = "160 mm"}
slider = {mass = "0.8 kg"}
""",
    "four_bar": """
[mechanism]
type = "four_bar"
name = "press"
branch = "crossed"
coupler_point = ["30 mm", "-12.5 mm"]
crank = {length = "40 mm"}
coupler = {length = "120 mm", mass = "0.3 kg"}
rocker = {length = "100 mm"}
ground = {length = "130 mm", angle = "5 deg"}
""",
    "inverted_slider_crank": """
[mechanism]
type = "inverted_slider_crank"
offset = "0 mm"
crank = {length = "50 mm", mass = "0.2 kg"}
ground = {length = "150 mm"}
block = {mass = "0.1 kg"}
rocker = {length = "250 mm", mass = "0.6 kg"}
""",
    "six_bar": """
[mechanism]
type = "six_bar"
crank = {length = "40 mm"}
coupler = {length = "120 mm"}
rocker = {length = "100 mm"}
ground = {length = "130 mm"}
coupler_point = ["60 mm", "30 mm"]
link5 = {length = "150 mm"}
link6 = {length = "120 mm"}
pivot6 = ["60 mm", "200 mm"]
branch2 = -1
""",
    "double_slider_crank": """
[mechanism]
type = "double_slider_crank"
crank = {length_1 = "3 mm", length_2 = "6 mm", phase = "90 deg", mass = "4 kg"}
rod_1 = {length = "200 mm"}
rod_2 = {length = "250 mm"}
slider_1 = {mass = "10 kg"}
slider_2 = {mass = "12 kg"}
offset_2 = "10 mm"
slide_angle_2 = "-90 deg"
""",
    "custom": """
[mechanism]
type = "custom"
name = "quick_return"
ground = {O = ["0 mm", "0 mm"], C = ["0 mm", "-150 mm"]}
crank = {body = "crank", pivot = "ground.O"}

[[mechanism.bodies]]
name = "crank"
mass = "0.4 kg"
inertia = "3e-4 kg*m^2"
com = ["25 mm", "0 mm"]
points = {O = ["0 mm", "0 mm"], A = ["50 mm", "0 mm"]}

[[mechanism.bodies]]
name = "block"
mass = "0.1 kg"
points = {A = ["0 mm", "0 mm"]}

[[mechanism.bodies]]
name = "lever"
mass = "1.2 kg"
inertia = "0.01 kg*m^2"
com = ["150 mm", "0 mm"]
points = {C = ["0 mm", "0 mm"], S = ["0 mm", "0 mm"], E = ["300 mm", "0 mm"]}

[[mechanism.dyads]]
type = "RPR"
a = "block"
b = "lever"
pin_a = "crank.A"
pin_b = "ground.C"
slide = {point = "S", angle = "0 deg"}
""",
}

LOADS = """
[loads]
gravity = ["0 m/s^2", "-9.81 m/s^2"]

[[loads.forces]]
point = "crank.{PIN}"
fx = "-20 N"
fy = "5 N"
active = ["30 deg", "90 deg"]

[[loads.torques]]
name = "brake"
body = "crank"
torque = "-0.5 N*m"

[[loads.springs]]
point_1 = "crank.{PIN}"
point_2 = "ground.O"
stiffness = "200 N/m"
free_length = "20 mm"

[[counterweights]]
body = "crank"
mass = "0.3 kg"
radius = "25 mm"
angle = "180 deg"

[output]
shaking_moment_about = ["10 mm", "-5 mm"]
harmonics = 4
"""


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_every_example_loads(path):
    problem = load_problem(path)
    assert problem is not None


@pytest.mark.parametrize("path", LINKAGE_EXAMPLES, ids=lambda p: p.stem)
def test_examples_round_trip(path):
    problem = load_problem(path)
    again = load_problem(dump_problem(problem))
    assert again == problem
    if isinstance(problem, LinkageProblem):
        assert build_mechanism(again) == build_mechanism(problem)
    elif isinstance(problem, RotaryScreenProblem):
        assert isinstance(again, RotaryScreenProblem)
        assert again.mechanism() == problem.mechanism()


@pytest.mark.parametrize("kind", sorted(MECHANISMS))
@pytest.mark.parametrize("with_loads", [False, True], ids=["bare", "loaded"])
def test_each_mechanism_type_round_trips(kind, with_loads):
    pin = "A1" if kind == "double_slider_crank" else "A"
    text = MECHANISMS[kind] + DRIVE + (LOADS.replace("{PIN}", pin) if with_loads else "")
    problem = load_problem(text)
    assert problem.mechanism.type == kind
    mech = build_mechanism(problem)
    dumped = dump_problem(problem)
    again = load_problem(dumped)
    assert again == problem
    assert build_mechanism(again) == mech
    # a dump of the dump is the same text
    assert dump_problem(again) == dumped


def test_units_are_converted_to_si():
    problem = load_problem(MECHANISMS["slider_crank"] + DRIVE + LOADS.replace("{PIN}", "A"))
    spec = problem.mechanism
    assert spec.crank.length == pytest.approx(0.040)
    assert spec.slide_angle == pytest.approx(math.radians(10))
    assert problem.drive.speed == pytest.approx(300 * 2 * math.pi / 60)
    assert problem.loads.forces[0].active == pytest.approx((math.radians(30), math.radians(90)))
    mech = build_mechanism(problem)
    assert mech.gravity == (0.0, -9.81)
    crank = mech.body("crank")
    assert (crank.mass, crank.inertia, crank.com) == (0.5, 2e-4, (0.02, 0.0))
    # a mass without an inertia: a uniform bar's m L^2 / 12; nothing given: the builder's default bar
    weights = mech.point_masses[0]
    assert weights.position == pytest.approx((-0.025, 0.0), abs=1e-15)
    assert crank_angles(problem).shape == (72,)


def test_mass_without_inertia_is_a_uniform_bar():
    problem = load_problem(MECHANISMS["four_bar"] + DRIVE)
    coupler = build_mechanism(problem).body("coupler")
    assert coupler.mass == 0.3
    assert coupler.inertia == pytest.approx(0.3 * 0.12**2 / 12)


def test_start_stop_positions():
    problem = load_problem(MECHANISMS["four_bar"] + '[drive]\nspeed = "1 rad/s"\nstart = "0 deg"\n'
                           'stop = "90 deg"\npositions = 10\n')
    angles = crank_angles(problem)
    assert angles[0] == 0.0 and angles[-1] == pytest.approx(math.pi / 2) and angles.size == 10


@given(st.floats(min_value=-1e6, max_value=1e6, allow_nan=False).filter(lambda x: x != 0.0))
def test_quantities_are_written_exactly(value):
    for meta in (Unit("m", "length"), Unit("rad", "angle"), Unit("rad/s", "angular_velocity"), Unit("kg", "mass")):
        text = format_quantity_exact(value, meta)
        from machdyn.units import parse_quantity

        assert parse_quantity(text, meta.unit) == value
