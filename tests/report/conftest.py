"""Analyses shared by the report tests: a four-bar with a coupler point, an offset slider-crank and a
four-bar with three design variants."""

from __future__ import annotations

import numpy as np
import pytest

from machdyn.linkage import analyse, crank_angles, four_bar, slider_crank

POSITIONS = 120
SPEED = 20.0


@pytest.fixture(scope="session")
def four_bar_analysis():
    mech = four_bar(0.05, 0.15, 0.12, 0.14, coupler_point=(0.07, 0.04))
    return analyse(mech, crank_angles(POSITIONS), SPEED)


@pytest.fixture(scope="session")
def slider_crank_analysis():
    mech = slider_crank(0.05, 0.2, 0.01)
    return analyse(mech, crank_angles(POSITIONS), SPEED)


@pytest.fixture(scope="session")
def sweep_analysis():
    mech = four_bar(0.05, np.array([0.14, 0.15, 0.16]), 0.12, 0.14)
    return analyse(mech, crank_angles(POSITIONS), SPEED)


@pytest.fixture(params=["four_bar", "slider_crank"])
def any_analysis(request, four_bar_analysis, slider_crank_analysis):
    return {"four_bar": four_bar_analysis, "slider_crank": slider_crank_analysis}[request.param]
