"""A synthesised linkage: a four-bar or an offset slider-crank placed in the task's own coordinates.

A candidate holds its dimensions, where its crank pivot sits in the task's coordinates, its assembly branch, the
crank angles at the task's precision positions and the free choices that made it. Its position closure is the
engine's (Norton, *Design of Machinery*, 5th ed., ch. 4, position analysis of the four-bar and the slider-crank,
written as intersections of circles and of a circle with a line), so what a candidate says about itself and what
the engine computes from its model agree to rounding. :meth:`Candidate.mechanism` builds that model with the
crank pivot at the origin (the builders' frame); :meth:`Candidate.place` moves engine results back to the task.

Conventions: angles [rad] counter-clockwise from the task's x axis; the crank angle is the absolute angle of the
crank O2-A; the coupler frame has its origin at A and its x axis towards B (the coupler point (u, v) [m] is in
it); branch +1 puts B to the left of the line from A to the rocker pivot O4 (four-bar) or the slider ahead of the
crank along the slide direction (slider-crank), as in :mod:`machdyn.linkage.builders`.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from ..linkage import four_bar, slider_crank
from ..linkage.reductions import worst_of

TWO_PI = 2.0 * np.pi


def wrap(angle: Any) -> Any:
    """Angle(s) [rad] wrapped to (-pi, pi]."""
    return np.pi - np.mod(np.pi - np.asarray(angle, dtype=float), TWO_PI)


@dataclass(frozen=True)
class Candidate:
    """One synthesised linkage.

    kind : "four_bar" or "slider_crank".
    origin : the crank pivot O2 in task coordinates [m] (complex x + iy).
    crank, coupler : crank O2-A and coupler (or connecting rod) A-B lengths [m].
    rocker, ground, ground_angle : four-bar rocker O4-B [m], |O2-O4| [m] and the direction O2->O4 [rad].
    coupler_point : (u, v) [m] of the traced point P in the coupler frame.
    offset, slide_angle : slider-crank slide line at signed distance ``offset`` [m] from O2, direction
        ``slide_angle`` [rad] (the builder's ``slider_crank``).
    branch : +1 or -1 (see the module's conventions).
    angles : crank angles [rad] at the task's precision positions, in the task's order.
    direction : +1 if the crank turns counter-clockwise through the positions, -1 clockwise.
    coupler_offset : target coupler angle minus the angle of A->B [rad] (motion tasks).
    output_offset : the task's output angle minus the rocker's angle O4->B [rad] (function generation, where a
        negative Freudenstein length turns the link by pi).
    free : the free choices that made the candidate (name -> value, SI).
    method : how it was found ("freudenstein", "three positions", "burmester", ...).
    """

    kind: str
    origin: complex
    crank: float
    coupler: float
    rocker: float = 0.0
    ground: float = 0.0
    ground_angle: float = 0.0
    coupler_point: tuple[float, float] = (0.0, 0.0)
    offset: float = 0.0
    slide_angle: float = 0.0
    branch: int = 1
    angles: np.ndarray = field(default_factory=lambda: np.zeros(0))
    direction: int = 1
    coupler_offset: float = 0.0
    output_offset: float = 0.0
    free: dict = field(default_factory=dict)
    method: str = ""

    # -------------------------------------------------------------------------------------------- geometry

    @property
    def rocker_pivot(self) -> complex:
        """O4 [m] in task coordinates (four-bar)."""
        return self.origin + self.ground * np.exp(1j * self.ground_angle)

    def lengths(self) -> dict[str, float]:
        """Link lengths [m] by name."""
        if self.kind == "slider_crank":
            return {"crank": self.crank, "rod": self.coupler, "offset": self.offset}
        return {"crank": self.crank, "coupler": self.coupler, "rocker": self.rocker, "ground": self.ground}

    def joints(self, phi: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(A, B, assembled) at crank angles ``phi`` [rad]: complex positions [m] in task coordinates (NaN where
        the linkage cannot close)."""
        phi = np.asarray(phi, dtype=float)
        a = self.origin + self.crank * np.exp(1j * phi)
        with np.errstate(invalid="ignore"):
            if self.kind == "slider_crank":
                u = np.exp(1j * self.slide_angle)
                s0 = self.origin + self.offset * 1j * u
                rel = (a - s0) * np.conj(u)  # A in the slide frame
                root2 = self.coupler**2 - rel.imag**2
                ok = root2 >= -1e-12 * self.coupler**2
                s = rel.real + self.branch * np.sqrt(np.maximum(root2, 0.0))
                b = s0 + s * u
            else:
                d = self.rocker_pivot
                r = d - a
                L = np.abs(r)
                cos_g = (self.coupler**2 + L**2 - self.rocker**2) / (2.0 * self.coupler * L)
                ok = np.abs(cos_g) <= 1.0 + 1e-12
                g = np.arccos(np.clip(cos_g, -1.0, 1.0))
                b = a + self.coupler * np.exp(1j * (np.angle(r) + self.branch * g))
        b = np.where(ok, b, np.nan + 1j * np.nan)
        return a, b, ok

    def coupler_angle(self, phi: Any) -> np.ndarray:
        """The angle [rad] of A->B plus ``coupler_offset`` (the coupler's angle as the task measures it)."""
        a, b, _ = self.joints(phi)
        return np.angle(b - a) + self.coupler_offset

    def point(self, phi: Any) -> np.ndarray:
        """The coupler point P [m] (complex, task coordinates) at crank angles ``phi``."""
        a, b, _ = self.joints(phi)
        u, v = self.coupler_point
        return a + (u + 1j * v) * np.exp(1j * np.angle(b - a))

    def output_angle(self, phi: Any) -> np.ndarray:
        """The rocker's angle O4->B [rad] (four-bar) or the slider's travel [m] from the foot of O2 on the slide
        line (slider-crank), at crank angles ``phi``."""
        _, b, _ = self.joints(phi)
        if self.kind == "slider_crank":
            u = np.exp(1j * self.slide_angle)
            return ((b - self.origin) * np.conj(u)).real
        return np.angle(b - self.rocker_pivot)

    def transmission(self, phi: Any) -> np.ndarray:
        """Transmission angle [rad], 0..pi/2 (pi/2 best): the acute angle between coupler and rocker (four-bar;
        Norton, ch. 3 and 4, the transmission angle) or 90 deg less the rod's angle to the slide line (slider-crank)."""
        a, b, _ = self.joints(phi)
        if self.kind == "slider_crank":
            beta = np.angle((b - a) * np.exp(-1j * self.slide_angle))
            return np.pi / 2 - np.abs(np.arcsin(np.sin(beta)))
        mu = np.abs(wrap(np.angle(b - a) - np.angle(b - self.rocker_pivot)))
        return worst_of(mu, mu)

    def working_angles(self, count: int = 181) -> np.ndarray:
        """``count`` crank angles [rad] from the first precision position to the last, the way the crank turns
        (a full turn when the task has fewer than two positions)."""
        if self.angles.size < 2:
            return np.linspace(0.0, TWO_PI, count)
        span = np.mod(self.direction * (self.angles[-1] - self.angles[0]), TWO_PI)
        return self.angles[0] + self.direction * np.linspace(0.0, span, count)

    # -------------------------------------------------------------------------------------------- the model

    def mechanism(self, *, linear_density: float = 1.0, name: str = "candidate") -> Any:
        """The engine's model (crank pivot at the origin; uniform bars of ``linear_density`` [kg/m])."""
        if self.kind == "slider_crank":
            return slider_crank(self.crank, self.coupler, self.offset, slide_angle=self.slide_angle,
                                branch=self.branch, linear_density=linear_density, name=name)
        return four_bar(self.crank, self.coupler, self.rocker, self.ground, ground_angle=self.ground_angle,
                        branch=self.branch, coupler_point=self.coupler_point, linear_density=linear_density,
                        name=name)

    def place(self, x: Any, y: Any) -> np.ndarray:
        """Engine coordinates (crank pivot at the origin) [m] -> task coordinates (complex) [m]."""
        return self.origin + np.asarray(x) + 1j * np.asarray(y)

    def scaled(self, factor: float) -> Candidate:
        """The same linkage ``factor`` times larger about the task's origin (angles unchanged)."""
        u, v = self.coupler_point
        return replace(self, origin=self.origin * factor, crank=self.crank * factor, coupler=self.coupler * factor,
                       rocker=self.rocker * factor, ground=self.ground * factor, offset=self.offset * factor,
                       coupler_point=(u * factor, v * factor))


def four_bar_from_points(o2: complex, a1: complex, b1: complex, o4: complex, p1: complex, angles: Any, *,
                         direction: int = 1, coupler_offset: float = 0.0, free: dict | None = None,
                         method: str = "") -> Candidate:
    """The four-bar with crank pivot ``o2``, moving pivots ``a1``, ``b1`` and rocker pivot ``o4`` [m] (complex,
    in its first position) tracing the point ``p1`` [m]; ``angles`` are the crank angles [rad] at the task's
    positions. The branch is read from the first position."""
    ab = b1 - a1
    rel = (p1 - a1) * np.exp(-1j * np.angle(ab))
    cross = ((o4 - a1) * np.conj(b1 - a1)).imag  # > 0: B left of A->O4  <=>  cross(O4-A, B-A) < 0
    branch = 1 if cross < 0 else -1
    return Candidate(
        kind="four_bar", origin=complex(o2), crank=float(abs(a1 - o2)), coupler=float(abs(ab)),
        rocker=float(abs(b1 - o4)), ground=float(abs(o4 - o2)), ground_angle=float(np.angle(o4 - o2)),
        coupler_point=(float(rel.real), float(rel.imag)), branch=branch,
        angles=np.asarray(angles, dtype=float), direction=direction, coupler_offset=float(coupler_offset),
        free=dict(free or {}), method=method,
    )
