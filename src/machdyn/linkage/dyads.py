"""Closed-form solutions of the class-II dyads (Assur groups): position with an explicit assembly branch,
velocity, acceleration, and the joint reactions of kinetostatics.

Each position solution is the intersection of two loci (circle-circle, circle-line, line through a pivot at
a fixed offset, line-line). Velocities and accelerations follow from differentiating the loop-closure
equation once and twice; each gives a 2x2 linear system solved by Cramer's rule. Reactions follow from the
equilibrium of the dyad's two bodies (3 equations each) with the loads on them known: the Assur-group method
of kinetostatics. Sources: Artobolevsky, *Theory of Mechanisms and Machines*, ch. 4-5 (Assur groups and their
kinetostatics); Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed., ch. 2-4 and 13;
the closed form of seed 003 as corrected in seed-reproduction.md §003.2.

Vector notation: cross(a, b) = a_x b_y - a_y b_x, k x a = (-a_y, a_x). All inputs broadcast (designs x
positions). Each kinematic solver returns the two new body states, an ``assembled`` mask, the determinant
``det`` of its linear system (zero at a dead/toggle position), the transmission angle [rad] and slides.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from . import dyad_forms as forms
from .dyad_forms import ASSEMBLY_TOL
from .state import BodyState, PointState, body_from_point, is_origin

__all__ = ["ASSEMBLY_TOL", "DyadMotion", "prp_forces", "prp_motion", "rpr_forces", "rpr_motion", "rrp_forces",
           "rrp_motion", "rrr_forces", "rrr_motion"]


@dataclass(slots=True)
class DyadMotion:
    a: BodyState
    b: BodyState
    assembled: np.ndarray
    det: np.ndarray
    transmission: object  # callable returning the transmission angle [rad]; computed only when asked for
    slides: dict  # body name -> (s, ds, dds)


def _anchor(pin: PointState, pin_local, other: PointState, other_local):
    """The joint from which to place a body's frame: its pin when that is the frame origin (cheapest)."""
    return (pin, pin_local) if is_origin(pin_local) else (other, other_local)


def _line(local_from, local_to):
    """Length and unit direction (in the body frame) from one local point to another."""
    dx = local_to[0] - local_from[0]
    dy = local_to[1] - local_from[1]
    length = np.hypot(dx, dy)
    return length, dx / length, dy / length


