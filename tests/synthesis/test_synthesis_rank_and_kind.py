"""Defects, the population's dynamics by the engine, the [synthesis] problem kind and its command line."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.linkage import analyse
from machdyn.reading import load_problem
from machdyn.runner import run_problem
from machdyn.synthesis.candidate import Candidate
from machdyn.synthesis.defects import Targets, check
from machdyn.synthesis.quick_return import crank_rocker
from machdyn.synthesis.rank import QUANTITIES, Drive, evaluate, order

QUICK = """
[meta]
name = "quick return"

[synthesis]
task = "quick_return"
swing = "40 deg"
time_ratio = 1.3
rocker = "250 mm"
candidates = 12

[synthesis.ranking]
by = "peak_torque"
speed = "120 rpm"
linear_density = "6 kg/m"
output_torque = "-60 N*m"
keep = 2
"""


def _crank_rockers():
    return [crank_rocker(np.radians(40), 1.3, 0.25, position=p, side=s) for p in (0.2, 0.4, 0.6) for s in (1, -1)]


def test_defects_name_grashof_order_and_transmission():
    non_grashof = Candidate(kind="four_bar", origin=0j, crank=0.1, coupler=0.1, rocker=0.1, ground=0.25,
                            angles=np.array([0.0, 0.2]))
    report = check(non_grashof, Targets(), need_full_turn=True)
    assert any(d.startswith("Grashof") for d in report.defects)
    good = crank_rocker(np.radians(40), 1.0, 0.25, position=0.3)
    out_of_order = replace(good, angles=np.array([0.0, 2.0, 1.0]))
    assert any(d.startswith("order") for d in check(out_of_order, Targets()).defects)
    strict = check(good, Targets(), transmission_limit=np.radians(89.0))
    assert any(d.startswith("transmission") for d in strict.defects)
    assert strict.min_transmission == pytest.approx(float(np.min(good.transmission(np.linspace(0, 2 * np.pi, 361)))))


def test_population_dynamics_equal_the_engines_run_of_each_design():
    """The vectorised evaluation of the population gives each design's peak torque and shaking force as the
    engine's own analysis of that design alone over the same crank angles."""
    cands = _crank_rockers()
    psi1 = np.pi / 2 - np.radians(20)
    reports = [check(c, Targets(outputs=np.array([psi1, psi1 + np.radians(40)]), scale=0.25)) for c in cands]
    drive = Drive(speed=12.0, linear_density=5.0, load=-30.0, positions=90)
    values = evaluate(cands, reports, drive)
    for i, (c, r) in enumerate(zip(cands, reports, strict=True)):
        if not r.full_turn:
            continue
        mech = replace(c.mechanism(linear_density=5.0), torques=())
        from machdyn.linkage import BodyTorque

        mech = replace(mech, torques=(BodyTorque("load", "rocker", -30.0),))
        phi = c.angles[0] + c.direction * np.linspace(0, 2 * np.pi, 90, endpoint=False)
        a = analyse(mech, phi, 12.0 * c.direction, diagnostics=False)
        assert values["peak_torque"][i] == pytest.approx(np.max(np.abs(a.forces.driving_torque)), rel=1e-9)
        assert values["frame_force"][i] == pytest.approx(np.max(a.forces.shaking_force), rel=1e-9)
        # the inertial shaking force, -sum m a_G of the engine's centres of mass, for this design alone
        kin = a.kinematics
        fx = -sum(b.mass * kin.com(b.name).ax for b in mech.bodies)
        fy = -sum(b.mass * kin.com(b.name).ay for b in mech.bodies)
        assert values["inertial_shaking_force"][i] == pytest.approx(np.max(np.hypot(fx, fy)), rel=1e-9)


def test_order_puts_defect_free_designs_first_and_sorts_by_the_chosen_quantity():
    cands = _crank_rockers()
    reports = [check(c, Targets(), transmission_limit=np.radians(35)) for c in cands]
    values = evaluate(cands, reports, Drive(positions=60))
    for key in QUANTITIES:
        idx = order(values, reports, key)
        ok = [reports[i].ok for i in idx]
        assert ok == sorted(ok, reverse=True)
        first = [values[key][i] for i in idx if reports[i].ok and np.isfinite(values[key][i])]
        assert first == sorted(first, reverse=QUANTITIES[key][2])


