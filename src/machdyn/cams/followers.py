"""Followers of a plate cam: translating (with offset) or oscillating (pivot and arm), with a knife edge, a roller
or a flat face.

The cam turns about the origin, counter-clockwise by the cam angle theta (a clockwise cam is the mirror image,
see :mod:`machdyn.cams.profile`). In the fixed frame:

* a **translating** follower slides along the line x = e (the offset e [m]) in +y; the follower's displacement s
  [m] is measured from its lowest position, where the roller centre (or the knife edge) lies on the prime circle
  of radius R_p = R_b + r_r (Norton, *Design of Machinery*, 5th ed., §8.6, fig 8-44): its centre is at
  (e, sqrt(R_p^2 - e^2) + s);
* an **oscillating** follower turns about a pivot at (d, 0) [m] with an arm of length l [m]; its angle psi [rad]
  is measured from the line pivot -> cam centre, psi = psi_0 + s with s [rad] the program's displacement and
  psi_0 where the roller centre lies on the prime circle, cos psi_0 = (d^2 + l^2 - R_p^2)/(2 d l) (Norton §8.6,
  eq 8.34 in the form of the triangle cam centre - pivot - roller centre). The roller centre is at
  (d - l cos psi, l sin psi): it moves away from the cam centre as psi grows.

A knife edge is a roller of radius 0. A flat face is perpendicular to a translating follower's path.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError

TYPES = ("translating", "oscillating")
#: Largest length of a cam and its follower accepted [m]: a plausibility bound ten times the largest plate cams
#: built (about 1 m in radius), which catches a unit mistake ("45 m" for "45 mm") before it gives results.
MAX_CAM_SIZE = 10.0
CONTACTS = ("knife", "roller", "flat")


@dataclass(frozen=True)
class Follower:
    """The follower and the cam's base circle.

    motion : "translating" or "oscillating".
    contact : "knife", "roller" or "flat" (flat only for a translating follower).
    base_radius : R_b, the smallest radius of the cam surface [m], > 0.
    roller_radius : r_r [m], > 0 for a roller, 0 for a knife edge or a flat face.
    offset : e, a translating follower's path from the cam centre [m]: the line x = e with the follower above
        the cam (+y) and a counter-clockwise cam; for a clockwise cam the whole drawing is mirrored, so e > 0 is
        then to the left (see the module docstring for the frame).
    pivot_distance : d, cam centre to the oscillating follower's pivot [m].
    arm_length : l, pivot to the roller centre [m].
    """

    motion: str = "translating"
    contact: str = "roller"
    base_radius: float = 0.05
    roller_radius: float = 0.0
    offset: float = 0.0
    pivot_distance: float = 0.0
    arm_length: float = 0.0

    def __post_init__(self):
        check_follower(self)

    @property
    def prime_radius(self) -> float:
        """R_p = R_b + r_r [m]: the circle the roller centre touches at zero displacement."""
        return self.base_radius + self.roller_radius

    @property
    def start_angle(self) -> float:
        """psi_0 of an oscillating follower [rad] (0 for a translating one)."""
        if self.motion != "oscillating":
            return 0.0
        d, arm, rp = self.pivot_distance, self.arm_length, self.prime_radius
        return float(np.arccos((d * d + arm * arm - rp * rp) / (2.0 * d * arm)))


def check_follower(f: Follower, field: str = "cam.follower") -> None:
    """Raise :class:`~machdyn.errors.InputError` naming the field if the follower cannot be built."""
    if f.motion not in TYPES:
        raise InputError(f"{field}.motion must be one of {', '.join(TYPES)}; got {f.motion!r}.")
    if f.contact not in CONTACTS:
        raise InputError(f"{field}.contact must be one of {', '.join(CONTACTS)}; got {f.contact!r}.")
    if f.contact == "flat" and f.motion != "translating":
        raise InputError(f"{field}.contact: a flat face is available on a translating follower only; got "
                         f"{f.motion!r}.")
    for name in ("base_radius", "roller_radius", "offset", "pivot_distance", "arm_length"):
        if not np.isfinite(getattr(f, name)):
            raise InputError(f"{field}.{name} must be a finite length; got {getattr(f, name)}.")
        if abs(getattr(f, name)) > MAX_CAM_SIZE:
            where = "cam.base_radius" if name == "base_radius" else f"{field}.{name}"
            raise InputError(f"{where} is {getattr(f, name):.4g} m, more than {MAX_CAM_SIZE:g} m: no plate cam is "
                             "that large (the largest cams of presses, looms and machine tools are about 1 m in "
                             "radius); check the value and its unit.")
    if f.base_radius <= 0:
        raise InputError(f"cam.base_radius must be > 0 m; got {f.base_radius:g} m.")
    if f.contact == "roller" and f.roller_radius <= 0:
        raise InputError(f"{field}.roller_radius of a roller follower must be > 0 m; got {f.roller_radius:g} m.")
    if f.contact != "roller" and f.roller_radius != 0:
        raise InputError(f"{field}.roller_radius must be 0 for a {f.contact} follower; got {f.roller_radius:g} m.")
    rp = f.base_radius + f.roller_radius
    if f.motion == "translating" and f.contact != "flat" and abs(f.offset) >= rp:
        raise InputError(f"cam.base_radius {f.base_radius:g} m is too small to assemble: the prime circle "
                         f"(base + roller radius = {rp:g} m) must exceed the offset |e| = {abs(f.offset):g} m.")
    if f.motion == "oscillating":
        d, arm = f.pivot_distance, f.arm_length
        if d <= 0 or arm <= 0:
            raise InputError(f"{field}.pivot_distance and arm_length of an oscillating follower must be > 0 m; "
                             f"got {d:g} m and {arm:g} m.")
        if not abs(d - arm) < rp < d + arm:
            raise InputError(f"cam.base_radius {f.base_radius:g} m does not assemble with the oscillating follower: "
                             f"the prime circle radius {rp:g} m must lie between |d - l| = {abs(d - arm):g} m and "
                             f"d + l = {d + arm:g} m.")


@dataclass(frozen=True)
class Path:
    """The roller centre (or knife edge) in the fixed frame and its derivatives with respect to the cam angle:
    f [m], f1 = df/dtheta [m/rad], f2 [m/rad^2], each (2, K); u the unit direction of its path (2, K)."""

    f: np.ndarray
    f1: np.ndarray
    f2: np.ndarray
    u: np.ndarray


def follower_path(f: Follower, s, v, a) -> Path:
    """The pitch point's position and derivatives in the fixed frame for displacement s and its derivatives
    v = ds/dtheta, a = d2s/dtheta2 (see the module docstring for the frame)."""
    s, v, a = (np.asarray(x, dtype=float) for x in (s, v, a))
    if f.motion == "translating":
        d = np.sqrt(f.prime_radius**2 - f.offset**2)
        zero = np.zeros_like(s)
        pos = np.array([zero + f.offset, d + s])
        return Path(pos, np.array([zero, v]), np.array([zero, a]), np.array([zero, zero + 1.0]))
    psi = f.start_angle + s
    arm = f.arm_length
    c, sn = np.cos(psi), np.sin(psi)
    pos = np.array([f.pivot_distance - arm * c, arm * sn])
    u = np.array([sn, c])
    d1 = arm * u * v
    d2 = arm * u * a + arm * np.array([c, -sn]) * v**2
    return Path(pos, d1, d2, u)
