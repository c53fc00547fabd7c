"""Shared models of the balancing tests."""

from __future__ import annotations

import pytest

from machdyn.linkage import four_bar, slider_crank


@pytest.fixture
def engine():
    """A slider-crank with a heavy rod (centre on its axis) and a piston; horizontal stroke."""
    return slider_crank(0.05, 0.2, masses=(1.0, 2.0, 3.0), inertias=(0.001, 0.012, 0.0),
                        coms=((0.01, 0.0), (0.06, 0.0), (0.0, 0.0)), gravity=(0.0, 0.0))


@pytest.fixture
def fourbar():
    """A crank-rocker with centres off the link axes and a coupler point (Grashof: 0.1 + 0.4 < 0.35 + 0.3)."""
    return four_bar(0.1, 0.35, 0.3, 0.4, masses=(1.0, 2.0, 1.5), coms=((0.05, 0.01), (0.15, 0.04), (0.12, -0.02)),
                    inertias=(0.002, 0.03, 0.015), coupler_point=(0.2, 0.05), gravity=(0.0, 0.0))
