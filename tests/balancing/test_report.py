"""Report plots of balancing: axes in, axes out, with the before and after curves drawn."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from machdyn.balancing.berkof_lowen import berkof_lowen
from machdyn.balancing.counterweights import tradeoff_curve
from machdyn.balancing.frame import cycle
from machdyn.balancing.general import CounterweightSlot
from machdyn.balancing.robust import OperatingState, robust_counterweights
from machdyn.report.balancing import plot_before_after, plot_polar_before_after, plot_state_reductions, plot_tradeoff


def test_plots_draw_before_and_after(fourbar, engine):
    result = berkof_lowen(fourbar, 0.08, 0.1, cycle(36), 20.0)
    fig = Figure()
    polar = fig.add_subplot(2, 2, 1, projection="polar")
    assert plot_polar_before_after(polar, result.before, result.after) is polar
    labels = [line.get_label() for line in polar.get_lines()]
    assert "before" in labels and "after" in labels
    # the balanced locus sits at the origin: zero shaking force
    after_line = polar.get_lines()[labels.index("after")]
    assert np.max(after_line.get_ydata()) < 1e-9
    ax = fig.add_subplot(2, 2, 2)
    assert plot_before_after(ax, result.before, result.after, "moment") is ax
    curve = tradeoff_curve(engine, 0.08, np.linspace(0, 1, 5), cycle(36), 50.0)
    ax = fig.add_subplot(2, 2, 3)
    assert plot_tradeoff(ax, curve, chosen=0.5) is ax
    assert len(ax.get_lines()) == 4  # along, across, resultant, chosen fraction
    states = [OperatingState("a", engine, 50.0), OperatingState("b", engine, 80.0)]
    robust = robust_counterweights(states, [CounterweightSlot("crank", radius=0.08)], crank_angle=cycle(36))
    ax = fig.add_subplot(2, 2, 4)
    assert plot_state_reductions(ax, robust.rows, reference=0.43) is ax