def test_the_synthesis_kind_runs_and_its_best_candidates_run_on_their_own(tmp_path):
    result = run_problem(QUICK)
    assert result.kind == "synthesis" and not result.failed_checks
    assert result.scalars["synthesis.candidates"]["value"] == 12
    outcome = result.outcomes["synthesis"]
    files = dict(outcome.files)
    assert {"best_1.toml", "best_2.toml"} <= set(files)
    synth = outcome.results
    best = synth.best
    problem = load_problem(files["best_1.toml"])
    from machdyn.problem.build import build_mechanism

    mech = build_mechanism(problem)
    assert mech.body("crank").points["A"][0] == pytest.approx(best.crank, rel=1e-15)
    assert mech.body("rocker").points["B"][0] == pytest.approx(best.rocker, rel=1e-15)
    run = run_problem(problem)
    rocker = run.analysis.kinematics.body("rocker").angle
    assert np.ptp(rocker) == pytest.approx(np.radians(40.0), rel=1e-3)  # 360 positions: extremes to sampling
    peak = float(np.max(np.abs(run.analysis.forces.driving_torque)))
    ranked = float(synth.values["peak_torque"][0])
    assert peak == pytest.approx(ranked, rel=0.05)  # 360 positions in the file, 121 in the ranking


def test_missing_task_fields_are_bad_input_in_check_and_run(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(QUICK.replace('swing = "40 deg"\n', ""), encoding="utf-8")
    runner = CliRunner()
    checked = runner.invoke(app, ["check", str(path)])
    ran = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "out"), "--quiet"])
    assert checked.exit_code == 2 and ran.exit_code == 2
    assert "synthesis.swing" in checked.stderr and "quick_return" in checked.stderr
    assert "Traceback" not in checked.output + ran.output


def test_a_task_without_a_defect_free_linkage_fails_its_design_check(tmp_path):
    path = tmp_path / "strict.toml"
    path.write_text(QUICK.replace('candidates = 12', 'candidates = 4\ntransmission_limit = "89 deg"'),
                    encoding="utf-8")
    ran = CliRunner().invoke(app, ["run", str(path), "--out", str(tmp_path / "out"), "--quiet"])
    assert ran.exit_code == 3


TASKS = {
    "function": """
task = "function"
function = "log10"
x_range = [1.0, 2.0]
input_range = ["30 deg", "120 deg"]
output_range = ["240 deg", "330 deg"]
ground = "100 mm"
""",
    "slider_quick_return": """
task = "slider_quick_return"
stroke = "120 mm"
time_ratio = 1.4
candidates = 10
""",
    "motion": """
task = "motion"
positions = [["0 mm", "0 mm", "0 deg"], ["80 mm", "60 mm", "-30 deg"], ["180 mm", "40 mm", "-90 deg"]]
candidates = 40
full_turn = false
""",
    "path": """
task = "path"
points = [["0 mm", "0 mm"], ["50 mm", "30 mm"], ["100 mm", "20 mm"]]
timing = ["40 deg", "90 deg"]
candidates = 20
full_turn = false
""",
}


@pytest.mark.parametrize("task", sorted(TASKS))
def test_every_task_runs_as_a_problem_file_and_writes_runnable_candidates(task, tmp_path):
    text = f'[meta]\nname = "{task}"\n\n[synthesis]{TASKS[task]}\n[synthesis.ranking]\nkeep = 1\n'
    result = run_problem(text)
    outcome = result.outcomes["synthesis"]
    assert result.scalars["synthesis.candidates"]["value"] >= 1
    if result.failed_checks:  # no defect-free linkage: the design check says so, and still writes the best
        assert "free of defects" in result.failed_checks[0]
    best = load_problem(outcome.files["best_1.toml"])
    run_problem(best)  # runs on its own
    html = result.report_html() if hasattr(result, "report_html") else ""
    assert "Synthesis" in html


