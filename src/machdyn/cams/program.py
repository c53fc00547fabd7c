"""Follower motion programs: rise, dwell and return segments over one turn of the cam, with their SVAJ.

A program is a list of segments laid end to end over 360 degrees of cam angle. Each rise or return follows a law
of :mod:`machdyn.cams.laws`; a dwell holds the follower. The displacement s [m, or rad for an oscillating
follower] and its derivatives with respect to the cam angle theta [rad] are exact (no finite differences):
v = ds/dtheta, a = d2s/dtheta2, j = d3s/dtheta3; at a cam speed omega [rad/s] they become per second as
v omega, a omega^2, j omega^3 (Norton, *Design of Machinery*, 5th ed., §8.2, eq 8.1).

Boundary conditions (Norton §8.3, the "fundamental law of cam design": s, v and a continuous over the whole
turn, so that jerk stays finite): a jump of velocity or acceleration at a segment's boundary is reported with the
angle where it happens. Rules checked, with the field named: segments neither overlap nor leave gaps, they fill
exactly 360 degrees, and the rises and returns close the cycle (the follower ends where it started).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .geometric import contour_law, contour_phi, rise_angle
from .laws import LAWS, normalised
from .table_law import check_points, table_law

#: Laws that follow from the cam's contour (:mod:`~machdyn.cams.geometric`).
CONTOURS = ("circular_arc", "tangent")

TWO_PI = 2.0 * np.pi
MOTIONS = ("rise", "return", "dwell")
#: The least span of a segment [rad], 0.001 deg: 17 micro-radians, an arc of 17 um on a cam of 1 m radius, finer
#: than any cam is cut; a shorter segment only divides its lift by a vanishing span (velocities of 1e300 and
#: more), so it is refused as an input error rather than carried into the analysis.
MIN_SEGMENT_ANGLE = np.radians(1e-3)


@dataclass(frozen=True)
class Segment:
    """One segment of a program.

    motion : "rise", "return" or "dwell".
    duration : cam angle it lasts [rad], > 0.
    lift : rise or fall [m] (translating) or [rad] (oscillating), > 0 for a rise or return, 0 for a dwell.
    law : the motion law of a rise or return (a name of :data:`~machdyn.cams.laws.LAWS`, or "table").
    start : cam angle where it starts [rad]; None: where the previous one ends (0 for the first).
    points : the "table" law's interior points (fraction of the angle, fraction of the lift)
        (:mod:`~machdyn.cams.table_law`).
    """

    motion: str
    duration: float
    lift: float = 0.0
    law: str = "cycloidal"
    start: float | None = None
    points: tuple[tuple[float, float], ...] = ()
    contour: tuple[float, ...] = ()  # a contour law's (base, nose, flank or roller radius) [m]

    def normalised(self, x) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """The normalised law's value and first three derivatives at x in [0, 1] (clipped)."""
        if self.law == "table":
            return table_law(self.points)(np.clip(np.asarray(x, dtype=float), 0.0, 1.0))
        if self.law in CONTOURS:
            base, nose, size = self.contour
            return contour_law(self.law, base, nose, self.lift, size, self.motion)(x)
        return normalised(self.law, x)


@dataclass(frozen=True)
class Jump:
    """A jump of velocity or acceleration at a segment boundary: quantity ("velocity", "acceleration"),
    cam angle [rad], the values before and after (per radian of cam angle), and the segments it lies between."""

    quantity: str
    angle: float
    before: float
    after: float
    between: tuple[int, int]

    def describe(self, lift_unit: str = "m") -> str:
        """``"an acceleration jump from 0 to 0.18 m/rad^2 at cam angle 110 deg (segments 1 to 2)"``:
        ``lift_unit`` the unit of the follower's lift ("m" for a translating follower, "rad" for an oscillating
        one), the values per radian (velocity) or per radian squared (acceleration) of cam angle."""
        unit = f"{lift_unit}/rad" if self.quantity == "velocity" else f"{lift_unit}/rad^2"
        article = "an" if self.quantity[:1] in "aeiou" else "a"
        return (f"{article} {self.quantity} jump from {self.before:.4g} to {self.after:.4g} {unit} at cam angle "
                f"{np.degrees(self.angle):.4g} deg (segments {self.between[0] + 1} to {self.between[1] + 1})")

    def __str__(self) -> str:
        return self.describe()


