"""The optimisation plots draw the result's own numbers (history and front), and the section renders."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from machdyn.pipeline import Outcome
from machdyn.report.optimise import plot_convergence, plot_pareto, sections
from machdyn.studies.optimisation import optimise

from .conftest import problem_with

TWO = """
[optimise]
population = 12
generations = 6
positions = 72
[[optimise.variables]]
parameter = "mechanism.crank.length"
lower = "20 mm"
upper = "55 mm"
[[optimise.objectives]]
result = "driving_torque.max_abs"
[[optimise.objectives]]
result = "stroke.rocker"
sense = "maximise"
"""


def test_pareto_and_convergence_plots_show_the_results_numbers():
    problem = problem_with(TWO)
    result = optimise(problem, problem.optimise)
    ax = plot_pareto(result, Figure().subplots())
    front = ax.lines[0]
    np.testing.assert_array_equal(front.get_xdata(), result.front_f[:, 0])
    np.testing.assert_array_equal(front.get_ydata(), result.front_f[:, 1])
    ax = plot_convergence(result, Figure().subplots())
    np.testing.assert_array_equal(ax.lines[0].get_xdata(), result.history.generation)
    html = sections(Outcome(results=result))[0][1]
    assert "Pareto front" in html and "[mechanism.crank]" in html
