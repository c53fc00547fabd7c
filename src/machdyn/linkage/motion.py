"""The motion a kinematic analysis returns: each body's and slider's state over crank angles and design
variants (:class:`Kinematics`), the dyads' determinants and transmission angles, and the checks every engine
applies to it (assembly, dead positions), so that the NumPy and the fused engine return one type."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from ..errors import AssemblyError, InputError, SingularPositionError
from .grashof import grashof_type
from .model import Mechanism
from .refs import GROUND, column, full, split_ref
from .state import BodyState, PointState, ground_state


@dataclass(frozen=True)
class SlideMotion:
    """Travel of a slider or block along its guide: s [m], its rate v [m/s] and acceleration a [m/s^2]."""

    s: np.ndarray
    v: np.ndarray
    a: np.ndarray


@dataclass(frozen=True)
class DyadReport:
    """Per-dyad quantities for diagnostics: the normalised determinant (0 at a dead position) and the
    transmission angle [rad]."""

    kind: str
    bodies: tuple[str, str]
    det: np.ndarray
    transmission_fn: Callable[[], np.ndarray]

    @property
    def transmission(self) -> np.ndarray:
        return self.transmission_fn()


@dataclass(frozen=True)
class Kinematics:
    """Motion of every body and point of ``mechanism`` at each crank angle (see :func:`kinematics`)."""

    mechanism: Mechanism
    crank_angle: np.ndarray
    speed: np.ndarray
    acceleration: np.ndarray
    assembled: np.ndarray
    bodies: dict
    slides: dict
    dyad_reports: tuple
    _points: dict = field(default_factory=dict, repr=False)

    @property
    def shape(self) -> tuple[int, ...]:
        return np.shape(self.assembled)

    def body(self, name: str) -> BodyState:
        """Angle [rad], omega [rad/s], alpha [rad/s^2] and frame-origin motion of a body."""
        if name == GROUND:
            return ground_state()
        key = ("body", name)
        if key not in self._points:
            try:
                raw = self.bodies[name]
            except KeyError:
                raise InputError(
                    f"No body '{name}' in mechanism '{self.mechanism.name}'; bodies: {', '.join(self.bodies)}."
                ) from None
            # Broadcast on first use only: scalars (e.g. a constant crank speed) stay cheap in the solve.
            self._points[key] = _broadcast_state(raw, self.shape)
        return self._points[key]

    def point(self, ref: str) -> PointState:
        """Motion of the point ``"body.point"``: x, y [m], vx, vy [m/s], ax, ay [m/s^2]."""
        if ref not in self._points:
            body, point = split_ref(ref)
            if body == GROUND:
                x, y = self.mechanism.ground[point]
                z = np.zeros(self.shape)
                self._points[ref] = PointState(z + x, z + y, z, z, z, z)
            else:
                b = self.mechanism.body(body)
                if point not in b.points:
                    raise InputError(
                        f"Body '{body}' has no point '{point}'; its points: {', '.join(b.points)}."
                    )
                self._points[ref] = self._broadcast(self.body(body).point(*map(column, b.points[point])))
        return self._points[ref]

    def com(self, body: str) -> PointState:
        """Motion of the centre of mass of ``body``."""
        key = ("com", body)
        if key not in self._points:  # used by kinetostatics and energy alike: computed once
            b = self.mechanism.body(body)
            self._points[key] = self._broadcast(self.body(body).point(*map(column, b.com)))
        return self._points[key]

    def local_point(self, body: str, xy) -> PointState:
        """Motion of an arbitrary body-frame point ``xy`` [m] of ``body``."""
        return self._broadcast(self.body(body).point(*map(column, xy)))

    def slide(self, body: str) -> SlideMotion:
        """Travel of the slider/block ``body`` along its guide."""
        try:
            return self.slides[body]
        except KeyError:
            raise InputError(
                f"Body '{body}' is not a slider or block; sliders: {', '.join(self.slides) or 'none'}."
            ) from None

    def _broadcast(self, p: PointState) -> PointState:
        shape = self.shape
        return PointState(*(full(v, shape) for v in (p.x, p.y, p.vx, p.vy, p.ax, p.ay)))


def crank_angles(count: int = 360, start: float = 0.0) -> np.ndarray:
    """``count`` crank angles [rad] evenly over one revolution from ``start`` (end point excluded), the
    sampling that makes cycle integrals and harmonics exact for smooth periodic results."""
    if int(count) != count or count < 2:
        raise InputError(f"The number of crank positions must be an integer >= 2; got {count!r}.")
    return start + np.arange(int(count)) * (2.0 * np.pi / count)


def is_full_turn(crank_angle) -> bool:
    """Whether crank angles are evenly spaced over one revolution without its end point, as
    :func:`crank_angles` makes them: the sampling over which cycle means, RMS values, harmonics and time ratios
    are exact. The one test of it, used wherever a full turn is required.

    Parameters
    ----------
    crank_angle : array_like
        Crank angles [rad], increasing.

    Returns
    -------
    bool
        True for at least two angles whose steps all equal 2 pi / count (to 1e-9 relative).

    Examples
    --------
    >>> import numpy as np
    >>> is_full_turn(crank_angles(360)), is_full_turn(np.linspace(0.0, 2 * np.pi, 361))
    (True, False)
    """
    phi = np.asarray(crank_angle, dtype=float).ravel()
    return phi.size >= 2 and bool(np.allclose(np.diff(phi), 2 * np.pi / phi.size, rtol=1e-9, atol=1e-12))



def kinematics_result(mech, phi, omega, eps, shape, on_fail, states, slides, reports, failing, assembled):
    """The :class:`Kinematics` of solved body states, after the assembly and dead-position checks."""
    assembled = np.broadcast_to(assembled, shape)
    if on_fail == "raise" and not np.all(assembled):
        raise AssemblyError(_assembly_message(mech, phi, assembled, failing))
    if on_fail == "raise":
        _check_not_dead(mech, phi, reports, shape)
    return Kinematics(
        mech, phi, full(omega, shape), full(eps, shape), assembled,
        states, slides, tuple(reports),
    )


def _broadcast_state(st: BodyState, shape) -> BodyState:
    return BodyState(*(full(v, shape) for v in (
        st.x, st.y, st.vx, st.vy, st.ax, st.ay, st.angle, st.omega, st.alpha, st.cos, st.sin)))


def angle_ranges(phi: np.ndarray, mask: np.ndarray) -> list[tuple[float, float]]:
    """Contiguous runs of ``mask`` over sorted crank angles ``phi`` as (start, end) [rad] pairs. Over a full
    revolution sampled evenly, a run through 0 is one range with start > end (e.g. 330°–30°)."""
    phi = np.asarray(phi, dtype=float).ravel()
    mask = np.asarray(mask, dtype=bool).ravel()
    order = np.argsort(phi)
    phi, mask = phi[order], mask[order]
    # starts: a True after a False (or first); ends: a True before a False (or last)
    edges = np.diff(np.concatenate(([False], mask, [False])).astype(np.int8))
    starts, ends = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1) - 1
    runs = [(float(phi[a]), float(phi[b])) for a, b in zip(starts, ends, strict=True)]
    full_turn = len(phi) > 2 and is_full_turn(phi)
    if full_turn and len(runs) > 1 and mask[0] and mask[-1]:
        runs = [(runs[-1][0], runs[0][1])] + runs[1:-1]
    return runs


def format_ranges(ranges, limit: int = 6) -> str:
    """Crank-angle ranges [rad] as text in degrees: '10.0°–40.0°, 200.0°' (a single angle where a range is one
    sample)."""
    parts = [
        f"{np.degrees(a):.1f}°" if np.isclose(a, b) else f"{np.degrees(a):.1f}°–{np.degrees(b):.1f}°"
        for a, b in ranges[:limit]
    ]
    if len(ranges) > limit:
        parts.append(f"and {len(ranges) - limit} more")
    return ", ".join(parts)


#: |normalised determinant| (the sine of the transmission angle) below which a position counts as dead. At an
#: exact toggle the closure discriminant rounds to ~1e-16 L^2, so the determinant (its square root) comes out
#: ~1e-8, not 0; below 1e-6 velocities are amplified a millionfold and carry no trustworthy digits.
DEAD_TOL = 1e-6


def singular(reports, shape) -> np.ndarray:
    """True where any dyad is at (or within rounding of) a dead position, or its determinant is not finite."""
    out = np.zeros(shape, dtype=bool)
    for rep in reports:
        det = rep.det
        out |= np.broadcast_to(~(np.abs(det) >= DEAD_TOL), shape)
    return out


def _check_not_dead(mech: Mechanism, phi, reports, shape) -> None:
    """Raise :class:`SingularPositionError` at a dead (toggle) position, where velocities are unbounded."""
    for rep in reports:
        dead = np.broadcast_to(~(np.abs(rep.det) >= DEAD_TOL), shape)
        if np.any(dead):
            at = np.broadcast_to(phi, shape)[dead]
            text = ", ".join(f"{np.degrees(a):.2f}°" for a in np.unique(at)[:6])
            raise SingularPositionError(
                f"Mechanism '{mech.name}' is in a dead (toggle) or indeterminate position of its {rep.kind} dyad "
                f"{rep.bodies[0]}-{rep.bodies[1]} at crank angle(s) {text}: velocities and forces are unbounded "
                "there. Leave these angles out or change the geometry."
            )


def _assembly_message(mech: Mechanism, phi, assembled, per_dyad=()) -> str:
    fails = ~assembled
    design_note = ""
    if assembled.ndim == 2:
        bad = np.flatnonzero(fails.any(axis=1))
        design_note = f" (design variants {', '.join(map(str, bad[:10]))}{'...' if len(bad) > 10 else ''})"
        fails = fails.any(axis=0)
    phi_row = np.broadcast_to(phi, fails.shape)
    ranges = angle_ranges(phi_row, fails)
    text = format_ranges(ranges)
    kind = grashof_type(mech)
    kind_note = f" Grashof type: {kind}." if isinstance(kind, str) else ""
    culprits = [f"{d.kind} {d.a}-{d.b}" for d, ok in per_dyad if not np.all(ok)]
    if len(mech.dyads) > 1 and culprits:
        kind_note += f" The dyad(s) that cannot close: {', '.join(culprits)}."
    if np.all(fails):
        return (
            f"Mechanism '{mech.name}' cannot be assembled at any of the requested crank angles"
            f"{design_note}: the links are too short or too long to close the loop.{kind_note}"
        )
    return (
        f"Mechanism '{mech.name}' cannot be assembled for crank angles {text}{design_note}; "
        f"restrict the crank angles to where it closes or change the link lengths.{kind_note}"
    )
