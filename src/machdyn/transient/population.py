"""The closed-form passage through a resonance for N designs at once: the same formulas as
:mod:`machdyn.transient.closed_forms`, over NumPy arrays whose leading axis is the design.

The envelope of a passage at the constant rate alpha through the natural frequency w with damping ratio zeta is
|x| = f / (2 w) |I(s)|, |I(s)| = sqrt(pi / (2 alpha)) |w(-i v)|, v = exp(-i pi / 4) sqrt(alpha / 2)
(s - i zeta w / alpha), w(z) the Faddeeva function (F. M. Lewis, "Vibration during acceleration through a critical
speed", Trans. ASME 54 (1932) 253-261; Abramowitz & Stegun, *Handbook of Mathematical Functions*, 7.1.3). Undamped,
the largest |I|, its time after the resonance and the |I| left after the passage are the Cornu spiral's universal
figures times sqrt(pi / alpha) (A & S 7.3), found once for the whole population. Valid for zeta << 1 and
alpha << w^2. A design the single-design functions refuse (a natural frequency or a sweep rate not > 0, a negative
damping ratio, a value that is not finite) is flagged (``valid`` False, NaN results).
"""

from __future__ import annotations

from functools import cache
from typing import Any

import numpy as np

from .closed_forms import undamped_passage_peak

__all__ = ["passage_envelope_population", "undamped_passage_population"]


def _valid(natural_frequency: Any, sweep_rate: Any, damping_ratio: Any = 0.0) -> tuple[np.ndarray, ...]:
    w, alpha, zeta = np.broadcast_arrays(*(np.atleast_1d(np.asarray(x, dtype=float)) for x in
                                           (natural_frequency, sweep_rate, damping_ratio)))
    valid = np.isfinite(w) & np.isfinite(alpha) & np.isfinite(zeta) & (w > 0) & (alpha > 0) & (zeta >= 0)
    return w, np.where(valid, alpha, 1.0), zeta, valid


def passage_envelope_population(s: Any, natural_frequency: Any, sweep_rate: Any, damping_ratio: Any = 0.0):
    """|I(s)| [s] of N passages at the times ``s`` [s] after each resonance: ``s`` (N, T) or (T,), the natural
    frequencies w [rad/s], sweep rates alpha [rad/s^2] and damping ratios zeta [-] (N,) each (or floats).
    Returns ((N, T) envelope, (N,) valid)."""
    from scipy.special import wofz

    w, alpha, zeta, valid = _valid(natural_frequency, sweep_rate, damping_ratio)
    a, sigma = alpha[:, None], (zeta * w)[:, None]
    v = np.exp(-0.25j * np.pi) * np.sqrt(a / 2.0) * (np.asarray(s, dtype=float) - 1j * sigma / a)
    envelope = np.sqrt(np.pi / (2.0 * a)) * np.abs(wofz(-1j * v))
    return np.where(valid[:, None], envelope, np.nan), valid


@cache
def _cornu() -> tuple[float, float, float]:
    """(largest |I|, its time, |I| after) of an undamped passage at alpha = pi: the spiral's own figures (the
    single function's search, made once)."""
    return undamped_passage_peak(1.0, np.pi)


def undamped_passage_population(natural_frequency: Any, sweep_rate: Any) -> dict[str, np.ndarray]:
    """The largest |I| [s], its time after the resonance [s] and the |I| left after the passage [s] of N undamped
    passages (:func:`machdyn.transient.closed_forms.undamped_passage_peak` of each), and ``valid``."""
    _w, alpha, _zeta, valid = _valid(natural_frequency, sweep_rate)
    peak, when, after = _cornu()  # at alpha = pi the scale sqrt(pi / alpha) is 1
    scale = np.sqrt(np.pi / alpha)
    out = {"peak": peak * scale, "time": when * scale, "after": np.sqrt(2.0) * scale}
    return {k: np.where(valid, v, np.nan) for k, v in out.items()} | {"valid": valid}
