"""The cam's profile by exact closed forms: pitch curve, cam surface, cutter path, pressure angle and radius of
curvature at every cam angle.

Kinematic inversion (Norton, *Design of Machinery*, 5th ed., §8.6; Uicker, Pennock & Shigley, *Theory of Machines
and Mechanisms*, 4th ed., §6.6-6.8): the cam is held still and the frame turns about it by -theta. A point F of
the fixed frame is at P = R(-theta) F on the cam, hence with J the rotation by +90 deg:

  dP/dtheta = R(-theta) (F' - J F),   d2P/dtheta2 = R(-theta) (F'' - 2 J F' - F).

With G1 = F' - J F and G2 = F'' - 2 J F' - F, the pitch curve's tangent is along G1, its radius of curvature is
rho = -|G1|^3 / (G1 x G2) (positive where the cam is convex), and the pressure angle phi, between the normal to the
pitch curve and the direction u of the follower's path, is tan phi = (G1 . u)/((J G1) . u). For a translating
roller follower this is Norton's eq 8.31, tan phi = (v - e)/(s + sqrt(R_p^2 - e^2)); for a radial one the radius
of curvature is the polar form rho = (r^2 + v^2)^{3/2}/(r^2 + 2 v^2 - r a), r = R_p + s (Norton eq 8.33).

The cam surface of a roller follower lies r_r inside the pitch curve along its normal; its radius of curvature
is rho - r_r (Norton §8.6: undercutting where the convex rho < r_r). A cutter or grinder of radius R_c follows the
pitch curve offset by R_c - r_r.

A translating flat-faced follower (face perpendicular to its path) touches the cam at the distance v = ds/dtheta
from the path through the cam centre; the cam point in the follower's frame is (v, R_b + s) and the radius of
curvature of the cam is rho = R_b + s + a (Uicker, Pennock & Shigley eqs 6.26-6.28; Norton eqs 8.37-8.38); the
pressure angle is 0. A clockwise cam is the mirror image of the counter-clockwise one about the y axis.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .followers import Follower, follower_path
from .program import SVAJ, Program


@dataclass(frozen=True)
class Profile:
    """The profile at cam angles theta [rad] (coordinates in the cam's frame, x/y arrays [m]).

    pitch : the roller centre's path (the cam surface itself for a knife edge; for a flat face the contact point).
    surface : the cam surface.
    cutter : the centre of a cutter of radius ``cutter_radius`` [m] machining the surface.
    pressure_angle : phi [rad] (signed), 0 for a flat face.
    pitch_curvature_radius : rho of the pitch curve [m] (positive convex, negative concave; inf where straight).
    surface_curvature_radius : rho of the cam surface [m].
    contact_offset : a flat face's contact point from the path through the cam centre [m] (v), else zero.
    """

    svaj: SVAJ
    follower: Follower
    pitch: np.ndarray
    surface: np.ndarray
    cutter: np.ndarray
    cutter_radius: float
    pressure_angle: np.ndarray
    pitch_curvature_radius: np.ndarray
    surface_curvature_radius: np.ndarray
    contact_offset: np.ndarray
    normal: np.ndarray  # outward unit normal of the surface in the cam frame (2, K)


def _rot(theta: np.ndarray, vec: np.ndarray) -> np.ndarray:
    """R(-theta) applied to vectors (2, K)."""
    c, s = np.cos(theta), np.sin(theta)
    return np.array([c * vec[0] + s * vec[1], -s * vec[0] + c * vec[1]])


def _j(vec: np.ndarray) -> np.ndarray:
    return np.array([-vec[1], vec[0]])


def cam_angles(positions: int) -> np.ndarray:
    """``positions`` cam angles evenly over one turn, 0 included, 360 deg excluded [rad]."""
    if int(positions) != positions or positions < 8:
        raise InputError(f"cam.positions must be an integer >= 8; got {positions!r}.")
    return np.arange(int(positions)) * (2.0 * np.pi / int(positions))


def profile(prog: Program, follower: Follower, theta, *, cutter_radius: float | None = None,
            clockwise: bool = False) -> Profile:
    """Pitch curve, cam surface, cutter path, pressure angle and radii of curvature at cam angles theta [rad].

    cutter_radius : R_c [m] of the cutter or grinder (default: the roller's radius, or 0 for a knife edge or flat
        face, when the cutter path is the pitch curve).
    clockwise : the cam turns clockwise (the profile is mirrored; the angles and values are unchanged).
    """
    th = np.asarray(theta, dtype=float)
    m = prog.svaj(th)
    rc = follower.roller_radius if cutter_radius is None else float(cutter_radius)
    if not np.isfinite(rc) or rc < 0:
        raise InputError(f"cam.output.cutter_radius must be >= 0 m; got {rc:g} m.")
    if follower.contact == "flat":
        p = follower.base_radius + m.s
        local = np.array([m.v, p])
        surface = _rot(th, local)
        normal = _rot(th, np.array([np.zeros_like(th), np.ones_like(th)]))
        rho = p + m.a
        out = Profile(m, follower, surface, surface, surface + rc * normal, rc, np.zeros_like(th), rho, rho,
                      m.v.copy(), normal)
    else:
        path = follower_path(follower, m.s, m.v, m.a)
        g1 = path.f1 - _j(path.f)
        g2 = path.f2 - 2.0 * _j(path.f1) - path.f
        speed = np.hypot(g1[0], g1[1])
        cross = g1[0] * g2[1] - g1[1] * g2[0]
        with np.errstate(divide="ignore"):
            rho = np.where(cross != 0.0, -(speed**3) / np.where(cross != 0.0, cross, 1.0), np.inf)
        jg = _j(g1)
        phi = np.arctan2(np.sum(g1 * path.u, axis=0), np.sum(jg * path.u, axis=0))
        # outward normal of the pitch curve: the cam turns counter-clockwise, so the pitch point runs clockwise
        # round the cam and the outward normal is +J t
        normal = _rot(th, jg / speed)
        pitch = _rot(th, path.f)
        r = follower.roller_radius
        out = Profile(m, follower, pitch, pitch - r * normal, pitch + (rc - r) * normal, rc, phi, rho, rho - r,
                      np.zeros_like(th), normal)
    if clockwise:
        flip = np.array([[-1.0], [1.0]])
        out = Profile(out.svaj, out.follower, out.pitch * flip, out.surface * flip, out.cutter * flip, rc,
                      out.pressure_angle, out.pitch_curvature_radius, out.surface_curvature_radius,
                      out.contact_offset, out.normal * flip)
    return out
