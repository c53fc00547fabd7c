"""The exact flywheel of every design of a population, from its sampled energy curve.

The energy-mass (Wittenbauer) sizing of :func:`machdyn.dynamics.flywheel.size_flywheel`, vectorised over
designs and evaluated on the crank angles the population is analysed at instead of a fine interpolated grid:
with the work excess W(phi) of the reduced moment of every load but inertia and the drive, M(phi), plus the
drive's mean torque, and the reduced moment of inertia J(phi) of the linkage, the least flywheel that keeps the
crank speed within omega_min..omega_max = omega_mean (1 -+ delta/2) is

    J_f = max(0, [max(J omega_min^2/2 - W) - min(J omega_max^2/2 - W)] / (delta omega_mean^2))

(the two tangents of slopes omega_max^2/2 and omega_min^2/2 to Wittenbauer's energy-mass diagram; seed 003,
text after eq 19; Artobolevsky, *Theory of Mechanisms and Machines*, the Wittenbauer method; derivation in
:mod:`machdyn.dynamics.flywheel`). W is the cumulative trapezoidal integral of M - mean(M) (the drive gives the
mean torque at every angle), J = 2 T / omega^2 (seed 003 eq 18) and M = P / omega (seed 003 eq 19, corrected)
from :func:`machdyn.linkage.energy`. Valid for loads that depend on the crank angle only, over one full crank
turn sampled evenly; the extremes are searched on the samples, so the result differs from the single run's
(cubic pieces, fine grid) by O(h^2), h the crank step.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from .flywheel import check_delta, speed_limits


def exact_flywheel_inertia(crank_angle, reduced_moment, reduced_inertia, mean_speed, delta) -> np.ndarray:
    """Least flywheel inertia [kg*m^2] of each design for the coefficient of speed fluctuation ``delta``.

    Parameters
    ----------
    crank_angle : (M,) crank angles [rad], evenly spaced over one turn, end point excluded.
    reduced_moment : (N, M) or (M,) reduced moment M(phi) [N*m] of every load but inertia and the drive.
    reduced_inertia : (N, M) or (M,) reduced moment of inertia J(phi) [kg*m^2] of the linkage, >= 0.
    mean_speed : omega_mean [rad/s] > 0, a float or one per design.
    delta : coefficient of speed fluctuation, 0 < delta < 1.

    Returns
    -------
    numpy.ndarray
        (N,) flywheel inertia [kg*m^2], 0 where the linkage alone keeps the speed within the limits; NaN for a
        design with a non-finite sample.

    Examples
    --------
    A constant J and a moment 10 sin(phi) N*m: W = 10 (1 - cos phi), max W - min W = 20 J, so the classic
    ΔE / (omega^2 delta) less J: 20 / (100 * 0.1) - 0.5 = 1.5 kg*m^2 (to the sampling's O(h^2)).

    >>> phi = np.arange(360) * 2 * np.pi / 360
    >>> round(float(exact_flywheel_inertia(phi, 10 * np.sin(phi), 0.5 + 0 * phi, 10.0, 0.1)[0]), 3)
    1.5
    """
    check_delta(delta)
    phi = np.asarray(crank_angle, dtype=float)
    moment = np.atleast_2d(np.asarray(reduced_moment, dtype=float))
    inertia = np.atleast_2d(np.asarray(reduced_inertia, dtype=float))
    speed = np.asarray(mean_speed, dtype=float).reshape(-1, 1) if np.ndim(mean_speed) else float(mean_speed)
    if np.any(np.asarray(speed) <= 0):
        raise InputError(f"The mean speed must be > 0 rad/s; got {float(np.min(speed)):g} rad/s.")
    moment, inertia = np.broadcast_arrays(moment, inertia)
    step = 2 * np.pi / phi.size
    # W_j = cumulative trapezoid of e = M - mean(M) from phi[0] = h (e_0 + ... + e_j - (e_0 + e_j) / 2) (periodic:
    # the mean of the samples is the cycle mean, so that the drive's mean torque closes the cycle)
    excess = moment - moment.mean(axis=1, keepdims=True)
    work = np.cumsum(excess, axis=1)
    work -= 0.5 * (excess[:, :1] + excess)
    work *= step
    wmax, wmin = speed_limits(speed, delta)
    tangent = inertia * (0.5 * wmax**2)
    tangent -= work
    upper = tangent.min(axis=1)
    np.multiply(inertia, 0.5 * wmin**2, out=tangent)
    tangent -= work
    lower = tangent.max(axis=1)
    raw = (lower - upper) / (delta * np.ravel(np.asarray(speed)) ** 2)
    # a non-finite sample makes its design's extremes NaN (or infinite): reported as NaN
    return np.where(np.isfinite(raw), np.maximum(raw, 0.0), np.nan)
