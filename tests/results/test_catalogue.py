"""A walk of the catalogue of results: every key a run of a shipped example writes is declared in it, every
declared quantity is written by some example, and every per-design quantity of a mechanism can be named as a
``[sweep]`` column and objective and as an ``[optimise]`` objective, and comes out as the run computes it; every
value results.json holds is in SI."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from machdyn.kinds import catalogue
from machdyn.problem.build import build_mechanism, crank_angles, harmonics_of
from machdyn.reading import load_problem
from machdyn.results.catalogue import (
    ALIASES,
    MECHANISM,
    RUN_TIME,
    STATUS,
    canonical,
    find,
    population_quantities,
)
from machdyn.results.population import evaluate_population, result_names
from machdyn.runner import run_problem
from machdyn.units import ureg

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))
#: Examples whose mechanisms between them have every kind of output: a rocker, a slider, two sliders, a compactor.
MECHANISMS = ("four_bar", "slider_crank", "double_tamper_balance", "compactor_optimise")


@pytest.fixture(scope="module")
def runs() -> dict[str, dict]:
    """The results.json of each shipped example's run."""
    return {p.stem: run_problem(p).results_json() for p in EXAMPLES}


@pytest.fixture(scope="module")
def written(runs) -> dict[str, set[str]]:
    """The result keys each shipped example's run writes to results.json."""
    return {name: set(data["scalars"]) for name, data in runs.items()}


def _si_factor(unit: str) -> float:
    """The factor from ``unit`` to its coherent SI base units: 1 for m, N*m, rad/s, Pa; 1e-3 for mm."""
    return float(ureg.Quantity(1.0, unit or "dimensionless").to_base_units().magnitude)


def test_every_value_of_results_json_is_in_si_and_shown_only_beside_it(runs):
    """results.json says it is SI and holds every value in a coherent SI unit (a factor of 1 to the base units);
    a key shown in another unit gives that value beside the SI one, converted by that unit's factor."""
    not_si, wrong_shown, shown_units = [], [], set()
    for name, data in runs.items():
        assert data["units"] == "SI"
        for key, entry in data["scalars"].items():
            if abs(_si_factor(entry["unit"]) - 1.0) > 1e-12:
                not_si.append(f"{name}: {key} in {entry['unit']}")
            shown = entry.get("shown")
            if shown is None or entry["value"] is None or isinstance(entry["value"], str | bool):
                continue
            shown_units.add(shown["unit"])
            factor = float(ureg.Quantity(1.0, entry["unit"] or "dimensionless").to(shown["unit"]).magnitude)
            si = np.asarray(entry["value"], dtype=float)
            if not np.allclose(si * factor, np.asarray(shown["value"], dtype=float), rtol=1e-12, atol=0.0,
                               equal_nan=True):
                wrong_shown.append(f"{name}: {key}")
    assert not not_si, not_si
    assert not wrong_shown, wrong_shown
    assert {"deg", "mm", "rpm"} <= shown_units  # the display units are there, beside the SI values


def test_every_key_a_run_writes_is_in_the_catalogue(written):
    everything = catalogue()
    unknown = sorted({f"{name}: {key}" for name, keys in written.items() for key in keys
                      if find(key, everything) is None})
    assert not unknown, unknown


#: Declared results no shipped example writes, each with the test that produces and checks it.
NOT_IN_EXAMPLES = {
    "parts.link.<name>.peak_stress": "a link whose stress point passes the ultimate strength (tests/drivetrain)",
    "balance.spring_stiffness": "a balancing spring (tests/balancing)",
    "balance.spring_free_length": "a balancing spring (tests/balancing)",
    "optimise.front_size": "a Pareto front of several objectives (tests/optimise/test_stage.py)",
    "optimise.front_spacing": "a Pareto front of several objectives (tests/correctness)",
    "optimise.front_hypervolume": "a Pareto front of several objectives (tests/correctness)",
    "cam.face_width": "a flat-faced follower (tests/cams)",
    "shaft_cam.face_width": "a flat-faced follower on a crank shaft (the same result as cam.face_width)",
    "shaft_cam.segment<segment>.min_surface_curvature_radius": "a flat-faced follower on a crank shaft (the same "
                                                                "result as cam.segment<segment>.min_surface_...)",
    "synthesis.best.offset": "the synthesis of a slider-crank (tests/synthesis)",
    "clutch.engagement_speed": "a centrifugal clutch (tests/drivetrain/test_geometry_cli.py)",
    "brake.max_pressure": "an internal shoe brake (tests/drivetrain/test_geometry_cli.py)",
}
#: Prefixes of capability keys that carry a result's own key after them.
CARRIERS = ("sweep.best.", "sweep.lowest_", "sweep.", "optimise.best.")


