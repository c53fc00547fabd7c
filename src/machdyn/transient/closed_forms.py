"""Closed forms of the passage through resonance and of the capture by it, against which runs are checked.

**Passage at a constant rate.** A single-degree-of-freedom oscillator x'' + 2 zeta w x' + w^2 x = f cos psi(t)
driven with the phase psi = Omega_0 t + alpha t^2 / 2 (its frequency psi' sweeping through w at the rate alpha)
is, by Duhamel's integral, near the resonance the slowly varying envelope

    |x|(s) = f / (2 w) |I(s)|,   I(s) = int_-inf^s exp(-zeta w (s - tau)) exp(i alpha tau^2 / 2) dtau,

s the time since psi' = w (the non-resonant term, of relative size sqrt(alpha) / w, left out; F. M. Lewis,
"Vibration during acceleration through a critical speed", Trans. ASME 54 (1932) 253-261, who gave this
Fresnel-integral solution and its curves). Undamped, I(s) = sqrt(pi / alpha) [C(u) + 1/2 + i (S(u) + 1/2)] with
u = s sqrt(alpha / pi) and C, S the Fresnel integrals (Abramowitz & Stegun, *Handbook of Mathematical Functions*,
7.3.1-7.3.2), whose spiral gives the largest amplitude after the resonance and the amplitude left after it,
f / (2 w) sqrt(2 pi / alpha). Damped, completing the square gives I(s) = sqrt(pi / (2 alpha)) w(-i v) (up to a
phase), v = exp(-i pi / 4) sqrt(alpha / 2) (s - i zeta w / alpha) and w(z) the Faddeeva function (Abramowitz &
Stegun 7.1.3), which tends to the steady resonant amplitude f / (2 zeta w^2) as alpha -> 0.

**Capture.** An unbalance m e turning at Omega on a mass M (the unbalance included) on a spring k with a damper
c takes from its drive the mean vibration torque S(Omega) = c Omega X^2 / 2, X = m e Omega^2 /
sqrt((k - M Omega^2)^2 + (c Omega)^2): the power the damper dissipates over the speed. The stationary speeds
are where the drive's torque L(Omega) equals S(Omega) plus the rotor's own resistance (Kononenko, *Vibrating
Systems with a Limited Power Supply*, Iliffe 1969, ch. 2, the stationary motions of an unbalanced rotor on an
elastic base); a drive whose L falls below S near the resonance is captured there.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError

__all__ = ["passage_envelope", "undamped_passage_peak", "vibration_torque"]


def _check(name, value, unit=""):
    v = np.asarray(value, dtype=float)
    if not np.all(np.isfinite(v)) or np.any(v <= 0):
        raise InputError(f"The {name} must be > 0 {unit}; got {value!r}.")


def passage_envelope(s, natural_frequency, sweep_rate, damping_ratio=0.0):
    """|I(s)| [s]: the envelope of the passage, |x| = f / (2 w) |I(s)| (see the module docstring).

    Parameters
    ----------
    s : time since the exciting frequency equalled the natural frequency [s]
    natural_frequency : w [rad/s] > 0
    sweep_rate : alpha [rad/s^2] > 0 (the exciting frequency's rate of change)
    damping_ratio : zeta [-] >= 0 (small: the envelope holds for zeta << 1 and alpha << w^2)

    Examples
    --------
    Long after an undamped passage the envelope is sqrt(2 pi / alpha):

    >>> round(float(passage_envelope(1e4, 100.0, 1.0)) / float(np.sqrt(2 * np.pi)), 4)
    1.0
    """
    from scipy.special import wofz

    _check("natural frequency", natural_frequency, "rad/s")
    _check("sweep rate", sweep_rate, "rad/s^2")
    if np.any(np.asarray(damping_ratio) < 0):
        raise InputError(f"The damping ratio must be >= 0; got {damping_ratio!r}.")
    alpha = float(sweep_rate)
    sigma = float(damping_ratio) * float(natural_frequency)
    s = np.asarray(s, dtype=float)
    v = np.exp(-0.25j * np.pi) * np.sqrt(alpha / 2.0) * (s - 1j * sigma / alpha)
    return np.sqrt(np.pi / (2.0 * alpha)) * np.abs(wofz(-1j * v))


def undamped_passage_peak(natural_frequency, sweep_rate) -> tuple[float, float, float]:
    """(largest |I| [s], its time after the resonance [s], |I| left after the passage [s]) of an undamped
    passage at the rate ``sweep_rate`` [rad/s^2]: the largest distance of the Cornu spiral's points
    C(u) + i S(u) from its start -(1 + i)/2, at u = s sqrt(alpha / pi) (Lewis 1932; Abramowitz & Stegun 7.3).

    Examples
    --------
    >>> peak, when, after = undamped_passage_peak(100.0, 1.0)
    >>> round(float(peak / after), 4), round(float(when * np.sqrt(1.0 / np.pi)), 3)
    (1.1707, 1.217)
    """
    from scipy.optimize import minimize_scalar
    from scipy.special import fresnel

    _check("natural frequency", natural_frequency, "rad/s")
    _check("sweep rate", sweep_rate, "rad/s^2")
    alpha = float(sweep_rate)

    def distance(u):
        s_val, c_val = fresnel(u)
        return -float(np.hypot(c_val + 0.5, s_val + 0.5))

    best = minimize_scalar(distance, bounds=(0.5, 2.0), method="bounded", options={"xatol": 1e-10})
    scale = np.sqrt(np.pi / alpha)
    return -float(best.fun) * scale, float(best.x) * scale, float(np.sqrt(2.0) * scale)


def vibration_torque(speed, unbalance, mass, stiffness, damping):
    """Mean torque [N*m] the vibration of an unbalanced rotor's elastic base takes from its drive,
    S = c Omega X^2 / 2, X = m e Omega^2 / sqrt((k - M Omega^2)^2 + (c Omega)^2) (Kononenko 1969, ch. 2).

    Parameters
    ----------
    speed : Omega [rad/s] >= 0
    unbalance : m e [kg*m] > 0
    mass : M [kg] > 0, everything that moves with the base (the unbalance included)
    stiffness : k [N/m] > 0
    damping : c [N*s/m] >= 0

    Examples
    --------
    At the resonance X = m e w / c, so S = m^2 e^2 w^3 / (2 c):

    >>> round(float(vibration_torque(50.0, 0.1, 100.0, 2.5e5, 200.0)), 6)
    3.125
    """
    w = np.asarray(speed, dtype=float)
    x = unbalance * w * w / np.hypot(stiffness - mass * w * w, damping * w)
    return 0.5 * damping * w * x * x
