"""Diagnostics describe the crank range analysed, not the full turn; a double slider-crank is described
per slider."""

from __future__ import annotations

import numpy as np

from machdyn.linkage import analyse, diagnose, kinematics
from machdyn.linkage.builders import double_slider_crank, four_bar


def _triple_rocker():
    # Non-Grashof (s + l = 40 + 130 > p + q = 100 + 60): the crank cannot turn fully; the ends of its
    # assembly range are dead positions, symmetric about 180 deg.
    return four_bar(0.04, 0.10, 0.06, 0.13)


def test_full_turn_of_a_range_changes_nothing():
    mech = four_bar(0.04, 0.12, 0.10, 0.13)
    assert diagnose(mech, crank_range=(0.0, 2 * np.pi)) is diagnose(mech)


def test_a_partial_range_has_no_dead_position_outside_it():
    mech = _triple_rocker()
    full = diagnose(mech)
    assert full.dead_positions and all(np.pi / 2 < d < 3 * np.pi / 2 for d in full.dead_positions)
    part = diagnose(mech, crank_range=(0.0, np.pi / 2))
    assert part.dead_positions == []
    assert not any("Dead" in w or "cannot assemble" in w for w in part.warnings)
    assert part.crank_range == (0.0, np.pi / 2)


def test_transmission_extremes_and_stroke_are_those_of_the_range():
    mech = four_bar(0.04, 0.12, 0.10, 0.13)
    start, stop = 0.0, np.pi / 2
    part = diagnose(mech, crank_range=(start, stop))
    # Independent figures: the kinematics sampled densely over the range itself.
    phi = np.linspace(start, stop, 9001)
    kin = kinematics(mech, phi, 1.0, 0.0)
    mu = np.asarray(kin.dyad_reports[0].transmission)
    rocker = np.unwrap(np.asarray(kin.body("rocker").angle))
    # 3600 samples per turn: an extreme is within one sample (0.1 deg) of the crank angle; the figures move
    # by at most |d mu / d phi| * 0.1 deg, well under 0.5 deg here.
    tol = np.radians(0.5)
    assert abs(part.transmission_angle_min - mu.min()) < tol
    assert abs(part.transmission_angle_max - mu.max()) < tol
    assert abs(part.strokes["rocker"] - (rocker.max() - rocker.min())) < tol
    assert part.time_ratio is None and part.time_ratios["rocker"] is None
    assert any("time ratio" in w for w in part.warnings)
    # The full turn reaches a larger transmission angle (near 180 deg of crank) than the quarter turn.
    assert diagnose(mech).transmission_angle_max > part.transmission_angle_max + np.radians(10.0)


def test_analysis_of_a_partial_range_sizes_its_diagnostics():
    mech = _triple_rocker()
    analysis = analyse(mech, np.linspace(0.0, np.pi / 2, 91), 10.0)
    assert analysis.diagnostics.crank_range == (0.0, np.pi / 2)
    assert analysis.diagnostics.dead_positions == []
    full = analyse(four_bar(0.04, 0.12, 0.10, 0.13), np.linspace(0, 2 * np.pi, 360, endpoint=False), 10.0)
    assert full.diagnostics.crank_range is None and full.diagnostics.time_ratio is not None


def test_double_slider_crank_time_ratio_and_transmission_per_slider():
    # Offset slider 1 (a quick return), centred slider 2 (time ratio exactly 1: symmetric motion).
    mech = double_slider_crank(0.03, 0.12, 0.02, 0.15, offset_1=0.02, phase=np.pi / 2)
    diag = diagnose(mech)
    sliders = [b for b in diag.strokes if b in diag.time_ratios]
    assert len(diag.time_ratios) == 2 and len(diag.transmission_angles) == 2
    ratios = [diag.time_ratios[b] for b in sliders]
    # Uicker, Pennock & Shigley 5th ed. §1.9: the centred slider-crank has Q = 1; an offset one Q > 1.
    assert min(abs(r - 1.0) for r in ratios) < 1e-3
    assert max(ratios) > 1.05
    for body in sliders:
        lo, hi = diag.transmission_angles[body]
        assert 0.0 < lo <= hi <= np.pi
