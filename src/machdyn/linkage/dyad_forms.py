"""The closed forms of the class-II dyads (Assur groups), written once for both engines.

Each function below is the whole solution of one dyad at one crank position — position with an explicit assembly
branch, velocity, acceleration (:func:`rrr_motion` ...), or the joint reactions of kinetostatics
(:func:`rrr_forces` ...) — in plain arithmetic on its arguments. The NumPy engine (:mod:`.dyads`) calls them with
arrays (designs x positions broadcast); the fused engine (:mod:`.fused`) compiles the very same code with numba
for scalars (:func:`scalar_forms`) and calls it from its generated kernel. The few operations that differ
between arrays and scalars are the helpers of the module's globals (NumPy) and :data:`SCALAR_OPS`
(``math``): a square root that is NaN where the dyad does not assemble, a choice by a
condition, an arcsine clipped to [-1, 1]. A new dyad type is one motion form and one force form here.

Sources: the position of each dyad is the intersection of two loci (circle-circle, circle-line, line through a
pivot at a fixed offset, line-line); velocities and accelerations follow from differentiating the loop-closure
equation once and twice, each a 2x2 linear system solved by Cramer's rule; reactions from the equilibrium of the
dyad's two bodies with the loads on them known (Artobolevsky, *Theory of Mechanisms and Machines*, ch. 4-5;
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed., ch. 2-4 and 13; the closed form of seed
003 as corrected in seed-reproduction.md §003.2). Vector notation: cross(a, b) = a_x b_y - a_y b_x,
k x a = (-a_y, a_x). Units: lengths [m], velocities [m/s], accelerations [m/s²], angular rates [rad/s, rad/s²],
forces [N], moments [N*m] about the global origin.
"""

from __future__ import annotations

import hashlib
import math
import types
from functools import cache
from pathlib import Path
from typing import Any

import numpy as np

#: Relative tolerance on the squared closure distance below which a position counts as just assembled (a toggle
#: position computed in floating point may come out as -1e-16 * L^2).
ASSEMBLY_TOL = 1e-12
#: |cross(u1, u2)| of two guides below which a PRP dyad counts as having parallel guides (no intersection).
PARALLEL_TOL = 1e-12


# ------------------------------------------------------------------------------------------ the two op sets

def _root_array(square, assembled):
    """sqrt of a closure discriminant: rounding below zero at a toggle is clipped, NaN where not assembled."""
    root = np.sqrt(np.maximum(square, 0.0))
    return root if np.all(assembled) else np.where(assembled, root, np.nan)


def _pick_array(condition, yes, no):
    """``yes`` where ``condition`` holds, else ``no`` (the common all-false case without a copy)."""
    if np.ndim(condition) and np.shape(no) == np.shape(condition) and not np.any(condition):
        return no
    return np.where(condition, yes, no)


def _asin_array(ratio, assembled):
    """arcsin of a ratio clipped to [-1, 1] (rounding at a toggle), NaN where not assembled."""
    return np.arcsin(np.clip(np.where(assembled, ratio, np.nan), -1.0, 1.0))


def _root_scalar(square, assembled):
    return math.sqrt(max(square, 0.0)) if assembled else math.nan


def _pick_scalar(condition, yes, no):
    return yes if condition else no


def _asin_scalar(ratio, assembled):
    return math.asin(min(max(ratio, -1.0), 1.0)) if assembled else math.nan


# The forms read these as globals: the NumPy ones here; scalar_forms() gives the same code the scalar ones.
root = _root_array
pick = _pick_array
asin_clipped = _asin_array
sqrt = np.sqrt
hypot = np.hypot
cos = np.cos
sin = np.sin
atan2 = np.arctan2
absolute = np.abs
nan = np.nan
pi = np.pi

#: The operations the forms use that differ between arrays and scalars, by name: for scalars.
SCALAR_OPS: dict[str, Any] = {"root": _root_scalar, "pick": _pick_scalar, "asin_clipped": _asin_scalar,
                              "sqrt": math.sqrt, "hypot": math.hypot, "cos": math.cos, "sin": math.sin,
                              "atan2": math.atan2, "absolute": abs, "nan": math.nan, "pi": math.pi}


def moment_about(m, fx, fy, x, y):
    """The moment [N*m] about the point (x, y) [m] of a load (fx, fy) [N] with moment m [N*m] about the global
    origin: M - cross(X, F)."""
    return m - (x * fy - y * fx)


# ------------------------------------------------------------------------------------------------- motion

