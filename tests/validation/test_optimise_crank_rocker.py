"""Validation of the optimiser against a closed-form optimum: the crank-rocker of unit time ratio.

Source: R.L. Norton, *Design of Machinery*, 5th ed., McGraw-Hill, §3.4, Example 3-1 ("rocker output, two
positions with angular displacement"): a crank-rocker whose rocker swings through psi between B1 and B2 with
equal forward and return times (time ratio 1) has its crank pivot O on the line B1B2 extended, and the crank is
half the chord, a = |B1B2| / 2 = c sin(psi/2). With the ground link d fixed, O lies at distance b (the coupler)
from the chord's midpoint M, and M lies c cos(psi/2) from the rocker pivot D, so d^2 = b^2 + c^2 cos^2(psi/2):
b = sqrt(d^2 - c^2 cos^2(psi/2)). For c = 100 mm, d = 150 mm, psi = 45 deg: a = 38.268 mm, b = 118.171 mm.

The optimiser is asked, over a in 10-80 mm and b in 60-250 mm, for the smallest time ratio with the rocker's
swing held to 45 +- 0.01 deg; time ratio 1 with that swing has exactly the closed-form solution, which the
search must find without being told where it is.
"""

from __future__ import annotations

import math

import pytest

from machdyn.reading import load_problem
from machdyn.studies.optimisation import optimise

PROBLEM = """
[meta]
name = "Crank-rocker of unit time ratio and 45 deg swing"
[mechanism]
type = "four_bar"
[mechanism.crank]
length = "40 mm"
[mechanism.coupler]
length = "120 mm"
[mechanism.rocker]
length = "100 mm"
[mechanism.ground]
length = "150 mm"
[drive]
speed = "10 rad/s"
positions = 720
[loads]
gravity = "off"
[optimise]
population = 30
generations = 200
tolerance = 1e-7
seed = 2
[[optimise.variables]]
parameter = "mechanism.crank.length"
lower = "10 mm"
upper = "80 mm"
[[optimise.variables]]
parameter = "mechanism.coupler.length"
lower = "60 mm"
upper = "250 mm"
[[optimise.objectives]]
result = "time_ratio"
[[optimise.constraints]]
result = "stroke.rocker"
min = "44.99 deg"
max = "45.01 deg"
"""


def test_unit_time_ratio_crank_rocker_matches_the_closed_form():
    problem = load_problem(PROBLEM)
    result = optimise(problem, problem.optimise)
    c, d, psi = 0.100, 0.150, math.radians(45.0)
    a = c * math.sin(psi / 2)
    b = math.sqrt(d**2 - (c * math.cos(psi / 2)) ** 2)
    assert result.converged and result.verified
    # The +-0.01 deg swing band allows da/a = 0.01/45 * cot-like factors ~ 2e-4; the time ratio found is 1
    # to the interpolation of the limit positions (720 crank angles).
    assert result.x[0] == pytest.approx(a, rel=5e-4)
    assert result.x[1] == pytest.approx(b, rel=5e-4)
    assert result.results["time_ratio"] == pytest.approx(1.0, abs=1e-4)
    assert math.degrees(result.results["stroke.rocker"]) == pytest.approx(45.0, abs=0.0101)