def test_every_catalogue_entry_is_written_by_some_example(written):
    keys = set().union(*written.values())
    everything = catalogue()
    produced = set()
    for key in keys:
        for candidate in (key, *(key[len(c):] for c in CARRIERS if key.startswith(c))):
            found = find(candidate, everything)
            if found is not None:
                produced.add(found[0].key)
        # The run-time patterns of the capabilities (sweep.best.<column*>, balance.<part>.mass) match their keys.
        found = find(key, RUN_TIME)
        if found is not None:
            produced.add(found[0].key)
    from machdyn.kinds import CAPABILITIES, KINDS

    # The catalogue may declare the run-time keys of a kind or capability that is not registered (not shipped).
    registered = {*KINDS, *CAPABILITIES, "mechanism:compactor", "population"}
    missing = sorted(q.key for q in everything if q.key not in produced and q.key not in NOT_IN_EXAMPLES
                     and q.producer in registered)
    assert not missing, missing


def test_every_mechanism_quantity_has_a_population_group_or_says_why_not():
    for q in MECHANISM:
        assert q.group or q.why, q.key
    for q in STATUS:
        assert q.group == "status"


def _problem(name: str):
    return load_problem(ROOT / "examples" / f"{name}.toml")


def test_every_mechanism_quantity_can_be_named_a_sweep_column_and_an_objective():
    """Each per-design quantity of the mechanism kind (and of the compactor) is a result of some shipped
    mechanism, is accepted as ``[sweep] objective`` and as an ``[optimise]`` objective, and is a column of
    that mechanism's sweep."""
    from machdyn.results.population import result_unit, sweep_columns
    from machdyn.studies.optimisation.objectives import parse_objectives
    from machdyn.studies.optimisation.schema import ObjectiveSpec
    from machdyn.studies.table import SweepSpec

    named: dict[str, list[str]] = {}
    for name in MECHANISMS:
        problem = _problem(name)
        machine = problem.mechanism.machine
        mech = build_mechanism(problem)
        names = result_names(mech, machine, harmonics_of(problem))
        for key in names:
            named.setdefault(find(key)[0].key, []).append(key)
            SweepSpec(method="sobol", samples=8, objective=key,
                      quantities=[{"parameter": "drive.speed", "start": "1 rad/s", "stop": "2 rad/s"}])
            assert key in sweep_columns(mech, machine, key)
        units = {k: result_unit(k, mech) for k in names}
        objectives = parse_objectives([ObjectiveSpec(result=k) for k in names], names, units.__getitem__)
        assert [o.result for o in objectives] == names
    missing = [q.key for q in population_quantities("compactor") if q.key not in named]
    assert not missing, missing


