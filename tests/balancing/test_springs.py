"""Spring compensation: the engine's torque with the spring equals the formula; the best spring evens it out."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.balancing.frame import cycle
from machdyn.balancing.springs import best_stiffness, optimise_spring, spring_compensation, spring_torque
from machdyn.errors import InputError


def test_engine_torque_with_the_spring_is_t0_plus_spring_torque(fourbar):
    result, design = spring_compensation(fourbar, "rocker", (0.3, 0.0), (0.6, 0.3), cycle(90), 10.0)
    spring = result.model.springs[-1]
    kin_len = np.hypot(*(np.array([0.6, 0.3])[:, None] - _rocker_tip(result.after.crank_angle, fourbar)))
    rate = np.gradient(kin_len, result.after.crank_angle)  # 4-degree steps: central differences to ~1e-3
    expected = result.before.torque + spring_torque(spring.stiffness, spring.free_length, kin_len, rate)
    scale = np.max(np.abs(result.before.torque))
    assert np.max(np.abs(result.after.torque - expected)[1:-1]) < 5e-3 * scale
    assert design.rms_after < design.rms_before


def _rocker_tip(phi, mech):
    from machdyn.linkage import kinematics

    p = kinematics(mech, phi, 10.0).point("rocker.B")
    return np.vstack([p.x, p.y])


def test_attachment_search_beats_a_fixed_attachment(fourbar):
    fixed, d0 = spring_compensation(fourbar, "rocker", (0.15, 0.0), (0.4, 0.4), cycle(60), 10.0)
    best, d1 = optimise_spring(fourbar, "rocker", ((0.0, 0.3), (-0.05, 0.05)), ((0.2, 0.6), (0.2, 0.5)),
                               cycle(60), 10.0)
    assert d1.rms_after <= d0.rms_after * (1 + 1e-9)
    assert "attachment search" in best.notes[-1]


def test_best_stiffness_respects_bounds():
    phi = cycle(64)
    length, rate = 1 + 0.1 * np.cos(phi), -0.1 * np.sin(phi)
    torque = -500.0 * (length - 1.0) * rate
    k, l0, _ = best_stiffness(torque, length, rate, stiffness_bounds=(0.0, 200.0))
    assert k == pytest.approx(200.0)
    with pytest.raises(InputError, match="bounds"):
        best_stiffness(torque, length, rate, free_length_bounds=(1.0, 0.5))
