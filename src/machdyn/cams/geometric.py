"""Cams with specified contours: the follower's motion from the cam's shape (base, flank and nose radii).

A symmetrical cam of base radius r1 [m] and nose radius r2 [m] with lift h [m] has its nose centre Q at
d = r1 + h - r2 from the cam centre O. The angle alpha [rad] the cam turns from the start of the rise to full
lift, and the angle phi [rad] where contact passes from the flank to the nose, follow from the shape; theta
[rad] is the cam angle from the start of the rise, omega [rad/s] the cam's constant speed. On the return the
motion runs back symmetrically. Source for every formula: R. S. Khurmi and J. K. Gupta, *Theory of Machines*,
14th ed., Eurasia 2009, ch. 20 "Cams", sections 20.13 (tangent cam with reciprocating roller follower) and 20.14
(circular arc cam with flat-faced follower).

**Circular-arc cam, flat-faced follower** (flank radius R [m], R > r1): the flank's centre P is at R - r1 from O
on the far side, and O P Q is a triangle with |PQ| = R - r2, so cos(pi - alpha) = ((R - r1)^2 + d^2 -
(R - r2)^2) / (2 (R - r1) d). On the flank (0 <= theta <= phi):

    x = (R - r1)(1 - cos theta),   v = omega (R - r1) sin theta,   a = omega^2 (R - r1) cos theta;

on the nose (phi <= theta <= alpha), with theta' = alpha - theta:

    x = d cos theta' + r2 - r1,    v = omega d sin theta',         a = -omega^2 d cos theta';

phi where the two agree in position and speed: tan phi = d sin alpha / (R - r1 + d cos alpha).

**Tangent cam, roller follower** (roller radius r [m], the follower's line through O): straight flanks tangent to
the base and nose circles, so cos alpha = (r1 - r2) / d. On the flank:

    x = (r1 + r)(1 - cos theta) / cos theta,   v = omega (r1 + r) sin theta / cos^2 theta,
    a = omega^2 (r1 + r)(2 - cos^2 theta) / cos^3 theta;

on the nose, with L = r2 + r and theta' = alpha - theta:

    x = d cos theta' + sqrt(L^2 - d^2 sin^2 theta') - (r1 + r),
    v = omega d (sin theta' + d sin 2theta' / (2 sqrt(L^2 - d^2 sin^2 theta'))),
    a = -omega^2 d (cos theta' + (L^2 d cos 2theta' + d^3 sin^4 theta') / (L^2 - d^2 sin^2 theta')^(3/2));

tan phi = d sin alpha / (r1 + r).

The books often give the angle of rise instead of one radius: :func:`flank_radius_for_angle` and
:func:`nose_radius_for_angle` solve these relations for R and r2.

Validity: 0 < r2 < r1, h > 0 with d > 0; circular arc: R > r1 + h (the flank must reach the nose); the roller
any r >= 0. Angles outside [0, alpha] are refused.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError


@dataclass(frozen=True)
class ContourMotion:
    """The rise of a cam with a specified contour: cam angles [rad], the follower's displacement x [m], velocity
    v [m/s] and acceleration a [m/s^2]; ``alpha`` [rad] the angle of the rise, ``phi`` [rad] where contact passes
    from the flank to the nose."""

    theta: np.ndarray
    x: np.ndarray
    v: np.ndarray
    a: np.ndarray
    alpha: float
    phi: float


def _shape(base: float, nose: float, lift: float) -> float:
    if not (np.isfinite([base, nose, lift]).all() and 0.0 < nose < base and lift > 0.0):
        raise InputError(f"A cam with specified contours needs 0 < nose radius < base radius and a lift > 0; got "
                         f"r1 = {base!r} m, r2 = {nose!r} m, h = {lift!r} m.")
    return base + lift - nose


def _angles(theta, alpha: float) -> np.ndarray:
    t = np.asarray(theta, dtype=float)
    if not (np.isfinite(t).all() and np.all(t >= -1e-12) and np.all(t <= alpha + 1e-12)):
        raise InputError(f"The cam angles must lie in the rise, 0 to alpha = {np.degrees(alpha):.6g} deg.")
    return np.clip(t, 0.0, alpha)


def circular_arc_flat(base: float, nose: float, lift: float, flank: float, theta, omega: float = 1.0
                      ) -> ContourMotion:
    """The rise of a circular-arc cam with a flat-faced follower (module docstring; Khurmi & Gupta §20.14).

    >>> m = circular_arc_flat(0.02, 0.005, 0.01, 0.08, [0.0], 1.0)
    >>> round(float(m.x[0]), 12), bool(0.0 < m.phi < m.alpha < np.pi)
    (0.0, True)
    """
    d = _shape(base, nose, lift)
    if not flank > base + lift:
        raise InputError(f"The flank radius of a circular-arc cam must exceed base radius + lift = "
                         f"{base + lift:.6g} m; got {flank!r} m.")
    op, pq = flank - base, flank - nose
    cos_poq = (op * op + d * d - pq * pq) / (2.0 * op * d)
    alpha = float(np.pi - np.arccos(np.clip(cos_poq, -1.0, 1.0)))
    phi = float(np.arctan2(d * np.sin(alpha), op + d * np.cos(alpha)))
    t = _angles(theta, alpha)
    on_flank = t <= phi
    tn = alpha - t
    x = np.where(on_flank, op * (1.0 - np.cos(t)), d * np.cos(tn) + nose - base)
    v = omega * np.where(on_flank, op * np.sin(t), d * np.sin(tn))
    a = omega**2 * np.where(on_flank, op * np.cos(t), -d * np.cos(tn))
    return ContourMotion(t, x, v, a, alpha, phi)


def tangent_roller(base: float, nose: float, lift: float, roller: float, theta, omega: float = 1.0
                   ) -> ContourMotion:
    """The rise of a tangent cam with a reciprocating roller follower (module docstring; Khurmi & Gupta §20.13).

    >>> m = tangent_roller(0.02, 0.005, 0.01, 0.008, [0.0], 1.0)
    >>> round(float(m.x[0]), 12)
    0.0
    """
    d = _shape(base, nose, lift)
    if not (np.isfinite(roller) and roller >= 0.0):
        raise InputError(f"The roller radius must be >= 0 m; got {roller!r} m.")
    alpha = float(np.arccos((base - nose) / d))
    rb, big = base + roller, nose + roller
    phi = float(np.arctan2(d * np.sin(alpha), rb))
    t = _angles(theta, alpha)
    on_flank = t <= phi
    tn = np.where(on_flank, 0.0, alpha - t)  # each formula evaluated only where it holds
    c = np.cos(np.where(on_flank, t, 0.0))
    root = np.sqrt(big * big - (d * np.sin(tn)) ** 2)
    x = np.where(on_flank, rb * (1.0 - c) / c, d * np.cos(tn) + root - rb)
    v = omega * np.where(on_flank, rb * np.sin(t) / c**2, d * (np.sin(tn) + d * np.sin(2 * tn) / (2.0 * root)))
    nose_a = -d * (np.cos(tn) + (big * big * d * np.cos(2 * tn) + d**3 * np.sin(tn) ** 4) / root**3)
    a = omega**2 * np.where(on_flank, rb * (2.0 - c * c) / c**3, nose_a)
    return ContourMotion(t, x, v, a, alpha, phi)


def contour_law(kind: str, base: float, nose: float, lift: float, size: float, motion: str = "rise"):
    """The normalised law (y, y', y'', y''') over x in [0, 1] of a contour's rise (``motion`` "rise") or return
    ("return": the rise run backwards, y(x) = 1 - Y(1 - x)) [-]; ``kind`` "circular_arc" (``size`` the flank
    radius [m]) or "tangent" (``size`` the roller radius [m]). The segment lasts alpha (:func:`rise_angle`). The
    jerk is exact on the circular arc's parts and a central difference of the acceleration (step 1e-6 of the
    rise) on the tangent cam's nose."""
    make = circular_arc_flat if kind == "circular_arc" else tangent_roller
    alpha = make(base, nose, lift, size, [0.0]).alpha

    def rise(x: np.ndarray):
        t = np.clip(np.asarray(x, dtype=float), 0.0, 1.0) * alpha
        m = make(base, nose, lift, size, t)
        if kind == "circular_arc":
            d = base + lift - nose
            jerk = np.where(t <= m.phi, -(size - base) * np.sin(t), -d * np.sin(alpha - t))
        else:
            h = 1e-6 * alpha
            up = make(base, nose, lift, size, np.clip(t + h, 0.0, alpha)).a
            down = make(base, nose, lift, size, np.clip(t - h, 0.0, alpha)).a
            jerk = (up - down) / (np.clip(t + h, 0.0, alpha) - np.clip(t - h, 0.0, alpha))
        return m.x / lift, m.v * alpha / lift, m.a * alpha**2 / lift, jerk * alpha**3 / lift

    if motion == "rise":
        return rise

    def back(x: np.ndarray):
        y, y1, y2, y3 = rise(1.0 - np.clip(np.asarray(x, dtype=float), 0.0, 1.0))
        return 1.0 - y, y1, -y2, y3

    return back


