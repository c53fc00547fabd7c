"""The [screw_conveyor] problem file: validation (every mistake at once), run, SI results, HTML section."""

import math

import pytest

from machdyn.conveyor import check, evaluate, load_conveyor_problem, run, run_conveyor, validate
from machdyn.errors import InputError, ProblemFileError


def _problems(data):
    with pytest.raises(ProblemFileError) as info:
        validate(data, source="test.toml")
    return dict(info.value.problems)


def test_valid_problem_runs_and_reports_in_si(base_problem):
    result = evaluate(validate(base_problem))
    assert result.scalars["diameter"] == pytest.approx(0.200)
    assert result.scalars["speed"] == pytest.approx(45 / math.sqrt(0.2) * math.pi / 30)  # rad/s
    assert set(result.powers) == {"textbook_360", "textbook_367", "iso7119", "cema"}
    assert result.selected_method == "iso7119"
    assert result.motor_rating >= result.motor_power_required
    for c in result.checks:
        assert c.utilisation == pytest.approx(c.value / c.limit)
        assert c.passed == (c.value <= c.limit)
    with pytest.raises(AttributeError):  # frozen
        result.selected_method = "cema"  # type: ignore[misc]


def test_old_names_still_work(base_problem):
    old = run_conveyor(load_conveyor_problem(base_problem))
    assert old.quantity("diameter").value == pytest.approx(0.2)
    assert old.scalars()["power_iso7119"]["unit"] == "W"
    rows = old.summary_rows()
    assert ("Diameter", "200", "mm") in rows


def test_kind_interface_outcome(base_problem):
    problem = validate(base_problem)
    steps = []
    outcome = run(problem, steps.append)
    assert steps == ["design"]
    assert outcome.scalars["shaft_power"] == pytest.approx(outcome.results.shaft_power)
    assert outcome.labels["shaft_power"].display == "kW"
    assert all(k in outcome.scalars for k in outcome.summary)
    assert outcome.failed_checks == ()
    assert check(problem) == list(outcome.warnings)


def test_volume_and_mass_throughput_agree(base_problem):
    a = validate(base_problem)
    base_problem["screw_conveyor"]["throughput"] = "6 m^3/h"
    b = validate(base_problem)
    assert a.mass_flow == pytest.approx(b.mass_flow)


def test_every_mistake_reported_at_once(base_problem):
    sc = base_problem["screw_conveyor"]
    sc["length"] = "-21 m"
    sc["material"]["filling"] = 1.3
    sc["material"]["bulk_densty"] = "1 t/m^3"
    sc["inclination"] = "10 kg"
    sc["power_method"] = "iso7191"
    sc["screw"]["hanger_bearing"] = "bronz"
    del sc["material"]["resistance"]
    problems = _problems(base_problem)
    assert problems["screw_conveyor.material.bulk_densty"] == (
        "unknown key 'bulk_densty'; did you mean 'bulk_density'?")
    assert problems["screw_conveyor.length"] == "must be > 0 m; got '-21 m'"
    assert problems["screw_conveyor.material.filling"] == "must be in (0, 1]; got 1.3"
    assert problems["screw_conveyor.inclination"].startswith("must be in units of")
    assert problems["screw_conveyor.power_method"].endswith("got 'iso7191'; did you mean 'iso7119'?")
    assert problems["screw_conveyor.screw.hanger_bearing"].endswith("got 'bronz'. Did you mean 'bronze'?")
    assert problems["screw_conveyor.material.resistance"].startswith("required: the resistance coefficient")
    assert len(problems) == 7


@pytest.mark.parametrize(("path", "value"), [
    (("length",), "inf m"), (("length",), "1e300 m"), (("material", "bulk_density"), "1e300 kg/m^3"),
    (("screw", "speed"), "1e300 rpm"), (("throughput",), "1e300 t/h"), (("strength", "elastic_modulus"), "nan Pa"),
])
def test_absurd_values_are_refused_with_the_field_named(base_problem, path, value):
    node = base_problem["screw_conveyor"]
    for key in path[:-1]:
        node = node.setdefault(key, {})
    node[path[-1]] = value
    problems = _problems(base_problem)
    assert "screw_conveyor." + ".".join(path) in problems


def test_missing_and_unknown_top_level(base_problem):
    del base_problem["screw_conveyor"]["length"]
    base_problem["screw_conveyer"] = {}
    problems = _problems(base_problem)
    assert problems["screw_conveyor.length"] == "required, but missing"
    assert problems["screw_conveyer"].startswith("unknown key 'screw_conveyer'")


