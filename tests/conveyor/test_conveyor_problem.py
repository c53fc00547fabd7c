"""The [screw_conveyor] problem file: validation (every mistake at once), run, result object, HTML."""

import math
import re

import pytest

from machdyn.conveyor import load_conveyor_problem, run_conveyor
from machdyn.errors import InputError, MachdynWarning, ProblemFileError


def _problems(data):
    with pytest.raises(ProblemFileError) as info:
        load_conveyor_problem(data, source="test.toml")
    return dict(info.value.problems)


def test_valid_problem_runs_and_reports(base_problem):
    result = run_conveyor(load_conveyor_problem(base_problem))
    assert result.quantity("diameter").value == pytest.approx(200.0)
    assert set(result.powers) == {"textbook_360", "textbook_367", "iso7119", "cema"}
    assert result.selected_method == "iso7119"
    assert result.motor_rating >= result.motor_power_required
    rows = result.summary_rows()
    assert all(len(r) == 3 and all(isinstance(x, str) for x in r) for r in rows)
    scalars = result.scalars()
    assert scalars["diameter"] == {"value": pytest.approx(200.0), "unit": "mm"}
    assert scalars["power_iso7119"]["unit"] == "kW"
    for c in result.checks:
        assert c.utilisation == pytest.approx(c.value / c.limit)
        assert c.passed == (c.value <= c.limit)


def test_volume_and_mass_throughput_agree(base_problem):
    a = load_conveyor_problem(base_problem)
    base_problem["screw_conveyor"]["throughput"] = "6 m^3/h"
    b = load_conveyor_problem(base_problem)
    assert a.mass_flow == pytest.approx(b.mass_flow)


def test_every_mistake_reported_at_once(base_problem):
    sc = base_problem["screw_conveyor"]
    sc["length"] = "-21 m"
    sc["material"]["filling"] = 1.3
    sc["material"]["bulk_densty"] = "1 t/m^3"
    sc["inclination"] = "10 kg"
    sc["power_method"] = "iso7191"
    sc["screw"]["hanger_bearing"] = "bronz"
    problems = _problems(base_problem)
    assert problems["screw_conveyor.material.bulk_densty"] == (
        "Unknown key 'bulk_densty'. Did you mean 'bulk_density'?")
    assert problems["screw_conveyor.length"] == "The length must be > 0 m; got -21 m."
    assert problems["screw_conveyor.material.filling"] == "The filling coefficient must be <= 1; got 1.3."
    assert problems["screw_conveyor.inclination"].startswith("The inclination must be in units of")
    assert problems["screw_conveyor.power_method"].endswith("got 'iso7191'. Did you mean 'iso7119'?")
    assert problems["screw_conveyor.screw.hanger_bearing"].endswith("got 'bronz'. Did you mean 'bronze'?")
    assert len(problems) == 6


def test_missing_and_unknown_top_level(base_problem):
    del base_problem["screw_conveyor"]["length"]
    base_problem["screw_conveyer"] = {}
    problems = _problems(base_problem)
    assert problems["screw_conveyor.length"] == "This value is required and missing."
    assert problems["screw_conveyer"] == "Unknown key 'screw_conveyer'. Did you mean 'screw_conveyor'?"


def test_bad_throughput_unit(base_problem):
    base_problem["screw_conveyor"]["throughput"] = "6 m/h"
    problems = _problems(base_problem)
    assert problems["screw_conveyor.throughput"] == (
        "The throughput must be a mass flow (like \"7.2 t/h\") or a volume flow (like \"6 m^3/h\"); got '6 m/h'.")


def test_steep_screw_needs_explicit_factor_and_skips_iso(base_problem):
    base_problem["screw_conveyor"]["inclination"] = "25 deg"
    problems = _problems(base_problem)
    assert problems["screw_conveyor.inclination"] == (
        "The inclination factor table covers 0 to 20 deg; got 25 deg. Give screw.inclination_factor "
        "explicitly for steeper screws.")
    base_problem["screw_conveyor"]["screw"]["inclination_factor"] = 0.5
    base_problem["screw_conveyor"]["power_method"] = "textbook_367"
    with pytest.warns(MachdynWarning, match=re.escape(
            "ISO 7119 skipped: it applies to inclinations up to 20 deg; got 25 deg.")):
        result = run_conveyor(load_conveyor_problem(base_problem))
    assert "iso7119" not in result.powers
    assert any("ISO 7119 skipped" in w for w in result.warnings)


def test_selected_method_out_of_range_is_an_error(base_problem):
    base_problem["screw_conveyor"]["inclination"] = "25 deg"
    base_problem["screw_conveyor"]["screw"]["inclination_factor"] = 0.5
    with pytest.warns(MachdynWarning), pytest.raises(InputError, match=re.escape(
            "The power method 'iso7119' that sizes the drive is not applicable here")):
        run_conveyor(load_conveyor_problem(base_problem))


def test_failing_check_is_reported_not_hidden(base_problem):
    base_problem["screw_conveyor"]["screw"]["speed"] = "150 rpm"
    with pytest.warns(MachdynWarning, match="Check failed: Screw speed"):
        result = run_conveyor(load_conveyor_problem(base_problem))
    speed = next(c for c in result.checks if c.name.startswith("Screw speed"))
    assert not speed.passed and speed.utilisation > 1
    assert not result.passed
    assert "FAIL" in result.to_html_section()


def test_html_section_is_self_contained(base_problem):
    html = run_conveyor(load_conveyor_problem(base_problem)).to_html_section()
    assert html.startswith("<section") and html.rstrip().endswith("</section>")
    for title in ("Design", "Power by method", "Checks"):
        assert f"<h3>{title}</h3>" in html
    assert "http" not in html and "<script" not in html and "src=" not in html


def test_power_methods_ranked_sensibly(base_problem):
    result = run_conveyor(load_conveyor_problem(base_problem))
    p = {k: v.shaft_power for k, v in result.powers.items()}
    # /360 uses g = 10, so it exceeds the /367 form by 10/g
    assert p["textbook_360"] / p["textbook_367"] == pytest.approx(10 / 9.80665)
    # ISO 7119 = /367 form + no-load D L/20 when lambda = C0
    assert p["iso7119"] - p["textbook_367"] == pytest.approx(1000 * 0.2 * 21 / 20)
    assert math.isfinite(p["cema"]) and p["cema"] > 0