def rrr_motion(P: PointState, Q: PointState, a_pin, a_inner, b_pin, b_inner, branch: int) -> DyadMotion:
    """RRR dyad: link a (pin P to inner joint B), link b (pin Q to B).

    Position: B = P + a u + branch · h n with d = |Q − P|, u = (Q − P)/d, n = k × u,
    a = (La² − Lb² + d²)/(2d), h = √(La² − a²) (circle-circle intersection; seed 003 eqs 2-7 as corrected in
    seed-reproduction.md §003.2). Velocity: ω_a = (w · q)/cross(p, q), ω_b = (w · p)/cross(p, q), p = B − P,
    q = B − Q, w = v_Q − v_P; acceleration the same with w' = a_Q − a_P − ω_b² q + ω_a² p (Uicker, Pennock &
    Shigley, 5th ed., ch. 2-4).

    Parameters
    ----------
    P, Q : PointState
        Motion of the two outer pins [m, m/s, m/s²].
    a_pin, a_inner : tuple of float
        Body-frame coordinates of link a's pin and inner joint [m].
    b_pin, b_inner : tuple of float
        Body-frame coordinates of link b's pin and inner joint [m].
    branch : int
        Assembly branch [-], +1 or −1.

    Returns
    -------
    DyadMotion
        Body states of a and b, the ``assembled`` mask (|La − Lb| ≤ d ≤ La + Lb), the determinant cross(p, q)
        [m²] (zero at the toggle position, the links in line) and the transmission angle.

    Examples
    --------
    A 3-4-5 triangle: links of 0.4 m and 0.3 m on pins 0.5 m apart meet at a right angle.

    >>> from machdyn.linkage.state import PointState
    >>> P, Q = PointState(0.0, 0.0, 0.0, 0.0, 0.0, 0.0), PointState(0.5, 0.0, 0.0, 0.0, 0.0, 0.0)
    >>> m = rrr_motion(P, Q, (0.0, 0.0), (0.4, 0.0), (0.0, 0.0), (0.3, 0.0), 1)
    >>> B = m.a.point(0.4, 0.0)
    >>> round(float(B.x), 12), round(float(B.y), 12), bool(m.assembled)
    (0.32, 0.24, True)
    """
    La, cda, sda = _line(a_pin, a_inner)
    Lb, cdb, sdb = _line(b_pin, b_inner)
    (assembled, _co, bx, by, Bvx, Bvy, Bax, Bay, px, py, qx, qy, om_a, al_a, om_b, al_b, ca, sa, cb, sb, _det,
     det) = forms.rrr_motion(P.x, P.y, P.vx, P.vy, P.ax, P.ay, Q.x, Q.y, Q.vx, Q.vy, Q.ax, Q.ay,
                             La, cda, sda, Lb, cdb, sdb, branch)
    if is_origin(a_pin) and is_origin(b_pin):
        # Both frames hang on their pins (the usual link frames): B's motion is not needed here.
        anchor_a, anchor_b = (P, a_pin), (Q, b_pin)
    else:
        B = PointState(bx, by, Bvx, Bvy, Bax, Bay)
        anchor_a, anchor_b = _anchor(P, a_pin, B, a_inner), _anchor(Q, b_pin, B, b_inner)
    body_a = body_from_point(*anchor_a, np.arctan2(sa, ca), om_a, al_a, ca, sa)
    body_b = body_from_point(*anchor_b, np.arctan2(sb, cb), om_b, al_b, cb, sb)

    def transmission():  # angle between the two links at B, 0..pi
        return np.arccos(np.clip((px * qx + py * qy) / (La * Lb), -1.0, 1.0))

    return DyadMotion(body_a, body_b, assembled, det, transmission, {})

def _guide_frame(S: BodyState, g_local, angle):
    """Global point G, unit direction u of a guide fixed in body S, and the guide's global angle."""
    G = S.point(*g_local)
    ca, sa = np.cos(angle), np.sin(angle)
    ux = S.cos * ca - S.sin * sa
    uy = S.sin * ca + S.cos * sa
    return G, ux, uy, S.angle + angle