def test_bad_throughput_unit(base_problem):
    base_problem["screw_conveyor"]["throughput"] = "6 m/h"
    problems = _problems(base_problem)
    assert problems["screw_conveyor.throughput"] == (
        "must be a mass flow (like \"7.2 t/h\") or a volume flow (like \"6 m^3/h\"); got '6 m/h'")


def test_steep_screw_needs_explicit_factor_and_skips_iso(base_problem):
    base_problem["screw_conveyor"]["inclination"] = "25 deg"
    problems = _problems(base_problem)
    assert problems["screw_conveyor.inclination"] == (
        "The inclination factor table covers 0 to 20 deg; got 25 deg. Give screw.inclination_factor "
        "explicitly for steeper screws.")
    base_problem["screw_conveyor"]["screw"]["inclination_factor"] = 0.5
    base_problem["screw_conveyor"]["power_method"] = "textbook_367"
    result = evaluate(validate(base_problem))
    assert "iso7119" not in result.powers
    assert [w for w in result.warnings if "ISO 7119 skipped" in w] == [
        "ISO 7119 skipped: it applies to inclinations up to 20 deg; got 25 deg."]


def test_selected_method_out_of_range_is_refused_by_validate_check_and_run(base_problem):
    base_problem["screw_conveyor"]["inclination"] = "25 deg"
    base_problem["screw_conveyor"]["screw"]["inclination_factor"] = 0.5
    problems = _problems(base_problem)
    assert problems["screw_conveyor.power_method"].startswith("'iso7119' applies to inclinations up to 20 deg")
    # a problem built in Python past the file's validation: check and run refuse it alike
    base_problem["screw_conveyor"]["power_method"] = "textbook_367"
    problem = validate(base_problem).replace(power_method="iso7119")
    with pytest.raises(ProblemFileError, match="The power method 'iso7119' that sizes the drive is not applicable"):
        check(problem)
    with pytest.raises(InputError, match="The power method 'iso7119' that sizes the drive is not applicable"):
        evaluate(problem)


def test_failing_check_is_reported_once_in_one_wording(base_problem):
    base_problem["screw_conveyor"]["screw"]["speed"] = "150 rpm"
    outcome = run(validate(base_problem))
    result = outcome.results
    speed = next(c for c in result.checks if c.name.startswith("Screw speed"))
    assert not speed.passed and speed.utilisation > 1
    assert not result.passed
    assert outcome.failed_checks == ("Screw speed n <= k/sqrt(D): 150 rpm > limit 100.6 rpm",)
    assert not any("Screw speed" in w for w in outcome.warnings)
    from machdyn.report.conveyor import conveyor_html_section

    assert "FAIL" in conveyor_html_section(run_conveyor(validate(base_problem)).result)


def test_html_section_is_self_contained(base_problem):
    from machdyn.report.conveyor import conveyor_html_section

    html = conveyor_html_section(evaluate(validate(base_problem)))
    assert html.startswith("<section") and html.rstrip().endswith("</section>")
    for title in ("Design", "Power by method", "Checks", "Bending along one span"):
        assert f"<h3>{title}</h3>" in html
    assert "<svg" in html and "<script" not in html and 'src="http' not in html


def test_power_methods_ranked_sensibly(base_problem):
    result = evaluate(validate(base_problem))
    p = {k: v.shaft_power for k, v in result.powers.items()}
    # /360 uses g = 10, so it exceeds the /367 form by 10/g
    assert p["textbook_360"] / p["textbook_367"] == pytest.approx(10 / 9.80665)
    # ISO 7119 = /367 form + no-load D L/20 when lambda = C0
    assert p["iso7119"] - p["textbook_367"] == pytest.approx(1000 * 0.2 * 21 / 20)
    assert math.isfinite(p["cema"]) and p["cema"] > 0


def test_duty_beyond_the_largest_screw_is_refused_at_validation(base_problem):
    base_problem["screw_conveyor"]["throughput"] = "5000 t/h"
    problems = _problems(base_problem)
    assert "exceeds the capacity of the largest standard screw" in problems["screw_conveyor.throughput"]


def test_pipe_larger_than_the_chosen_screw_is_refused_at_validation(base_problem):
    # with the whole circle as the capacity's section the duty chooses 200 mm whatever the pipe (with the pipe
    # deducted, the default, the duty chooses a screw around the pipe: see test_capacity_deducts_the_pipe...)
    base_problem["screw_conveyor"]["screw"]["capacity_section"] = "circle"
    base_problem["screw_conveyor"]["screw"]["pipe_outer_diameter"] = "250 mm"
    problems = _problems(base_problem)
    assert problems["screw_conveyor.screw.pipe_outer_diameter"] == "must be < the screw diameter 0.2 m; got 0.25 m"
