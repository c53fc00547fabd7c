"""Every result a run of a linkage reports can be swept and optimised under its own key: the four-bar example's
85 results (its 48 harmonics and its load's mean power included) are each accepted as a ``[sweep]`` column and
objective and as an ``[optimise]`` objective, and the population evaluator gives, for the example's own design,
the number the run reports."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from machdyn.problem.build import build_mechanism, crank_angles, harmonics_of
from machdyn.reading import load_problem
from machdyn.results.population import evaluate_population, result_names, result_unit, sweep_columns
from machdyn.runner import run_problem
from machdyn.studies.optimisation.objectives import parse_objectives
from machdyn.studies.optimisation.schema import ObjectiveSpec
from machdyn.studies.table import SweepSpec

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "four_bar.toml"
#: Figures of the file rather than of a design: the point the shaking moment is taken about ([output]).
NOT_OF_A_DESIGN = {"shaking_moment.about_x", "shaking_moment.about_y"}


@pytest.fixture(scope="module")
def reported() -> dict[str, float]:
    run = run_problem(EXAMPLE)
    return {k: float(np.ravel(v)[0]) for k, v in run.results.values.items() if k not in NOT_OF_A_DESIGN}


def test_every_key_the_run_reports_is_a_sweep_column_and_an_objective(reported):
    problem = load_problem(EXAMPLE)
    mech = build_mechanism(problem)
    names = result_names(mech, problem.mechanism.machine, harmonics_of(problem))
    assert len(reported) == 85
    assert sum(".harmonic_" in k for k in reported) == 48 and "load.resistance.mean_power" in reported
    missing = sorted(set(reported) - set(names))
    assert not missing, missing
    for key in reported:
        SweepSpec(method="sobol", samples=8, objective=key, columns=[key],
                  quantities=[{"parameter": "drive.speed", "start": "1 rad/s", "stop": "2 rad/s"}])
        assert key in sweep_columns(mech, problem.mechanism.machine, key)
    keys = sorted(reported)
    objectives = parse_objectives([ObjectiveSpec(result=k) for k in keys], names, lambda k: result_unit(k, mech))
    assert [o.result for o in objectives] == keys


def test_the_population_gives_what_the_run_reports_for_harmonics_and_load_power(reported):
    """The analysis group of the population evaluator (a sweep's, an optimiser's) against the run: the same
    function reduces the same series, so they agree to rounding."""
    problem = load_problem(EXAMPLE)
    mech = build_mechanism(problem)
    wanted = [k for k in reported if ".harmonic_" in k or k.startswith("load.") or k == "dead_positions.count"]
    got = evaluate_population(mech, crank_angles(problem), problem.drive.speed, problem.drive.acceleration,
                              wanted, about=tuple(problem.output.shaking_moment_about), engine="numpy")
    assert got["regular"][0]
    for key in wanted:
        ours, theirs = float(got[key][0]), reported[key]
        if ".harmonic_" not in key:
            assert ours == pytest.approx(theirs, rel=1e-9, abs=1e-12), key
            continue
        series = key.split(".harmonic_")[0]
        largest = max(reported[k] for k in wanted if k.startswith(series + ".harmonic_") and k.endswith("amplitude"))
        amplitude = reported[key.replace(".phase", ".amplitude")]
        if key.endswith(".amplitude"):
            assert ours == pytest.approx(theirs, abs=1e-9 * largest), key
        elif amplitude > 1e-6 * largest:  # the phase of a vanishing harmonic is rounding noise
            assert np.angle(np.exp(1j * (ours - theirs))) == pytest.approx(0.0, abs=1e-9), key


def test_two_designs_get_their_own_harmonics():
    """With a designs axis the harmonics are per design: doubling every load and mass doubles every amplitude
    of the driving torque and leaves its phases."""
    from machdyn.linkage import four_bar

    phi = np.linspace(0.0, 2 * np.pi, 72, endpoint=False)
    scale = np.array([1.0, 2.0])
    mech = four_bar(0.04, 0.12, 0.08, 0.10, masses=(1.0 * scale, 0.5 * scale, 0.8 * scale),
                    inertias=(1e-3 * scale, 2e-3 * scale, 1.5e-3 * scale))
    keys = [f"driving_torque.harmonic_{k}.{part}" for k in (1, 2, 3) for part in ("amplitude", "phase")]
    got = evaluate_population(mech, phi, 10.0, 0.0, keys, engine="numpy")
    for k in (1, 2, 3):
        amp = got[f"driving_torque.harmonic_{k}.amplitude"]
        assert amp[1] == pytest.approx(2 * amp[0], rel=1e-12)
        if amp[0] > 1e-9 * amp.max():
            phase = got[f"driving_torque.harmonic_{k}.phase"]
            assert phase[1] == pytest.approx(phase[0], abs=1e-9)


def test_a_compactor_run_reports_the_figures_its_sweeps_report():
    """The compactor's figures (seed 003: plate angle, crank and lever force gains) are results of a run of the
    machine, as they are columns of its sweeps, by the same function."""
    from machdyn.pipeline import no_step
    from machdyn.pipelines.linkage_run import analyse_linkage

    problem = load_problem(EXAMPLE.with_name("compactor_optimise.toml"))
    mech = build_mechanism(problem)
    run = analyse_linkage(problem, mech, no_step).scalars
    keys = [k for k in result_names(mech, "compactor") if k.startswith("compactor.")]
    assert len(keys) == 4
    got = evaluate_population(mech, crank_angles(problem), problem.drive.speed, problem.drive.acceleration, keys,
                              machine="compactor", engine="numpy")
    for key in keys:
        assert run[key] == pytest.approx(float(got[key][0]), rel=1e-12), key


def test_the_optimiser_minimises_a_harmonic_under_a_load_power_constraint():
    """A harmonic amplitude as an [optimise] objective and a load's mean power as a constraint: the optimiser's
    population gives each design its own values, and its verification of a design alone (the best design's
    figures) gives the population's number for it."""
    from machdyn.studies.optimisation.study import setup, verify

    text = EXAMPLE.with_name("compactor_optimise.toml").read_text(encoding="utf-8")
    objective = 'result = "compactor.force_gain.min"\nsense = "maximise"'
    assert objective in text
    text = text.replace(objective, 'result = "driving_torque.harmonic_2.amplitude"\nsense = "minimise"')
    text = text.replace("[optimise]\n", '[output]\nharmonics = 3\n\n[optimise]\n', 1) + (
        '\n[[optimise.constraints]]\nresult = "load.compaction_at_A.mean_power"\nmax = "0 W"\n')
    problem = load_problem(text)
    ev = setup(problem, problem.optimise)
    x = ev.space.lower + np.array([[0.3], [0.6]]) * (ev.space.upper - ev.space.lower)
    results, costs, _violations = ev(x)
    amplitude = results["driving_torque.harmonic_2.amplitude"]
    assert np.all(amplitude > 0) and amplitude[0] != amplitude[1]
    assert np.allclose(costs[:, 0], amplitude)
    alone, _feasible = verify(ev.space.problem_at(x[1]), ev)
    assert alone["driving_torque.harmonic_2.amplitude"] == pytest.approx(float(amplitude[1]), rel=1e-9)
    assert alone["load.compaction_at_A.mean_power"] == pytest.approx(
        float(results["load.compaction_at_A.mean_power"][1]), rel=1e-9)