@pytest.mark.parametrize("name", MECHANISMS)
def test_a_population_of_one_gives_what_the_run_gives(name):
    """The population evaluator and the run compute the same numbers for the example's own design: the force
    and analysis groups to rounding; the motion group to the run's finer sampling where it locates limit
    positions (the run's diagnostics sample 3600 positions, the population the problem's own); the extremes
    of a series to the sampling (the run's are exact between the samples, a population's are sampled)."""
    problem = _problem(name)
    machine = problem.mechanism.machine
    mech = build_mechanism(problem)
    got = evaluate_population(mech, crank_angles(problem), problem.drive.speed, problem.drive.acceleration,
                              result_names(mech, machine), about=tuple(problem.output.shaking_moment_about),
                              machine=machine)
    assert got["regular"][0] and got["status"][0] == "regular"
    run = run_problem(ROOT / "examples" / f"{name}.toml").results
    compared = 0
    for key in result_names(mech, machine):
        if key not in run:
            continue
        ours, theirs = float(got[key][0]), float(np.ravel(run[key])[0])
        quantity = find(key)[0]
        group = quantity.group
        rel = 1e-9 if group in ("forces", "analysis", "geometry") else 2e-3
        if key == "flywheel.energy_fluctuation":
            rel = 1e-6
        if quantity.series and quantity.over_positions in ("max", "min", "max_abs", "range"):
            # The run's extremes are the closed form's (between the samples); a population's are the largest
            # samples: never beyond the run's, and short of them by the series' change over half a step.
            rel = 2e-3
            inwards = -ours if quantity.over_positions == "min" else abs(ours)
            outwards = -theirs if quantity.over_positions == "min" else abs(theirs)
            assert inwards <= outwards + 1e-12 * abs(theirs) + 1e-9, key
        assert ours == pytest.approx(theirs, rel=rel, abs=1e-9 * max(abs(theirs), 1.0)), key
        compared += 1
    assert compared >= 20


def test_old_names_map_to_their_keys_once():
    assert canonical("max_driving_torque") == "driving_torque.max_abs"
    assert canonical("shaking_force.max") == "frame_force.max"
    assert canonical("sweep.max_shaking_force") == "sweep.frame_force.max"
    assert canonical("sweep.best.max_driving_torque") == "sweep.best.driving_torque.max_abs"
    assert canonical("shaking_force.fx.harmonic_2.phase") == "frame_force.fx.harmonic_2.phase"
    assert canonical("driving_torque.max_abs") == "driving_torque.max_abs"
    for old, new in ALIASES.items():
        assert find(new) is not None and find(old) is None, old


def test_inertial_shaking_moment_is_the_frame_moment_without_loads_or_weight():
    """Newton-Euler for the moving bodies together: with gravity off and no external loads, the moment the
    mechanism puts on its frame (kinetostatics: joint reactions and the drive's reaction) equals the moment of
    the d'Alembert loads (Uicker, Pennock & Shigley, 5th ed., chapter "Balancing")."""
    from machdyn.linkage import four_bar, kinematics, kinetostatics
    from machdyn.linkage.mass_centre import inertial_shaking_moment

    mech = four_bar(0.04, 0.12, 0.10, 0.13, masses=(0.3, 0.5, 0.4), inertias=(1e-4, 8e-4, 5e-4),
                    coms=((0.02, 0.0), (0.06, 0.01), (0.05, -0.005)), gravity=(0.0, 0.0))
    phi = np.linspace(0.0, 2 * math.pi, 72, endpoint=False)
    kin = kinematics(mech, phi, 12.0, 3.0)
    about = (0.05, -0.02)
    frame = kinetostatics(mech, kinematics_result=kin).shaking_moment(about)
    np.testing.assert_allclose(inertial_shaking_moment(kin, about), frame, rtol=1e-10,
                               atol=1e-12 * float(np.max(np.abs(frame))))


def test_inertial_shaking_force_is_not_the_frame_force_of_a_press():
    """The crank press's punch force (60 kN) closes through its frame: the frame force is some 59 kN, the
    inertial shaking force tens of N (docs/results.md quotes both)."""
    result = run_problem(ROOT / "examples" / "crank_press.toml").results
    assert result["frame_force.max"] > 50e3
    assert result["inertial_shaking_force.max"] < 1e-2 * result["frame_force.max"]


def test_the_documented_catalogue_example_runs_and_lists_every_mechanism_key():
    """docs/results.md: its Python example runs, and its table lists every quantity of the mechanism kind."""
    import re

    text = (ROOT / "docs" / "results.md").read_text(encoding="utf-8")
    block = re.findall(r"```python\n(.*?)```", text, flags=re.S)[0]
    exec(compile(block, "docs/results.md", "exec"), {})  # noqa: S102 - the documentation's own example
    from machdyn.results.catalogue import COMPACTOR

    missing = [q.key for q in MECHANISM + COMPACTOR if f"`{q.key}`" not in text]
    assert not missing, missing
    assert all(f"`{old}`" in text for old in ALIASES)
