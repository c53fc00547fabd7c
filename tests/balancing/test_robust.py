"""Robust balancing over several operating states."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.balancing.frame import cycle
from machdyn.balancing.general import CounterweightSlot, least_squares_counterweights
from machdyn.balancing.robust import OperatingState, robust_counterweights
from machdyn.errors import InputError
from machdyn.linkage import slider_crank


def _engine(stroke_radius):
    return slider_crank(stroke_radius, 0.25, masses=(1.0, 2.0, 3.0), inertias=(0.001, 0.01, 0.0),
                        coms=((0.01, 0.0), (0.08, 0.0), (0.0, 0.0)), gravity=(0.0, 0.0))


def test_one_state_is_the_least_squares_solution():
    slot = CounterweightSlot("crank", radius=0.06)
    robust = robust_counterweights([OperatingState("only", _engine(0.05), 30.0)], [slot], crank_angle=cycle(90))
    ls = least_squares_counterweights(_engine(0.05), [slot], cycle(90), 30.0)
    assert robust.rows[0].rms_after == pytest.approx(ls.after.rms_force, rel=1e-9)


def test_worst_mode_lowers_the_worst_state():
    # the crank pin of the other states is not where the counterweight's arm assumes: one counterweight
    # cannot balance all strokes, so the modes trade off
    states = [OperatingState(f"r = {r} m", _engine(r), w) for r, w in ((0.03, 40.0), (0.05, 30.0), (0.07, 20.0))]
    slot = [CounterweightSlot("crank", radius=0.06)]
    total = robust_counterweights(states, slot, "sum", cycle(60))
    worst = robust_counterweights(states, slot, "worst", cycle(60))
    assert worst.worst_after <= total.worst_after * (1 + 1e-9)
    ms = [np.mean([r.rms_after**2 for r in res.rows]) for res in (total, worst)]
    assert ms[0] <= ms[1] * (1 + 1e-9)
    assert len(worst.rows) == 3 and all(r.rms_before > r.rms_after for r in total.rows)


def test_bad_input():
    with pytest.raises(InputError, match="mode"):
        robust_counterweights([OperatingState("a", _engine(0.05))], [CounterweightSlot("crank", radius=0.1)], "max")
    with pytest.raises(InputError, match="speed"):
        robust_counterweights([OperatingState("a", _engine(0.05), -1.0)], [CounterweightSlot("crank", radius=0.1)])