def rrp_motion(P: PointState, S: BodyState, g_local, g_angle, a_pin, a_inner, b_inner, branch) -> DyadMotion:
    """RRP dyad: link a (pin P to inner joint B), slider b whose point B moves along a guide line of body S.

    Position: B = G + s u, s = t0 + branch · √(La² − e²), with t0 = (P − G) · u and e = cross(u, P − G) the
    distance of P from the line (circle-line intersection; the exact offset slider-crank of seed 000 eqs 5-7 and
    seed 002 eqs 1-3 is the special case of a ground guide). Velocity: ω_a (k × p) − s' u = v_B|S − v_P with
    p = B − P, solved by dotting with n = k × u and u; acceleration likewise, with the Coriolis term 2 s' ω_S n of
    a moving guide.

    Parameters
    ----------
    P : PointState
        Motion of link a's outer pin [m, m/s, m/s²].
    S : BodyState
        Motion of the body carrying the guide.
    g_local : tuple of float
        A point of the guide in S's frame [m].
    g_angle : float
        Guide direction in S's frame [rad].
    a_pin, a_inner : tuple of float
        Body-frame coordinates of link a's pin and inner joint [m].
    b_inner : tuple of float
        Body-frame coordinates of the slider's joint B [m].
    branch : int
        Assembly branch [-], +1 or −1.

    Returns
    -------
    DyadMotion
        Body states, ``assembled`` mask (La ≥ |e|), determinant p · u [m] (zero at the dead position, the link
        perpendicular to the guide), transmission angle and ``slides`` {slider: (s [m], s' [m/s], s'' [m/s²])}.

    Examples
    --------
    A 0.3 m link from a pin 0.1 m above a horizontal ground guide through the origin, the pin moving at
    (−1, 0) m/s: s = √(0.3² − 0.1²).

    >>> from machdyn.linkage.state import BodyState, PointState
    >>> ground = BodyState(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0)
    >>> P = PointState(0.0, 0.1, -1.0, 0.0, 0.0, -10.0)
    >>> m = rrp_motion(P, ground, (0.0, 0.0), 0.0, (0.0, 0.0), (0.3, 0.0), (0.0, 0.0), 1)
    >>> [round(float(v), 6) for v in m.slides["b"]]
    [0.282843, -1.0, 3.535534]
    """
    La, cda, sda = _line(a_pin, a_inner)
    G, ux, uy, g_ang = _guide_frame(S, g_local, g_angle)
    (assembled, s, bx, by, Bvx, Bvy, Bax, Bay, om_a, al_a, ca, sa, ds, dds, det, normalised) = forms.rrp_motion(
        P.x, P.y, P.vx, P.vy, P.ax, P.ay, G.x, G.y, G.vx, G.vy, G.ax, G.ay, S.omega, S.alpha, ux, uy, La, cda, sda,
        branch)
    B = PointState(bx, by, Bvx, Bvy, Bax, Bay)
    anchor, anchor_local = _anchor(P, a_pin, B, a_inner)
    body_a = body_from_point(anchor, anchor_local, np.arctan2(sa, ca), om_a, al_a, ca, sa)
    body_b = body_from_point(B, b_inner, g_ang, S.omega, S.alpha, ux, uy)

    def transmission():
        return np.arcsin(np.clip(np.abs(det) / La, 0.0, 1.0))

    return DyadMotion(body_a, body_b, assembled, normalised, transmission, {"b": (s, ds, dds)})

def rpr_motion(P: PointState, Q: PointState, a_pin, b_pin, slide_local, slide_angle, branch) -> DyadMotion:
    """RPR dyad: block a pinned at P slides along a line of rocker b, which is pinned at Q.

    The line passes at the signed offset e = cross(u_b, c − q) from the rocker's pin (c: the slide point,
    q: the pin, u_b: slide direction, all in b's frame). Position: ψ = atan2(P − Q) − asin(e/D) for branch +1
    (π − asin(e/D) for −1), D = |P − Q|, θ_b = ψ − slide_angle; block travel t = u · (P − Q − R(θ_b)(c − q)).
    Velocity: ω_b (k × d) + t' u = v_P − v_Q (d = P − Q); acceleration with the Coriolis term 2 ω_b t' n
    (inverted slider-crank: Uicker, Pennock & Shigley, 5th ed., §3.6).

    Parameters
    ----------
    P, Q : PointState
        Motion of the block's pin and of the rocker's pin [m, m/s, m/s²].
    a_pin : tuple of float
        Block's pin in its frame [m].
    b_pin : tuple of float
        Rocker's pin in its frame [m].
    slide_local : tuple of float
        A point of the slide line in the rocker's frame [m].
    slide_angle : float
        Slide direction in the rocker's frame [rad].
    branch : int
        Assembly branch [-], +1 or −1.

    Returns
    -------
    DyadMotion
        Body states, ``assembled`` mask (D ≥ |e|), determinant d · u [m] (zero at the dead position),
        transmission angle and ``slides`` {block: (t [m], t' [m/s], t'' [m/s²])}.

    Examples
    --------
    >>> from machdyn.linkage.state import PointState
    >>> P, Q = PointState(0.0, 0.2, 0.0, 0.0, 0.0, 0.0), PointState(0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    >>> m = rpr_motion(P, Q, (0.0, 0.0), (0.0, 0.0), (0.0, 0.0), 0.0, 1)
    >>> round(float(m.b.angle), 6), [round(float(v), 6) for v in m.slides["a"]]
    (1.570796, [0.2, 0.0, 0.0])
    """
    cx = slide_local[0] - b_pin[0]
    cy = slide_local[1] - b_pin[1]
    e = np.cos(slide_angle) * cy - np.sin(slide_angle) * cx
    (assembled, _co, psi, ux, uy, theta_b, c_b, s_b, t, om, al, dt, ddt, det, D, normalised) = forms.rpr_motion(
        P.x, P.y, P.vx, P.vy, P.ax, P.ay, Q.x, Q.y, Q.vx, Q.vy, Q.ax, Q.ay, cx, cy, e, slide_angle, branch)
    rocker = body_from_point(Q, b_pin, theta_b, om, al, c_b, s_b)
    block = body_from_point(P, a_pin, psi, om, al, ux, uy)

    def transmission():
        return np.arcsin(np.clip(np.abs(det) / D, 0.0, 1.0))

    return DyadMotion(block, rocker, assembled, normalised, transmission, {"a": (t, dt, ddt)})

