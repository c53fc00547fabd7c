"""The report's design-space section: a scatter matrix of a bounded sample of the regular designs coloured by
the objective, the best designs marked and tabulated; a one-quantity sweep keeps its own section."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from machdyn.reading import load_problem
from machdyn.report.explore import exploration_section, plot_design_space, sections
from machdyn.studies.exploration import explore
from machdyn.studies.exploration.digest import SAMPLE
from machdyn.studies.sweep.stage import outcome

from .conftest import explore_text


def test_scatter_matrix_of_the_sample_coloured_by_the_objective(tmp_path):
    done = explore(load_problem(explore_text(samples=4000, partition=1024)), store=tmp_path / "s")
    sample = done.digest.sample_in_design_order()
    assert len(sample["design"]) == SAMPLE  # bounded, however many designs
    assert np.all(sample["regular"]) and np.all(np.diff(sample["design"]) > 0)
    axes = plot_design_space(Figure(figsize=(8, 7)), done)
    assert axes.shape == (4, 4)
    lower = axes[3, 0]
    points, best = lower.collections[:2]
    assert len(points.get_offsets()) == SAMPLE
    np.testing.assert_allclose(points.get_array(), sample["driving_torque.max_abs"])  # colour = objective
    np.testing.assert_allclose(best.get_offsets()[:, 0], done.digest.best["mechanism.crank.length"] * 1e3)
    assert not axes[0, 3].get_visible()


def test_section_html_names_what_was_explored(tmp_path):
    done = explore(load_problem(explore_text(samples=128, partition=64)), store=tmp_path / "s")
    html = exploration_section(done)
    assert "<svg" in html and "Best designs" in html
    assert f"{done.digest.regular:,} regular" in html and "Sobol" in html
    heading, body = sections(outcome(done))[0]
    assert heading == "Design space of mechanism.crank.length, mechanism.coupler.mass, drive.speed, " \
                      "loads.torques[0].torque"
    assert body.count("<tr>") == 1 + min(20, done.digest.regular)
