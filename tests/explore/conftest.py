"""A small four-bar problem whose exploration varies a link length, a link mass, the crank speed and a load."""

from __future__ import annotations

import pytest

from problem_texts import four_bar

BASE = four_bar("explore", positions=36)

FOUR = """
[[sweep.quantities]]
parameter = "mechanism.crank.length"
start = "30 mm"
stop = "70 mm"

[[sweep.quantities]]
parameter = "mechanism.coupler.mass"
start = "0.3 kg"
stop = "0.8 kg"

[[sweep.quantities]]
parameter = "drive.speed"
start = "5 rad/s"
stop = "15 rad/s"

[[sweep.quantities]]
parameter = "loads.torques[0].torque"
start = "-1 N*m"
stop = "0 N*m"
"""


def explore_text(method: str = "sobol", samples: int = 200, partition: int = 64, extra: str = "") -> str:
    """The base problem with a four-quantity exploration (crank lengths up to 70 mm do not all assemble)."""
    head = f'\n[sweep]\nmethod = "{method}"\nsamples = {samples}\nseed = 5\npartition = {partition}\n{extra}'
    return BASE + head + FOUR


@pytest.fixture
def problem_text() -> str:
    return explore_text()
