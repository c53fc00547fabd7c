"""Averages over time of results sampled at crank angles.

Samples evenly spaced in crank angle are not evenly spaced in time when the crank speed varies: each sample
stands for dt = dphi / omega. The time mean of f over the analysed range is sum(f dt) / sum(dt) and the RMS is
sqrt(sum(f^2 dt) / sum(dt)); at constant speed these are the plain means over the samples. The angle weights
dphi are equal over an evenly sampled full revolution and the trapezoidal weights otherwise.
"""

from __future__ import annotations

import numpy as np

from .motion import Kinematics, is_full_turn


def angle_weights(crank_angle) -> np.ndarray:
    """The crank-angle step each sample stands for, up to a common factor.

    Equal over an evenly sampled full revolution; the trapezoidal-rule weights Δφ_i = (φ_{i+1} − φ_{i−1})/2
    (halved at the ends) otherwise.

    Parameters
    ----------
    crank_angle : float or array
        Crank angles φ [rad], increasing.

    Returns
    -------
    numpy.ndarray
        Weights [rad] (or ones), shaped like ``crank_angle``.

    Examples
    --------
    >>> angle_weights([0.0, 0.1, 0.3])
    array([0.05, 0.15, 0.1 ])
    >>> angle_weights(np.arange(4) * np.pi / 2)
    array([1., 1., 1., 1.])
    """
    phi = np.asarray(crank_angle, dtype=float)
    if phi.ndim == 0 or phi.size < 2:
        return np.ones(np.shape(phi))
    if is_full_turn(phi):
        return np.ones(phi.shape)
    dphi = np.zeros(phi.shape)
    steps = np.diff(phi)
    dphi[:-1] += 0.5 * steps
    dphi[1:] += 0.5 * steps
    return dphi


def time_weights(kin: Kinematics) -> np.ndarray:
    """Weights proportional to the time each sample stands for, dt = dφ / |ω|, summing to 1 along the last axis.

    Where the crank stands still (a static analysis) time has no meaning and the angle weights are used.

    Parameters
    ----------
    kin : Kinematics
        The result of :func:`~machdyn.linkage.kinematics.kinematics`.

    Returns
    -------
    numpy.ndarray
        Weights [-] shaped like the kinematics.

    Examples
    --------
    >>> from machdyn.linkage import crank_angles, kinematics, slider_crank
    >>> kin = kinematics(slider_crank(0.1, 0.3), crank_angles(360), speed=10.0)
    >>> w = time_weights(kin)
    >>> w.shape, round(float(w.sum()), 12)
    ((360,), 1.0)
    """
    dphi = angle_weights(kin.crank_angle)
    speed = np.abs(np.asarray(kin.speed, dtype=float))
    # Where the crank stands still (a static analysis) time has no meaning: fall back to angle weights.
    w = np.broadcast_to(dphi, kin.shape) / speed if np.all(speed > 0) else np.broadcast_to(dphi, kin.shape)
    return w / w.sum(axis=-1, keepdims=True)


def time_mean(values, kin: Kinematics) -> np.ndarray:
    """Mean over time of ``values``: Σ f dt / Σ dt with dt = dφ / |ω|.

    At constant speed over an evenly sampled revolution it is the plain mean of the samples (rectangle rule,
    exact for trigonometric polynomials of degree below N).

    Parameters
    ----------
    values : array
        Samples shaped like the kinematics [any unit].
    kin : Kinematics
        The kinematics the samples belong to.

    Returns
    -------
    numpy.ndarray
        The time mean [same unit as values], one per design.

    Examples
    --------
    Mean kinetic energy of a 2 kg slider driven by a 0.1 m crank and a 0.3 m rod at 10 rad/s:

    >>> from machdyn.linkage import crank_angles, energy, kinematics, slider_crank
    >>> mech = slider_crank(0.1, 0.3, masses=(0.0, 0.0, 2.0))
    >>> phi = crank_angles(360)
    >>> kinetic = sum(energy(mech, phi, speed=10.0).kinetic.values())
    >>> round(float(time_mean(kinetic, kinematics(mech, phi, speed=10.0))), 6)
    0.514719
    """
    return np.sum(np.asarray(values) * time_weights(kin), axis=-1)


def time_rms(values, kin: Kinematics) -> np.ndarray:
    """Root mean square over time of ``values``: √(Σ f² dt / Σ dt) with dt = dφ / |ω|.

    Parameters
    ----------
    values : array
        Samples shaped like the kinematics [any unit].
    kin : Kinematics
        The kinematics the samples belong to.

    Returns
    -------
    numpy.ndarray
        The RMS [same unit as values], one per design.

    Examples
    --------
    >>> from machdyn.linkage import crank_angles, energy, kinematics, slider_crank
    >>> mech = slider_crank(0.1, 0.3, masses=(0.0, 0.0, 2.0))
    >>> phi = crank_angles(360)
    >>> kinetic = sum(energy(mech, phi, speed=10.0).kinetic.values())
    >>> round(float(time_rms(kinetic, kinematics(mech, phi, speed=10.0))), 6)
    0.648175
    """
    v = np.asarray(values)
    return np.sqrt(np.sum(v * v * time_weights(kin), axis=-1))
