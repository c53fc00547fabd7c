"""A bare number is never read as an angle: every angle-valued field of a problem file needs its unit, whether
the number is written in quotes or as a TOML number; both ``check`` and ``run`` refuse it (exit 2) naming the
field, the value and the fix."""

from __future__ import annotations

import pytest

from machdyn.errors import InputError
from machdyn.units import parse_quantity

from .helpers import EXAMPLES, check_and_run

SLIDER = (EXAMPLES / "slider_crank.toml").read_text(encoding="utf-8")
OPTIMISE = (EXAMPLES / "compactor_optimise.toml").read_text(encoding="utf-8")
SWEEP = (EXAMPLES / "four_bar_sweep.toml").read_text(encoding="utf-8")

CASES = [
    ("active_window_in_quotes", SLIDER, 'active = ["300 deg", "360 deg"]', 'active = ["300", "360 deg"]',
     "loads.forces[0].active[0]", "'300 deg'"),
    ("active_window_toml_number", SLIDER, 'active = ["300 deg", "360 deg"]', 'active = ["300 deg", 360]',
     "loads.forces[0].active[1]", '"360 deg"'),
    ("slide_angle_in_quotes", SLIDER, 'slide_angle = "0 deg"', 'slide_angle = "-90"',
     "mechanism.slide_angle", "'-90 deg'"),
    ("counterweight_angle_percent", SLIDER, 'angle = "180 deg"', 'angle = "50 %"',
     "counterweights[0].angle", "deg"),
    ("optimiser_constraint_bound", OPTIMISE, 'min = "45 deg"', 'min = "40"',
     "optimise.constraints[1].min", "'40 deg'"),
    ("ground_angle", SWEEP, 'angle = "0 deg"', 'angle = "0"', "mechanism.ground.angle", "'0 deg'"),
]


@pytest.mark.parametrize(("base", "old", "new", "path", "fix"), [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_bare_angle_refused_by_check_and_run(tmp_path, base, old, new, path, fix):
    assert old in base
    check, run = check_and_run(tmp_path, base.replace(old, new, 1))
    assert check.code == 2 and run.code == 2, (check, run)
    for said in (check, run):
        assert path in said.stderr and fix in said.stderr, said.stderr
        assert "Traceback" not in said.stderr


def test_sweep_of_an_angle_needs_units(tmp_path):
    text = SWEEP.replace('parameter = "mechanism.crank.length"', 'parameter = "mechanism.ground.angle"')
    text = text.replace('start = "25 mm"', 'start = "10"').replace('stop = "55 mm"', 'stop = "20 deg"')
    check, run = check_and_run(tmp_path, text)
    assert check.code == 2 and run.code == 2
    assert "sweep.start" in check.stderr and "'10 deg'" in check.stderr


@pytest.mark.parametrize("value", ["40", "40 %", 40, 40.0, "1e-3"])
def test_parse_quantity_refuses_a_pure_number_for_an_angle(value):
    with pytest.raises(InputError, match="angle|unit"):
        parse_quantity(value, "rad", field="slide angle")


@pytest.mark.parametrize(("value", "expected"), [("40 deg", 0.6981317007977318), ("0.5 revolution", 3.141592653589793),
                                                  ("1 rad", 1.0), ("60 arcmin", 0.017453292519943295)])
def test_parse_quantity_reads_an_angle_with_its_unit(value, expected):
    assert parse_quantity(value, "rad") == pytest.approx(expected, rel=1e-15)


def test_dimensionless_fields_still_take_bare_numbers():
    assert parse_quantity("0.05", "") == 0.05 and parse_quantity(3, "") == 3.0
