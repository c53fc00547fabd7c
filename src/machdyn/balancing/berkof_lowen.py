"""Full shaking-force balance of the four-bar by two counterweights (Berkof-Lowen), and what it costs.

Berkof & Lowen, "A new method for completely force balancing simple linkages", ASME J. Eng. Ind. 91(1), 1969,
21-26 ("method of linearly independent vectors"); Norton, *Design of Machinery*, 5th ed., sec. 12.4. Write the
centres of mass as complex numbers: crank G2 = O + g2 e^{i t2}, coupler G3 = A + c (B - A) with the constant
complex ratio c = (G3 - A)/(B - A) in the coupler frame, rocker G4 = D + g4 e^{i t4}, with A = O + a e^{i t2}
and B = D + b e^{i t4}. Then the total first moment is

    m2 G2 + m3 G3 + m4 G4 = const + [m2 g2 + m3 (1 - c) a] e^{i t2} + [m4 g4 + m3 c b] e^{i t4},

and the two brackets vanish for a stationary total centre of mass, i.e. zero shaking force at every speed and
acceleration: m2 g2 = -m3 (1 - c) a and m4 g4 = -m3 c b (first moments about the pivots, in the link frames).
The price: the counterweights add mass and inertia, so the shaking moment, the driving torque and the joint
forces usually grow (Berkof & Lowen 1971; Norton, sec. 12.5) - :func:`berkof_lowen` reports them before/after.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..errors import InputError, check_positive
from ..linkage import RRR, Mechanism, PointMass
from ..linkage.model import GROUND, split_ref
from .frame import BalanceResult, compare, cycle, frame_loads

__all__ = ["FourBarMasses", "four_bar_masses", "required_first_moments", "berkof_lowen"]


@dataclass(frozen=True)
class FourBarMasses:
    """The four-bar read from a model: body names, the crank pin A and pivot O in the crank frame, the coupler
    points A, B, the rocker pivot D and pin B in the rocker frame [m], the coupler mass [kg] and its centroid
    ratio c, and the current first moments [kg*m] of crank and rocker about their pivots (link frames)."""

    crank: str
    coupler: str
    rocker: str
    crank_pivot: np.ndarray
    crank_pin: np.ndarray
    rocker_pivot: np.ndarray
    rocker_pin: np.ndarray
    coupler_mass: float
    coupler_ratio: complex
    crank_moment: complex
    rocker_moment: complex


def _mass_and_moment(mech: Mechanism, body: str, about: np.ndarray) -> tuple[float, complex]:
    b = mech.body(body)
    if any(np.ndim(v) for v in (b.mass, *b.com)):
        raise InputError(f"Berkof-Lowen balancing takes a single design; body '{body}' has design arrays.")
    mass = float(b.mass)
    moment = float(b.mass) * complex(*(np.asarray(b.com, dtype=float) - about))
    for pm in mech.point_masses:
        if pm.body == body:
            mass += float(pm.mass)
            moment += float(pm.mass) * complex(*(np.asarray(pm.position, dtype=float) - about))
    return mass, moment


def four_bar_masses(mech: Mechanism) -> FourBarMasses:
    """Read a four-bar (crank + one RRR dyad pinned to the crank and to a ground point) from ``mech``."""
    if len(mech.dyads) != 1 or not isinstance(mech.dyads[0], RRR):
        raise InputError(f"Berkof-Lowen balancing needs a four-bar: a crank and one RRR dyad; mechanism "
                         f"'{mech.name}' has {len(mech.dyads)} dyad(s) of types "
                         f"{', '.join(type(d).__name__ for d in mech.dyads) or 'none'}.")
    d = mech.dyads[0]
    if split_ref(d.pin_a)[0] != mech.crank.body or split_ref(d.pin_b)[0] != GROUND:
        raise InputError(f"The RRR dyad of '{mech.name}' must hang on the crank (pin_a) and a ground point (pin_b); "
                         f"got {d.pin_a!r}, {d.pin_b!r}.")
    crank, coupler, rocker = mech.body(mech.crank.body), mech.body(d.a), mech.body(d.b)
    o = np.asarray(crank.points[split_ref(mech.crank.pivot)[1]], dtype=float)
    a_name = split_ref(d.pin_a)[1]
    d_name = split_ref(d.pin_b)[1]
    crank_pin = np.asarray(crank.points[a_name], dtype=float)
    ca = np.asarray(coupler.points[a_name], dtype=float)
    cb = np.asarray(coupler.points[d.inner], dtype=float)
    rd = np.asarray(rocker.points[d_name], dtype=float)
    rb = np.asarray(rocker.points[d.inner], dtype=float)
    m3, first3 = _mass_and_moment(mech, coupler.name, ca)
    ratio = first3 / m3 / complex(*(cb - ca)) if m3 > 0 else 0j
    _, first2 = _mass_and_moment(mech, crank.name, o)
    _, first4 = _mass_and_moment(mech, rocker.name, rd)
    return FourBarMasses(crank.name, coupler.name, rocker.name, o, crank_pin, rd, rb, m3, ratio, first2, first4)


def required_first_moments(coupler_mass, coupler_ratio, crank_vector, rocker_vector):
    """Total first moments [kg*m] of crank and rocker about their pivots (complex, link frames) that make the
    four-bar's total centre of mass stationary (Berkof & Lowen 1969; Norton, 5th ed., eqs. 12.8).

    m2 g2 = -m3 (1 - c) a,  m4 g4 = -m3 c b.

    Parameters
    ----------
    coupler_mass : m3 [kg], >= 0
    coupler_ratio : c = (G3 - A)/(B - A), complex [-]
    crank_vector : a = A - O in the crank frame, complex [m]
    rocker_vector : b = B - D in the rocker frame, complex [m]

    Examples
    --------
    A uniform coupler (c = 1/2) of 2 kg on a 0.1 m crank and a 0.3 m rocker:

    >>> crank, rocker = required_first_moments(2.0, 0.5, 0.1, 0.3)
    >>> round(crank.real, 12), round(rocker.real, 12)
    (-0.1, -0.3)
    """
    check_positive("coupler mass", coupler_mass, "kg", allow_zero=True)
    c = complex(coupler_ratio)
    for name, value in (("coupler_ratio", c), ("crank_vector", complex(crank_vector)),
                        ("rocker_vector", complex(rocker_vector))):
        if not np.isfinite(value):
            raise InputError(f"{name} must be a finite complex number; got {value!r}.")
    return -coupler_mass * (1.0 - c) * complex(crank_vector), -coupler_mass * c * complex(rocker_vector)


def berkof_lowen(mech: Mechanism, crank_radius: float, rocker_radius: float, crank_angle=None,
                 speed: float = 1.0) -> BalanceResult:
    """Fully force-balance a four-bar with a counterweight on the crank at ``crank_radius`` [m] and one on the
    rocker at ``rocker_radius`` [m] from their pivots (:func:`required_first_moments`).

    Returns a :class:`~machdyn.balancing.frame.BalanceResult` (point masses ``cw_<crank>``, ``cw_<rocker>``)
    whose table shows the cost: the shaking moment, the driving torque and the joint forces before and after.
    """
    check_positive("crank counterweight radius", crank_radius, "m")
    check_positive("rocker counterweight radius", rocker_radius, "m")
    fb = four_bar_masses(mech)
    need2, need4 = required_first_moments(fb.coupler_mass, fb.coupler_ratio, complex(*(fb.crank_pin - fb.crank_pivot)),
                                          complex(*(fb.rocker_pin - fb.rocker_pivot)))
    added = []
    for body, pivot, need, have, radius in ((fb.crank, fb.crank_pivot, need2, fb.crank_moment, crank_radius),
                                            (fb.rocker, fb.rocker_pivot, need4, fb.rocker_moment, rocker_radius)):
        extra = need - have
        if abs(extra) == 0:
            continue
        position = pivot + radius * np.array([extra.real, extra.imag]) / abs(extra)
        added.append(PointMass(f"cw_{body}", body, abs(extra) / radius, (float(position[0]), float(position[1]))))
    balanced = replace(mech, point_masses=tuple(mech.point_masses) + tuple(added))
    phi = cycle() if crank_angle is None else crank_angle
    before, after = frame_loads(mech, phi, speed), frame_loads(balanced, phi, speed)
    pivots = {fb.crank: fb.crank_pivot, fb.rocker: fb.rocker_pivot}
    notes = tuple(f"{p.name}: {p.mass:.6g} kg at {np.hypot(*(np.asarray(p.position) - pivots[p.body])):.4g} m "
                  "from its pivot" for p in added)
    return BalanceResult(balanced, before, after, compare(before, after), tuple(added), notes)
