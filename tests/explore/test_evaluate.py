"""An explored design gives what the same design gives written as its own problem file; models built for a
whole partition at once equal the same designs built one by one."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from machdyn.linkage import crank_angles, kinetostatics
from machdyn.problem.build import build_mechanism
from machdyn.reading import load_problem
from machdyn.studies.exploration import explore, plan_exploration
from machdyn.studies.exploration.evaluate import evaluate_partition
from machdyn.studies.exploration.sampling import partition_designs

from .conftest import BASE, explore_text


def _alone(crank: float, coupler_mass: float, speed: float, torque: float):
    """Peak |driving torque| and peak shaking force of one design written as its own problem file."""
    text = (BASE.replace('length = "40 mm", mass = "0.2 kg"', f'length = "{crank!r} m", mass = "0.2 kg"')
            .replace('length = "120 mm", mass = "0.5 kg"', f'length = "120 mm", mass = "{coupler_mass!r} kg"')
            .replace('speed = "10 rad/s"', f'speed = "{speed!r} rad/s"')
            .replace('torque = "-0.5 N*m"', f'torque = "{torque!r} N*m"'))
    problem = load_problem(text)
    forces = kinetostatics(build_mechanism(problem), crank_angles(36), problem.drive.speed)
    return float(np.max(np.abs(forces.driving_torque))), float(np.max(forces.shaking_force))


def test_each_explored_design_equals_that_design_alone(tmp_path):
    done = explore(load_problem(explore_text(samples=64)), store=tmp_path / "s")
    frame = done.frame()
    assert len(frame) == 64 and list(frame["design"]) == list(range(64))
    regular = frame[frame["regular"]]
    assert 0 < len(regular) < 64  # long cranks cannot turn: kept, not regular, NaN summaries
    assert frame.loc[~frame["regular"], "driving_torque.max_abs"].isna().all()
    for _, row in regular.iloc[:6].iterrows():
        torque, shaking = _alone(row["mechanism.crank.length"], row["mechanism.coupler.mass"], row["drive.speed"],
                                 row["loads.torques[0].torque"])
        assert row["driving_torque.max_abs"] == pytest.approx(torque, rel=1e-12)
        assert row["frame_force.max"] == pytest.approx(shaking, rel=1e-12)


def test_vectorised_build_equals_design_by_design():
    plan = plan_exploration(load_problem(explore_text(samples=40, partition=40)))
    assert plan.vectorised
    _, values = next(partition_designs(plan.space, [0]))
    fast = evaluate_partition(plan, 0, values)
    slow = evaluate_partition(replace(plan, vectorised=False), 0, values)
    assert list(fast) == list(slow)
    for name in fast:
        if fast[name].dtype.kind in "fi":
            np.testing.assert_allclose(fast[name], slow[name], rtol=1e-12, atol=0, equal_nan=True)
        else:  # the status and the Grashof class, and the yes/no checks
            np.testing.assert_array_equal(fast[name], slow[name])


def test_drive_only_exploration_with_as_many_designs_as_positions(tmp_path):
    """Per-design speeds are never read as per-position speeds, even when the counts agree."""
    text = BASE + '\n[sweep]\nmethod = "lhs"\nsamples = 36\nseed = 1\n\n[[sweep.quantities]]\n' \
                  'parameter = "drive.speed"\nstart = "5 rad/s"\nstop = "20 rad/s"\n'
    frame = explore(load_problem(text), store=tmp_path / "s").frame()
    assert frame["regular"].all()
    for _, row in frame.iloc[:3].iterrows():
        torque, _ = _alone(0.04, 0.5, row["drive.speed"], -0.5)
        assert row["driving_torque.max_abs"] == pytest.approx(torque, rel=1e-12)


def test_a_grid_of_one_quantity_explored_equals_the_one_quantity_sweep(tmp_path):
    from machdyn.runner import run_problem

    sweep = '\n[sweep]\nparameter = "mechanism.crank.length"\nvalues = ["30 mm", "35 mm", "40 mm"]\n'
    legacy = run_problem(load_problem(BASE + sweep)).frames["sweep"]
    grid = explore(load_problem(BASE + sweep + "seed = 0\n"), store=tmp_path / "s").frame()
    np.testing.assert_array_equal(grid["driving_torque.max_abs"], legacy["driving_torque.max_abs [N*m]"])
    np.testing.assert_array_equal(grid["driving_torque.rms"], legacy["driving_torque.rms [N*m]"])


def test_an_exploration_keeps_the_columns_asked_for_and_flags_each_design(tmp_path):
    """``columns`` adds an analysis result to every design; each design's status is regular or names its fault,
    and only regular designs have results."""
    text = explore_text(samples=32, partition=32, extra='columns = ["kinetic_energy.max"]\n')
    frame = explore(load_problem(text), store=tmp_path / "s").frame()
    regular = frame["regular"].to_numpy(dtype=bool)
    assert regular.any() and (~regular).any()
    assert set(frame.loc[regular, "status"]) == {"regular"}
    assert "regular" not in set(frame.loc[~regular, "status"])
    assert np.isfinite(frame.loc[regular, "kinetic_energy.max"]).all()
    assert frame.loc[~regular, "kinetic_energy.max"].isna().all()