def rise_angle(kind: str, base: float, nose: float, lift: float, size: float) -> float:
    """alpha [rad]: the cam angle of a contour's rise (module docstring)."""
    make = circular_arc_flat if kind == "circular_arc" else tangent_roller
    return make(base, nose, lift, size, [0.0]).alpha


def contour_phi(kind: str, base: float, nose: float, lift: float, size: float) -> float:
    """phi [rad]: the cam angle from the start of a contour's rise where contact passes from flank to nose."""
    make = circular_arc_flat if kind == "circular_arc" else tangent_roller
    return make(base, nose, lift, size, [0.0]).phi


def flank_radius_for_angle(base: float, nose: float, lift: float, alpha: float) -> float:
    """R [m]: the flank radius of the circular-arc cam whose rise lasts alpha [rad] — the shape the books give by
    its angle of rise (T. Bevan, *The Theory of Machines*, 3rd ed., ch. 9, Example 5; Khurmi & Gupta, *Theory of
    Machines*, 14th ed., §20.14). From the triangle O P Q of the module docstring, with u = R - r1 = |OP|,
    |PQ| = u + r1 - r2 and the angle at O equal to pi - alpha:

        u = (d^2 - (r1 - r2)^2) / (2 ((r1 - r2) - d cos alpha)),   d = r1 + h - r2.

    Validity: 0 < r2 < r1, h > 0, and alpha between the tangent cam's angle arccos((r1 - r2)/d) (R infinite: the
    flanks become straight) and the angle at which R = r1 + h; outside that an :class:`InputError` says which.

    >>> R = flank_radius_for_angle(0.02, 0.005, 0.012, rise_angle("circular_arc", 0.02, 0.005, 0.012, 0.09))
    >>> round(R, 12)
    0.09
    """
    d = _shape(base, nose, lift)
    if not (np.isfinite(alpha) and 0.0 < alpha < np.pi):
        raise InputError(f"A cam's angle of rise must lie between 0 and 180 deg; got {np.degrees(alpha)!r} deg.")
    straight = float(np.arccos((base - nose) / d))
    gap = (base - nose) - d * np.cos(alpha)
    if gap <= 0.0:
        raise InputError(f"A circular-arc cam with these radii and lift needs an angle of rise above "
                         f"{np.degrees(straight):.6g} deg (the tangent cam's, straight flanks); got "
                         f"{np.degrees(alpha):.6g} deg.")
    flank = base + (d * d - (base - nose) ** 2) / (2.0 * gap)
    if not flank > base + lift:
        raise InputError(f"An angle of rise of {np.degrees(alpha):.6g} deg gives a flank radius {flank:.6g} m, not "
                         f"above base radius + lift = {base + lift:.6g} m: the angle is too large for this cam.")
    return float(flank)


