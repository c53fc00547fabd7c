"""The frame on its mounts for a population of designs at once: stacked modes and the steady response at the
running speed and its orders, with NumPy arrays whose leading axis is the design.

The same formulas as the single-design path: the modes solve K phi = omega^2 M phi (Rao, *Mechanical Vibrations*,
5th ed., 2011, §6.10; :func:`machdyn.vibration.modes.modes`), here for N frames in one stacked call of
:func:`numpy.linalg.eigh` on the Cholesky-reduced matrices L^-1 K L^-T (M = L L^T; Golub & Van Loan, *Matrix
Computations*, 4th ed., sec. 8.7.2, the symmetric-definite problem); the response solves
(K - (k Omega)^2 M + i k Omega C) q_k = Q_k for every order k of the shaking loads (Rao, §6.14;
:func:`machdyn.vibration.response.steady_state`) in one stacked :func:`numpy.linalg.solve`; RMS values are sums over
the orders, sqrt(sum |a_k|^2 / 2) (Parseval), and a point's predicted zone is its RMS velocity against the zone
boundaries of ISO 10816-1 (:func:`machdyn.vibration.severity.classify`).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..balancing.population import kinetostatics_masked
from ..linkage import harmonics
from ..linkage.motion import is_full_turn
from .frame import Frame
from .modes import _SINGULAR
from .response import MAX_MAGNIFICATION
from .severity import _machine_class, _standard, zone_boundaries
from .study import build_frame, with_variant

__all__ = ["frame_matrices", "modes_population", "response_population", "frame_population"]

#: designs x crank positions analysed at once by the population form: memory bounded for any population
CHUNK_POSITIONS = 1 << 18


def frame_matrices(mass, inertia, com, positions, directions, stiffness, damping) -> tuple[np.ndarray, ...]:
    """M, K, C (N, 3, 3) of N rigid planar frames on mounts (:meth:`~machdyn.vibration.frame.Frame.mass_matrix`,
    :func:`~machdyn.vibration.frame.mount_sum`), for q = (x, y, theta) of each frame's reference point.

    Parameters
    ----------
    mass [kg], inertia [kg*m^2] (about the centre of mass) : (N,) or floats.
    com : (N, 2) or (2,) centre of mass [m].
    positions : (N, k, 2) or (k, 2) the mounts' points [m]; directions : (N, k) or (k,) their lines [rad];
    stiffness [N/m], damping [N*s/m] : (N, k) or (k,) along the lines.
    """
    mass, inertia = np.asarray(mass, dtype=float), np.asarray(inertia, dtype=float)
    com = np.asarray(com, dtype=float)
    xg, yg = com[..., 0], com[..., 1]
    n = np.broadcast_shapes(mass.shape, inertia.shape, xg.shape)
    m = np.zeros((*n, 3, 3))
    m[..., 0, 0] = m[..., 1, 1] = mass
    m[..., 0, 2] = m[..., 2, 0] = -mass * yg
    m[..., 1, 2] = m[..., 2, 1] = mass * xg
    m[..., 2, 2] = inertia + mass * (xg**2 + yg**2)
    p = np.asarray(positions, dtype=float)
    d = np.asarray(directions, dtype=float)
    nx, ny = np.cos(d), np.sin(d)
    b = np.stack([nx, ny, p[..., 0] * ny - p[..., 1] * nx], axis=-1)  # (..., k, 3)

    def summed(rate):
        return np.einsum("...ki,...k,...kj->...ij", b, np.asarray(rate, dtype=float), b)

    return m, summed(stiffness), summed(damping)


def supported(stiffness: np.ndarray, size: Any) -> np.ndarray:
    """Whether the mounts hold every rigid motion of each frame (:func:`~machdyn.vibration.modes.check_supported`):
    every eigenvalue of S K S (S = diag(1, 1, 1/size), size [m] the largest mount distance, at least 1 m) at least
    1e-10 of the largest, and the largest > 0."""
    s = np.ones(np.shape(stiffness)[:-2] + (3,))
    s[..., 2] = 1.0 / np.asarray(size, dtype=float)
    values = np.linalg.eigvalsh(s[..., :, None] * stiffness * s[..., None, :])
    top = values[..., -1]
    return (top > 0) & (values[..., 0] >= _SINGULAR * top)


def modes_population(mass_matrix, stiffness, damping) -> dict[str, np.ndarray]:
    """Natural frequencies, mass-normalised shapes and modal damping of N frames at once.

    Returns ``angular_frequencies`` (N, 3) [rad/s] ascending, ``shapes`` (N, 3, 3) (column j mode j, phi^T M phi =
    1, its largest entry positive as :func:`~machdyn.vibration.modes.modes` fixes it) and ``damping_ratios``
    (N, 3) phi^T C phi / (2 omega).
    """
    m, k, c = (np.asarray(a, dtype=float) for a in (mass_matrix, stiffness, damping))
    lower = np.linalg.cholesky(m)
    inv = np.linalg.inv(lower)
    values, y = np.linalg.eigh(inv @ k @ np.swapaxes(inv, -1, -2))
    vectors = np.swapaxes(inv, -1, -2) @ y  # phi = L^-T y: phi^T M phi = y^T y = 1
    omega = np.sqrt(np.clip(values, 0.0, None))
    with np.errstate(divide="ignore", invalid="ignore"):
        zeta = np.einsum("...ij,...ik,...kj->...j", vectors, c, vectors) / (2 * omega)
    largest = np.take_along_axis(vectors, np.argmax(np.abs(vectors), axis=-2)[..., None, :], axis=-2)
    return {"angular_frequencies": omega, "shapes": vectors * np.sign(largest), "damping_ratios": zeta}


def response_population(mass_matrix, stiffness, damping, angular_frequencies, loads) -> dict[str, np.ndarray]:
    """The steady response q_k (N, K, 3) of N frames to the complex loads Q_k (N, K, 3) at the angular frequencies
    w_k (N, K) or (K,) [rad/s], and ``valid`` (N,): False where an order lies so close to an undamped mode that the
    single path refuses it (dynamic magnification above :data:`~machdyn.vibration.response.MAX_MAGNIFICATION`, or
    a dynamic stiffness of condition number above 1e14)."""
    m, k, c = (np.asarray(a, dtype=float)[..., None, :, :] for a in (mass_matrix, stiffness, damping))
    w = np.asarray(angular_frequencies, dtype=float)[..., None, None]
    dyn = k - w**2 * m + 1j * w * c
    found = modes_population(mass_matrix, stiffness, damping)
    wn, zeta = found["angular_frequencies"][..., None, :], found["damping_ratios"][..., None, :]
    with np.errstate(divide="ignore", invalid="ignore"):
        r = np.asarray(angular_frequencies, dtype=float)[..., :, None] / wn
        magnified = (wn > 0) & (np.hypot(1.0 - r * r, 2.0 * zeta * r) * MAX_MAGNIFICATION < 1.0)
    valid = ~np.any(magnified, axis=(-1, -2)) & np.all(np.linalg.cond(dyn) <= 1e14, axis=-1)
    safe = np.where(valid[..., None, None, None], dyn, np.eye(3))
    q = np.linalg.solve(safe, np.asarray(loads, dtype=complex)[..., None])[..., 0]
    return {"coordinates": q, "valid": np.broadcast_to(valid, q.shape[:-2])}


def _rms(a: np.ndarray, axes: tuple[int, ...]) -> np.ndarray:
    return np.sqrt(0.5 * np.sum(np.abs(a) ** 2, axis=axes))


def _figures(frame: Frame, table: Any, q: np.ndarray, w: np.ndarray, tag: str, out: dict[str, np.ndarray]) -> dict:
    """The RMS figures of the response ``q`` (N, K, 3) at the angular frequencies ``w`` (K,), as a run reports
    them (:func:`machdyn.vibration.stage._frame_values`); returns {point: banded RMS acceleration (N,)}."""
    f = w / (2 * np.pi)
    low, high = (float(v) for v in table.band)
    band = (f >= low) & (f <= high)
    key = _standard(table.standard)
    bounds = np.asarray(zone_boundaries(_machine_class(table.machine_class), key))
    d = None if table.direction is None else np.array([math.cos(table.direction), math.sin(table.direction)])
    accelerations = {}
    for name, point in table.points.items():
        u = q @ Frame.point_matrix(point).T  # (N, K, 2)
        u = u[:, band]
        wb = w[band][:, None]
        velocity, acceleration = 1j * wb * u, -(wb**2) * u
        if d is None:
            acc, vel = _rms(acceleration, (1, 2)), _rms(velocity, (1, 2))
        else:
            acc, vel = _rms(acceleration @ d, (1,)), _rms(velocity @ d, (1,))
        out[f"frame.rms_acceleration.{tag}.{name}"] = acc
        out[f"frame.rms_velocity.{tag}.{name}"] = vel
        out[f"frame.zone.{tag}.{name}"] = np.searchsorted(bounds, vel, side="left").astype(float)
        accelerations[name] = acc
    for mount in frame.mounts:
        force = (mount.stiffness + 1j * w * mount.damping) * (q @ mount.influence)
        out[f"frame.transmitted_force.{tag}.{mount.name}"] = _rms(force, (1,))
    return accelerations


def _curves(forces: Any, n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The frame force fx, fy [N] and the shaking moment about the origin [N*m] of the designs of ``forces``, (n, M)
    each."""
    shape = (n, np.size(forces.kinematics.crank_angle))
    fx, fy = (np.broadcast_to(np.asarray(v, dtype=float), shape) for v in forces.frame_force)
    return fx, fy, np.broadcast_to(np.asarray(forces.shaking_moment((0.0, 0.0)), dtype=float), shape)


