"""Exact kinematics of a linkage over crank angles and design variants: the crank, then each dyad in turn.

``kinematics(mech, phi, speed, acceleration)`` returns positions, velocities and accelerations of every body
and every named point. Arrays of design parameters (N,) and crank angles (M,) broadcast to (N, M).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError, check_finite
from .engines import check_engine, use_fused
from .fused import fused_kinematics
from .model import Mechanism
from .motion import DyadReport, Kinematics, SlideMotion, kinematics_result
from .refs import GROUND, column, full, local_point, split_ref
from .state import BodyState, PointState, body_from_point, ground_state


def kinematics(
    mech: Mechanism,
    crank_angle,
    speed=1.0,
    acceleration=0.0,
    *,
    on_fail: str = "raise",
    engine: str = "numpy",
) -> Kinematics:
    """Positions, velocities and accelerations of every body of ``mech`` at each crank angle.

    Parameters
    ----------
    mech : the linkage (parameters may be arrays of N design variants).
    crank_angle : crank angles phi [rad], scalar or (M,).
    speed : crank angular velocity [rad/s], scalar or broadcastable to phi (a given speed law); for N design
        variants also an (N,) array, one speed per design (when its length differs from phi's).
    acceleration : crank angular acceleration [rad/s^2], shaped like ``speed``.
    on_fail : "raise" raises :class:`AssemblyError` listing the crank-angle ranges where the linkage cannot
        close; "mask" returns NaN there, flagged ``assembled = False``.
    engine : "numpy" (the reference), "fused" (one compiled pass per position, :mod:`machdyn.linkage.fused`;
        1-D crank angles) or "auto" (fused when numba is present and the request is large enough to pay for
        a compilation).

    Closed form per dyad (see :mod:`machdyn.linkage.dyads`), valid at every assembled, non-dead position.
    """
    if on_fail not in ("raise", "mask"):
        raise InputError(f"on_fail must be 'raise' or 'mask'; got {on_fail!r}.")
    phi = np.asarray(crank_angle, dtype=float)
    check_finite("crank angle", phi, "rad")
    check_finite("crank speed", speed, "rad/s")
    check_finite("crank acceleration", acceleration, "rad/s^2")
    omega = np.asarray(speed, dtype=float)
    eps = np.asarray(acceleration, dtype=float)
    check_engine(engine)
    if mech.design_count is not None:
        # A 1-D speed or acceleration that does not match the crank angles is one value per design.
        omega = column(omega) if omega.ndim == 1 and omega.shape != phi.shape else omega
        eps = column(eps) if eps.ndim == 1 and eps.shape != phi.shape else eps
    designs = (mech.design_count, 1) if mech.design_count is not None else ()
    shape = np.broadcast_shapes(designs, np.shape(phi), np.shape(omega), np.shape(eps))
    if engine != "numpy" and use_fused(engine, mech, phi, math.prod(shape)):
        return fused_kinematics(mech, phi, omega, eps, shape, on_fail, reference=kinematics)
    states: dict[str, BodyState] = {GROUND: ground_state()}
    slides: dict[str, SlideMotion] = {}
    reports = []
    # Crank: its frame turns with phi about the pivot.
    crank = mech.body(mech.crank.body)
    _, pivot_name = split_ref(mech.crank.pivot)
    ox, oy = local_point(mech, GROUND, pivot_name)
    cu, cv = local_point(mech, crank.name, pivot_name)
    with np.errstate(all="ignore"):
        # Scalars stay scalars through the solution (cheaper); results are broadcast to full shape at the end.
        pivot = PointState(ox, oy, 0.0, 0.0, 0.0, 0.0)
        states[crank.name] = body_from_point(pivot, (cu, cv), phi, omega, eps, np.cos(phi), np.sin(phi))
        assembled = True
        failing = []
        for d in mech.dyads:
            motion = d.solve_motion(mech, states)
            states[d.a], states[d.b] = motion.a, motion.b
            assembled = assembled & motion.assembled
            failing.append((d, motion.assembled))
            for key, (sv, dsv, ddsv) in motion.slides.items():
                slides[d.a if key == "a" else d.b] = SlideMotion(*(full(v, shape) for v in (sv, dsv, ddsv)))
            reports.append(DyadReport(d.kind, (d.a, d.b), motion.det, motion.transmission))
    states.pop(GROUND)
    return kinematics_result(mech, phi, omega, eps, shape, on_fail, states, slides, reports, failing, assembled)


