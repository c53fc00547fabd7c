"""Function generation: the placement of the input and output ranges searched under ``candidates``, each
candidate's Freudenstein constants and its error in degrees, checked against the engine."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.linkage import kinematics
from machdyn.runner import run_problem
from machdyn.synthesis.task import placements

TASK = """
[meta]
name = "log10"

[synthesis]
task = "function"
function = "log10"
x_range = [1.0, 2.0]
input_range = ["30 deg", "120 deg"]
output_range = ["60 deg", "150 deg"]
ground = "100 mm"
{extra}

[synthesis.ranking]
by = "error"
keep = 0
"""


def _outcome(extra: str):
    return run_problem(TASK.format(extra=extra)).outcomes["synthesis"]


def test_placements_start_with_the_given_ranges_and_cover_the_turn():
    p = placements(17, seed=3)
    assert p.shape == (17, 2) and np.all(p[0] == 0.0)
    assert np.all((p[1:] > 0.0) & (p[1:] < 2 * np.pi)) and len({tuple(r) for r in p}) == 17


def test_candidates_are_honoured_and_the_search_never_does_worse_than_the_given_placement():
    given = _outcome("")
    searched = _outcome("candidates = 24")
    assert len(searched.results.candidates) == 24
    assert len(given.results.candidates) == 2  # Chebyshev points and the least-squares fit, ranges as given
    assert searched.scalars["synthesis.best.error"] <= given.scalars["synthesis.best.error"] + 1e-15


def test_the_best_candidates_constants_and_error_agree_with_its_links_and_the_engine():
    out = _outcome("candidates = 12")
    c = out.results.candidates[0]
    k1, k2, k3 = (out.scalars[f"synthesis.best.{n}"] for n in ("K1", "K2", "K3"))
    # Freudenstein's constants from the link lengths (Uicker, Pennock & Shigley, 4th ed., ch. 10): signed links
    a = c.ground / k1
    cc = c.ground / k2
    assert abs(a) == pytest.approx(c.crank, rel=1e-12) and abs(cc) == pytest.approx(c.rocker, rel=1e-12)
    assert k3 == pytest.approx((a * a - c.coupler**2 + cc * cc + c.ground**2) / (2 * a * cc), rel=1e-10)
    # the error over the range by the engine: the candidate's model run at the task's (moved) crank angles
    x = np.linspace(1.0, 2.0, 201)
    t2 = np.radians(30.0 + 90.0 * (x - 1.0)) + c.free["input_shift"] + c.free["input_offset"]
    want = np.radians(60.0) + np.log10(x) / np.log10(2.0) * np.radians(90.0) + c.free["output_shift"]
    rocker = np.asarray(kinematics(c.mechanism(), t2, 1.0).body("rocker").angle, dtype=float)
    err = np.angle(np.exp(1j * (rocker + c.output_offset - want)))
    assert np.max(np.abs(err)) == pytest.approx(out.scalars["synthesis.best.error"], rel=1e-9)
    # and the run shows it in degrees
    assert out.labels["synthesis.best.error"].display == "deg"
