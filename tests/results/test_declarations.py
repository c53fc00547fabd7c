"""Every result declares how it reduces over the positions and which way is better, and the studies read it
(the optimiser's warning: tests/optimise/test_objective_direction.py)."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.kinds import catalogue
from machdyn.linkage.reductions import REDUCTIONS
from machdyn.results.catalogue import BETTER, against, best_index, better_of, worst
from machdyn.studies.exploration.digest import Digest


def test_every_key_of_the_catalogue_declares_its_reduction_and_better_direction():
    entries = catalogue()
    assert len(entries) > 400  # the linkage's, the kinds' and every capability's keys, patterns included
    undeclared = [q.key for q in entries if q.over_positions not in REDUCTIONS or q.better not in BETTER]
    assert undeclared == []


@pytest.mark.parametrize("key, better", [
    ("driving_torque.max_abs", "lower"), ("transmission_angle.worst", "higher"), ("cam.peak_torque", "lower"),
    ("cam.jump_speed", "higher"), ("flywheel.motor_starts_per_hour", "higher"), ("parts.link.B.fatigue_safety",
                                                                                 "higher"),
    ("max_driving_torque", "lower"),  # an old name, read as its key
])
def test_the_better_direction_of_a_key_comes_from_its_declaration(key, better):
    assert better_of(key, catalogue()) == better


def test_best_and_worst_pick_by_the_declared_direction():
    values = np.array([3.0, np.nan, 1.0, 7.0])
    assert best_index(values, "lower") == 2 and best_index(values, "higher") == 3
    per_state = np.array([[3.0, 5.0, np.nan], [2.0, 1.0, 4.0]])  # designs x operating states
    np.testing.assert_array_equal(worst(per_state, "lower"), [5.0, 4.0])
    np.testing.assert_array_equal(worst(per_state, "higher"), [3.0, 1.0])
    with pytest.raises(ValueError, match="lower or higher"):
        worst(per_state, "none")
    assert against("minimise", "higher") and against("maximise", "lower")
    assert not against("minimise", "lower") and not against("maximise", "none")


def test_an_exploration_keeps_the_highest_of_a_result_of_which_more_is_better():
    cols = {"design": np.arange(5), "regular": np.ones(5, bool), "assembled": np.ones(5, bool),
            "transmission_angle.worst": np.array([0.3, 0.9, 0.5, 0.7, 0.1])}
    digest = Digest("transmission_angle.worst", "higher", best_size=2)
    digest.add(cols, 0, 1)
    np.testing.assert_array_equal(digest.best["design"], [1, 3])
    lowest = Digest("transmission_angle.worst", "lower", best_size=2)
    lowest.add(cols, 0, 1)
    np.testing.assert_array_equal(lowest.best["design"], [4, 0])

