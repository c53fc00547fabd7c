"""Averages over time of results sampled at crank angles.

Samples evenly spaced in crank angle are not evenly spaced in time when the crank speed varies: each sample
stands for dt = dphi / omega. The time mean of f over the analysed range is sum(f dt) / sum(dt) and the RMS is
sqrt(sum(f^2 dt) / sum(dt)); at constant speed these are the plain means over the samples. The angle weights
dphi are equal over an evenly sampled full revolution and the trapezoidal weights otherwise.
"""

from __future__ import annotations

import numpy as np

from .kinematics import Kinematics


def angle_weights(crank_angle) -> np.ndarray:
    """The crank-angle step each sample stands for, up to a common factor: equal over an evenly sampled full
    revolution, the trapezoidal weights otherwise."""
    phi = np.asarray(crank_angle, dtype=float)
    if phi.ndim == 0 or phi.size < 2:
        return np.ones(np.shape(phi))
    if np.allclose(np.diff(phi), 2 * np.pi / phi.size, rtol=1e-9, atol=1e-12):
        return np.ones(phi.shape)
    dphi = np.zeros(phi.shape)
    steps = np.diff(phi)
    dphi[:-1] += 0.5 * steps
    dphi[1:] += 0.5 * steps
    return dphi


def time_weights(kin: Kinematics) -> np.ndarray:
    """Weights proportional to the time each sample stands for, summing to 1 along the last axis."""
    dphi = angle_weights(kin.crank_angle)
    speed = np.abs(np.asarray(kin.speed, dtype=float))
    # Where the crank stands still (a static analysis) time has no meaning: fall back to angle weights.
    w = np.broadcast_to(dphi, kin.shape) / speed if np.all(speed > 0) else np.broadcast_to(dphi, kin.shape)
    return w / w.sum(axis=-1, keepdims=True)


def time_mean(values, kin: Kinematics) -> np.ndarray:
    """Mean over time of ``values`` (shaped like the kinematics) [same unit as values]."""
    return np.sum(np.asarray(values) * time_weights(kin), axis=-1)


def time_rms(values, kin: Kinematics) -> np.ndarray:
    """Root mean square over time of ``values`` [same unit as values]."""
    v = np.asarray(values)
    return np.sqrt(np.sum(v * v * time_weights(kin), axis=-1))