def rrr_motion(Px, Py, Pvx, Pvy, Pax, Pay, Qx, Qy, Qvx, Qvy, Qax, Qay, La, cda, sda, Lb, cdb, sdb, branch):
    """RRR dyad: link a (length La, pin P to inner joint B), link b (length Lb, pin Q to B).

    Position: B = P + a u + branch · h n with d = |Q − P|, u = (Q − P)/d, n = k × u,
    a = (La² − Lb² + d²)/(2d), h = √(La² − a²) (circle-circle intersection; seed 003 eqs 2-7 as corrected in
    seed-reproduction.md §003.2). Velocity: ω_a = (w · q)/cross(p, q), ω_b = (w · p)/cross(p, q), p = B − P,
    q = B − Q, w = v_Q − v_P; acceleration the same with w' = a_Q − a_P − ω_b² q + ω_a² p (Uicker, Pennock &
    Shigley, 5th ed., ch. 2-4). (cda, sda), (cdb, sdb): the direction of each link's segment in its own frame.

    Returns (assembled, coincident pins, B (x, y, vx, vy, ax, ay), p, q, ω_a, α_a, ω_b, α_b, cos/sin of each
    body's angle, cross(p, q) [m²], cross(p, q)/(La Lb) [-]). Valid for |La − Lb| ≤ d ≤ La + Lb; NaN outside;
    the determinant is zero at the toggle position (the links in line).
    """
    dx = Qx - Px
    dy = Qy - Py
    d2 = dx * dx + dy * dy
    d = sqrt(d2)
    along = (La * La - Lb * Lb + d2) / (2.0 * d)
    h2 = La * La - along * along
    coincident = d == 0.0  # coincident pins leave the dyad free to turn: reported as a singular position
    assembled = (h2 >= -ASSEMBLY_TOL * La * La) | coincident
    h = root(h2, assembled)
    ux = dx / d
    uy = dy / d
    bx = Px + along * ux - branch * h * uy
    by = Py + along * uy + branch * h * ux
    px = bx - Px
    py = by - Py
    qx = bx - Qx
    qy = by - Qy
    det = px * qy - py * qx
    inv = 1.0 / det
    wx = Qvx - Pvx
    wy = Qvy - Pvy
    oa = (wx * qx + wy * qy) * inv
    ob = (wx * px + wy * py) * inv
    w2a = oa * oa
    w2b = ob * ob
    wax = Qax - Pax - w2b * qx + w2a * px
    way = Qay - Pay - w2b * qy + w2a * py
    aa = (wax * qx + way * qy) * inv
    ab = (wax * px + way * py) * inv
    ca = (px * cda + py * sda) / La
    sa = (py * cda - px * sda) / La
    cb = (qx * cdb + qy * sdb) / Lb
    sb = (qy * cdb - qx * sdb) / Lb
    Bvx = Pvx - oa * py
    Bvy = Pvy + oa * px
    Bax = Pax - aa * py - w2a * px
    Bay = Pay + aa * px - w2a * py
    normalised = pick(coincident, 0.0, det / (La * Lb))
    return (assembled, coincident, bx, by, Bvx, Bvy, Bax, Bay, px, py, qx, qy, oa, aa, ob, ab, ca, sa, cb, sb,
            det, normalised)