def _loads(curves: tuple[np.ndarray, ...], phi: np.ndarray, table: Any) -> tuple[np.ndarray, np.ndarray]:
    """The complex harmonic loads (n, K, 3) on the frame's reference point from each design's frame force and
    shaking moment ``curves`` (:func:`machdyn.vibration.response.shaking_loads`), and whether they are finite."""
    fx, fy, mz = curves
    finite = np.all(np.isfinite(fx) & np.isfinite(fy) & np.isfinite(mz), axis=1)
    fx, fy, mz = (np.where(finite[:, None], v, 0.0) for v in (fx, fy, mz))
    ox, oy = (float(v) for v in table.mechanism_origin)
    c, s = np.cos(table.mechanism_angle), np.sin(table.mechanism_angle)
    gx, gy = c * fx - s * fy, s * fx + c * fy
    moment = mz + ox * gy - oy * gx
    h = harmonics(np.stack([gx, gy, moment], axis=-1).swapaxes(-1, -2), phi, table.orders)  # (n, 3, K)
    return (h.amplitude * np.exp(1j * h.phase)).swapaxes(-1, -2), finite


def frame_population(problem: Any, forces: Any) -> dict[str, np.ndarray] | None:
    """The ``[frame]`` results of N linkage designs at once from their kinetostatics over the file's crank positions
    (the capability's population form): the modes (one frame, the same for every design), the response to each
    design's shaking loads before and, with ``[frame.after]``, after; a design that does not close is NaN. None
    (each design run on its own) where the designs turn at different or changing speeds, or where the variant
    compared is the mechanism as ``[balance]`` left it."""
    table = problem.frame
    speed = np.ravel(np.asarray(forces.kinematics.speed, dtype=float))
    accel = np.asarray(forces.kinematics.acceleration, dtype=float)
    phi = np.asarray(forces.kinematics.crank_angle, dtype=float)
    if np.any(speed != speed[0]) or not speed[0] > 0 or np.any(accel != 0) or not is_full_turn(phi):
        return None
    if table.after is None and getattr(problem, "balance", None) is not None:
        return None
    omega = float(speed[0])
    frame = build_frame(table, omega / (2 * np.pi))
    m, k, c = frame.mass_matrix(), frame.stiffness_matrix(), frame.damping_matrix()
    if not supported(k, max(1.0, *(math.hypot(*mount.position) for mount in frame.mounts))):
        return None  # the file's check refuses a frame its mounts do not hold
    found = modes_population(m, k, c)
    out: dict[str, np.ndarray] = {}
    for j in range(3):
        out[f"frame.mode_{j + 1}.frequency"] = np.asarray(found["angular_frequencies"][j] / (2 * np.pi))
        out[f"frame.mode_{j + 1}.damping_ratio"] = np.asarray(found["damping_ratios"][j])
    w = np.arange(1, table.orders + 1) * omega
    response = response_population(m, k, c, w, np.zeros((1, w.size, 3)))
    if not response["valid"][0]:
        return None  # an order on an undamped mode: every design's run refuses it, with the reason
    mech = forces.mechanism
    n = mech.design_count or 1
    # the frame is every design's: its dynamic flexibility (K - w^2 M + i w C)^-1 at each order, once
    flexibility = np.linalg.inv(_dynamic(m, k, c, w))
    per = max(1, CHUNK_POSITIONS // phi.size)
    valid = np.ones(n, dtype=bool)
    acc: dict[str, dict[str, list[np.ndarray]]] = {"before": {}, "after": {}}
    chunks: dict[str, list[np.ndarray]] = {}
    curves = _curves(forces, n)
    for start in range(0, n, per):  # chunks of designs: the memory stays bounded for any population
        part = slice(start, min(n, start + per))
        variants = [("before", tuple(v[part] for v in curves))]
        if table.after is not None:  # the variant's kinetostatics, chunk by chunk
            sub = mech.take_designs(part) if mech.design_count else mech
            variants.append(("after", _curves(kinetostatics_masked(with_variant(sub, table.after), phi, omega),
                                              part.stop - part.start)))
        for tag, curve in variants:
            loads, finite = _loads(curve, phi, table)
            valid[part] &= finite
            q = np.einsum("kij,nkj->nki", flexibility, loads)
            found_part: dict[str, np.ndarray] = {}
            a = _figures(frame, table, q, w, tag, found_part)
            for key, value in found_part.items():
                chunks.setdefault(key, []).append(value)
            for name, value in a.items():
                acc[tag].setdefault(name, []).append(value)
    out |= {key: np.concatenate(values) for key, values in chunks.items()}
    if acc["after"]:
        before = {p: np.concatenate(v) for p, v in acc["before"].items()}
        after = {p: np.concatenate(v) for p, v in acc["after"].items()}
        with np.errstate(divide="ignore", invalid="ignore"):
            for p in table.points:
                out[f"frame.acceleration_reduction.{p}"] = (before[p] - after[p]) / before[p]  # a fraction (SI)
                valid &= before[p] > 0  # the single path refuses a reduction of a level 0
            b = np.mean(np.stack(list(before.values())), axis=0)
            a_ = np.mean(np.stack(list(after.values())), axis=0)
            out["frame.mean_acceleration_reduction"] = (b - a_) / b
    return {key: np.where(valid, np.broadcast_to(v, (n,)), np.nan) for key, v in out.items()}


def _dynamic(m: np.ndarray, k: np.ndarray, c: np.ndarray, w: np.ndarray) -> np.ndarray:
    """K - w^2 M + i w C (K, 3, 3) of one frame at the angular frequencies w (K,) [rad/s]."""
    ww = w[:, None, None]
    return k - ww**2 * m + 1j * ww * c
