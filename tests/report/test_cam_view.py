"""The animated cam in the report: drawn from the run's own profile and lift, the follower touching the cam.

At every drawn cam angle the roller (of the computed radius) touches the turned cam surface: the smallest
distance from its centre to the surface equals the roller radius; and the drawn roller centre is at the computed
lift above its lowest position."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from machdyn.report import cam_view
from machdyn.runner import run_problem

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.fixture(scope="module")
def feeder():
    return run_problem(EXAMPLES / "feeder_cam.toml").outcomes["cam"].results


def test_the_drawn_roller_touches_the_turned_cam_at_every_angle(feeder, monkeypatch):
    monkeypatch.setattr(cam_view, "SURFACE_POINTS", 100_000)  # every computed surface point
    data = cam_view.cam_scene(feeder)
    cam = np.array([[data["points"][f"cam.{n}"][axis] for n in data["bodies"][0]["points"]] for axis in (0, 1)])
    centre = np.asarray(data["points"]["follower.centre"], dtype=float)
    gaps = np.hypot(cam[0] - centre[0][None, :], cam[1] - centre[1][None, :]).min(axis=0)
    rr = feeder.model.follower.roller_radius
    # the surface is sampled at 0.5° of cam angle: the nearest sample lies within ~0.2 mm of the true contact
    np.testing.assert_allclose(gaps, rr, atol=2e-4)


def test_the_drawn_follower_rises_by_the_computed_lift(feeder):
    data = cam_view.cam_scene(feeder)
    y = np.asarray(data["points"]["follower.centre"][1], dtype=float)
    lift = np.asarray(data["curves"][0]["y"], dtype=float) / 1e3
    # coordinates are rounded to 1e-5 of the drawing (< 0.3 m here), the lift to 5 significant digits
    np.testing.assert_allclose(y - y.min(), lift - lift.min(), atol=1e-5)

