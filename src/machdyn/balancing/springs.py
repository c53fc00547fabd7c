"""Spring compensation: a linear spring between a moving body and the frame that evens out the driving torque.

Generalised from seed 002 (Yuan Rui et al., rotary grading screen): there a spring K = m_C w^2 on the slider
stores the kinetic energy the reciprocating mass gives up, so the total energy, and hence the input torque,
hardly fluctuates (seed 002 eqs 13-20; repro 002.3). For any linkage at constant speed w the spring adds the
torque T_s = dV/dphi = k (l - l0) dl/dphi to the drive, with l(phi) the spring length. T_s is linear in the
unknowns k and k*l0, so for given attachment points the stiffness and free length that minimise the mean
square torque fluctuation come from a linear least-squares problem; the attachment points are then chosen by
a small bounded search (:func:`scipy.optimize.minimize`) around that closed-form inner solution.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..errors import InputError, check_finite
from ..linkage import Mechanism, Spring, kinematics
from .frame import BalanceResult, compare, cycle, frame_loads

__all__ = ["SpringDesign", "spring_torque", "best_stiffness", "spring_compensation", "optimise_spring"]


def spring_torque(stiffness, free_length, length, length_rate):
    """Driving torque [N*m] a linear spring adds at constant crank speed: T_s = k (l - l0) dl/dphi.

    Energy balance of the drive: the power the drive supplies to the spring is dV/dt = k (l - l0) dl/dt, and
    T_s w = dV/dt (seed 002 eq 12, M_in = dW/dalpha).

    Parameters
    ----------
    stiffness : k [N/m], >= 0
    free_length : l0 [m], >= 0
    length : spring length l [m] at each crank angle
    length_rate : dl/dphi [m/rad]

    Examples
    --------
    >>> round(float(spring_torque(1000.0, 0.1, 0.12, 0.05)), 12)
    1.0
    """
    for name, v, unit in (("stiffness", stiffness, "N/m"), ("free length", free_length, "m"),
                          ("spring length", length, "m"), ("length rate", length_rate, "m/rad")):
        check_finite(name, v, unit)
    return stiffness * (np.asarray(length) - free_length) * length_rate


def best_stiffness(torque, length, length_rate, stiffness_bounds=(0.0, np.inf), free_length_bounds=(0.0, np.inf)):
    """Stiffness k [N/m] and free length l0 [m] minimising the mean square of (T + T_s) about its mean.

    Closed form: least squares of T - mean(T) on the centred columns l dl/dphi and -dl/dphi (unknowns k and
    k l0); if that leaves the bounds, l0 is searched in its bounds with k at its clipped closed-form optimum
    (:func:`scipy.optimize.minimize_scalar`).

    Parameters: torque T [N*m], length l [m], length_rate dl/dphi [m/rad] at the same crank angles (a uniform
    cycle); bounds as (low, high). Returns (k, l0, rms fluctuation [N*m] after).

    Examples
    --------
    A torque -k0 (l - 1) l' is cancelled exactly by k = k0, l0 = 1:

    >>> phi = np.linspace(0, 2 * np.pi, 64, endpoint=False)
    >>> l, dl = 1 + 0.1 * np.cos(phi), -0.1 * np.sin(phi)
    >>> k, l0, rms = best_stiffness(-500.0 * (l - 1.0) * dl, l, dl)
    >>> round(k, 6), round(l0, 9)
    (500.0, 1.0)
    """
    t = np.asarray(torque, dtype=float)
    l, dl = np.broadcast_arrays(np.asarray(length, dtype=float), np.asarray(length_rate, dtype=float))
    check_finite("torque", t, "N*m")
    klo, khi = stiffness_bounds
    llo, lhi = free_length_bounds
    if not (0 <= klo <= khi and 0 <= llo <= lhi):
        raise InputError(f"Spring bounds must satisfy 0 <= low <= high; got stiffness {stiffness_bounds} N/m and "
                         f"free length {free_length_bounds} m.")
    target = -(t - t.mean())
    c1, c2 = l * dl - np.mean(l * dl), -(dl - dl.mean())

    def rms(k, l0):
        return float(np.sqrt(np.mean((target - k * c1 - k * l0 * c2) ** 2)))

    y, *_ = np.linalg.lstsq(np.stack([c1, c2], axis=1), target, rcond=None)
    k = float(y[0])
    if k > 0 and klo <= k <= khi and llo <= y[1] / k <= lhi:
        return k, float(y[1] / k), rms(k, float(y[1] / k))

    from scipy.optimize import minimize_scalar

    def k_at(l0):
        col = c1 + l0 * c2
        den = float(col @ col)
        return float(np.clip(col @ target / den if den > 0 else 0.0, klo, khi))

    top = lhi if np.isfinite(lhi) else llo + 10.0 * float(np.max(l))
    res = minimize_scalar(lambda l0: rms(k_at(l0), l0), bounds=(llo, top), method="bounded")
    l0 = float(res.x)
    return k_at(l0), l0, rms(k_at(l0), l0)


@dataclass(frozen=True)
class SpringDesign:
    """A compensating spring: body point (body frame) and ground anchor [m], stiffness [N/m], free length [m],
    and the RMS driving-torque fluctuation [N*m] before and after."""

    body: str
    point: tuple[float, float]
    anchor: tuple[float, float]
    stiffness: float
    free_length: float
    rms_before: float
    rms_after: float


def spring_geometry(kin, body, point, anchor):
    """(length [m], d length / d crank angle [m/rad]) over the cycle of a spring from ``point`` [m, body frame]
    on ``body`` to ``anchor`` [m, frame]; InputError where its length comes to zero."""
    P = kin.local_point(body, tuple(point))
    dx, dy = P.x - anchor[0], P.y - anchor[1]
    length = np.hypot(dx, dy)
    if np.any(length <= 0):
        raise InputError(f"The spring from '{body}' point {tuple(point)} to the ground anchor {tuple(anchor)} m "
                         "passes through zero length; move the anchor.")
    rate = (dx * P.vx + dy * P.vy) / length / np.asarray(kin.speed)
    return np.asarray(length, dtype=float), np.asarray(rate, dtype=float)


def _with_spring(mech, body, point, anchor, k, l0, name):
    b = mech.body(body)
    bodies = tuple(replace(x, points={**x.points, name: (float(point[0]), float(point[1]))}) if x.name == body else x
                   for x in mech.bodies)
    ground = {**mech.ground, f"{name}_anchor": (float(anchor[0]), float(anchor[1]))}
    spring = Spring(name, f"{b.name}.{name}", f"ground.{name}_anchor", float(k), float(l0))
    return replace(mech, bodies=bodies, ground=ground, springs=tuple(mech.springs) + (spring,))


def spring_compensation(mech: Mechanism, body: str, point, anchor, crank_angle=None, speed: float = 1.0, *,
                        stiffness_bounds=(0.0, np.inf), free_length_bounds=(0.0, np.inf),
                        name: str = "compensating_spring") -> tuple[BalanceResult, SpringDesign]:
    """Best stiffness and free length (:func:`best_stiffness`) of a spring from the body-frame ``point`` [m] of
    ``body`` to the ground ``anchor`` [m]; returns the balanced model with the spring and its design."""
    phi = cycle() if crank_angle is None else np.asarray(crank_angle, dtype=float)
    before = frame_loads(mech, phi, speed)
    kin = kinematics(replace(mech, gravity=(0.0, 0.0)), phi, speed, 0.0)
    length, rate = spring_geometry(kin, body, np.asarray(point, dtype=float), np.asarray(anchor, dtype=float))
    k, l0, rms = best_stiffness(before.torque, length, rate, stiffness_bounds, free_length_bounds)
    balanced = _with_spring(mech, body, point, anchor, k, l0, name)
    after = frame_loads(balanced, phi, speed)
    design = SpringDesign(body, (float(point[0]), float(point[1])), (float(anchor[0]), float(anchor[1])), k, l0,
                          float(np.std(before.torque)), float(np.std(after.torque)))
    note = f"spring {name}: k = {k:.6g} N/m, free length {l0:.6g} m"
    return BalanceResult(balanced, before, after, compare(before, after), (balanced.springs[-1],), (note,)), design


def optimise_spring(mech: Mechanism, body: str, point_bounds, anchor_bounds, crank_angle=None, speed: float = 1.0,
                    **bounds) -> tuple[BalanceResult, SpringDesign]:
    """Attachment points too: the body point within ``point_bounds`` = ((x_lo, x_hi), (y_lo, y_hi)) [m] (body
    frame) and the anchor within ``anchor_bounds`` (global) minimising the RMS torque fluctuation, each
    candidate with its closed-form best stiffness and free length; L-BFGS-B from the box centres."""
    from scipy.optimize import minimize

    phi = cycle(120) if crank_angle is None else np.asarray(crank_angle, dtype=float)
    base = frame_loads(mech, phi, speed)
    kin = kinematics(replace(mech, gravity=(0.0, 0.0)), phi, speed, 0.0)
    box = [*point_bounds, *anchor_bounds]
    for lo, hi in box:
        if not hi >= lo:
            raise InputError(f"Attachment bounds must be (low, high) with high >= low; got ({lo}, {hi}) m.")

    def objective(z):
        try:
            length, rate = spring_geometry(kin, body, z[:2], z[2:])
        except InputError:
            return float(np.std(base.torque)) * 10.0
        return best_stiffness(base.torque, length, rate, bounds.get("stiffness_bounds", (0.0, np.inf)),
                              bounds.get("free_length_bounds", (0.0, np.inf)))[2]

    start = np.array([0.5 * (lo + hi) for lo, hi in box])
    res = minimize(objective, start, method="L-BFGS-B", bounds=box)
    result, design = spring_compensation(mech, body, res.x[:2], res.x[2:], phi, speed, **bounds)
    status = "converged" if res.success else f"did not converge ({res.message})"
    return replace(result, notes=result.notes + (f"attachment search {status} after {res.nit} iterations",)), design
