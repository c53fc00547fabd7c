"""Mass substitution: a rigid body replaced by point masses that move with it.

Three forms, each saying what it keeps and what it drops:

- **static two-point** (:func:`static_two_point`): two masses on a line through the centre of mass G keep the
  mass and G, so they give the body's inertia *force* exactly; their moment of inertia about G is m a b instead
  of I, so the inertia *moment* is wrong unless I = m a b (Uicker, Pennock & Shigley, *Theory of Machines and
  Mechanisms*, 5th ed., sec. 16.5; Khurmi & Gupta, *Theory of Machines*, 14th ed., sec. 15.10).
- **dynamic (equimomental) two-point** (:func:`dynamic_two_point`): the second mass at b = k^2 / a on the far
  side of G (k^2 = I/m) keeps the mass, G and the moment of inertia: force and moment are both exact (same
  sources; Routh's equimomental systems).
- **complex two-point** of seed 000 (:func:`complex_two_point`): for a centroid off the line E-B, complex masses
  m_E = m (l - p - i q)/l and m_B = m (p + i q)/l (seed 000 eq 14 with its sign corrected, repro 000.3) keep
  m r_G = m_E r_E + m_B r_B as complex numbers, so the force is exact; a complex mass has no moment of inertia,
  so the moment is dropped.

:func:`substituted_model` puts a real substitute into an engine model in place of the body, and
:func:`compare_substitute` measures the force and moment error of any substitute against the real body along
the body's true motion.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..errors import InputError, check_finite, check_positive
from ..linkage import Body, Mechanism, PointMass, kinematics

__all__ = [
    "Substitute",
    "SubstitutionCheck",
    "two_point_masses",
    "equimomental_distance",
    "complex_point_masses",
    "static_two_point",
    "dynamic_two_point",
    "complex_two_point",
    "substituted_model",
    "compare_substitute",
]


def two_point_masses(mass, a, b):
    """Masses (m_1, m_2) [kg] at distances a and b [m] on either side of the centre of mass, on one line.

    m_1 = m b / (a + b), m_2 = m a / (a + b): the sum is m and the first moment about G is zero (Uicker et al.,
    *Theory of Machines and Mechanisms*, 5th ed., eq. 16.14). Their moment of inertia about G is m a b.

    Parameters
    ----------
    mass : body mass m [kg], >= 0
    a, b : distances [m] of the two points from the centre of mass, on opposite sides; a + b > 0

    Examples
    --------
    >>> two_point_masses(12.0, 0.1, 0.2)
    (8.0, 4.0)
    """
    check_positive("mass", mass, "kg", allow_zero=True)
    check_positive("distance a", a, "m", allow_zero=True)
    check_positive("distance b", b, "m", allow_zero=True)
    if not np.all(np.asarray(a) + b > 0):
        raise InputError(f"The two substitute points must not both sit at the centre of mass; got a = {a}, b = {b} m.")
    return mass * b / (a + b), mass * a / (a + b)


def equimomental_distance(mass, inertia, a):
    """Distance b = k^2 / a [m] of the second mass of a dynamically equivalent two-point system.

    k^2 = I / m is the squared radius of gyration about the centre of mass; with the first mass at distance a,
    the second at b on the opposite side keeps mass, centre of mass and moment of inertia (Uicker et al., 5th
    ed., eq. 16.15; Khurmi & Gupta, 14th ed., sec. 15.10: l_1 l_2 = k_G^2).

    Parameters: mass m [kg] > 0; inertia I about G [kg*m^2] >= 0; a [m] > 0.

    Examples
    --------
    >>> round(equimomental_distance(2.0, 0.02, 0.05), 6)
    0.2
    """
    check_positive("mass", mass, "kg")
    check_positive("moment of inertia", inertia, "kg*m^2", allow_zero=True)
    check_positive("distance a", a, "m")
    return inertia / mass / a


def complex_point_masses(mass, length, p, q):
    """Seed 000's complex substitution, corrected: (m_E, m_B) [kg, complex] of a body with its centroid at
    (p, q) [m] in the frame along E->B (origin E, |EB| = length).

    m_E = m (l - p - i q) / l, m_B = m (p + i q) / l (seed 000 eq 14 with the sign of eq 12 corrected,
    repro 000.3). m_E + m_B = m and m_E r_E + m_B r_B = m r_G hold as complex numbers at every position.

    Parameters: mass [kg] >= 0; length l [m] > 0; p, q [m] finite.

    Examples
    --------
    >>> complex_point_masses(90.0, 0.5, 0.25, 0.01)
    ((45-1.8j), (45+1.8j))
    """
    check_positive("mass", mass, "kg", allow_zero=True)
    check_positive("length E-B", length, "m")
    check_finite("centroid offset p", p, "m")
    check_finite("centroid offset q", q, "m")
    c = complex(p, q) / length
    return mass * (1.0 - c), mass * c


@dataclass(frozen=True)
class Substitute:
    """Point masses standing in for body ``body``: ``masses`` [kg] (complex for the seed 000 form) at
    ``points`` [m] in the body frame; what the form ``preserves`` and ``drops``; ``inertia_error`` [kg*m^2] =
    the substitute's moment of inertia about G minus the body's (None where undefined)."""

    body: str
    kind: str
    masses: tuple
    points: tuple
    preserves: tuple[str, ...]
    drops: tuple[str, ...]
    inertia_error: float | None


def _xy(body: Body, point) -> np.ndarray:
    if isinstance(point, str):
        if point not in body.points:
            raise InputError(f"Body '{body.name}' has no point '{point}'; its points: {', '.join(body.points)}.")
        point = body.points[point]
    xy = np.asarray(point, dtype=float)
    if xy.shape != (2,):
        raise InputError(f"A substitute point must be a point name or (x, y) in m; got {point!r}.")
    check_finite(f"substitute point of body '{body.name}'", xy, "m")
    return xy


def _scalar_body(body: Body) -> tuple[float, float, np.ndarray]:
    if any(np.ndim(v) for v in (body.mass, body.inertia, *body.com)):
        raise InputError(f"Mass substitution takes a single design; body '{body.name}' has design arrays.")
    return float(body.mass), float(body.inertia), np.asarray(body.com, dtype=float)


def static_two_point(body: Body, point_1, point_2, *, tolerance: float = 1e-9) -> Substitute:
    """Static two-point substitute of ``body`` at two points (names or body-frame (x, y) [m]) whose line passes
    through the centre of mass (within ``tolerance`` times their distance).

    Keeps mass and centre of mass (the inertia force); drops the moment of inertia (error m a b - I).
    A centroid off the line needs :func:`complex_two_point` (seed 000) or three points.
    """
    m, inertia, g = _scalar_body(body)
    p1, p2 = _xy(body, point_1), _xy(body, point_2)
    span = float(np.hypot(*(p2 - p1)))
    if span <= 0:
        raise InputError(f"The two substitute points of body '{body.name}' must differ; both are at {p1.tolist()} m.")
    c = complex(*(g - p1)) / complex(*(p2 - p1))
    if abs(c.imag) * span > tolerance * span + 1e-15:
        raise InputError(
            f"The centre of mass of body '{body.name}' lies {abs(c.imag) * span:.3g} m off the line through the two "
            "points; a static two-point substitute needs it on the line (use complex_two_point or other points)."
        )
    a, b = abs(c.real) * span, abs(1.0 - c.real) * span
    if not 0.0 <= c.real <= 1.0:
        # G outside the segment: the masses have opposite signs but still keep m and G.
        m1, m2 = m * (1.0 - c.real), m * c.real
    else:
        m1, m2 = two_point_masses(m, a, b)
    substitute_inertia = m1 * a * a + m2 * b * b
    return Substitute(body.name, "static", (float(m1), float(m2)), (tuple(p1), tuple(p2)),
                      ("mass", "centre of mass", "inertia force"), ("moment of inertia", "inertia moment"),
                      float(substitute_inertia - inertia))


def dynamic_two_point(body: Body, point) -> Substitute:
    """Dynamic (equimomental) two-point substitute of ``body``: one mass at ``point`` (name or (x, y) [m]), the
    other on the far side of G at b = k^2 / a (:func:`equimomental_distance`).

    Keeps mass, centre of mass and moment of inertia: the inertia force and moment are both exact.
    """
    m, inertia, g = _scalar_body(body)
    check_positive(f"mass of body '{body.name}'", m, "kg")
    p = _xy(body, point)
    d = p - g
    a = float(np.hypot(*d))
    if a <= 0:
        raise InputError(
            f"The substitute point of body '{body.name}' must differ from its centre of mass {g.tolist()} m."
        )
    b = equimomental_distance(m, inertia, a)
    q = g - d * (b / a)
    m1, m2 = two_point_masses(m, a, b)
    return Substitute(body.name, "dynamic", (float(m1), float(m2)), (tuple(p), tuple(q)),
                      ("mass", "centre of mass", "moment of inertia", "inertia force", "inertia moment"), (),
                      float(m1 * a * a + m2 * b * b - inertia))


def complex_two_point(body: Body, point_e, point_b) -> Substitute:
    """Seed 000's complex substitute (corrected eq 14): complex masses at E and B for a centroid anywhere.

    Keeps mass and centre of mass as complex first moments (the inertia force); drops the moment (a complex
    mass has no moment of inertia) - ``inertia_error`` is None.
    """
    m, _, g = _scalar_body(body)
    e, b = _xy(body, point_e), _xy(body, point_b)
    eb = complex(*(b - e))
    if eb == 0:
        raise InputError(f"The two substitute points of body '{body.name}' must differ; both are at {e.tolist()} m.")
    z = complex(*(g - e)) / eb * abs(eb)  # centroid in the E->B frame: p + i q
    m_e, m_b = complex_point_masses(m, abs(eb), z.real, z.imag)
    return Substitute(body.name, "complex", (m_e, m_b), (tuple(e), tuple(b)),
                      ("mass", "centre of mass (complex)", "inertia force"),
                      ("moment of inertia", "inertia moment", "real point masses"), None)


def substituted_model(mech: Mechanism, sub: Substitute) -> Mechanism:
    """``mech`` with body ``sub.body`` massless and its substitute attached as point masses ``<body>_sub1``,
    ``<body>_sub2`` (static or dynamic forms; complex masses are not physical and raise InputError)."""
    if sub.kind == "complex":
        raise InputError("A complex substitute has no real point masses; compare it with compare_substitute.")
    body = mech.body(sub.body)
    bodies = tuple(replace(b, mass=0.0, inertia=0.0) if b.name == body.name else b for b in mech.bodies)
    added = tuple(
        PointMass(f"{body.name}_sub{i + 1}", body.name, float(m), (float(xy[0]), float(xy[1])))
        for i, (m, xy) in enumerate(zip(sub.masses, sub.points, strict=True))
    )
    return replace(mech, bodies=bodies, point_masses=tuple(mech.point_masses) + added)


@dataclass(frozen=True)
class SubstitutionCheck:
    """Inertia loads of the real body and of its substitute along the body's motion: ``force_error`` [N] and
    ``moment_error`` [N*m] (largest over the positions; moment about the origin, None for complex masses) and
    the scales ``force_scale``, ``moment_scale`` (largest real values) to judge them by."""

    force_error: float
    moment_error: float | None
    force_scale: float
    moment_scale: float


def compare_substitute(mech: Mechanism, sub: Substitute, crank_angle, speed: float = 1.0,
                       acceleration: float = 0.0) -> SubstitutionCheck:
    """Compare the inertia force -m a_G and moment -(r_G x m a_G + I alpha) of body ``sub.body`` with those of
    its substitute, on the motion of ``mech`` at ``crank_angle`` [rad], ``speed`` [rad/s], ``acceleration``
    [rad/s^2]."""
    kin = kinematics(mech, crank_angle, speed, acceleration)
    body = mech.body(sub.body)
    m, inertia, g = _scalar_body(body)
    st = kin.body(body.name)
    G = kin.local_point(body.name, tuple(g))
    fx, fy = -m * G.ax, -m * G.ay
    moment = G.x * fy - G.y * fx - inertia * st.alpha
    sfx = sfy = smom = 0.0
    complex_form = sub.kind == "complex"
    for mass, xy in zip(sub.masses, sub.points, strict=True):
        P = kin.local_point(body.name, xy)
        if complex_form:
            f = -mass * (P.ax + 1j * P.ay)
            sfx, sfy = sfx + f.real, sfy + f.imag
        else:
            px, py = -mass * P.ax, -mass * P.ay
            sfx, sfy = sfx + px, sfy + py
            smom = smom + P.x * py - P.y * px
    force_error = float(np.max(np.hypot(np.asarray(fx - sfx), np.asarray(fy - sfy))))
    moment_error = None if complex_form else float(np.max(np.abs(moment - smom)))
    return SubstitutionCheck(force_error, moment_error, float(np.max(np.hypot(fx, fy))),
                             float(np.max(np.abs(moment))))