def rrp_motion(Px, Py, Pvx, Pvy, Pax, Pay, Gx, Gy, Gvx, Gvy, Gax, Gay, Sw, Sal, ux, uy, La, cda, sda, branch):
    """RRP dyad: link a (length La, pin P to inner joint B), slider b whose point B moves along a guide line
    through G with unit direction u, fixed in a body S turning at ω_S, α_S.

    Position: B = G + s u, s = t0 + branch · √(La² − e²), with t0 = (P − G) · u and e = cross(u, P − G) the
    distance of P from the line (circle-line intersection; the exact offset slider-crank of seed 000 eqs 5-7 and
    seed 002 eqs 1-3 is the special case of a ground guide). Velocity: ω_a (k × p) − s' u = v_B|S − v_P with
    p = B − P, solved by dotting with n = k × u and u; acceleration likewise, with the Coriolis term 2 s' ω_S n of
    a moving guide.

    Returns (assembled, s, B (x, y, vx, vy, ax, ay), ω_a, α_a, cos/sin of link a's angle, s' [m/s], s'' [m/s²],
    p · u [m], p · u / La [-]). Valid for La ≥ |e|; the determinant is zero at the dead position (the link
    perpendicular to the guide).
    """
    rx = Px - Gx
    ry = Py - Gy
    t0 = rx * ux + ry * uy
    e = ux * ry - uy * rx
    disc = La * La - e * e
    assembled = disc >= -ASSEMBLY_TOL * La * La
    s = t0 + branch * root(disc, assembled)
    bx = Gx + s * ux
    by = Gy + s * uy
    px = bx - Px
    py = by - Py
    nx = -uy
    ny = ux
    det = px * ux + py * uy
    cross_pu = px * uy - py * ux
    gx = bx - Gx
    gy = by - Gy
    vbx = Gvx - Sw * gy
    vby = Gvy + Sw * gx
    wx = vbx - Pvx
    wy = vby - Pvy
    oa = (wx * nx + wy * ny) / det
    ds = oa * cross_pu - (wx * ux + wy * uy)
    w2s = Sw * Sw
    abx = Gax - Sal * gy - w2s * gx + 2.0 * ds * Sw * nx
    aby = Gay + Sal * gx - w2s * gy + 2.0 * ds * Sw * ny
    wax = abx - Pax + oa * oa * px
    way = aby - Pay + oa * oa * py
    aa = (wax * nx + way * ny) / det
    dds = aa * cross_pu - (wax * ux + way * uy)
    Bvx = Pvx - oa * py
    Bvy = Pvy + oa * px
    Bax = Pax - aa * py - oa * oa * px
    Bay = Pay + aa * px - oa * oa * py
    ca = (px * cda + py * sda) / La
    sa = (py * cda - px * sda) / La
    return assembled, s, bx, by, Bvx, Bvy, Bax, Bay, oa, aa, ca, sa, ds, dds, det, det / La


def rpr_motion(Px, Py, Pvx, Pvy, Pax, Pay, Qx, Qy, Qvx, Qvy, Qax, Qay, cx, cy, e, slide_angle, branch):
    """RPR dyad: block a pinned at P slides along a line of rocker b, which is pinned at Q.

    The line passes at the signed offset e = cross(u_b, c − q) from the rocker's pin ((cx, cy) = c − q, the
    slide point from the pin, and ``slide_angle`` the slide's direction, both in b's frame). Position:
    ψ = atan2(P − Q) − asin(e/D) for branch +1 (π − asin(e/D) for −1), D = |P − Q|, θ_b = ψ − slide_angle;
    block travel t = u · (P − Q − R(θ_b)(c − q)). Velocity: ω_b (k × d) + t' u = v_P − v_Q (d = P − Q);
    acceleration with the Coriolis term 2 ω_b t' n (inverted slider-crank: Uicker, Pennock & Shigley, 5th ed.,
    §3.6).

    Returns (assembled, coincident pins, ψ, cos ψ, sin ψ, θ_b, cos θ_b, sin θ_b, t, ω, α, t', t'', d · u [m],
    D [m], d · u / D [-]). Valid for D ≥ |e|; the determinant is zero at the dead position.
    """
    dx = Px - Qx
    dy = Py - Qy
    D = hypot(dx, dy)
    ratio = e / D
    coincident = D == 0.0  # the block's pin on the rocker's pivot leaves the rocker free to turn: singular
    assembled = (absolute(ratio) <= 1.0 + ASSEMBLY_TOL) | coincident
    shift = asin_clipped(ratio, assembled)
    at = atan2(dy, dx)
    psi = at - shift if branch == 1 else at - (pi - shift)
    ux = cos(psi)
    uy = sin(psi)
    tb = psi - slide_angle
    cb = cos(tb)
    sb = sin(tb)
    rcx = cb * cx - sb * cy
    rcy = sb * cx + cb * cy
    t = ux * (dx - rcx) + uy * (dy - rcy)
    nx = -uy
    ny = ux
    det = dx * ux + dy * uy
    cross_du = dx * uy - dy * ux
    wx = Pvx - Qvx
    wy = Pvy - Qvy
    om = (wx * nx + wy * ny) / det
    dt = (wx * ux + wy * uy) - om * cross_du
    wax = Pax - Qax + om * om * dx - 2.0 * om * dt * nx
    way = Pay - Qay + om * om * dy - 2.0 * om * dt * ny
    al = (wax * nx + way * ny) / det
    ddt = (wax * ux + way * uy) - al * cross_du
    normalised = pick(coincident, 0.0, det / D)
    return assembled, coincident, psi, ux, uy, tb, cb, sb, t, om, al, dt, ddt, det, D, normalised


