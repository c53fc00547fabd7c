"""Builders of common linkages as :class:`~machdyn.linkage.model.Mechanism` models.

Every length may be an array of design variants. Link frames: origin at the first joint, x axis towards the
second. Mass properties default to uniform slender bars of ``linear_density`` [kg/m] (centre of mass at
mid-length, I = m L^2 / 12 about it); pass ``masses``, ``inertias`` and ``coms`` to give your own.
"""

from __future__ import annotations

import numpy as np

from ..constants import DOWNWARD_GRAVITY
from ..errors import InputError, check_finite, check_positive
from .model import RPR, RRP, RRR, Body, Crank, Guide, Mechanism

BRANCHES = {"open": 1, "crossed": -1, "up": 1, "down": -1, 1: 1, -1: -1, "+1": 1, "-1": -1}


def branch_sign(branch, field: str = "branch") -> int:
    """+1 or -1 from a branch given as +1/-1 or a name ('open'/'up' = +1, 'crossed'/'down' = -1)."""
    try:
        return BRANCHES[branch]
    except (KeyError, TypeError):
        raise InputError(
            f"The {field} must be one of +1, -1, 'open', 'crossed', 'up', 'down'; got {branch!r}."
        ) from None


def _bar(name, points, length, mass, inertia, com, density):
    m = density * np.asarray(length) if mass is None else mass
    i = m * np.asarray(length) ** 2 / 12.0 if inertia is None else inertia
    c = (np.asarray(length) / 2.0, 0.0) if com is None else com
    return Body(name, points, _f(m), _f(i), tuple(_f(v) for v in c))


def _f(v):
    a = np.asarray(v, dtype=float)
    return float(a) if a.ndim == 0 else a


def _props(values, n, field):
    if values is None:
        return (None,) * n
    if len(values) != n:
        raise InputError(f"The {field} must list {n} values (one per moving body); got {len(values)}.")
    return tuple(values)


def slider_crank(
    crank,
    rod,
    offset=0.0,
    *,
    slide_angle=0.0,
    branch=1,
    masses=None,
    inertias=None,
    coms=None,
    linear_density=1.0,
    name="slider_crank",
    gravity=DOWNWARD_GRAVITY,
) -> Mechanism:
    """Offset slider-crank: crank O-A [m], rod A-B [m], slider B on a line at distance ``offset`` [m] from O.

    The slide line passes through the ground point S = offset * (-sin a, cos a) with direction a =
    ``slide_angle`` [rad]; the slider's travel s [m] is measured from S along the line. Branch +1 puts the
    slider ahead of the crank along the slide direction. Valid where rod >= |offset| + crank for a fully
    rotating crank. (Exact form of seed 000 eqs 5-7 and seed 002 eqs 1-3.)
    """
    check_positive("crank length of slider_crank '" + name + "'", crank, "m")
    check_positive("rod length of slider_crank '" + name + "'", rod, "m")
    check_finite(f"offset of slider_crank '{name}'", offset, "m")
    check_finite(f"slide_angle of slider_crank '{name}'", slide_angle, "rad")
    m, i, c = (_props(v, 3, f) for v, f in ((masses, "masses"), (inertias, "inertias"), (coms, "coms")))
    sa, ca = np.sin(slide_angle), np.cos(slide_angle)
    bodies = (
        _bar("crank", {"O": (0.0, 0.0), "A": (_f(crank), 0.0)}, crank, m[0], i[0], c[0], linear_density),
        _bar("rod", {"A": (0.0, 0.0), "B": (_f(rod), 0.0)}, rod, m[1], i[1], c[1], linear_density),
        Body(
            "slider",
            {"B": (0.0, 0.0)},
            _f(linear_density * np.asarray(rod)) if m[2] is None else _f(m[2]),
            0.0 if i[2] is None else _f(i[2]),
            (0.0, 0.0) if c[2] is None else c[2],
        ),
    )
    ground = {"O": (0.0, 0.0), "S": (_f(-np.asarray(offset) * sa), _f(np.asarray(offset) * ca))}
    dyad = RRP("rod", "slider", "crank.A", "B", Guide("ground.S", _f(slide_angle)), branch_sign(branch))
    return Mechanism(name, ground, bodies, Crank("crank", "ground.O"), (dyad,), gravity=gravity)