def prp_motion(Si: BodyState, g1_local, g1_angle, Sj: BodyState, g2_local, g2_angle, a_inner, b_inner) -> DyadMotion:
    """PRP dyad: slider a on a guide of body Si, slider b on a guide of body Sj, pinned together at B.

    Position: B = G1 + s1 u1 = G2 + s2 u2 with s1 = cross(G2 − G1, u2)/cross(u1, u2),
    s2 = cross(G2 − G1, u1)/cross(u1, u2) (line-line intersection). Velocity and acceleration from the same
    2×2 system with the guides' own motion and Coriolis terms.

    Parameters
    ----------
    Si, Sj : BodyState
        Motion of the bodies carrying the two guides.
    g1_local, g2_local : tuple of float
        A point of each guide in its body's frame [m].
    g1_angle, g2_angle : float
        Guide directions in their bodies' frames [rad].
    a_inner, b_inner : tuple of float
        The joint B in the frames of slider a and slider b [m].

    Returns
    -------
    DyadMotion
        Body states, ``assembled`` mask, determinant cross(u1, u2) [-] (zero for parallel guides), transmission
        angle and ``slides`` {slider: (s [m], s' [m/s], s'' [m/s²])}.

    Examples
    --------
    A horizontal guide at y = 0.1 m and a vertical one at x = 0.3 m, both fixed:

    >>> import numpy as np
    >>> from machdyn.linkage.state import BodyState
    >>> ground = BodyState(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0)
    >>> m = prp_motion(ground, (0.0, 0.1), 0.0, ground, (0.3, 0.0), np.pi / 2, (0.0, 0.0), (0.0, 0.0))
    >>> round(float(m.a.x), 6), round(float(m.a.y), 6)
    (0.3, 0.1)
    """
    G1, u1x, u1y, ang1 = _guide_frame(Si, g1_local, g1_angle)
    G2, u2x, u2y, ang2 = _guide_frame(Sj, g2_local, g2_angle)
    (assembled, cr, s1, s2, bx, by, Bvx, Bvy, Bax, Bay, ds1, ds2, dds1, dds2) = forms.prp_motion(
        G1.x, G1.y, G1.vx, G1.vy, G1.ax, G1.ay, Si.omega, Si.alpha, u1x, u1y,
        G2.x, G2.y, G2.vx, G2.vy, G2.ax, G2.ay, Sj.omega, Sj.alpha, u2x, u2y)
    B = PointState(bx, by, Bvx, Bvy, Bax, Bay)
    body_a = body_from_point(B, a_inner, ang1, Si.omega, Si.alpha, u1x, u1y)
    body_b = body_from_point(B, b_inner, ang2, Sj.omega, Sj.alpha, u2x, u2y)

    def transmission():
        return np.arcsin(np.clip(np.abs(cr), 0.0, 1.0))

    return DyadMotion(body_a, body_b, assembled, cr, transmission, {"a": (s1, ds1, dds1), "b": (s2, ds2, dds2)})

