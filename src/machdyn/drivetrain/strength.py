"""Pins and links under the joint forces of a cycle: pin shear and bearing pressure, the axial force and the
inertial bending of a two-pin link, and the fatigue safety factor of the fluctuating stress.

Sources
-------
- Direct shear of a pin in n shear planes, τ = F / (n·πd²/4), and the bearing pressure on its projected area,
  p = F/(d·l): R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering Design*, 8th ed., ch. 3 (load
  and stress analysis: uniformly distributed stresses) and ch. 8 (bearing stress of pins and bolts).
- Modified Goodman line, 1/n = σa/Se + σm/Sut for σm >= 0; for a compressive mean the amplitude governs,
  n = Se/σa: Shigley's MED, 8th ed., §6-12, eq. (6-46) and the remark on compressive midrange stress.
- Inertial bending of a uniform slender link with pinned ends: the link carries its own transverse inertia
  load q(x) = −(m/L)·a_t(x), with a_t the transverse acceleration of its points (linear in x for a rigid body:
  a(x) = a_A + α × r − ω² r); the bending moment follows from statics of the simply supported beam. This is the
  distributed-inertia treatment of R. L. Norton, *Machine Design*, 5th ed., ch. 3 (dynamic loading of links);
  the accelerations here are the engine's exact ones.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..errors import InputError


def pin_stresses(force: Any, diameter: float, length: float, shear_planes: int = 2) -> tuple[Any, Any]:
    """Shear stress and bearing pressure of a pin carrying ``force``.

    τ = F / (n·π·d²/4),   p = F / (d·l)

    Parameters
    ----------
    force : F [N] (magnitude; arrays are taken element-wise).
    diameter : d [m] > 0.
    length : l [m] > 0, the length of the pin in the eye (its projected bearing area is d·l).
    shear_planes : n, 1 (single shear) or 2 (double shear, a fork joint).

    Returns
    -------
    (τ [Pa], p [Pa])

    Examples
    --------
    A 20 mm pin in double shear under 10 kN, 30 mm long in its eye:

    >>> tau, p = pin_stresses(10e3, 0.02, 0.03)
    >>> round(float(tau) / 1e6, 2), round(float(p) / 1e6, 2)
    (15.92, 16.67)
    """
    if diameter <= 0 or length <= 0:
        raise InputError(f"A pin needs a diameter and a length > 0 m; got {diameter:g} m and {length:g} m.")
    if shear_planes not in (1, 2):
        raise InputError(f"A pin is sheared in 1 or 2 planes; got {shear_planes}.")
    f = np.abs(np.asarray(force, dtype=float))
    return f / (shear_planes * math.pi * diameter**2 / 4.0), f / (diameter * length)


def strength_problem(endurance_limit: float, ultimate_strength: float) -> str | None:
    """Why a part's endurance limit Se [Pa] and ultimate strength Sut [Pa] cannot both hold, else None.

    Both must be > 0, and Se <= Sut: a stress the part endures for ever cannot break it in one cycle (the
    rotating-beam endurance limit of steels is Se' ~= 0.5 Sut up to 1400 MPa, Shigley's MED, 8th ed., eq 6-8,
    and the Marin factors only lower it). Se > Sut is an input mistake (the two values swapped, or a unit).
    """
    if not (endurance_limit > 0 and ultimate_strength > 0):
        return (f"endurance_limit and ultimate_strength must be > 0 Pa; got {endurance_limit:.4g} Pa and "
                f"{ultimate_strength:.4g} Pa")
    if endurance_limit > ultimate_strength:
        return (f"endurance_limit {endurance_limit / 1e6:.4g} MPa exceeds ultimate_strength "
                f"{ultimate_strength / 1e6:.4g} MPa: a part cannot endure for ever a stress that breaks it in one "
                "cycle (steels: Se <= 0.5 Sut before the Marin factors, Shigley's MED eq 6-8); are the two "
                "values swapped?")
    return None


def goodman_safety(stress_max: Any, stress_min: Any, endurance_limit: float, ultimate_strength: float) -> Any:
    """Fatigue safety factor of a stress fluctuating between ``stress_min`` and ``stress_max`` by the modified
    Goodman line (Shigley's MED, 8th ed., eq. 6-46); a compressive mean stress is judged by its amplitude alone.

    σa = (σmax − σmin)/2,  σm = (σmax + σmin)/2;  n = 1/(σa/Se + σm/Sut) for σm >= 0, n = Se/σa for σm < 0.

    Parameters
    ----------
    stress_max, stress_min : [Pa].
    endurance_limit : Se [Pa] > 0, the fully corrected endurance limit of the part.
    ultimate_strength : Sut [Pa] > 0.

    Returns
    -------
    float or ndarray
        n [-] (inf for a constant zero stress).

    Examples
    --------
    A stress from 0 to 200 MPa with Se = 150 MPa and Sut = 600 MPa: σa = σm = 100 MPa, n = 1/(2/3 + 1/6) = 1.2:

    >>> round(float(goodman_safety(200e6, 0.0, 150e6, 600e6)), 3)
    1.2
    """
    problem = strength_problem(endurance_limit, ultimate_strength)
    if problem:
        raise InputError(f"The part's {problem}.")
    hi = np.asarray(stress_max, dtype=float)
    lo = np.asarray(stress_min, dtype=float)
    amp = 0.5 * (hi - lo)
    mid = 0.5 * (hi + lo)
    usage = np.where(mid >= 0, amp / endurance_limit + mid / ultimate_strength, amp / endurance_limit)
    with np.errstate(divide="ignore"):
        n = np.where(usage > 0, 1.0 / np.where(usage > 0, usage, 1.0), np.inf)
    return n if n.ndim else float(n)


def link_section_loads(state_a: Any, state_b: Any, force_a: tuple[Any, Any], mass: Any) -> tuple[Any, Any]:
    """Axial force and the largest bending moment of a uniform two-pin link A–B over a cycle.

    The axial force is the end reaction at A projected on the link's axis (positive: tension, the force on the
    link at A pointing away from B); the bending moment is that of a simply supported beam of mass ``mass``
    under its transverse inertia load −(m/L)·a_t(x), where a_t(x) varies linearly from a_t(A) to a_t(B). Along
