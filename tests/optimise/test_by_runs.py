"""``[optimise]`` in a file of a kind with no linkage population: every design run whole through the file's own
stages. The worked case: the crank phases of a four-cylinder in-line engine."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from machdyn.errors import ProblemFileError
from machdyn.runner import check_problem, run_problem

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "shaft_inline_four_phases_optimise.toml"


def test_the_optimiser_finds_the_in_line_fours_0_180_180_0_shaft():
    """Outer cranks at 0 deg, the inner two free: the primary couple about the central plane vanishes for equal
    inner phases, the primary force too only for both at 180 deg — the four-crank engine's balanced shaft of every
    text (Khurmi & Gupta, *Theory of Machines*, ch. 22). Tolerances: the search's best of 40 generations of 24
    designs lands within 0.5 deg, where the residual primary force is below 1e-3 of one cylinder's
    m r omega^2 (the constraint allows 1 N of 7,900 N)."""
    run = run_problem(EXAMPLE)
    best = run.outcomes["optimise"].results
    assert best.verified
    phases = [math.degrees(v) for v in best.x]
    assert phases == pytest.approx([180.0, 180.0], abs=0.5)
    one_cylinder = 1.0 * 0.045 * (4000 * math.pi / 30) ** 2  # (0.6 + 0.4) kg x 45 mm x omega^2
    assert best.results["shaft.engine.primary_force"] < 1e-3 * one_cylinder
    assert best.results["shaft.engine.primary_couple"] < 1e-3 * one_cylinder * 0.135
    alone = run_problem(best.problem_text)  # the best design written out and run on its own
    assert alone.results["shaft.engine.primary_couple"] == pytest.approx(best.results["shaft.engine.primary_couple"],
                                                                         rel=1e-12)


def test_a_result_the_shaft_line_does_not_report_is_refused_by_check_and_run_alike():
    text = EXAMPLE.read_text(encoding="utf-8").replace('result = "shaft.engine.primary_couple"',
                                                       'result = "shaft.engine.primary_coupel"')
    with pytest.raises(ProblemFileError) as checked:
        check_problem(text)
    with pytest.raises(ProblemFileError) as ran:
        run_problem(text)
    assert str(checked.value) == str(ran.value)
    assert "optimise.objectives[0].result" in str(ran.value) and "primary_couple" in str(ran.value)


def test_the_smallest_cam_found_by_search_is_the_smallest_base_circle_found_directly():
    """A cam file with ``[optimise]``: the smallest base radius whose pressure angle stays within the limit, found
    by the search, is the one machdyn finds directly (``cam.min_base_radius_pressure``, the pressure-angle
    condition solved for the base radius); the cam's geometry only, so that each design runs in milliseconds.
    The search approaches the pressure-angle boundary from its feasible side only (Deb's rules rank every design
    that breaks it last), so it never beats the direct minimum and comes within 2 % of it in 30 generations."""
    text = (ROOT / "examples" / "feeder_cam.toml").read_text(encoding="utf-8").split("[cam.dynamics]")[0]
    direct = run_problem(text).results["cam.min_base_radius_pressure"]
    limit = run_problem(text).results["cam.pressure_angle_limit"]
    study = text + f"""
[optimise]
population = 10
generations = 30
seed = 4

[[optimise.variables]]
name = "base"
parameter = "cam.base_radius"
lower = "{0.8 * direct * 1000} mm"
upper = "{1.6 * direct * 1000} mm"

[[optimise.objectives]]
result = "cam.base_radius"
sense = "minimise"

[[optimise.constraints]]
result = "cam.max_pressure_angle"
max = "{math.degrees(limit)} deg"
"""
    best = run_problem(study).outcomes["optimise"].results
    assert best.verified
    assert direct * (1 - 1e-9) <= best.results["cam.base_radius"] <= direct * 1.02
