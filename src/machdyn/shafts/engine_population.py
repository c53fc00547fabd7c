"""The engine orders of N reciprocating machines at once: NumPy arrays, designs on the leading axis, the C
cylinders of each design on the second, the shaft angles on the last.

The same formulas as :func:`machdyn.shafts.reciprocating.engine_orders`: the exact piston acceleration of a
zero-offset slider-crank, x'' = -w^2 (r cos phi + r^2 cos 2phi / S + r^4 sin^2 phi cos^2 phi / S^3),
S = sqrt(l^2 - r^2 sin^2 phi), puts -m x'' on the frame along each line of stroke (Uicker, Pennock & Shigley,
*Theory of Machines and Mechanisms*, 5th ed., sec. 16.6); the rotating masses at the crank pins add
w^2 sum(m r e^{i phase}) e^{i theta} (Khurmi & Gupta, *Theory of Machines*, 14th ed., sec. 21.7-21.8); the largest
force and couple of each harmonic order come from the discrete Fourier transform of the exact loads; the textbooks'
primary and secondary forces and couples are the peaks of the two-term series m w^2 r cos phi and
m w^2 r cos 2phi / n, and the direct and reverse crank resultants their closed forms (Khurmi & Gupta, 14th ed., sec.
22.4-22.5, 22.10-22.11). Valid for zero-offset cylinders, rods longer than the cranks, a rigid shaft at constant
speed. A design whose cylinders the single-design path refuses (a crank not > 0, a rod not longer than its crank, a
negative mass, a non-finite value) is flagged (``valid`` False) with NaN results.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .rotating import cycle

__all__ = ["engine_orders_population", "CHUNK_VALUES"]

#: designs x cylinders x shaft angles evaluated at once: the memory stays bounded for any population, and a chunk
#: of this size (512 kB an array) stays in the cache (twice as fast as chunks of 1 << 20)
CHUNK_VALUES = 1 << 16


def _peaks(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """max over the last axis of |(a, b)|: the square root of the largest a^2 + b^2 (one root per design)."""
    return np.sqrt(np.max(a * a + b * b, axis=-1))


def _order_peaks(a: np.ndarray, b: np.ndarray, theta: np.ndarray, orders: np.ndarray) -> np.ndarray:
    """(n, K) largest |(a_k, b_k)| over the turn of the order-k parts of a and b (n, S)."""
    scale = 2.0 / theta.size
    fa, fb = scale * np.fft.rfft(a, axis=-1)[:, orders], scale * np.fft.rfft(b, axis=-1)[:, orders]
    wave = orders[:, None] * theta  # (K, S)
    cos, sin = np.cos(wave), np.sin(wave)
    # |F| cos(k theta + arg F) = Re F cos k theta - Im F sin k theta: no cosine per design and angle
    ak = fa.real[..., None] * cos - fa.imag[..., None] * sin
    bk = fb.real[..., None] * cos - fb.imag[..., None] * sin
    return _peaks(ak, bk)


def engine_orders_population(cylinders: dict[str, Any], speed: Any, samples: int = 360, harmonics: int = 6,
                             reference: Any = 0.0, include_rotating: bool = True) -> dict[str, np.ndarray]:
    """The engine figures of N machines of C cylinders (the ``shaft.engine.*`` results of a shaft line).

    Parameters
    ----------
    cylinders : ``position`` [m], ``phase`` [rad], ``axis`` [rad], ``crank`` [m] > 0, ``rod`` [m] > crank,
        ``reciprocating_mass`` [kg] >= 0 and ``rotating_mass`` [kg] >= 0, each (N, C) or broadcast to it.
    speed : w [rad/s], (N,) or a float. samples : shaft angles over one turn. harmonics : highest order kept,
        1 <= harmonics < samples / 2. reference : the reference plane [m], (N,) or a float.
    include_rotating : the rotating masses in the exact loads (as a shaft line's run counts them).

    Returns
    -------
    dict of (N,) arrays: ``primary_force``, ``secondary_force`` [N], ``primary_couple``, ``secondary_couple``
    [N*m], ``primary_direct``, ``primary_reverse``, ``secondary_direct``, ``secondary_reverse`` [kg*m],
    ``gross_force`` [N], ``gross_couple`` [N*m], ``peak_force`` [N] and ``peak_couple`` [N*m] of the exact loads,
    ``order<k>.force`` [N] and ``order<k>.couple`` [N*m] for k = 1 ... harmonics, and ``valid``.
    """
    names = ("position", "phase", "axis", "crank", "rod", "reciprocating_mass", "rotating_mass")
    arrays = np.broadcast_arrays(*(np.atleast_2d(np.asarray(cylinders.get(k, 0.0), dtype=float)) for k in names))
    z, phase, axis, crank, rod, m_rec, m_rot = arrays
    n, c = z.shape
    w = np.broadcast_to(np.ravel(np.asarray(speed, dtype=float)), (n,))
    ref = np.broadcast_to(np.ravel(np.asarray(reference, dtype=float)), (n,))
    finite = np.isfinite(w) & np.isfinite(ref)
    for a in arrays:  # one input at a time: no stacked copy of the population's cylinders
        finite &= np.all(np.isfinite(a), axis=1)
    valid = finite & np.all((crank > 0) & (rod > crank) & (m_rec >= 0) & (m_rot >= 0), axis=1)
    safe = [np.where(valid[:, None], a, 1.0) for a in (crank, rod)]
    crank, rod = safe[0], np.where(valid[:, None], rod, 2.0)
    theta = cycle(samples)
    orders = np.arange(1, harmonics + 1)
    per = max(1, CHUNK_VALUES // max(1, c * theta.size))
    out: dict[str, np.ndarray] = {}
    for i in range(0, n, per):  # chunk by chunk into the results: only they grow with the population
        s = slice(i, min(n, i + per))
        found = _chunk(z[s], phase[s], axis[s], crank[s], rod[s], m_rec[s], m_rot[s], w[s], ref[s], theta, orders,
                       include_rotating)
        for key, value in found.items():
            out.setdefault(key, np.empty(n))[s] = np.where(valid[s], value, np.nan)
    return out | {"valid": valid}


def _chunk(z, phase, axis, crank, rod, m_rec, m_rot, w, ref, theta, orders, include_rotating) -> dict:
    w2 = (w * w)[:, None]
    zr = z - ref[:, None]
    phi = theta + (phase - axis)[..., None]  # (n, C, S)
    r, length = crank[..., None], rod[..., None]
    sin, cos, cos2 = np.sin(phi), np.cos(phi), np.cos(2 * phi)  # each once: the exact and two-term loads share them
    s = np.sqrt(length**2 - (r * sin) ** 2)
    acc = -(w[:, None, None] ** 2) * (r * cos + r**2 * cos2 / s + r**4 * sin**2 * cos**2 / s**3)
    along = -m_rec[..., None] * acc
    ca, sa = np.cos(axis)[..., None], np.sin(axis)[..., None]
    fx_c, fy_c = ca * along, sa * along
    fx, fy = fx_c.sum(axis=1), fy_c.sum(axis=1)
    mx, my = (-zr[..., None] * fy_c).sum(axis=1), (zr[..., None] * fx_c).sum(axis=1)
    if include_rotating:
        u = m_rot * crank * np.exp(1j * phase)
        turn = np.exp(1j * theta)
        f = w2 * u.sum(axis=1)[:, None] * turn
        first = w2 * (u * zr).sum(axis=1)[:, None] * turn
        fx, fy, mx, my = fx + f.real, fy + f.imag, mx - first.imag, my + first.real
    out = {"peak_force": _peaks(fx, fy), "peak_couple": _peaks(mx, my)}
    for name, (a, b) in (("force", (fx, fy)), ("couple", (mx, my))):
        for k, value in zip(orders, _order_peaks(a, b, theta, orders).T, strict=True):
            out[f"order{k}.{name}"] = value
    amp = m_rec * w2 * crank
    ratio = rod / crank
    for name, along2 in (("primary", amp[..., None] * cos), ("secondary", amp[..., None] * cos2 / ratio[..., None])):
        gx, gy = ca * along2, sa * along2
        out[f"{name}_force"] = _peaks(gx.sum(axis=1), gy.sum(axis=1))
        out[f"{name}_couple"] = _peaks((-zr[..., None] * gy).sum(axis=1), (zr[..., None] * gx).sum(axis=1))
    mr = m_rec * crank
    out["primary_direct"] = np.abs((mr / 2 * np.exp(1j * phase)).sum(axis=1))
    out["primary_reverse"] = np.abs((mr / 2 * np.exp(1j * (2 * axis - phase))).sum(axis=1))
    out["secondary_direct"] = np.abs((mr / (2 * ratio) * np.exp(1j * (2 * phase - axis))).sum(axis=1))
    out["secondary_reverse"] = np.abs((mr / (2 * ratio) * np.exp(1j * (3 * axis - 2 * phase))).sum(axis=1))
    out["gross_force"] = (amp).sum(axis=1)
    out["gross_couple"] = (amp * np.abs(zr)).sum(axis=1)
    return out