# ------------------------------------------------------------------------------------------ kinetostatics
# Loads on a body are (Fx, Fy, M) with M about the global origin. The moment about a point X is
# M - cross(X, F). Each solver returns the reactions ON the dyad's bodies.


def _load(load) -> tuple[Any, Any, Any]:
    """(Fx, Fy, M) of a load resultant, as the forms take it."""
    fx, fy, m = load
    return fx, fy, m


def rrr_forces(load_a, load_b, P, Q, B):
    """RRR reactions: F_P on a at its pin, F_Q on b at its pin, F_ab on b from a at B.

    Moments about B: cross(p, F_P) = −M_a^B, cross(q, F_Q) = −M_b^B with p = P − B, q = Q − B, and
    F_P + F_Q = −(F_a + F_b); solved by Cramer's rule (Artobolevsky, *Theory of Mechanisms and Machines*, ch. 5,
    the RRR group).

    Parameters
    ----------
    load_a, load_b : tuple
        Resultant (Fx [N], Fy [N], M [N m] about the global origin) of the known loads on each link.
    P, Q, B : PointState
        Positions of the two pins and of the inner joint [m].

    Returns
    -------
    tuple
        (F_P, F_Q, F_ab), each (Fx, Fy) [N]. Valid away from the toggle position (cross(p, q) = 0).

    Examples
    --------
    >>> from machdyn.linkage.state import PointState
    >>> def at(x, y):
    ...     return PointState(x, y, 0.0, 0.0, 0.0, 0.0)
    >>> reactions = rrr_forces((0.0, -10.0, 0.0), (0.0, -20.0, 0.0), at(0.0, 0.0), at(0.5, 0.0), at(0.32, 0.24))
    >>> [tuple(round(float(f), 6) + 0.0 for f in force) for force in reactions]
    [(26.666667, 30.0), (-26.666667, 0.0), (26.666667, 20.0)]
    """
    fpx, fpy, fqx, fqy = forms.rrr_forces(*_load(load_a), *_load(load_b), P.x, P.y, Q.x, Q.y, B.x, B.y)
    return (fpx, fpy), (fqx, fqy), (fpx + load_a[0], fpy + load_a[1])

def rrp_forces(load_a, load_b, P, B, ux, uy):
    """RRP reactions: F_P on link a at its pin, F_ab on the slider from a at B, and the guide's normal force N
    (along n = k × u, at B) and couple C on the slider.

    N = (cross(p, S) + M_a^B)/cross(p, n), p = P − B, S = −(F_a + F_b); C = −M_b^B (Artobolevsky, *Theory of
    Mechanisms and Machines*, ch. 5).

    Parameters
    ----------
    load_a, load_b : tuple
        Resultant (Fx [N], Fy [N], M [N m] about the global origin) of the known loads on link and slider.
    P, B : PointState
        Positions of the link's pin and of the slider joint [m].
    ux, uy : float or array
        Unit guide direction [-].

    Returns
    -------
    tuple
        (F_P [N], F_ab [N], N [N], C [N m]); valid away from the dead position (cross(p, n) = 0).

    Examples
    --------
    >>> from machdyn.linkage.state import PointState
    >>> def at(x, y):
    ...     return PointState(x, y, 0.0, 0.0, 0.0, 0.0)
    >>> f_p, f_ab, normal, couple = rrp_forces((0.0, -10.0, 0.0), (0.0, -20.0, 0.0), at(0.0, 0.1), at(0.3, 0.0),
    ...                                        1.0, 0.0)
    >>> [round(float(f), 6) + 0.0 for f in f_p], round(float(normal), 6), round(float(couple), 6)
    ([0.0, 10.0], 20.0, -6.0)
    """
    fpx, fpy, N, _nx, _ny, couple = forms.rrp_forces(*_load(load_a), *_load(load_b), P.x, P.y, B.x, B.y, ux, uy)
    return (fpx, fpy), (fpx + load_a[0], fpy + load_a[1]), N, couple

