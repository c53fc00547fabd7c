"""Slotted-lever quick returns from a time ratio and a stroke: the crank-and-slotted-lever and the Whitworth.

Both are inversions of the slider-crank: a crank O-A of radius r [m] turns about O, its pin A slides in a lever
pivoted at C, the line of centres O-C of length d [m]. The lever's end P, at l [m] from C, drives the ram
through a connecting rod of length rho [m]. The time ratio Q is the crank angle of the slow (cutting) stroke over
that of the fast (return) stroke at constant crank speed.

**Crank and slotted lever** (d > r, the lever swings): the lever is at its extremes when the crank is at right
angles to it, so the crank turns through the return angle beta with

    cos(beta / 2) = r / d,                        Q = (360 deg - beta) / beta,

and the ram, driven from the lever's end at l from C, travels the chord of the lever's swing,

    L = 2 l sin(90 deg - beta / 2) = 2 l r / d

(Khurmi & Gupta, *Theory of Machines*, 14th ed., ch. 5, section 5.14 "Crank and slotted lever quick return
motion mechanism", eqs. on p. 109, examples 5.1 and 5.2 p. 110). Inverted for synthesis:
r / d = cos(180 deg / (1 + Q)) and l = L d / (2 r); the centre distance d is the free scale.

**Whitworth** (d < r, the lever turns fully): with the ram's line of stroke through C at right angles to O-C,
the ram is at its extremes when the lever lies along that line, i.e. when the crank pin is on it:

    cos(beta / 2) = d / r,                        Q = (360 deg - beta) / beta,       L = 2 l

(Khurmi & Gupta, ch. 5, section 5.13 "Whitworth quick return motion mechanism", p. 108). Inverted:
d / r = cos(180 deg / (1 + Q)), l = L / 2; the crank radius r is the free scale.

The ram's position depends on the crank only through the lever's angle, so its extremes are the lever's
whenever the rod is long enough that the ram never stops in between (rho > l for the Whitworth, rho greater
than the lever end's excursion across the line of stroke for the slotted lever); both are checked.

Validity: Q > 1 (Q = 1 would need r = 0 for the slotted lever, d = 0 for the Whitworth); Q < 5.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import InputError, check_positive
from ..linkage import RRP, Body, Guide, Mechanism, inverted_slider_crank, kinematics
from ..linkage.builders import _bar

KINDS = ("slotted_lever", "whitworth")


def return_angle(time_ratio: float) -> float:
    """The crank angle beta [rad] of the fast (return) stroke for a time ratio Q > 1: beta = 2 pi / (1 + Q)
    (Khurmi & Gupta, *Theory of Machines*, 14th ed., ch. 5, p. 109: Q = (360 deg - beta) / beta).

    >>> round(float(np.degrees(return_angle(2.0))), 9)
    120.0
    """
    if not (np.isfinite(time_ratio) and 1.0 < time_ratio):
        raise InputError(f"The time ratio of a slotted-lever quick return must be a finite number > 1 (slow "
                         f"stroke over fast stroke); got {time_ratio!r}.")
    return float(2.0 * np.pi / (1.0 + time_ratio))


def slotted_lever_time_ratio(crank: float, centre_distance: float) -> float:
    """Q [-] of a crank-and-slotted-lever with crank radius r = ``crank`` [m] and centre distance d =
    ``centre_distance`` [m], 0 < r < d: beta = 2 arccos(r / d), Q = (2 pi - beta) / beta (Khurmi & Gupta,
    *Theory of Machines*, 14th ed., ch. 5, p. 109, example 5.1 p. 110).

    >>> round(slotted_lever_time_ratio(0.12, 0.24), 9)
    2.0
    """
    if not 0.0 < crank < centre_distance:
        raise InputError(f"A crank-and-slotted-lever needs 0 < crank radius < centre distance; got r = {crank!r} m, "
                         f"d = {centre_distance!r} m.")
    beta = 2.0 * np.arccos(crank / centre_distance)
    return float((2.0 * np.pi - beta) / beta)


def slotted_lever_stroke(crank: float, centre_distance: float, lever: float) -> float:
    """The ram's stroke L [m] of a crank-and-slotted-lever driven from the lever's end at ``lever`` = l [m] from
    its pivot: L = 2 l r / d (Khurmi & Gupta, *Theory of Machines*, 14th ed., ch. 5, p. 109, example 5.2 p. 110).

    >>> round(slotted_lever_stroke(0.12, 0.24, 0.45), 9)
    0.45
    """
    slotted_lever_time_ratio(crank, centre_distance)  # the same validity
    return float(2.0 * lever * crank / centre_distance)


def whitworth_time_ratio(crank: float, centre_distance: float) -> float:
    """Q [-] of a Whitworth quick return, crank radius r = ``crank`` [m] > centre distance d [m] > 0, line of
    stroke through the lever's pivot at right angles to the line of centres: beta = 2 arccos(d / r)
    (Khurmi & Gupta, *Theory of Machines*, 14th ed., ch. 5, section 5.13, p. 108).

    >>> round(whitworth_time_ratio(0.1, 0.05), 9)
    2.0
    """
    if not 0.0 < centre_distance < crank:
        raise InputError(f"A Whitworth quick return needs 0 < centre distance < crank radius; got r = {crank!r} m, "
                         f"d = {centre_distance!r} m.")
    beta = 2.0 * np.arccos(centre_distance / crank)
    return float((2.0 * np.pi - beta) / beta)


@dataclass(frozen=True)
class SlottedLever:
    """A slotted-lever quick return [m]: ``kind`` "slotted_lever" or "whitworth"; crank radius, centre distance
    O-C, lever length C-P (to the rod's pin), rod length P-R; ``guide`` the distance [m] of the ram's line of
    stroke from C along C->O (negative: beyond C, away from O). ``free`` the free choice that made it."""

    kind: str
    crank: float
    centre_distance: float
    lever: float
    rod: float
    guide: float
    free: dict = field(default_factory=dict)
    method: str = ""

    def lengths(self) -> dict[str, float]:
        return {"crank": self.crank, "centre_distance": self.centre_distance, "lever": self.lever,
                "rod": self.rod}

    @property
    def time_ratio(self) -> float:
        """Q by the closed form of its kind."""
        if self.kind == "whitworth":
            return whitworth_time_ratio(self.crank, self.centre_distance)
        return slotted_lever_time_ratio(self.crank, self.centre_distance)

    @property
    def stroke(self) -> float:
        """L [m] by the closed form of its kind."""
        if self.kind == "whitworth":
            return 2.0 * self.lever
        return slotted_lever_stroke(self.crank, self.centre_distance, self.lever)

    def mechanism(self, *, linear_density: float = 1.0, ram_mass: float | None = None,
                  name: str = "quick_return") -> Any:
        """The engine's model: :func:`machdyn.linkage.inverted_slider_crank` (crank pivot O at the origin, lever
        pivot C at (d, 0), the lever's end ``rocker.E`` at l) with a rod from E to the ram, which slides on a line
        at right angles to O-C at x = d - ``guide`` (ram point ``ram.R``; uniform bars of ``linear_density``
        [kg/m], the ram ``ram_mass`` [kg], default the rod's mass)."""
        # The lever points from C through the pin: for the slotted lever the pin is between C and O, and the
        # lever's end lies beyond O; the ram's guide points along +y.
        base = inverted_slider_crank(self.crank, self.centre_distance, rocker_length=self.lever,
                                     linear_density=linear_density, name=name)
        rod = _bar("rod", {"E": (0.0, 0.0), "R": (float(self.rod), 0.0)}, self.rod, None, None, None,
                   linear_density)
        mass = linear_density * self.rod if ram_mass is None else ram_mass
        ram = Body("ram", {"R": (0.0, 0.0)}, float(mass), 0.0)
        ground = dict(base.ground, G=(float(self.centre_distance - self.guide), 0.0))
        # branch +1: the ram ahead of the lever end's foot along +y, so a lever turning counter-clockwise
        # drives it the same way at the ends of the stroke
        dyad = RRP("rod", "ram", "rocker.E", "R", Guide("ground.G", float(np.pi / 2)), 1)
        return Mechanism(name, ground, base.bodies + (rod, ram), base.crank, base.dyads + (dyad,),
                         gravity=base.gravity)


def slotted_lever(time_ratio: float, stroke: float, centre_distance: float, *, rod: float | None = None
                  ) -> SlottedLever:
    """The crank-and-slotted-lever of time ratio Q = ``time_ratio`` and stroke L = ``stroke`` [m] with the centre
    distance d = ``centre_distance`` [m] (the free scale): r = d cos(pi / (1 + Q)), l = L d / (2 r) (module
    docstring). The ram's line crosses the middle of the lever end's excursion; ``rod`` [m] defaults to l / 4 or
    1.5 times that excursion, the larger.

    >>> s = slotted_lever(2.0, 0.45, 0.24)
    >>> round(s.crank, 9), round(s.lever, 9)
    (0.12, 0.45)
    """
    beta = return_angle(time_ratio)
    check_positive("stroke", stroke, "m")
    check_positive("centre distance", centre_distance, "m")
    ratio = float(np.cos(beta / 2.0))  # r / d
    r = centre_distance * ratio
    lever = stroke / (2.0 * ratio)
    if not lever > centre_distance + r:
        raise InputError(f"The slotted lever of {lever:.6g} m (from the stroke) must reach past the crank pin's "
                         f"farthest place, d + r = {centre_distance + r:.6g} m: take a centre distance below "
                         f"{lever / (1.0 + ratio):.6g} m.")
    half_swing = np.pi / 2.0 - beta / 2.0
    # the lever end's excursion along O-C between the middle and the ends of the swing
    excursion = lever * (1.0 - np.cos(half_swing))
    rho = max(0.25 * lever, 1.5 * excursion) if rod is None else float(rod)
    if not rho > excursion:
        raise InputError(f"The rod of {rho:.6g} m must be longer than the lever end's excursion across the line "
                         f"of stroke, {excursion:.6g} m, or the ram stops inside its stroke.")
    # the line of stroke beyond O, midway across the excursion: x = d - guide with guide = l (1 + cos) / 2
    guide = 0.5 * lever * (1.0 + np.cos(half_swing))
    return SlottedLever("slotted_lever", float(r), float(centre_distance), float(lever), rho, float(guide),
                        free={"centre_distance": float(centre_distance)},
                        method="crank and slotted lever (Khurmi & Gupta 5.14)")


def whitworth(time_ratio: float, stroke: float, crank: float, *, rod: float | None = None) -> SlottedLever:
    """The Whitworth quick return of time ratio Q = ``time_ratio`` and stroke L = ``stroke`` [m] with crank
    radius r = ``crank`` [m] (the free scale): d = r cos(pi / (1 + Q)), l = L / 2, the line of stroke through
    C (module docstring); ``rod`` [m] defaults to 2 l and must exceed l.

    >>> w = whitworth(2.0, 0.3, 0.1)
    >>> round(w.centre_distance, 9), round(w.lever, 9)
    (0.05, 0.15)
    """
    beta = return_angle(time_ratio)
    check_positive("stroke", stroke, "m")
    check_positive("crank radius", crank, "m")
    lever = 0.5 * stroke
    rho = 2.0 * lever if rod is None else float(rod)
    if not rho > lever:
        raise InputError(f"The rod of a Whitworth quick return must be longer than the lever ({lever:.6g} m), or "
                         f"the ram stops inside its stroke; got {rho:.6g} m.")
    d = crank * float(np.cos(beta / 2.0))
    return SlottedLever("whitworth", float(crank), d, float(lever), rho, 0.0, free={"crank": float(crank)},
                        method="Whitworth (Khurmi & Gupta 5.13)")


@dataclass(frozen=True)
class Measured:
    """What the engine's kinematics say of a quick return: the crank angles [rad] at the ram's two dead
    positions, the time ratio [-], the stroke [m] and the ram's largest speed in each stroke over the stroke's
    mean speed [-] (at constant crank speed), and the largest force [N] of the crank pin on the slot per newton
    of a force resisting the ram over the slow stroke (friction and inertia aside; by virtual work: the lever's
    moment F v_ram / omega_lever over the pin's distance from the lever's pivot)."""

    dead_angles: tuple[float, float]
    time_ratio: float
    stroke: float
    peak_over_mean_slow: float
    peak_over_mean_fast: float
    slot_force_per_ram_force: float


def measure(design: SlottedLever, samples: int = 720) -> Measured:
    """The time ratio and stroke measured from the engine's exact kinematics of :meth:`SlottedLever.mechanism`:
    the ram's velocity sampled over a turn, its two sign changes refined by :func:`scipy.optimize.brentq` on the
    engine's velocity, the stroke the difference of the engine's ram positions there. Independent of the
    closed forms (it uses neither beta nor r / d)."""
    from scipy.optimize import brentq

    mech = design.mechanism()
    phi = np.linspace(0.0, 2.0 * np.pi, samples, endpoint=False)
    kin = kinematics(mech, phi, 1.0)
    vy = np.asarray(kin.point("ram.R").vy, dtype=float)
    lever_speed = np.asarray(kin.body("rocker").omega, dtype=float)
    pin = kin.point("crank.A")
    pin_radius = np.hypot(np.asarray(pin.x) - design.centre_distance, np.asarray(pin.y))

    def velocity(angle: float) -> float:
        return float(kinematics(mech, np.array([angle]), 1.0).point("ram.R").vy[0])

    roots = []
    for k in np.flatnonzero(np.sign(vy) != np.sign(np.roll(vy, -1))):
        lo, hi = phi[k], phi[k] + 2.0 * np.pi / samples
        roots.append(float(brentq(velocity, lo, hi, xtol=1e-14, rtol=1e-14)))
    if len(roots) != 2:
        raise InputError(f"The ram of this quick return stops {len(roots)} times a turn (a quick return stops "
                         "twice): lengthen the rod.")
    y = [float(kinematics(mech, np.array([a]), 1.0).point("ram.R").y[0]) for a in roots]
    lo_angle, hi_angle = (roots[0], roots[1]) if y[0] < y[1] else (roots[1], roots[0])
    rise = float(np.mod(hi_angle - lo_angle, 2.0 * np.pi))  # the crank turns counter-clockwise
    fall = 2.0 * np.pi - rise
    stroke = abs(y[1] - y[0])
    in_rise = np.mod(phi - lo_angle, 2.0 * np.pi) < rise
    speed = np.abs(vy)
    peak_rise, peak_fall = float(speed[in_rise].max()), float(speed[~in_rise].max())
    slow, fast = (rise, fall) if rise >= fall else (fall, rise)
    peak_slow, peak_fast = (peak_rise, peak_fall) if rise >= fall else (peak_fall, peak_rise)
    in_slow = in_rise if rise >= fall else ~in_rise
    with np.errstate(divide="ignore", invalid="ignore"):  # the lever stands still only at the dead positions
        slot = np.abs(vy / lever_speed) / pin_radius
    slot_force = float(np.max(slot[in_slow & np.isfinite(slot)]))
    return Measured(dead_angles=(lo_angle, hi_angle), time_ratio=slow / fast, stroke=stroke,
                    peak_over_mean_slow=peak_slow / (stroke / slow), peak_over_mean_fast=peak_fast / (stroke / fast),
                    slot_force_per_ram_force=slot_force)


def candidates(kind: str, time_ratio: float, stroke: float, count: int, *, rod_ratio: float | None = None
               ) -> list[SlottedLever]:
    """``count`` designs over the free scale: the centre distance from 10 % to 90 % of its largest value
    l / (1 + r / d) (slotted lever), the crank radius from 10 % to 90 % of the lever (Whitworth).
    ``rod_ratio`` is the rod over the lever (default: each kind's default rod)."""
    if kind not in KINDS:
        raise InputError(f"The slotted-lever kind must be one of {', '.join(KINDS)}; got {kind!r}.")
    beta = return_angle(time_ratio)
    ratio = float(np.cos(beta / 2.0))
    fractions = 0.1 + 0.8 * (np.arange(count) + 0.5) / count
    out = []
    if kind == "slotted_lever":
        lever = stroke / (2.0 * ratio)
        for f in fractions:
            rod = None if rod_ratio is None else rod_ratio * lever
            out.append(slotted_lever(time_ratio, stroke, float(f) * lever / (1.0 + ratio), rod=rod))
    else:
        lever = 0.5 * stroke
        for f in fractions:
            rod = None if rod_ratio is None else rod_ratio * lever
            out.append(whitworth(time_ratio, stroke, float(f) * lever, rod=rod))
    return out
