"""The population form of a problem kind (:attr:`machdyn.pipeline.ProblemKind.population`): a cam's and a shaft
line's results for N designs at once equal each design's own run, the optimiser uses it and reaches the optimum
the runs reach, and a variable it cannot vary falls back to the runs with a message.

Every comparison is against the single-design run (:func:`machdyn.runner.design_results`, the run a ``machdyn
run`` of the design makes), to 1e-12 relative: the cam's largest pressure angle and smallest radius of curvature
are refined between samples as the run's exact extremes are (:mod:`machdyn.cams.kind_population`), so the exact
values, not the sampled ones, are compared.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from machdyn.cams.kind_population import population as cam_population
from machdyn.problem.paths import design_problem
from machdyn.reading import load_problem
from machdyn.runner import design_results, run_problem
from machdyn.shafts.kind_population import population as shaft_population
from machdyn.studies.optimisation import by_runs
from machdyn.studies.optimisation.study import optimise, setup
from machdyn.studies.sweep.runs import run_sweep

ROOT = Path(__file__).resolve().parents[2]
CAM = ROOT / "examples" / "cam_base_circle_optimise.toml"
ENGINE = ROOT / "examples" / "shaft_inline_four_phases_optimise.toml"
ROTOR = ROOT / "examples" / "shaft_rotor_g63.toml"


def _runs(problem, values, keys):
    """The keys of each design's own run, NaN where the run refuses the design."""
    n = len(next(iter(values.values())))
    out = {k: np.full(n, math.nan) for k in keys}
    for i in range(n):
        try:
            got = design_results(design_problem(problem, {p: float(v[i]) for p, v in values.items()}))
        except Exception:  # noqa: BLE001 - a design the run refuses (not built) is NaN in both
            continue
        for k in keys:
            out[k][i] = got.get(k, math.nan)
    return out


def _same(found, runs, keys, scale=None):
    for k in keys:
        a, b = np.asarray(found[k]), runs[k]
        assert np.array_equal(np.isnan(a), np.isnan(b)), k  # a degenerate design flagged the same way
        ok = ~np.isnan(b)
        atol = 0.0 if scale is None else 1e-12 * scale[ok]
        assert np.allclose(a[ok], b[ok], rtol=1e-12, atol=atol), (k, a[ok], b[ok])


def test_a_cams_checks_for_random_designs_equal_each_designs_run():
    """Random base radii, roller radii and offsets; two degenerate designs: one whose offset is not smaller than
    its prime radius (it does not assemble), one whose roller has no radius."""
    problem = load_problem(CAM)
    rng = np.random.default_rng(7)
    n = 6
    values = {"cam.base_radius": 0.02 + 0.05 * rng.random(n),
              "cam.follower.roller_radius": 0.004 + 0.012 * rng.random(n),
              "cam.follower.offset": -0.012 + 0.024 * rng.random(n)}
    values["cam.base_radius"][4], values["cam.follower.roller_radius"][4], values["cam.follower.offset"][4] = \
        0.01, 0.005, 0.02  # |e| >= R_b + r_r
    values["cam.follower.roller_radius"][5] = 0.0  # a roller follower without a roller
    keys = ["cam.max_pressure_angle", "cam.min_pitch_curvature_radius", "cam.min_surface_curvature_radius",
            "cam.min_base_radius_pressure", "cam.base_radius"]
    found = cam_population(problem, values, keys)
    runs = _runs(problem, values, keys)
    assert np.isnan(runs["cam.max_pressure_angle"][4:]).all()
    _same(found, runs, keys)


def test_a_shaft_lines_engine_orders_for_random_phases_equal_each_designs_run():
    """Random crank phases, positions and masses of the in-line four; one design whose rod is shorter than its
    crank (refused by the run). Forces and couples compared to 1e-12 of the engine's gross force and couple
    (a balanced engine's primary force is a cancellation of terms of that size)."""
    problem = load_problem(ENGINE)
    rng = np.random.default_rng(3)
    n = 5
    values = {"cylinders[1].phase": rng.random(n) * 2 * np.pi, "cylinders[2].phase": rng.random(n) * 2 * np.pi,
              "cylinders[3].position": 0.2 + 0.1 * rng.random(n), "cylinders[0].reciprocating_mass": rng.random(n),
              "cylinders[2].rod": 0.1 + 0.1 * rng.random(n)}
    values["cylinders[2].rod"][4] = 0.04  # shorter than the 45 mm crank
    two_term = [f"shaft.engine.{k}" for k in ("primary_force", "secondary_force", "primary_couple",
                                              "secondary_couple", "primary_direct", "secondary_reverse",
                                              "gross_force", "gross_couple")]
    exact = ["shaft.engine.order1.force", "shaft.engine.order2.couple", "shaft.unbalance", "shaft.couple_unbalance"]
    runs = _runs(problem, values, two_term + exact + ["shaft.engine.gross_force"])
    assert np.isnan(runs["shaft.engine.primary_force"][4])
    gross = runs["shaft.engine.gross_force"]
    _same(shaft_population(problem, values, two_term), runs, two_term, scale=np.maximum(gross, 1.0))
    _same(shaft_population(problem, values, exact), runs, exact, scale=np.maximum(gross, 1.0))