def rpr_forces(load_a, load_b, P, Q, ux, uy):
    """RPR reactions: F_P on the block at its pin, F_Q on the rocker at its pin, and the slide's normal force N
    (along n = k × u, acting on the block at P) and couple C on the block.

    C = −M_a^P; N = (M_b^Q + M_a^P)/cross(P − Q, n); F_P = −N n − F_a; F_Q = N n − F_b (equilibrium of the two
    bodies; Artobolevsky, *Theory of Mechanisms and Machines*, ch. 5).

    Parameters
    ----------
    load_a, load_b : tuple
        Resultant (Fx [N], Fy [N], M [N m] about the global origin) of the known loads on block and rocker.
    P, Q : PointState
        Positions of the block's pin and of the rocker's pin [m].
    ux, uy : float or array
        Unit slide direction [-].

    Returns
    -------
    tuple
        (F_P [N], F_Q [N], N [N], C [N m]); valid away from the dead position (cross(P − Q, n) = 0).

    Examples
    --------
    >>> from machdyn.linkage.state import PointState
    >>> def at(x, y):
    ...     return PointState(x, y, 0.0, 0.0, 0.0, 0.0)
    >>> f_p, f_q, normal, couple = rpr_forces((0.0, -10.0, 0.0), (0.0, -20.0, 0.0), at(0.0, 0.2), at(0.0, 0.0),
    ...                                       0.0, 1.0)
    >>> [round(float(f), 6) + 0.0 for f in f_p + f_q], round(float(normal), 6) + 0.0
    ([0.0, 10.0, 0.0, 20.0], 0.0)
    """
    fpx, fpy, fqx, fqy, N, _nx, _ny, couple = forms.rpr_forces(*_load(load_a), *_load(load_b), P.x, P.y, Q.x, Q.y,
                                                               ux, uy)
    return (fpx, fpy), (fqx, fqy), N, couple

def prp_forces(load_a, load_b, B, u1, u2):
    """PRP reactions: guide normal forces N_a (on a along n1), N_b (on b along n2) at B, their couples, and F_ab on
    b from a at B.

    N_a = cross(S, n2)/cross(n1, n2), N_b = cross(n1, S)/cross(n1, n2), S = −(F_a + F_b) (equilibrium of the
    two sliders; Artobolevsky, *Theory of Mechanisms and Machines*, ch. 5).

    Parameters
    ----------
    load_a, load_b : tuple
        Resultant (Fx [N], Fy [N], M [N m] about the global origin) of the known loads on each slider.
    B : PointState
        Position of the joint [m].
    u1, u2 : tuple
        Unit guide directions (ux, uy) [-].

    Returns
    -------
    tuple
        (N_a [N], C_a [N m], N_b [N], C_b [N m], F_ab (Fx, Fy) [N]); valid for non-parallel guides.

    Examples
    --------
    >>> from machdyn.linkage.state import PointState
    >>> B = PointState(0.3, 0.1, 0.0, 0.0, 0.0, 0.0)
    >>> n_a, c_a, n_b, c_b, f_ab = prp_forces((0.0, -10.0, 0.0), (0.0, -20.0, 0.0), B, (1.0, 0.0), (0.0, 1.0))
    >>> [round(float(v), 6) + 0.0 for v in (n_a, c_a, n_b, c_b)]
    [30.0, -3.0, 0.0, -6.0]
    """
    Na, ca, Nb, cb, n1x, n1y, _n2x, _n2y = forms.prp_forces(*_load(load_a), *_load(load_b), B.x, B.y,
                                                            u1[0], u1[1], u2[0], u2[1])
    return Na, ca, Nb, cb, (Na * n1x + load_a[0], Na * n1y + load_a[1])