def nose_radius_for_angle(base: float, lift: float, alpha: float) -> float:
    """r2 [m]: the nose radius of the tangent cam whose rise lasts alpha [rad] (Khurmi & Gupta, *Theory of
    Machines*, 14th ed., §20.13: cos alpha = (r1 - r2)/(r1 + h - r2)), so

        r2 = (r1 - (r1 + h) cos alpha) / (1 - cos alpha).

    Validity: r1 > 0, h > 0, alpha < 90 deg and (r1 + h) cos alpha < r1 (a nose radius > 0, which is then below
    r1); otherwise an :class:`InputError`.

    >>> round(nose_radius_for_angle(0.030, 0.0175, np.radians(75)) * 1e3, 2)
    23.89
    """
    if not (np.isfinite([base, lift, alpha]).all() and base > 0.0 and lift > 0.0 and 0.0 < alpha < np.pi / 2):
        raise InputError(f"A tangent cam needs a base radius and a lift > 0 and an angle of rise between 0 and "
                         f"90 deg; got r1 = {base!r} m, h = {lift!r} m, {np.degrees(alpha)!r} deg.")
    c = float(np.cos(alpha))
    nose = (base - (base + lift) * c) / (1.0 - c)
    if not nose > 0.0:
        raise InputError(f"A tangent cam of base radius {base:.6g} m and lift {lift:.6g} m needs an angle of rise "
                         f"above {np.degrees(np.arccos(base / (base + lift))):.6g} deg (a nose of radius 0); got "
                         f"{np.degrees(alpha):.6g} deg.")
    return nose