@dataclass(frozen=True)
class SVAJ:
    """Displacement and its derivatives over cam angles theta [rad]: s [m|rad], v = ds/dtheta, a, j."""

    theta: np.ndarray
    s: np.ndarray
    v: np.ndarray
    a: np.ndarray
    j: np.ndarray

    def per_second(self, omega: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Velocity [m/s], acceleration [m/s^2] and jerk [m/s^3] at a constant cam speed omega [rad/s]."""
        return self.v * omega, self.a * omega**2, self.j * omega**3


@dataclass(frozen=True)
class Program:
    """A checked motion program (built by :func:`program`): segments with their start angles [rad] and the
    follower's level at each start [m|rad]."""

    segments: tuple[Segment, ...]
    starts: tuple[float, ...]
    levels: tuple[float, ...]
    jumps: tuple[Jump, ...]

    @property
    def stroke(self) -> float:
        """Largest displacement over the cycle [m|rad]."""
        return max(self.levels[i] + (s.lift if s.motion == "rise" else 0.0) for i, s in enumerate(self.segments))

    def svaj(self, theta) -> SVAJ:
        """Exact s, v, a, j at cam angles theta [rad] (any values; taken modulo 360 degrees)."""
        th = np.asarray(theta, dtype=float)
        t = np.mod(th, TWO_PI)
        s, v, a, j = (np.zeros_like(t) for _ in range(4))
        for k, seg in enumerate(self.segments):
            t0 = self.starts[k]
            last = k == len(self.segments) - 1
            inside = (t >= t0) & ((t <= t0 + seg.duration) if last else (t < t0 + seg.duration))
            if not np.any(inside):
                continue
            level = self.levels[k]
            if seg.motion == "dwell":
                s = np.where(inside, level, s)
                continue
            y, y1, y2, y3 = seg.normalised((t - t0) / seg.duration)
            sign = 1.0 if seg.motion == "rise" else -1.0
            b, h = seg.duration, seg.lift
            s = np.where(inside, level + sign * h * y, s)
            v = np.where(inside, sign * h * y1 / b, v)
            a = np.where(inside, sign * h * y2 / b**2, a)
            j = np.where(inside, sign * h * y3 / b**3, j)
        return SVAJ(th, s, v, a, j)

    def boundary(self, k: int) -> float:
        """Cam angle where segment k starts [rad]."""
        return self.starts[k]


def _ends(seg: Segment) -> tuple[float, float, float, float]:
    """(v, a) at the start and at the end of a segment, per rad and per rad^2."""
    if seg.motion == "dwell":
        return 0.0, 0.0, 0.0, 0.0
    sign = 1.0 if seg.motion == "rise" else -1.0
    b, h = seg.duration, seg.lift
    _, v0, a0, _ = seg.normalised(0.0)
    _, v1, a1, _ = seg.normalised(1.0)
    return (sign * h * float(v0) / b, sign * h * float(a0) / b**2, sign * h * float(v1) / b,
            sign * h * float(a1) / b**2)


def program(segments, field: str = "cam.segments", tolerance: float = 1e-9) -> Program:
    """Check segments laid end to end and return the :class:`Program`.

    Raises :class:`~machdyn.errors.InputError` naming the segment (``cam.segments[i]``), the rule and the value:
    unknown motion or law, non-positive duration or lift, overlapping segments or a gap, a program that does not
    fill 360 degrees or does not close (the follower ends away from where it started).
    """
    segs = tuple(segments)
    if not segs:
        raise InputError(f"{field}: a program needs at least one rise and one return; got no segments.")
    starts: list[float] = []
    levels: list[float] = []
    angle = 0.0
    level = 0.0
    for i, seg in enumerate(segs):
        name = f"{field}[{i}]"
        if seg.motion not in MOTIONS:
            raise InputError(f"{name}.motion must be one of {', '.join(MOTIONS)}; got {seg.motion!r}.")
        if seg.motion != "dwell" and seg.law not in LAWS and seg.law not in ("table", *CONTOURS):
            raise InputError(f"{name}.law must be one of {', '.join((*LAWS, 'table', *CONTOURS))}; got {seg.law!r}.")
        if seg.motion != "dwell" and seg.law in CONTOURS:
            if len(seg.contour) != 3:
                raise InputError(f"{name}: a {seg.law} law needs the cam's base radius, its nose radius and its "
                                 "flank (circular arc) or roller (tangent) radius.")
            try:
                want = rise_angle(seg.law, seg.contour[0], seg.contour[1], seg.lift, seg.contour[2])
            except InputError as exc:
                raise InputError(f"{name}: {exc}") from None
            if abs(seg.duration - want) > 1e-9:
                raise InputError(f"{name}.angle of a {seg.law.replace('_', '-')} cam follows from its shape: "
                                 f"{np.degrees(want):.10g} deg; got {np.degrees(seg.duration):.10g} deg.")
        if seg.motion != "dwell" and seg.law == "table":
            check_points(seg.points, f"{name}.points")
        elif seg.points:
            raise InputError(f"{name}.points belong to the 'table' law only; the segment's law is "
                             f"{'a dwell' if seg.motion == 'dwell' else repr(seg.law)}.")
        if not np.isfinite(seg.duration) or seg.duration <= 0:
            raise InputError(f"{name}.angle must be > 0 deg; got {np.degrees(seg.duration):g} deg.")
        if seg.duration < MIN_SEGMENT_ANGLE:
            raise InputError(f"{name}.angle must be at least {np.degrees(MIN_SEGMENT_ANGLE):g} deg (the least span "
                             f"of a segment: finer than any cam is cut); got {np.degrees(seg.duration):g} deg.")
        if seg.motion != "dwell" and (not np.isfinite(seg.lift) or seg.lift <= 0):
            raise InputError(f"{name}.lift of a {seg.motion} must be > 0; got {seg.lift:g}.")
        if seg.motion == "dwell" and seg.lift != 0:
            raise InputError(f"{name}.lift of a dwell must be 0 (a dwell holds the follower); got {seg.lift:g}.")
        if seg.start is not None:
            if seg.start < angle - tolerance:
                raise InputError(f"{name}.start {np.degrees(seg.start):.6g} deg overlaps segment {i} which ends at "
                                 f"{np.degrees(angle):.6g} deg; segments must not overlap.")
            if seg.start > angle + tolerance:
                raise InputError(f"{name}.start {np.degrees(seg.start):.6g} deg leaves a gap after "
                                 f"{np.degrees(angle):.6g} deg; fill it with a dwell.")
        starts.append(angle)
        levels.append(level)
        angle += seg.duration
        level += seg.lift if seg.motion == "rise" else -seg.lift if seg.motion == "return" else 0.0
        if level < -tolerance:
            raise InputError(f"{name} returns the follower {-level:.6g} below its lowest position (the base "
                             "circle); the returns must not exceed the rises before them.")
    if abs(angle - TWO_PI) > 1e-6:
        raise InputError(f"{field}: the segments must fill one turn of the cam, 360 deg; they add up to "
                         f"{np.degrees(angle):.6g} deg.")
    scale = max(max(s.lift for s in segs), 1e-300)
    if abs(level) > tolerance * max(scale, 1.0):
        raise InputError(f"{field}: the program does not close the cycle: the rises exceed the returns by "
                         f"{level:.6g}; the follower must end where it started.")
    jumps = []
    n = len(segs)
    for k in range(n):
        prev, nxt = segs[k - 1], segs[k]
        _, _, v_end, a_end = _ends(prev)
        v_start, a_start, _, _ = _ends(nxt)
        where = starts[k]
        vs = max(abs(v_end), abs(v_start), 1e-300)
        if abs(v_end - v_start) > 1e-9 * vs and abs(v_end - v_start) > 1e-12:
            jumps.append(Jump("velocity", where, v_end, v_start, ((k - 1) % n, k)))
        if abs(a_end - a_start) > 1e-9 * max(abs(a_end), abs(a_start)) and abs(a_end - a_start) > 1e-12:
            jumps.append(Jump("acceleration", where, a_end, a_start, ((k - 1) % n, k)))
    # jumps inside a segment: the parabolic law's change of sign at half its interval
    for k, seg in enumerate(segs):
        if seg.motion != "dwell" and seg.law == "parabolic":
            sign = 1.0 if seg.motion == "rise" else -1.0
            a = 4.0 * sign * seg.lift / seg.duration**2
            jumps.append(Jump("acceleration", starts[k] + seg.duration / 2.0, a, -a, (k, k)))
    # and the contour cams' passing from flank to nose, where the acceleration changes sign
    for k, seg in enumerate(segs):
        if seg.motion != "dwell" and seg.law in CONTOURS:
            phi = contour_phi(seg.law, seg.contour[0], seg.contour[1], seg.lift, seg.contour[2])
            x = phi / seg.duration if seg.motion == "rise" else 1.0 - phi / seg.duration
            sign = 1.0 if seg.motion == "rise" else -1.0
            before = sign * seg.lift * float(seg.normalised(x - 1e-12)[2]) / seg.duration**2
            after = sign * seg.lift * float(seg.normalised(x + 1e-12)[2]) / seg.duration**2
            jumps.append(Jump("acceleration", starts[k] + x * seg.duration, before, after, (k, k)))
    jumps.sort(key=lambda j: j.angle)
    return Program(segs, tuple(starts), tuple(levels), tuple(jumps))
