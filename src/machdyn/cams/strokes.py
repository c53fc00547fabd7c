"""Each stroke's own extremes: the peak velocity, acceleration and jerk of every rise and return of a cam's motion
program, its largest pressure angle, its smallest radius of curvature and, with a follower train, its largest
contact force, normal force and camshaft torque — found on the segment's exact closed forms, piece by smooth
piece, as :mod:`machdyn.cams.exact` finds the turn's.

A designer reads a cam by its strokes: a valve's opening may be gentle and its closing harsh, a feeder's return
may carry no load. The whole turn's peaks (``cam.max_velocity`` ...) hide which stroke sets them; here each rise and
return reports its own, under the key ``cam.segment<n>.<figure>`` with n the segment's number in the program (1 for
the file's first ``[[cam.segments]]``, dwells counted but not reported).

Quantities (SI, at the constant cam speed ω):

* velocity v = ω ds/dθ, acceleration a = ω² d²s/dθ², jerk j = ω³ d³s/dθ³ from the law's normalised closed form
  y(x), x = (θ − θ0)/β: ds/dθ = ±h y'/β, d²s/dθ² = ±h y''/β², d³s/dθ³ = ±h y'''/β³ (Norton, *Design of
  Machinery*, 5th ed., §8.3, eqs 8.1-8.3);
* the pressure angle and the pitch curve's convex curvature of :mod:`machdyn.cams.exact` (Norton §8.6, eqs
  8.31-8.33); a flat face's radius of curvature R_b + s + d²s/dθ² (Norton §8.8, eq 8.38);
* the contact force along the follower's path F = m a + c v + k s + F0 + F_L, the normal force F / cos φ and the
  camshaft torque T = F ds/dθ by virtual work (:mod:`machdyn.cams.dynamics`; Norton §8.9-8.10); for an
  oscillating follower F is a moment about the pivot, divided by the arm for the forces.

Each smooth piece of a segment is sampled at :data:`~machdyn.cams.exact.GRID` points and the best sample refined
by a bounded scalar search, so the extremes do not depend on the angles the profile is drawn at; the largest of the
strokes' peaks is the turn's exact peak (a dwell adds nothing to v, a or j, and its force equals a stroke's end).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from .dynamics import FollowerTrain, Spring
from .exact import _largest, _pitch, smooth_pieces
from .followers import Follower
from .program import Program

#: The figures of a stroke, in the order the report's table shows them: key -> (text, translating unit,
#: oscillating unit).
FIGURES: dict[str, tuple[str, str, str]] = {
    "max_velocity": ("peak |v|", "m/s", "rad/s"),
    "max_acceleration": ("peak |a|", "m/s^2", "rad/s^2"),
    "max_jerk": ("peak |j|", "m/s^3", "rad/s^3"),
    "max_pressure_angle": ("largest |pressure angle|", "rad", "rad"),
    "min_pitch_curvature_radius": ("smallest convex radius of curvature of the pitch curve", "m", "m"),
    "min_surface_curvature_radius": ("flat face: smallest radius of curvature R_b + s + a", "m", "m"),
    "max_contact_force": ("largest contact force along the follower's path", "N", "N"),
    "max_normal_force": ("largest contact force along the common normal", "N", "N"),
    "peak_torque": ("peak camshaft torque |T|", "N*m", "N*m"),
}


@dataclass(frozen=True)
class Stroke:
    """One rise or return: its segment's number (1-based, as in the report), motion, law, start and end cam angles
    [rad], lift [m|rad] and its figures {name of :data:`FIGURES`: value (SI)} with the cam angle [rad] where each
    is reached. Figures a stroke does not have (a pitch curve without a convex part, forces without a follower
    train, a flat face's pressure angle) are absent."""

    number: int
    motion: str
    law: str
    start: float
    end: float
    lift: float
    figures: dict[str, float]
    where: dict[str, float]

    def key(self, figure: str) -> str:
        """The result key of a figure of this stroke: ``cam.segment<n>.<figure>``."""
        return f"cam.segment{self.number}.{figure}"


def _evaluate(prog: Program, k: int, x: np.ndarray) -> tuple[np.ndarray, ...]:
    """Cam angle [rad], s, ds/dθ, d²s/dθ², d³s/dθ³ of segment k at x in its interval, from the law's closed form."""
    seg, t0, level = prog.segments[k], prog.starts[k], prog.levels[k]
    y, y1, y2, y3 = seg.normalised(x)
    sign = 1.0 if seg.motion == "rise" else -1.0
    b, h = seg.duration, seg.lift
    return (t0 + b * x, level + sign * h * np.asarray(y), sign * h * np.asarray(y1) / b,
            sign * h * np.asarray(y2) / b**2, sign * h * np.asarray(y3) / b**3)


def strokes(prog: Program, follower: Follower, speed: float, train: FollowerTrain | None = None,
            spring: Spring | None = None, arm: float = 1.0) -> tuple[Stroke, ...]:
    """Every rise and return of ``prog`` with its own exact extremes (module docstring).

    Parameters
    ----------
    prog : the checked motion program; follower : its follower and base circle.
    speed : ω [rad/s] > 0, the constant cam speed.
    train, spring : the follower train and its spring (in the follower's coordinate, as
        :func:`~machdyn.cams.dynamics.cam_forces` takes them); None: no forces.
    arm : l [m] of an oscillating follower (its moments are divided by it for the forces), 1 for a translating one.

    Returns
    -------
    tuple of Stroke
        in the program's order.

    Examples
    --------
    A cycloidal rise of 20 mm over 90° and a return over 180° at 1 rad/s: the rise's peak velocity is
    2h/β = 25.46 mm/s, the return's half of it:

    >>> from machdyn.cams.program import Segment, program
    >>> prog = program([Segment("rise", np.pi / 2, 0.02), Segment("return", np.pi, 0.02),
    ...                 Segment("dwell", np.pi / 2)])
    >>> knife = Follower(contact="knife", base_radius=0.05)
    >>> [round(s.figures["max_velocity"] * 1e3, 2) for s in strokes(prog, knife, 1.0)]
    [25.46, 12.73]
    """
    pieces: dict[int, list[tuple[float, float]]] = {}
    for k, x0, x1 in smooth_pieces(prog):
        if prog.segments[k].motion != "dwell":
            pieces.setdefault(k, []).append((x0, x1))
    return tuple(_stroke(prog, follower, speed, k, spans, train, spring, arm) for k, spans in pieces.items())


def _stroke(prog: Program, follower: Follower, speed: float, k: int, spans: list[tuple[float, float]],
            train: FollowerTrain | None, spring: Spring | None, arm: float) -> Stroke:
    """Segment k's figures over its smooth pieces ``spans`` (intervals of x)."""
    seg = prog.segments[k]
    flat = follower.contact == "flat"
    figures: dict[str, float] = {}
    where: dict[str, float] = {}

    def largest(name: str, fn: Callable[[np.ndarray], np.ndarray], sign: float = 1.0) -> None:
        best, at = -np.inf, 0.0
        for x0, x1 in spans:
            value, x = _largest(fn, x0, x1)
            if value > best:
                best, at = value, x
        figures[name] = sign * float(best)
        where[name] = float(prog.starts[k] + seg.duration * at)

    def motion(x: np.ndarray) -> tuple[np.ndarray, ...]:
        return _evaluate(prog, k, x)

    largest("max_velocity", lambda x: np.abs(motion(x)[2]) * speed)
    largest("max_acceleration", lambda x: np.abs(motion(x)[3]) * speed**2)
    largest("max_jerk", lambda x: np.abs(motion(x)[4]) * speed**3)
    if flat:
        largest("min_surface_curvature_radius",
                lambda x: -(follower.base_radius + motion(x)[1] + motion(x)[3]), sign=-1.0)
    else:
        largest("max_pressure_angle", lambda x: _pitch(follower, *motion(x)[1:4])[0])
        largest("min_pitch_curvature_radius", lambda x: _pitch(follower, *motion(x)[1:4])[1])
        curvature = figures.pop("min_pitch_curvature_radius")
        at = where.pop("min_pitch_curvature_radius")
        if curvature > 0:  # convex somewhere
            figures["min_pitch_curvature_radius"] = 1.0 / curvature
            where["min_pitch_curvature_radius"] = at
    if train is not None and spring is not None:
        def contact(x: np.ndarray) -> np.ndarray:  # along the follower's path [N | N·m about the pivot]
            _, s, v, a, _ = motion(x)
            return (train.mass * a * speed**2 + train.damping * v * speed + spring.rate * s + spring.preload
                    + train.load)

        def cos_phi(x: np.ndarray) -> np.ndarray:
            return np.ones_like(x) if flat else np.cos(_pitch(follower, *motion(x)[1:4])[0])

        largest("max_contact_force", lambda x: contact(x) / arm)
        largest("max_normal_force", lambda x: contact(x) / cos_phi(x) / arm)
        largest("peak_torque", lambda x: np.abs(contact(x) * motion(x)[2]))
    return Stroke(k + 1, seg.motion, seg.law, float(prog.starts[k]), float(prog.starts[k] + seg.duration),
                  float(seg.lift), figures, where)
