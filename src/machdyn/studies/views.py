"""Chosen designs of a design space, analysed one by one so that the report can play them back.

A sweep, an exploration or an optimisation keeps per-design summaries, not every design's motion. The few
designs a reader wants to see move — the best ones, the optimum and the nominal design beside it, a handful of
a one-quantity sweep — are rebuilt here from their own validated problem (written out and read back, as a
file would be) and analysed over the problem's crank range by the same engine as a run.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from ..errors import InputError, ProblemFileError, SingularPositionError
from ..linkage import analyse
from ..pipelines.linkage_run import crank_range
from ..problem.build import build_mechanism
from ..problem.paths import design_problem

#: At most this many designs of a design space are analysed for playback (each adds ~100 kB to the report).
MAX_VIEWS = 6


@dataclass(frozen=True)
class DesignView:
    """One design ready to be drawn: its label ("nominal", "optimum", "design 12"), its index in the design
    space (-1 for the nominal design), the engine's model and analysis, and the point [m] the shaking moment is
    taken about."""

    label: str
    design: int
    mechanism: Any
    analysis: Any
    about: tuple[float, float]


def analysed(problem: Any, label: str, design: int = -1) -> DesignView | None:
    """The view of a validated linkage problem, or None when it does not build or assemble over its crank
    range (such a design has no motion to show)."""
    try:
        mech = build_mechanism(problem)
        angles, speed, accel = crank_range(problem)
        analysis = analyse(mech, angles, speed, accel)
    except (InputError, ProblemFileError, SingularPositionError, ValueError):
        return None
    about = tuple(float(v) for v in problem.output.shaking_moment_about)
    return DesignView(label, design, mech, analysis, (about[0], about[1]))


def views_of(problem: Any, designs: Mapping[int, Mapping[str, float]], *, labels: Mapping[int, str] | None = None,
             nominal: bool = True) -> tuple[DesignView, ...]:
    """Views of chosen designs (index -> {quantity path: SI value}), at most :data:`MAX_VIEWS`, and of the
    nominal design first when ``nominal``; designs that cannot be rebuilt are left out."""
    views: list[DesignView] = []
    if nominal:
        base = design_problem(problem, {})
        view = analysed(base, "nominal")
        if view is not None:
            views.append(view)
    for index, values in list(designs.items())[:MAX_VIEWS]:
        try:
            candidate = design_problem(problem, values)
        except ValueError:  # a design whose file does not validate (InputError) simply has no view
            continue
        view = analysed(candidate, (labels or {}).get(index, f"design {index}"), index)
        if view is not None:
            views.append(view)
    return tuple(views)
