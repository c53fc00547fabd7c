"""The machine on its mounts in the report: the drawn frame moves as the steady-state response says.

The view computes the frame's rigid-body motion with its own small-rotation formula; here every drawn corner is
checked against :meth:`machdyn.vibration.response.FrameResponse.displacement` (the response's own point
matrix), evaluated at the view's crank angles, times the stated exaggeration."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from machdyn.report.frame_view import EXCURSION, frame_scene, frame_view
from machdyn.runner import run_problem

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.fixture(scope="module")
def study():
    return run_problem(EXAMPLES / "tamper_on_tyres.toml").outcomes["frame"].results


def test_each_drawn_corner_of_the_frame_moves_as_the_response_displacement_times_the_stated_factor(study):
    data, factor = frame_scene(study, study.before)
    phi = np.radians(np.asarray(data["angles"], dtype=float))
    c, s = np.cos(study.angle), np.sin(study.angle)
    origin = np.asarray(study.origin)
    orders = study.before.loads.orders
    for i in range(1, 5):
        xs, ys = (np.asarray(v, dtype=float) for v in data["points"][f"frame.c{i}"])
        # the rest position: the drawn position minus the drawn excursion must be one fixed point
        rest_mech = None
        for k in (0, len(phi) // 3, 2 * len(phi) // 3):
            drawn = np.array([xs[k], ys[k]])
            rest = drawn.copy()
            for _ in range(60):  # drawn = rest + factor * u(rest): solve for the rest position by iteration
                p_frame = origin + np.array([[c, -s], [s, c]]) @ rest
                u = (study.before.displacement(p_frame) * np.exp(1j * orders * phi[k])[:, None]).sum(axis=0).real
                rest = drawn - factor * (np.array([[c, s], [-s, c]]) @ u)
            if rest_mech is None:
                rest_mech = rest
            # one rest position for every crank angle: the corner moved exactly by factor * u
            assert rest == pytest.approx(rest_mech, abs=1e-9)


def test_the_largest_drawn_excursion_is_the_stated_share_of_the_drawing(study):
    data, factor = frame_scene(study, study.before)
    corners = np.array([[np.asarray(data["points"][f"frame.c{i}"][j], dtype=float) for j in (0, 1)]
                        for i in range(1, 5)])  # corner, axis, frame
    span = max(np.ptp(corners[:, 0, 0]), np.ptp(corners[:, 1, 0]))
    assert factor > 1e3, "micrometres on a metre-sized machine need a large exaggeration"
    moves = [np.hypot(*(v - v.mean(axis=1, keepdims=True))) for v in corners]
    # the largest excursion from the mean position is at most the stated share (it equals it about the rest)
    assert max(float(m.max()) for m in moves) <= 2 * EXCURSION * span


def test_the_balanced_machine_moves_beside_the_unbalanced_one_with_the_same_exaggeration(study):
    html = str(frame_view(study))
    assert study.labels[0] in html and study.labels[1] in html
    (_, f_before), (_, f_after) = frame_scene(study, study.before), frame_scene(study, study.after, after=True)
    assert f"{min(f_before, f_after):.3g} times larger" in html
