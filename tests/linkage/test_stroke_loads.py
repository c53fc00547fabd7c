"""Force-stroke tables against the engine's own constant forces and work balance."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from machdyn.errors import InputError
from machdyn.linkage import analyse, crank_angles
from machdyn.linkage.builders import slider_crank
from machdyn.linkage.model import PointForce
from machdyn.linkage.stroke_loads import stroke_load, table_work

PRESS = slider_crank(0.04, 0.25, 0.0, masses=(12.0, 8.0, 60.0), slide_angle=-np.pi / 2)


def test_a_constant_table_is_the_constant_force_over_the_same_crank_range():
    """60 kN over the last 10 mm before bottom dead centre gives the driving torque of a constant upward force
    active from the crank angle where the ram is 10 mm above BDC (on its way down) to BDC."""
    table = stroke_load(PRESS, "punch", "slider.B", [0.0, 0.010], [60e3, 60e3])
    phi = crank_angles(3600)
    bdc = 1.5 * np.pi  # the crank points down along the slide
    assert table.working_end == pytest.approx(bdc, abs=2 * np.pi / 3600 + 1e-12)
    y = np.asarray(analyse(PRESS, phi, 4.0).kinematics.point("slider.B").y)
    start = float(phi[np.flatnonzero((phi < bdc) & (y <= -(0.04 + 0.25) + 0.010))[0]])
    constant = PointForce("punch", "slider.B", 0.0, 60e3, (start, bdc))
    from_table = analyse(replace(PRESS, forces=(table.force,)), phi, 4.0).forces.driving_torque
    from_constant = analyse(replace(PRESS, forces=(constant,)), phi, 4.0).forces.driving_torque
    away = (np.abs(phi - start) > 0.01) & (np.abs(phi - bdc) > 0.01)  # the windows' edges sit between samples
    assert np.allclose(from_table[away], from_constant[away], rtol=1e-9, atol=1e-6)
    assert np.max(np.abs(from_table)) > 1e3  # the punch is felt


def test_the_work_per_stroke_is_the_area_under_the_table():
    """The engine's work balance over a cycle: the load's work equals -area under the table (it resists)."""
    x, f = [0.0, 0.001, 0.003, 0.006], [0.0, 80e3, 50e3, 0.0]
    table = stroke_load(PRESS, "blank", "slider.B", x, f)
    res = analyse(replace(PRESS, forces=(table.force,), gravity=(0.0, 0.0)), crank_angles(36000), 4.0)
    assert res.work_balance.load_work == pytest.approx(-table_work(x, f), rel=2e-3)
    assert table.work == pytest.approx(table_work(x, f))


def test_tables_outside_the_stroke_or_not_increasing_are_refused():
    with pytest.raises(InputError, match="but the stroke of slider.B is 0.08 m"):
        stroke_load(PRESS, "too_long", "slider.B", [0.0, 0.1], [1.0, 1.0])
    with pytest.raises(InputError, match="must start at >= 0 m and increase"):
        stroke_load(PRESS, "bad", "slider.B", [0.0, 0.002, 0.001], [1.0, 1.0, 1.0])
    with pytest.raises(InputError, match="straight line"):
        stroke_load(PRESS, "pin", "crank.A", [0.0, 0.01], [1.0, 1.0])


def test_design_variants_with_their_own_force_stroke_tables_analyse_as_each_alone():
    """A sweep of the crank length stacks presses whose strokes differ, so each converts the same force-stroke
    table to its own crank-angle table: the stacked population's driving torque equals each design's own run
    (it used to stop with an internal error when the tables were stacked)."""
    from machdyn.linkage import stack_designs

    x, f = [0.0, 0.004], [60e3, 60e3]
    designs = [slider_crank(r, 0.25, 0.0, masses=(12.0, 8.0, 60.0), slide_angle=-np.pi / 2) for r in (0.035, 0.045)]
    alone = [replace(d, forces=(stroke_load(d, "punch", "slider.B", x, f).force,)) for d in designs]
    phi = crank_angles(720)
    stacked = analyse(stack_designs(alone), phi, 4.0).forces.driving_torque
    for i, design in enumerate(alone):
        own = analyse(design, phi, 4.0).forces.driving_torque
        assert np.allclose(np.asarray(stacked)[i], own, rtol=1e-12, atol=1e-9)
    assert not np.allclose(np.asarray(stacked)[0], np.asarray(stacked)[1])  # the two presses differ
