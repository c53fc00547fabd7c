"""Exact extremes: a peak of a series (the driving torque, a joint's force) reported by a run is the extreme of
the closed form between the samples and at the loads' breakpoints, not the largest sample; so it does not
depend on ``[drive] positions``. Checked against a 100 times denser sampling that holds the loads' breakpoints
too: where the peak sits at a breakpoint (a kink or a step of the series) its largest sample is the peak
itself; where the peak is smooth, the dense grid's miss is of the order f'' h²/8 ~ 1e-8 relative (h = 0.01 deg),
well inside the 1e-6 asked for."""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

from machdyn.linkage import PointForce, analyse, slider_crank
from machdyn.linkage.extremes import ANGLE_TOL, breakpoints, refine
from machdyn.linkage.stroke_loads import PeriodicTable
from machdyn.problem.build import build_mechanism
from machdyn.reading import load_problem
from machdyn.results.linkage import linkage_scalars

ROOT = Path(__file__).resolve().parents[2]
DENSER = 100


def _angles(positions: int) -> np.ndarray:
    return np.linspace(0.0, 2 * math.pi, positions, endpoint=False)


def _punch_press():
    """A vertical slider-crank press (crank 40 mm, rod 250 mm, ram 60 kg) under a sharp punch: 60 kN rising
    from nothing at 247.13 deg to its peak at 250.37 deg and gone at 251.99 deg (a breakpoint table whose angles
    lie between the samples of 360 positions and on those of 36000)."""
    mech = slider_crank(0.040, 0.250, slide_angle=-math.pi / 2, masses=(12.0, 8.0, 60.0),
                        inertias=(0.02, 0.05, 0.0))
    table = PeriodicTable(tuple(math.radians(a) for a in (0.0, 247.13, 250.37, 251.99)),
                          (0.0, 0.0, 60e3, 0.0))
    return dataclasses.replace(mech, forces=(PointForce("punch", "slider.B", 0.0, table),))


def _scalars(mech, positions: int, exact: bool, speed: float = 40 * 2 * math.pi / 60) -> dict:
    values, _ = linkage_scalars(analyse(mech, _angles(positions), speed), mech, exact=exact)
    return values


def _dense(mech, speed: float = 40 * 2 * math.pi / 60) -> dict:
    """The sampled extremes over 100 times as many positions, and the loads' breakpoints themselves (an edge of
    a window computed in degrees is not, to the last bit, one of the dense angles)."""
    phi = np.union1d(_angles(360 * DENSER), breakpoints(mech))
    values, _ = linkage_scalars(analyse(mech, phi, speed), mech)
    return values


def test_a_peak_driving_torque_under_a_sharp_punch_is_exact_at_any_number_of_positions():
    mech = _punch_press()
    dense = _dense(mech)
    sampled = _scalars(mech, 360, exact=False)
    # Sampled at 360 positions the peak is missed by several percent: the punch peaks between two samples.
    assert sampled["driving_torque.max_abs"] < 0.97 * dense["driving_torque.max_abs"]
    for positions in (360, 97, 1000):
        exact = _scalars(mech, positions, exact=True)
        for key in ("driving_torque.max_abs", "driving_torque.max", "driving_torque.min", "input_power.max",
                    "frame_force.max", "joint.A.max_force", "joint.B.max_force"):
            assert exact[key] == pytest.approx(dense[key], rel=1e-6), (positions, key)
            # an extreme of the closed form is never less extreme than one of its samples
            assert abs(exact[key]) >= abs(dense[key]) * (1 - 1e-12), (positions, key)


def test_a_peak_joint_force_of_the_press_example_is_exact_with_its_window_between_samples():
    """The crank press of the examples: its 60 kN punch acts from 250 deg to 270 deg; at 100 positions (a step
    of 3.6 deg) its window's start lies between two samples and the sampled peaks miss it."""
    problem = load_problem(ROOT / "examples" / "crank_press.toml")
    mech = build_mechanism(problem)
    speed = problem.drive.speed
    dense = _dense(mech, speed)
    sampled = _scalars(mech, 100, exact=False, speed=speed)
    exact = _scalars(mech, 100, exact=True, speed=speed)
    for key in ("joint.A.max_force", "joint.B.max_force", "driving_torque.max_abs", "frame_force.max"):
        assert exact[key] == pytest.approx(dense[key], rel=1e-6), key
    assert sampled["driving_torque.max_abs"] < 0.99 * dense["driving_torque.max_abs"]


def test_a_smooth_extreme_is_found_between_samples_and_breakpoints_are_the_loads_kinks():
    """refine on closed forms: the maximum of sin(x - 0.3) and the minimum of a triangle whose kink is a
    breakpoint lie between the samples; both come out exact, and so does a range (max - min)."""
    phi = _angles(12)
    kink = 2.0

    def triangle(x):
        return -np.abs(np.angle(np.exp(1j * (x - kink))))

    def evaluate(x):
        return {"sin": np.sin(x - 0.3), "tri": triangle(x), "low": np.sin(x - 0.3)}

    sampled = {"sin": (np.sin(phi - 0.3), "max"), "tri": (triangle(phi), "max"), "low": (np.sin(phi - 0.3), "min")}
    got = refine(evaluate, phi, sampled, [kink])
    assert got["sin"] == pytest.approx(1.0, abs=1e-15)
    assert got["low"] == pytest.approx(-1.0, abs=1e-15)
    assert got["tri"] == pytest.approx(0.0, abs=1e-15)
    # A kink not given is found by the search alone, to its angle tolerance (the triangle's slope is 1).
    without = refine(evaluate, phi, {"tri": sampled["tri"]})
    assert without["tri"] == pytest.approx(0.0, abs=ANGLE_TOL)
    press = _punch_press()
    assert np.degrees(breakpoints(press)) == pytest.approx([0.0, 247.13, 250.37, 251.99])


def test_a_partial_crank_range_is_searched_within_it():
    """Over a partial range the search stays within the first and last crank angle: the maximum of sin over
    [0, 1] rad is sin 1 at the end, not 1 beyond it."""
    phi = np.linspace(0.0, 1.0, 7)
    got = refine(lambda x: {"s": np.sin(x)}, phi, {"s": (np.sin(phi), "max")}, periodic=False)
    assert got["s"] == pytest.approx(math.sin(1.0), abs=1e-15)
