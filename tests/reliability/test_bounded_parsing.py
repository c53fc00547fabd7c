"""Quantities and derived formulas are parsed by bounded grammars: no text can make machdyn compute for long."""

from __future__ import annotations

import time

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from machdyn.errors import InputError
from machdyn.problem.fields import FieldError, Unit
from machdyn.studies.optimisation.formula import MAX_FORMULA_TEXT, compile_formula
from machdyn.units import MAX_QUANTITY_TEXT, parse_quantity

from .conftest import FOUR_BAR, machdyn

POWER_TOWERS = ["9**9**9 mm", "2**2**33 mm", "10^10^10 mm", "(9**9)**9 mm", "9e9**9e9 mm", "mm**99999999"]


@pytest.mark.parametrize("text", POWER_TOWERS)
def test_a_quantity_written_as_a_power_tower_is_refused_at_once(text):
    start = time.perf_counter()
    with pytest.raises(InputError, match="not a quantity with a unit"):
        parse_quantity(text, "m", field="crank length")
    assert time.perf_counter() - start < 0.05


def test_check_refuses_a_power_tower_length_in_seconds(write):
    path = write(FOUR_BAR.replace('length = "40 mm"', 'length = "9**9**9 mm"'))
    code, _, err, seconds = machdyn("check", str(path), timeout=60)
    assert code == 2
    assert "mechanism.crank.length" in err and "9**9**9 mm" in err and "Traceback" not in err
    assert seconds < 30  # the interpreter's start and imports; the parse itself takes microseconds


@pytest.mark.parametrize(("text", "value"), [
    ("45 mm", 0.045), ("1.2 t/m^3", 1200.0), ("5 N*m*s/rad", 5.0), ("-1.5 N*m", -1.5), ("0.02 kg*m^2", 0.02),
    ("2 kg·m²", 2.0), ("1e3 mm", 1.0), ("3 (m/s)**2/m", 3.0), (".5 m", 0.5), ("7 N m", 7.0),
])
def test_quantities_written_as_users_write_them_still_parse(text, value):
    unit = {"45 mm": "m", "1.2 t/m^3": "kg/m^3", "5 N*m*s/rad": "N*m*s/rad", "1e3 mm": "m", ".5 m": "m",
            "3 (m/s)**2/m": "m/s^2"}.get(text, "N*m" if "N" in text else "kg*m^2")
    assert parse_quantity(text, unit) == pytest.approx(value, rel=1e-15)


TEXT = st.text(alphabet=st.sampled_from(list("0123456789.eE+-*/^() mkgsNradegµ²³·,%°xinf")), max_size=MAX_QUANTITY_TEXT)


@settings(max_examples=50, deadline=None)
@given(TEXT)
def test_any_quantity_text_up_to_the_limit_is_decided_within_50_ms(text):
    start = time.perf_counter()
    try:
        value = parse_quantity(text, "m", field="length")
    except InputError:
        value = None
    assert time.perf_counter() - start < 0.05
    assert value is None or np.isfinite(value)


@settings(max_examples=50, deadline=None)
@given(st.text(max_size=MAX_QUANTITY_TEXT))
def test_any_unicode_text_up_to_the_limit_is_decided_within_50_ms(text):
    start = time.perf_counter()
    try:
        parse_quantity(text, "m", field="length")
    except InputError:
        pass
    assert time.perf_counter() - start < 0.05


@pytest.mark.parametrize("formula", ["9**9**9", "r ** 9**9**9", "r ** (9**9)", "2**2**33", "r**1e300"])
def test_a_derived_formula_with_a_huge_exponent_is_refused_when_compiled(formula):
    start = time.perf_counter()
    with pytest.raises(FieldError, match="power|larger than"):
        compile_formula("mechanism.rocker.length", formula, ["r"], Unit("m", "length"))
    assert time.perf_counter() - start < 0.05


@pytest.mark.parametrize("formula", ["+".join(["r"] * 300), "r" + "*1" * 250, "x" * (MAX_FORMULA_TEXT + 1)])
def test_a_derived_formula_of_too_many_operations_is_refused(formula):
    with pytest.raises(FieldError, match="at most"):
        compile_formula("mechanism.rocker.length", formula, ["r"], Unit("m", "length"))


def test_a_derived_formula_is_evaluated_as_numpy_arithmetic_of_floats():
    f = compile_formula("mechanism.rocker.length", "hypot(r, 0.1) + 2.5 * r**2 - sin(pi / 6) * atan2(r, 1)",
                        ["r"], Unit("m", "length"))
    r = np.array([0.02, 0.05, 0.1])
    expected = np.hypot(r, 0.1) + 2.5 * r**2 - np.sin(np.pi / 6) * np.arctan2(r, 1)
    assert np.array_equal(f({"r": r}), expected)
    overflow = compile_formula("mechanism.rocker.length", "r ** 16 * 1e12 ** 16", ["r"], Unit("m", "length"))
    assert not np.isfinite(overflow({"r": np.array([1e12])})).any()  # inf marks the design unbuildable


def test_check_refuses_a_derived_power_tower_naming_the_field(write):
    text = FOUR_BAR + """
[[optimise.objectives]]
result = "max_driving_torque"
[[optimise.variables]]
parameter = "mechanism.crank.length"
lower = "30 mm"
upper = "45 mm"
name = "r"
[optimise.derived]
"mechanism.rocker.length" = "r ** 9**9**9"
"""
    path = write(text)
    code, _, err, seconds = machdyn("check", str(path), timeout=60)
    assert code == 2, err
    assert "optimise.derived.mechanism.rocker.length" in err and "Traceback" not in err
    assert seconds < 30