the link (s = x/L) the moment is the cubic M(s) = s (c1 + s (c2 + s c3)), zero at both pins; its largest
magnitude is found exactly at the roots of M'(s) = c1 + 2 c2 s + 3 c3 s² in [0, 1] (the quadratic solved in its
cancellation-free form, W. H. Press et al., *Numerical Recipes*, 3rd ed., §5.6, eq. 5.6.4–5.6.5).

    Parameters
    ----------
    state_a, state_b : the global motion of the pins A and B (objects with x, y, ax, ay [m, m/s²]).
    force_a : (fx, fy) [N], the force on the link at A from the body before it.
    mass : m [kg] of the link (uniform along A–B); (N, 1) for N designs whose states are (N, K).

    Returns
    -------
    (N [N], M [N·m]) at each position: the axial force and the bending moment of largest magnitude (signed).

    Examples
    --------
    A link at rest with its ends accelerating transversely at 10 m/s² (a uniform load): M = q L²/8 = mL·a/8:

    >>> from types import SimpleNamespace as S
    >>> a, b = S(x=0.0, y=0.0, ax=0.0, ay=10.0), S(x=1.0, y=0.0, ax=0.0, ay=10.0)
    >>> n, m = link_section_loads(a, b, (0.0, -10.0), mass=2.0)
    >>> float(n) == 0.0, round(abs(float(m)), 6)
    (True, 2.5)
    """
    ax_, ay_ = np.asarray(state_a.x, float), np.asarray(state_a.y, float)
    dx, dy = np.asarray(state_b.x, float) - ax_, np.asarray(state_b.y, float) - ay_
    length = np.hypot(dx, dy)
    if np.any(length <= 0):
        raise InputError("A link's two pins coincide: its axial force and bending are not defined.")
    ux, uy = dx / length, dy / length
    nx, ny = -uy, ux
    fx, fy = (np.asarray(f, float) for f in force_a)
    axial = -(fx * ux + fy * uy)  # the force on the link at A pulling away from B is tension
    at_a = np.asarray(state_a.ax, float) * nx + np.asarray(state_a.ay, float) * ny
    at_b = np.asarray(state_b.ax, float) * nx + np.asarray(state_b.ay, float) * ny
    # load per unit length q(s) = -(m/L) a_t(s), s in [0, 1]: linear, q = q0 + (q1 - q0) s
    q0, q1 = -mass / length * at_a, -mass / length * at_b
    # simply supported: reaction at A, R_A = L (q0/3 + q1/6); M(s) = R_A L s - L^2 (q0 s^2/2 + (q1-q0) s^3/6),
    # i.e. M(s) = s (c1 + s (c2 + s c3))
    c1 = length * length * (q0 / 3.0 + q1 / 6.0)
    c2 = -length**2 * q0 / 2.0
    c3 = -length**2 * (q1 - q0) / 6.0
    # M'(s) = 0: a s^2 + b s + c with a = 3 c3, b = 2 c2, c = c1; q = -(b + sign(b) sqrt(b^2 - 4ac))/2, the roots
    # q/a and c/q (a root outside [0, 1], or none, is clipped to an end, where M is 0 or smaller)
    a, b = 3.0 * c3, 2.0 * c2
    with np.errstate(invalid="ignore", divide="ignore"):
        root = np.sqrt(np.maximum(b * b - 4.0 * a * c1, 0.0))
        q = -0.5 * (b + np.where(b >= 0, root, -root))
        s1, s2 = q / a, c1 / q

    def moment_at(s: Any) -> Any:
        s = np.clip(np.where(np.isfinite(s), s, 0.0), 0.0, 1.0)
        return s * (c1 + s * (c2 + s * c3))

    m1, m2 = moment_at(s1), moment_at(s2)
    hi, lo = np.maximum(m1, m2), np.minimum(m1, m2)
    hi, lo = np.maximum(hi, 0.0), np.minimum(lo, 0.0)  # the ends, where M = 0
    nan = ~np.isfinite(c1 + c2 + c3)
    hi, lo = np.where(nan, np.nan, hi), np.where(nan, np.nan, lo)
    worst = np.where(np.abs(lo) > np.abs(hi), lo, hi)
    return axial, (worst if worst.ndim else float(worst))