def test_fluctuation_of_energy_is_the_swing_of_kinetic_energy_without_loads():
    """Work-energy: with no gravity and no load the crank's work at constant speed goes into kinetic energy
    only, so the fluctuation of energy the ranking reports is max T - min T of the engine's kinetic energy, and
    the flywheel needed is that over omega^2 Cs."""
    cands = _crank_rockers()[:3]
    reports = [check(c, Targets()) for c in cands]
    drive = Drive(speed=10.0, linear_density=4.0, load=0.0, positions=720, gravity=False, speed_fluctuation=0.04)
    values = evaluate(cands, reports, drive)
    for i, c in enumerate(cands):
        if not reports[i].full_turn:
            continue
        mech = replace(c.mechanism(linear_density=4.0), gravity=(0.0, 0.0))
        phi = c.angles[0] + c.direction * np.linspace(0, 2 * np.pi, 720, endpoint=False)
        kinetic = analyse(mech, phi, 10.0 * c.direction, diagnostics=False).energy.kinetic_total
        assert values["flywheel_energy"][i] == pytest.approx(np.ptp(kinetic), rel=2e-4)  # 720 samples: ~5e-5
        assert values["flywheel_inertia"][i] == pytest.approx(values["flywheel_energy"][i] / (100.0 * 0.04))


@pytest.mark.parametrize(("body", "field"), [
    ('task = "motion"\npositions = [["0 mm", "0 mm", "0 deg"]]\n', "synthesis.positions"),
    ('task = "path"\npoints = [["0 mm", "0 mm"], ["1 mm", "0 mm"], ["2 mm", "1 mm"]]\ntiming = ["10 deg"]\n',
     "synthesis.timing"),
    ('task = "motion"\npositions = [["0 mm", "0 mm", "0 deg"], ["9 mm", "1 mm", "5 deg"]]\n'
     'crank_pivot = ["0 mm", "-50 mm"]\n', "synthesis.crank_pivot"),
    ('task = "function"\nfunction = "log10"\nx_range = [0.0, 1.0]\ninput_range = ["0 deg", "90 deg"]\n'
     'output_range = ["0 deg", "90 deg"]\n', "synthesis.x_range"),
    ('task = "quick_return"\nswing = "200 deg"\nrocker = "100 mm"\n', "synthesis.swing"),
    ('task = "motion"\npositions = [["0 mm", "0 mm", "0 deg"], ["0 mm", "0 mm", "0 deg"], ["5 mm", "0 mm", "9 deg"]]\n',
     "synthesis.positions"),
    ('task = "quick_return"\nswing = "40 deg"\nrocker = "100 mm"\ntime_ratio = 0.5\n', "synthesis.time_ratio"),
])
def test_task_rules_name_the_field(body, field, tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(f'[meta]\nname = "bad"\n\n[synthesis]\n{body}', encoding="utf-8")
    checked = CliRunner().invoke(app, ["check", str(path)])
    assert checked.exit_code == 2 and field in checked.stderr, checked.stderr


def test_a_task_without_any_linkage_fails_its_check_and_still_writes_its_report(tmp_path):
    path = tmp_path / "none.toml"
    path.write_text('[meta]\nname = "none"\n\n[synthesis]\ntask = "motion"\npositions = [["0 mm", "0 mm", "0 deg"], '
                    '["80 mm", "60 mm", "-30 deg"], ["180 mm", "40 mm", "-90 deg"]]\nmax_length = "1 mm"\n'
                    'candidates = 5\n', encoding="utf-8")
    ran = CliRunner().invoke(app, ["run", str(path), "--out", str(tmp_path / "out")])
    assert ran.exit_code == 3 and "gave no linkage" in ran.output
    assert "No linkage was found" in (tmp_path / "out" / "report.html").read_text()


def test_a_degenerate_motion_task_ends_with_a_failed_check(tmp_path):
    """Three positions that turn about one fixed point (a pole common to all): no dyad's system is regular; the
    sampling of free choices gives up and the run says so (exit 3) instead of searching forever."""
    path = tmp_path / "pole.toml"
    path.write_text('[meta]\nname = "pole"\n\n[synthesis]\ntask = "motion"\npositions = [["0 mm", "0 mm", "0 deg"], '
                    '["0 mm", "0 mm", "10 deg"], ["0 mm", "0 mm", "20 deg"]]\ncandidates = 5\n', encoding="utf-8")
    ran = CliRunner().invoke(app, ["run", str(path), "--out", str(tmp_path / "out"), "--quiet"])
    assert ran.exit_code == 3