def prp_motion(G1x, G1y, G1vx, G1vy, G1ax, G1ay, S1w, S1al, u1x, u1y,
               G2x, G2y, G2vx, G2vy, G2ax, G2ay, S2w, S2al, u2x, u2y):
    """PRP dyad: slider a on a guide through G1 (direction u1) of a body turning at ω_1, α_1, slider b on a guide
    through G2 (direction u2) of a body turning at ω_2, α_2, pinned together at B.

    Position: B = G1 + s1 u1 = G2 + s2 u2 with s1 = cross(G2 − G1, u2)/cross(u1, u2),
    s2 = cross(G2 − G1, u1)/cross(u1, u2) (line-line intersection). Velocity and acceleration from the same
    2×2 system with the guides' own motion and Coriolis terms.

    Returns (assembled, cross(u1, u2) [-] (NaN for parallel guides), s1, s2, B (x, y, vx, vy, ax, ay), s1', s2',
    s1'', s2''). Valid for guides that are not parallel.
    """
    cross0 = u1x * u2y - u1y * u2x
    assembled = absolute(cross0) > PARALLEL_TOL
    cr = pick(assembled, cross0, nan)
    Dx = G2x - G1x
    Dy = G2y - G1y
    s1 = (Dx * u2y - Dy * u2x) / cr
    s2 = (Dx * u1y - Dy * u1x) / cr
    bx = G1x + s1 * u1x
    by = G1y + s1 * u1y
    g1x = bx - G1x
    g1y = by - G1y
    g2x = bx - G2x
    g2y = by - G2y
    vix = G1vx - S1w * g1y
    viy = G1vy + S1w * g1x
    vjx = G2vx - S2w * g2y
    vjy = G2vy + S2w * g2x
    wx = vjx - vix
    wy = vjy - viy
    ds1 = (wx * u2y - wy * u2x) / cr
    ds2 = (wx * u1y - wy * u1x) / cr
    wi2 = S1w * S1w
    wj2 = S2w * S2w
    aix = G1ax - S1al * g1y - wi2 * g1x - 2.0 * ds1 * S1w * u1y
    aiy = G1ay + S1al * g1x - wi2 * g1y + 2.0 * ds1 * S1w * u1x
    ajx = G2ax - S2al * g2y - wj2 * g2x - 2.0 * ds2 * S2w * u2y
    ajy = G2ay + S2al * g2x - wj2 * g2y + 2.0 * ds2 * S2w * u2x
    wax = ajx - aix
    way = ajy - aiy
    dds1 = (wax * u2y - way * u2x) / cr
    dds2 = (wax * u1y - way * u1x) / cr
    Bvx = vix + ds1 * u1x
    Bvy = viy + ds1 * u1y
    Bax = aix + dds1 * u1x
    Bay = aiy + dds1 * u1y
    return assembled, cr, s1, s2, bx, by, Bvx, Bvy, Bax, Bay, ds1, ds2, dds1, dds2


# ------------------------------------------------------------------------------------------ kinetostatics

def rrr_forces(lax, lay, lam, lbx, lby, lbm, Px, Py, Qx, Qy, Bx, By):
    """RRR reactions: F_P on link a at its pin, F_Q on link b at its pin (the force on b from a at B is
    F_P + F_a). Moments about B: cross(p, F_P) = −M_a^B, cross(q, F_Q) = −M_b^B with p = P − B, q = Q − B, and
    F_P + F_Q = −(F_a + F_b); solved by Cramer's rule (Artobolevsky, *Theory of Mechanisms and Machines*, ch. 5,
    the RRR group). (la*, lb*): the resultant (Fx, Fy, M about the origin) of the known loads on each link.

    Returns (F_P x, F_P y, F_Q x, F_Q y) [N]; valid away from the toggle position (cross(p, q) = 0).
    """
    Sx = -(lax + lbx)
    Sy = -(lay + lby)
    px = Px - Bx
    py = Py - By
    qx = Qx - Bx
    qy = Qy - By
    c1 = -moment_about(lam, lax, lay, Bx, By)
    c2 = (qx * Sy - qy * Sx) + moment_about(lbm, lbx, lby, Bx, By)
    det = px * qy - py * qx
    fpx = (c1 * qx - px * c2) / det
    fpy = (qy * c1 - py * c2) / det
    return fpx, fpy, Sx - fpx, Sy - fpy