def test_a_rotors_two_plane_corrections_and_grade_equal_each_designs_run():
    """The fan rotor's discs at random angles and masses: its two correction masses and its ISO 21940-11 check
    (balanced state: the corrections fitted) equal the run's, to 1e-12 relative or 1e-14 kg*m (of a gross
    unbalance of about 0.05 kg*m: the balanced rotor's residual is rounding, ~1e-17). The file's rounding and
    holes are left out (the population form declines them: test below)."""
    text = ROTOR.read_text(encoding="utf-8").replace('resolution = "0.5 g"\n', "").replace(", holes = 8", "")
    problem = load_problem(text)
    rng = np.random.default_rng(5)
    n = 4
    values = {"masses[0].angle": rng.random(n) * 2 * np.pi, "masses[2].mass": 0.02 + 0.05 * rng.random(n),
              "masses[3].position": 0.5 + 0.2 * rng.random(n)}
    keys = ["shaft.balance.L.mass", "shaft.balance.L.angle", "shaft.balance.R.mass", "shaft.balance.R.angle",
            "shaft.grade.U_per", "shaft.grade.A.residual", "shaft.grade.B.allowed", "shaft.grade.achieved_G"]
    runs = _runs(problem, values, keys)
    _same(shaft_population(problem, values, keys), runs, keys, scale=np.full(n, 1e-2))
    assert shaft_population(load_problem(ROTOR.read_text(encoding="utf-8")), values, keys[:1]) is None  # holes


def test_the_optimiser_reaches_the_runs_optimum_with_the_population_form(monkeypatch):
    """A short search of the in-line four's inner phases: the population form and the runs (the form switched
    off) make the same search and end at the same best design (the force limit relaxed so
    that so short a search finds feasible designs)."""
    text = ENGINE.read_text(encoding="utf-8").replace("population = 12", "population = 5").replace(
        "generations = 40", "generations = 1").replace('max = "1 N"', 'max = "20 kN"')
    problem = load_problem(text)
    fast = optimise(problem, problem.optimise, design_results)
    assert "population form: " in fast.message and "designs at once" in fast.message
    monkeypatch.setattr(by_runs, "kind_population_form", lambda *a: (None, "each design run whole: switched off"))
    slow = optimise(problem, problem.optimise, design_results)
    assert slow.evaluations == fast.evaluations
    # the polish ends in a valley where every pair of equal inner phases has no primary couple: rounding moves
    # the end along it by ~1e-7 rad; the couple reached is the same
    assert np.allclose(fast.x, slow.x, rtol=0, atol=1e-5)
    assert fast.results["shaft.engine.primary_couple"] == pytest.approx(slow.results["shaft.engine.primary_couple"],
                                                                       rel=1e-9, abs=1e-9)


def test_the_cam_examples_smallest_base_circle_is_the_direct_one_at_its_offset():
    """The shipped cam example, optimised through the population form: its best base radius is the smallest
    base circle meeting the 30 deg limit at the offset it chose, found directly (Norton, *Design of Machinery*,
    5th ed., eq 8.31 solved for R_b: ``cam.min_base_radius_pressure``) — two independent routes to one answer;
    the search comes within 0.1 % of it from the feasible side (the curvature constraint is not active)."""
    run = run_problem(CAM)
    best = run.outcomes["optimise"].results
    assert best.verified and "population form: " in best.message
    alone = run_problem(best.problem_text).results
    assert alone["cam.min_base_radius_pressure"] <= best.results["cam.base_radius"] * (1 + 1e-9)
    assert best.results["cam.base_radius"] <= alone["cam.min_base_radius_pressure"] * 1.001
    assert run.results["optimise.designs_per_second"] > 50.0  # the runs managed about 6 per second


def test_a_variable_the_form_cannot_vary_falls_back_to_the_runs_with_a_message():
    """The cam's speed is no field of its population form: each design is run whole, and the result says so."""
    text = CAM.read_text(encoding="utf-8").replace('parameter = "cam.follower.offset"', 'parameter = "cam.speed"')
    text = text.replace('lower = "-15 mm"\nupper = "15 mm"', 'lower = "100 rpm"\nupper = "300 rpm"')
    problem = load_problem(text)
    ev = setup(problem, problem.optimise, design_results)
    assert ev.at_once is None
    assert "each design run whole" in ev.note and "cam.speed" in ev.note
    x = np.array([[0.045, 20.0]])
    results, _costs, _viol = ev(x)
    alone = design_results(ev.space.problem_at(x[0]))
    assert results["cam.max_pressure_angle"][0] == alone["cam.max_pressure_angle"]


def test_a_cam_sweep_through_the_population_form_equals_the_variants_runs():
    """A sweep of the roller radius whose columns the cam's population form gives: its values are those of each
    variant's own run; a variant the run refuses (a roller follower without a roller) is run whole, so that its
    status names why."""
    text = CAM.read_text(encoding="utf-8").split("[optimise]")[0] + """
[sweep]
parameter = "cam.follower.roller_radius"
start = "0 mm"
stop = "12 mm"
count = 3
columns = ["cam.max_pressure_angle", "cam.min_base_radius_pressure"]
"""
    problem = load_problem(text)
    done = run_sweep(problem, design_results)
    values = {"cam.follower.roller_radius": np.asarray(done.plan.values_si, dtype=float)}
    keys = list(done.asked)
    _same({k: done.columns[k] for k in keys}, _runs(problem, values, keys), keys)
    status = list(done.columns["status"])
    assert status[1:] == ["regular", "regular"] and status[0].startswith("not built")
