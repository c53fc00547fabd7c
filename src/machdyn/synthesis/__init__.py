"""Dimensional synthesis: from the motion a designer needs to four-bar and slider-crank linkages that do it.

Tasks (each returns :class:`~machdyn.synthesis.candidate.Candidate` linkages in the task's own coordinates):

- function generation: :func:`~.function.freudenstein` (three precision points, Chebyshev spacing offered) and
  :func:`~.function.freudenstein_least_squares` (many points);
- quick return: :func:`~.quick_return.crank_rocker` (a rocker swing and a time ratio) and
  :func:`~.quick_return.slider_crank` (a stroke and a time ratio), in closed form; the crank-and-slotted-lever
  and the Whitworth quick return from a time ratio and a stroke (:mod:`~.slotted_lever`, closed form, measured
  by the engine);
- motion generation: :func:`~.dyads.dyad_positions` (two and three positions, the standard dyad form with its
  free choices), :mod:`~.burmester` (four and five positions, circle-point and centre-point curves) and
  :func:`~.motion.motion_candidates` (dyads paired into four-bars);
- path generation: :func:`~.path.path_candidates` (precision points, with or without prescribed timing, closed
  form for three points, least squares seeded from closed-form solutions for more).

Every candidate is checked for its defects (:mod:`~.defects`), can be built as the engine's model
(:meth:`Candidate.mechanism`) and is ranked by its dynamics with the rest of its population
(:mod:`~.rank`). The ``[synthesis]`` problem kind (:mod:`~.kind`) reaches all of it from a problem file.
"""

from __future__ import annotations

from .candidate import Candidate

__all__ = ["Candidate"]
