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



OSCILLATING = (EXAMPLES / "feeder_cam.toml").read_text(encoding="utf-8").replace(
    'motion = "translating"\ncontact = "roller"\nroller_radius = "12 mm"\noffset = "5 mm"',
    'motion = "oscillating"\ncontact = "roller"\nroller_radius = "12 mm"\npivot_distance = "120 mm"\n'
    'arm_length = "100 mm"').replace('lift = "30 mm"', 'swing = "15 deg"').replace("[cam.dynamics]", "[cam.unused]")


@pytest.fixture(scope="module")
def rocker():
    text = OSCILLATING.split("[cam.unused]")[0] + "[cam.output]\ncutter_radius = \"12 mm\"\n"
    return run_problem(text).outcomes["cam"].results


def test_an_oscillating_follower_touches_the_turned_cam_on_its_arm_at_the_computed_swing(rocker, monkeypatch):
    """The oscillating roller follower (arm 100 mm, pivot 120 mm from the cam centre, 15° swing): at every drawn
    angle the roller touches the turned cam (as above), the arm keeps its length about the fixed pivot, and its
    angle from the line of centres is psi_0 + s, the computed swing (coordinates rounded to 1e-5 of the drawing)."""
    monkeypatch.setattr(cam_view, "SURFACE_POINTS", 100_000)
    data = cam_view.cam_scene(rocker)
    follower = rocker.model.follower
    assert follower.motion == "oscillating"
    cam = np.array([[data["points"][f"cam.{n}"][axis] for n in data["bodies"][0]["points"]] for axis in (0, 1)])
    centre = np.asarray(data["points"]["follower.centre"], dtype=float)
    pivot = np.asarray(data["points"]["follower.pivot"], dtype=float)
    gaps = np.hypot(cam[0] - centre[0][None, :], cam[1] - centre[1][None, :]).min(axis=0)
    np.testing.assert_allclose(gaps, follower.roller_radius, atol=2e-4)
    np.testing.assert_allclose(pivot[0], follower.pivot_distance, atol=1e-5)
    np.testing.assert_allclose(np.hypot(*(centre - pivot)), follower.arm_length, atol=1e-5)
    psi = np.arctan2(centre[1], pivot[0] - centre[0])  # the arm's angle from the line towards the cam centre
    swing = np.radians(np.asarray(data["curves"][0]["y"], dtype=float))
    np.testing.assert_allclose(psi, follower.start_angle + swing, atol=2e-4)
    assert data["curves"][0]["unit"] == "°" and data["guides"] == []
