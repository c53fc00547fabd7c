"""Shared problems of the optimisation tests: small populations and coarse crank grids keep them fast."""

from __future__ import annotations

from pathlib import Path

import pytest

from machdyn.reading import load_problem

ROOT = Path(__file__).resolve().parents[2]

FOUR_BAR = """
[meta]
name = "crank-rocker"
[mechanism]
type = "four_bar"
coupler_point = ["60 mm", "20 mm"]
[mechanism.crank]
length = "40 mm"
mass = "0.3 kg"
[mechanism.coupler]
length = "120 mm"
mass = "0.5 kg"
[mechanism.rocker]
length = "100 mm"
mass = "0.4 kg"
[mechanism.ground]
length = "150 mm"
[drive]
speed = "120 rpm"
positions = 180
[[loads.torques]]
body = "rocker"
torque = "-2 N*m"
"""


def problem_with(optimise: str, base: str = FOUR_BAR):
    """A validated problem: ``base`` with the ``[optimise]`` text appended."""
    return load_problem(base + "\n" + optimise)


@pytest.fixture
def compactor():
    """The shipped compactor example, validated."""
    return load_problem(ROOT / "examples" / "compactor_optimise.toml")
