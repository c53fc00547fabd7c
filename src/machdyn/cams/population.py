"""A population of translating roller (or knife-edge) cams analysed at once: NumPy arrays over designs x cam
angles, no loop over designs.

The designs share the shape of one motion program and differ in base radius R_b, roller radius r_r, offset e and
lift scale (each an array of N values, or one value for all): s = lift_scale * s_0(theta). With d = sqrt(R_p^2 - e^2),
R_p = R_b + r_r, the closed forms of :mod:`machdyn.cams.profile` become, per design and angle,

  tan phi = (v - e)/(d + s)          (Norton, *Design of Machinery*, 5th ed., eq 8.31)
  rho = -|G1|^3 / (G1 x G2)          (the radius of curvature of the pitch curve, positive where convex)

with G1 = (d + s, v - e), G2 = (2 v - e, a - d - s) (:mod:`machdyn.cams.profile`), and the smallest base circle
meeting a pressure-angle limit R_b = sqrt(d_min^2 + e^2) - r_r, d_min = max(|v - e|/tan phi_max - s) (direct, as
in :mod:`machdyn.cams.checks`). Valid where every design assembles (|e| < R_p).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .program import Program


@dataclass(frozen=True)
class PopulationCams:
    """Per design (N): largest |pressure angle| [rad], smallest convex radius of curvature of the pitch curve
    [m] (inf if none), the smallest base radius meeting the limit [m]; and the (N, K) pressure angles [rad]."""

    max_pressure_angle: np.ndarray
    min_pitch_curvature_radius: np.ndarray
    min_base_radius_pressure: np.ndarray
    pressure_angle: np.ndarray


def analyse_population(prog: Program, theta, base_radius, roller_radius=0.0, offset=0.0, lift_scale=1.0,
                       pressure_limit: float = np.radians(30.0)) -> PopulationCams:
    """Pressure angle, radius of curvature and smallest base circle of N translating cams (module docstring)."""
    th = np.asarray(theta, dtype=float)
    rb, rr, e, k = (np.atleast_1d(np.asarray(x, dtype=float))[:, None] for x in
                    (base_radius, roller_radius, offset, lift_scale))
    rp = rb + rr
    if np.any(~np.isfinite(rp)) or np.any(rb <= 0) or np.any(rr < 0) or np.any(k <= 0):
        raise InputError("Every design needs a finite base radius > 0, roller radius >= 0 and lift scale > 0.")
    if np.any(np.abs(e) >= rp):
        bad = int(np.argmax(np.abs(e) >= rp))
        raise InputError(f"Design {bad} does not assemble: its offset {float(np.ravel(e)[min(bad, e.size - 1)]):g} m "
                         f"is not smaller than its prime radius {float(np.ravel(rp)[min(bad, rp.size - 1)]):g} m.")
    m = prog.svaj(th)
    s, v, a = k * m.s, k * m.v, k * m.a
    d = np.sqrt(rp**2 - e**2)
    g1x, g1y = d + s, v - e
    g2x, g2y = 2.0 * v - e, a - d - s
    cross = g1x * g2y - g1y * g2x
    speed3 = np.hypot(g1x, g1y) ** 3
    with np.errstate(divide="ignore"):
        rho = np.where(cross != 0.0, -speed3 / np.where(cross != 0.0, cross, 1.0), np.inf)
    phi = np.arctan2(g1y, g1x)
    dmin = np.maximum(np.max(np.abs(v - e) / np.tan(pressure_limit) - s, axis=1), 0.0)
    n = np.broadcast_shapes(rb.shape, rr.shape, e.shape, k.shape)[0]
    dmin = np.broadcast_to(dmin, (n,))
    rbmin = np.maximum(np.hypot(dmin, np.broadcast_to(np.ravel(e), (n,))) - np.broadcast_to(np.ravel(rr), (n,)),
                       0.0)
    convex = np.where(rho > 0, rho, np.inf)
    return PopulationCams(np.max(np.abs(phi), axis=1), np.min(convex, axis=1), rbmin, phi)