def rrp_forces(lax, lay, lam, lbx, lby, lbm, Px, Py, Bx, By, ux, uy):
    """RRP reactions: F_P on link a at its pin, and the guide's normal force N (along n = k × u, at B) and couple
    C on the slider (the force on the slider from a at B is F_P + F_a).
    N = (cross(p, S) + M_a^B)/cross(p, n), p = P − B, S = −(F_a + F_b); C = −M_b^B (Artobolevsky, *Theory of
    Mechanisms and Machines*, ch. 5).

    Returns (F_P x, F_P y [N], N [N], n x, n y, C [N*m]); valid away from the dead position (cross(p, n) = 0).
    """
    Sx = -(lax + lbx)
    Sy = -(lay + lby)
    px = Px - Bx
    py = Py - By
    nx = -uy
    ny = ux
    N = ((px * Sy - py * Sx) + moment_about(lam, lax, lay, Bx, By)) / (px * ny - py * nx)
    return Sx - N * nx, Sy - N * ny, N, nx, ny, -moment_about(lbm, lbx, lby, Bx, By)


def rpr_forces(lax, lay, lam, lbx, lby, lbm, Px, Py, Qx, Qy, ux, uy):
    """RPR reactions: F_P on the block at its pin, F_Q on the rocker at its pin, and the slide's normal force N
    (along n = k × u, acting on the block at P) and couple C on the block.
    C = −M_a^P; N = (M_b^Q + M_a^P)/cross(P − Q, n); F_P = −N n − F_a; F_Q = N n − F_b (equilibrium of the two
    bodies; Artobolevsky, *Theory of Mechanisms and Machines*, ch. 5).

    Returns (F_P x, F_P y, F_Q x, F_Q y [N], N [N], n x, n y, C [N*m]); valid away from the dead position.
    """
    nx = -uy
    ny = ux
    ma_p = moment_about(lam, lax, lay, Px, Py)
    mb_q = moment_about(lbm, lbx, lby, Qx, Qy)
    dx = Px - Qx
    dy = Py - Qy
    N = (mb_q + ma_p) / (dx * ny - dy * nx)
    return -N * nx - lax, -N * ny - lay, N * nx - lbx, N * ny - lby, N, nx, ny, -ma_p


def prp_forces(lax, lay, lam, lbx, lby, lbm, Bx, By, u1x, u1y, u2x, u2y):
    """PRP reactions: the guide normal forces N_a (on slider a along n1 = k × u1) and N_b (on b along n2) at B,
    and their couples C_a, C_b (the force on b from a at B is N_a n1 + F_a).
    N_a = cross(S, n2)/cross(n1, n2), N_b = cross(n1, S)/cross(n1, n2), S = −(F_a + F_b) (equilibrium of the
    two sliders; Artobolevsky, *Theory of Mechanisms and Machines*, ch. 5).

    Returns (N_a [N], C_a [N*m], N_b [N], C_b [N*m], n1 x, n1 y, n2 x, n2 y); valid for guides not parallel.
    """
    Sx = -(lax + lbx)
    Sy = -(lay + lby)
    n1x = -u1y
    n1y = u1x
    n2x = -u2y
    n2y = u2x
    cr = n1x * n2y - n1y * n2x
    Na = (Sx * n2y - Sy * n2x) / cr
    Nb = (n1x * Sy - n1y * Sx) / cr
    ca = -moment_about(lam, lax, lay, Bx, By)
    cb = -moment_about(lbm, lbx, lby, Bx, By)
    return Na, ca, Nb, cb, n1x, n1y, n2x, n2y


#: Every form, by name: the fused engine compiles these for scalars.
FORMS = {f.__name__: f for f in (moment_about, rrr_motion, rrp_motion, rpr_motion, prp_motion,
                                 rrr_forces, rrp_forces, rpr_forces, prp_forces)}


@cache
def forms_version() -> str:
    """A hash of this module's text: a compiled kernel that inlined the forms is valid for this text only."""
    return hashlib.sha1(Path(__file__).read_bytes()).hexdigest()[:16]


def scalar_forms() -> types.SimpleNamespace:
    """The forms compiled by numba for scalars: the same code objects with the scalar ops (:data:`SCALAR_OPS`) as
    their globals, each inlined into the kernel that calls it (so the kernel's loop over positions stays one
    straight-line body the compiler can vectorise). numba is imported here only."""
    import numba

    space: dict[str, Any] = {"ASSEMBLY_TOL": ASSEMBLY_TOL, "PARALLEL_TOL": PARALLEL_TOL}
    jit = numba.njit(inline="always", error_model="numpy", nogil=True)
    for name, op in SCALAR_OPS.items():
        space[name] = jit(op) if callable(op) and op.__module__ == __name__ else op
    compiled = {}
    for name, form in FORMS.items():  # moment_about first: the force forms call it
        fn = types.FunctionType(form.__code__, space, name)
        compiled[name] = space[name] = jit(fn)
    return types.SimpleNamespace(**compiled)
