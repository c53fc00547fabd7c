"""The periodic steady state of the energy equation by Fourier collocation, for smooth machines.

The energy equation dK/dphi = M(phi, omega), omega = sqrt(2K/J(phi)) (see :mod:`machdyn.dynamics.simulate`) has,
for a machine whose curves are all trigonometric polynomials, a smooth periodic solution K(phi). Sampled at the N
nodes of the cycle it satisfies D K = f(K), D the spectral derivative of periodic samples (L. N. Trefethen,
*Spectral Methods in MATLAB*, SIAM 2000, ch. 3). The nodes' values are found by the iteration
(D - g_mean) K_new = f(K) - g_mean K, g = df/dK, whose operator is diagonal in Fourier space (one FFT pair per
step); it contracts where g varies little about its mean, which is the case of every machine with a flywheel.
Where it does not contract, or the solution is not resolved by the nodes, None is returned and the caller falls
back on shooting with an ODE integrator.
"""

from __future__ import annotations

import numpy as np


def collocation_steady(model, n: int, phi: np.ndarray, speed: np.ndarray, tolerance: float,
                       max_iterations: int = 60):
    """K [J] and time [s] at the nodes ``phi`` (evenly spaced over the cycle, without the end), the period [s]
    and the truncation estimate (relative amplitude of the upper half of the resolved spectrum of K), or None.

    ``model`` is the simulation's right-hand side (a ``_Model`` on its Fourier path), ``speed`` [rad/s] a start per
    design (the speed that balances the mean load).
    """
    size = phi.size
    period = model.m.period
    q = np.broadcast_to(phi, (n, size))
    j, _, mp, c = model.curves(q)
    j = np.broadcast_to(model._plus_added(j), (n, size))
    mp, c = np.broadcast_to(mp, (n, size)), np.broadcast_to(c, (n, size))
    wave = (2.0 * np.pi / period) * np.arange(size // 2 + 1)
    ik = 1j * wave
    if size % 2 == 0:
        ik[-1] = 0.0  # the Nyquist mode has no derivative on the nodes
    k = 0.5 * j * np.asarray(speed, dtype=float)[:, None] ** 2
    change_before = np.inf
    for _ in range(max_iterations):
        omega = np.sqrt(np.maximum(2.0 * k / j, 0.0))
        if np.any(omega <= 0.0):
            return None
        td, dtd = model.drive_torque(omega)
        f = td + mp - c * omega
        g = (dtd - c) / (j * omega)
        g_mean = g.mean(axis=1, keepdims=True)
        if np.any(g_mean >= 0.0):  # the drive does not hold the mean speed: not for this method
            return None
        k_new = np.fft.irfft(np.fft.rfft(f - g_mean * k, axis=1) / (ik - g_mean), n=size, axis=1)
        change = float(np.max(np.abs(k_new - k) / k.max(axis=1, keepdims=True)))
        k = k_new
        if change <= 0.01 * tolerance:
            break
        if change > 0.5 * change_before:  # too slow a contraction (or divergence): shoot instead
            return None
        change_before = change
    else:
        return None
    spectrum = np.abs(np.fft.rfft(k, axis=1)) / size
    truncation = float(np.max(spectrum[:, size // 4:].max(axis=1) / k.mean(axis=1)))
    if not np.all(k > 0) or truncation > tolerance:
        return None
    omega = np.sqrt(2.0 * k / j)
    inverse = np.fft.rfft(1.0 / omega, axis=1)
    mean_inverse = inverse[:, :1].real / size
    inverse[:, 0] = 0.0
    with np.errstate(divide="ignore", invalid="ignore"):
        inverse = np.where(ik != 0, inverse / np.where(ik != 0, ik, 1.0), 0.0)
    wobble = np.fft.irfft(inverse, n=size, axis=1)
    time = mean_inverse * (phi - phi[0]) + wobble - wobble[:, :1]
    return k, time, mean_inverse[:, 0] * period, np.full(n, truncation)