def four_bar(
    crank,
    coupler,
    rocker,
    ground,
    *,
    ground_angle=0.0,
    branch=1,
    masses=None,
    inertias=None,
    coms=None,
    linear_density=1.0,
    coupler_point=None,
    name="four_bar",
    gravity=DOWNWARD_GRAVITY,
) -> Mechanism:
    """Four-bar linkage O-A-B-D: crank O-A, coupler A-B, rocker D-B, ground O-D, all lengths [m].

    D = ground * (cos g, sin g) with g = ``ground_angle`` [rad]. Branch +1 ('open') puts B to the left of the
    line from A to D. ``coupler_point`` = (u, v) [m] in the coupler frame adds the point P. Crank-rocker,
    double-crank, double-rocker and change-point types follow from Grashof's rule
    (:func:`~machdyn.linkage.diagnostics.grashof_type`).
    """
    for field, value in (("crank", crank), ("coupler", coupler), ("rocker", rocker), ("ground", ground)):
        check_positive(f"{field} length of four_bar '{name}'", value, "m")
    check_finite(f"ground_angle of four_bar '{name}'", ground_angle, "rad")
    if coupler_point is not None:
        check_finite(f"coupler_point of four_bar '{name}'", coupler_point, "m")
    m, i, c = (_props(v, 3, f) for v, f in ((masses, "masses"), (inertias, "inertias"), (coms, "coms")))
    coupler_points = {"A": (0.0, 0.0), "B": (_f(coupler), 0.0)}
    if coupler_point is not None:
        coupler_points["P"] = tuple(_f(v) for v in coupler_point)
    bodies = (
        _bar("crank", {"O": (0.0, 0.0), "A": (_f(crank), 0.0)}, crank, m[0], i[0], c[0], linear_density),
        _bar("coupler", coupler_points, coupler, m[1], i[1], c[1], linear_density),
        _bar("rocker", {"D": (0.0, 0.0), "B": (_f(rocker), 0.0)}, rocker, m[2], i[2], c[2], linear_density),
    )
    g = np.asarray(ground)
    ground_pts = {"O": (0.0, 0.0), "D": (_f(g * np.cos(ground_angle)), _f(g * np.sin(ground_angle)))}
    dyad = RRR("coupler", "rocker", "crank.A", "ground.D", "B", branch_sign(branch))
    return Mechanism(name, ground_pts, bodies, Crank("crank", "ground.O"), (dyad,), gravity=gravity)


def inverted_slider_crank(
    crank,
    ground,
    *,
    offset=0.0,
    rocker_length=None,
    branch=1,
    masses=None,
    inertias=None,
    linear_density=1.0,
    name="inverted_slider_crank",
    gravity=DOWNWARD_GRAVITY,
) -> Mechanism:
    """Inverted slider-crank (crank-shaper / oscillating-cylinder type): crank O-A [m]; a block pinned at A
    slides along a rocker pivoted at C = (ground, 0) [m]; the slide line is parallel to the rocker's axis at
    ``offset`` [m]. ``rocker_length`` [m] (default crank + ground) sets the rocker's end point E and its bar
    mass properties."""
    check_positive(f"crank length of inverted_slider_crank '{name}'", crank, "m")
    check_positive(f"ground length of inverted_slider_crank '{name}'", ground, "m")
    check_finite(f"offset of inverted_slider_crank '{name}'", offset, "m")
    length = np.asarray(crank) + np.asarray(ground) if rocker_length is None else np.asarray(rocker_length)
    check_positive(f"rocker length of inverted_slider_crank '{name}'", length, "m")
    m, i, _ = (_props(v, 3, f) for v, f in ((masses, "masses"), (inertias, "inertias"), (None, "coms")))
    block_mass = 0.25 * linear_density * np.asarray(crank) if m[1] is None else m[1]
    bodies = (
        _bar("crank", {"O": (0.0, 0.0), "A": (_f(crank), 0.0)}, crank, m[0], i[0], None, linear_density),
        Body("block", {"A": (0.0, 0.0)}, _f(block_mass), 0.0 if i[1] is None else _f(i[1])),
        _bar(
            "rocker",
            {"C": (0.0, 0.0), "E": (_f(length), 0.0), "S": (0.0, _f(offset))},
            length, m[2], i[2], None, linear_density,
        ),
    )
    ground_pts = {"O": (0.0, 0.0), "C": (_f(ground), 0.0)}
    dyad = RPR("block", "rocker", "crank.A", "ground.C", ("S", 0.0), branch_sign(branch))
    return Mechanism(name, ground_pts, bodies, Crank("crank", "ground.O"), (dyad,), gravity=gravity)


