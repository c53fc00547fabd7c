"""Harmonic content of a periodic result over one crank revolution (orders of the crank frequency).

For N samples evenly spaced over one revolution, the discrete Fourier transform gives the exact
coefficients of a trigonometric polynomial of degree < N/2: value(phi) = mean + sum_k A_k cos(k phi + psi_k)
(Oppenheim & Schafer, *Discrete-Time Signal Processing*, 3rd ed., §8.1). Order 1 is the crank frequency.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .motion import is_full_turn


@dataclass(frozen=True)
class Harmonics:
    """Mean, and amplitude and phase [rad] of orders 1..n (cosine form), along the last axis."""

    orders: np.ndarray
    mean: np.ndarray
    amplitude: np.ndarray
    phase: np.ndarray


def harmonics(values, crank_angle, orders: int = 6) -> Harmonics:
    """Harmonic orders 1..``orders`` of ``values`` sampled at ``crank_angle`` (the last axis).

    value(φ) = mean + Σ_k A_k cos(kφ + ψ_k), from the discrete Fourier transform of N samples evenly spaced over
    one revolution, exact for trigonometric polynomials of degree < N/2 (Oppenheim & Schafer,
    *Discrete-Time Signal Processing*, 3rd ed., §8.1).

    Parameters
    ----------
    values : array
        Samples, the last axis along the crank angles [any unit].
    crank_angle : array
        Crank angles [rad], evenly spaced over exactly one revolution without repeating the first angle
        (as :func:`~machdyn.linkage.kinematics.crank_angles` makes them); at least 4.
    orders : int
        Highest order [-], 1 ≤ orders < N/2.

    Returns
    -------
    Harmonics
        orders [-], mean and amplitude A_k [unit of values], phase ψ_k [rad].

    Examples
    --------
    >>> phi = np.arange(360) * (2.0 * np.pi / 360)
    >>> h = harmonics(3.0 + 2.0 * np.cos(2.0 * phi + 0.5), phi, orders=3)
    >>> h.orders, float(h.mean)
    (array([1, 2, 3]), 3.0)
    >>> np.round(h.amplitude, 12), np.round(h.phase, 12)
    (array([0., 2., 0.]), array([0. , 0.5, 0. ]))
    """
    phi = np.asarray(crank_angle, dtype=float)
    y = np.asarray(values, dtype=float)
    n = phi.size
    if phi.ndim != 1 or n < 4:
        raise InputError(f"Harmonics need a 1-D array of at least 4 crank angles; got shape {phi.shape}.")
    if not is_full_turn(phi):
        raise InputError(
            "Harmonics need crank angles evenly spaced over one full revolution (end point excluded); "
            f"got {n} angles from {np.degrees(phi[0]):.3f}° to {np.degrees(phi[-1]):.3f}°."
        )
    if not 1 <= orders < n / 2:
        raise InputError(f"The number of harmonic orders must be between 1 and {n // 2 - 1}; got {orders}.")
    if not np.all(np.isfinite(y)):
        raise InputError("Harmonics need finite values at every crank angle; got NaN or infinity.")
    spectrum = np.fft.rfft(y, axis=-1) / n
    # Samples start at phi[0], not 0: shift the phase so it refers to phi = 0.
    k = np.arange(orders + 1)
    spectrum = spectrum[..., : orders + 1] * np.exp(-1j * k * phi[0])
    amplitude = 2.0 * np.abs(spectrum[..., 1:])
    # The phase of an order that is absent is rounding noise: report 0 for orders below 1e-12 of the largest.
    floor = 1e-12 * np.max(amplitude, axis=-1, keepdims=True)
    phase = np.where(amplitude > floor, np.angle(spectrum[..., 1:]), 0.0)
    return Harmonics(k[1:], spectrum[..., 0].real, amplitude, phase)