def six_bar(
    crank,
    coupler,
    rocker,
    ground,
    coupler_point,
    link5,
    link6,
    pivot6,
    *,
    branch=1,
    branch2=1,
    linear_density=1.0,
    name="six_bar",
    gravity=DOWNWARD_GRAVITY,
) -> Mechanism:
    """Stephenson III six-bar: a four-bar (as :func:`four_bar`) whose coupler point P drives a second RRR dyad,
    link5 P-F [m] and link6 E-F [m], to the ground pivot E = ``pivot6`` (x, y) [m]."""
    base = four_bar(
        crank, coupler, rocker, ground, branch=branch, coupler_point=coupler_point,
        linear_density=linear_density, name=name, gravity=gravity,
    )
    check_positive(f"link5 length of six_bar '{name}'", link5, "m")
    check_positive(f"link6 length of six_bar '{name}'", link6, "m")
    check_finite(f"pivot6 of six_bar '{name}'", pivot6, "m")
    bodies = base.bodies + (
        _bar("link5", {"P": (0.0, 0.0), "F": (_f(link5), 0.0)}, link5, None, None, None, linear_density),
        _bar("link6", {"E": (0.0, 0.0), "F": (_f(link6), 0.0)}, link6, None, None, None, linear_density),
    )
    ground_pts = dict(base.ground, E=tuple(_f(v) for v in pivot6))
    dyads = base.dyads + (RRR("link5", "link6", "coupler.P", "ground.E", "F", branch_sign(branch2, "branch2")),)
    return Mechanism(name, ground_pts, bodies, base.crank, dyads, gravity=gravity)


def double_slider_crank(
    crank_1,
    rod_1,
    crank_2,
    rod_2,
    *,
    offset_1=0.0,
    offset_2=0.0,
    phase=np.pi,
    slide_angle_1=0.0,
    slide_angle_2=0.0,
    branch_1=1,
    branch_2=1,
    masses=None,
    inertias=None,
    linear_density=1.0,
    name="double_slider_crank",
    gravity=DOWNWARD_GRAVITY,
) -> Mechanism:
    """Two slider-cranks on one crank shaft (the paver screed's double tamper, seed 000): pins A1 at radius
    crank_1 [m] and angle 0, A2 at radius crank_2 [m] and angle ``phase`` [rad] on the one crank body; rods
    rod_1, rod_2 [m]; sliders on lines at offsets offset_1, offset_2 [m] from O with directions
    slide_angle_1, slide_angle_2 [rad].

    ``masses``/``inertias`` list (crank, rod_1, slider_1, rod_2, slider_2).
    """
    for field, value in (("crank_1", crank_1), ("rod_1", rod_1), ("crank_2", crank_2), ("rod_2", rod_2)):
        check_positive(f"{field} length of double_slider_crank '{name}'", value, "m")
    for field, value, unit in (("offset_1", offset_1, "m"), ("offset_2", offset_2, "m"), ("phase", phase, "rad"),
                               ("slide_angle_1", slide_angle_1, "rad"), ("slide_angle_2", slide_angle_2, "rad")):
        check_finite(f"{field} of double_slider_crank '{name}'", value, unit)
    m, i = (_props(v, 5, f) for v, f in ((masses, "masses"), (inertias, "inertias")))
    a2 = (_f(np.asarray(crank_2) * np.cos(phase)), _f(np.asarray(crank_2) * np.sin(phase)))
    crank_mass = linear_density * (np.asarray(crank_1) + np.asarray(crank_2)) if m[0] is None else m[0]
    crank_inertia = crank_mass * (np.asarray(crank_1) ** 2 + np.asarray(crank_2) ** 2) / 6.0
    bodies = (
        Body("crank", {"O": (0.0, 0.0), "A1": (_f(crank_1), 0.0), "A2": a2}, _f(crank_mass),
             _f(crank_inertia if i[0] is None else i[0])),
        _bar("rod_1", {"A1": (0.0, 0.0), "B1": (_f(rod_1), 0.0)}, rod_1, m[1], i[1], None, linear_density),
        Body("slider_1", {"B1": (0.0, 0.0)}, _f(linear_density * np.asarray(rod_1) if m[2] is None else m[2]),
             0.0 if i[2] is None else _f(i[2])),
        _bar("rod_2", {"A2": (0.0, 0.0), "B2": (_f(rod_2), 0.0)}, rod_2, m[3], i[3], None, linear_density),
        Body("slider_2", {"B2": (0.0, 0.0)}, _f(linear_density * np.asarray(rod_2) if m[4] is None else m[4]),
             0.0 if i[4] is None else _f(i[4])),
    )

    def line_point(offset, angle):
        return (_f(-np.asarray(offset) * np.sin(angle)), _f(np.asarray(offset) * np.cos(angle)))

    ground = {"O": (0.0, 0.0), "S1": line_point(offset_1, slide_angle_1), "S2": line_point(offset_2, slide_angle_2)}
    dyads = (
        RRP("rod_1", "slider_1", "crank.A1", "B1", Guide("ground.S1", _f(slide_angle_1)), branch_sign(branch_1)),
        RRP("rod_2", "slider_2", "crank.A2", "B2", Guide("ground.S2", _f(slide_angle_2)), branch_sign(branch_2)),
    )
    return Mechanism(name, ground, bodies, Crank("crank", "ground.O"), dyads, gravity=gravity)
