"""Follower motion laws: normalised displacement and its exact derivatives over one rise.

Every law is written for a unit rise over a unit interval, x = (theta - theta_0)/beta in [0, 1] [-], returning
y(x) [-] and its derivatives y', y'', y''' with respect to x. A rise of h [m or rad] over a cam angle beta [rad]
is then s = h y, ds/dtheta = h y'/beta, d2s/dtheta2 = h y''/beta^2, d3s/dtheta3 = h y'''/beta^3; a return is
s = h (1 - y). Sources (all laws, their peak coefficients and their boundary conditions):

* uniform velocity, simple harmonic, cycloidal, 3-4-5 and 4-5-6-7 polynomials, modified trapezoid and modified
  sine: R. L. Norton, *Design of Machinery*, 5th ed., McGraw-Hill, ch. 8, §8.3 "Double-dwell cam design"
  (eqs 8.3 to 8.25) and table 8-2 of the peak factors (Ca = 4.888 modified trapezoid, 5.528 modified sine,
  6.283 cycloidal, 5.774 = 10/sqrt(3) 3-4-5, 7.513 4-5-6-7);
* the same laws and the modified trapezoid's and modified sine's construction from sine and constant
  acceleration pieces in the ratios 1/8, 1/4, 1/8: H. A. Rothbart (ed.), *Cam Design Handbook*, McGraw-Hill
  2004, ch. 3 "Cam motion laws";
* the parabolic law (uniform acceleration and retardation): Khurmi & Gupta, *Theory of Machines*, S. Chand,
  ch. 20, §20.8.

Valid for 0 <= x <= 1; outside it the caller holds the end values (a dwell).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..errors import InputError

#: (y, y', y'', y''') of the normalised law at x (arrays).
Values = tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]


def uniform(x: np.ndarray) -> Values:
    """Uniform (constant) velocity: y = x. Velocity jumps at both ends (infinite acceleration): shown to say why
    not (Norton §8.3, the "bad" cam)."""
    z = np.zeros_like(x)
    return x.copy(), z + 1.0, z, z


def parabolic(x: np.ndarray) -> Values:
    """Uniform acceleration and retardation: y = 2x^2 for x <= 1/2, 1 - 2(1-x)^2 after (Khurmi & Gupta §20.8);
    peak y'' = 4, acceleration jumps at 0, 1/2 and 1."""
    lo = x <= 0.5
    y = np.where(lo, 2.0 * x**2, 1.0 - 2.0 * (1.0 - x) ** 2)
    y1 = np.where(lo, 4.0 * x, 4.0 * (1.0 - x))
    y2 = np.where(lo, 4.0, -4.0)
    return y, y1, y2, np.zeros_like(x)


def harmonic(x: np.ndarray) -> Values:
    """Simple harmonic: y = (1 - cos pi x)/2 (Norton eq 8.6); acceleration jumps at the ends of a double dwell."""
    p = np.pi
    c, s = np.cos(p * x), np.sin(p * x)  # once each: the law is evaluated on large arrays of a population
    return (1.0 - c) / 2.0, p / 2.0 * s, p**2 / 2.0 * c, -(p**3) / 2.0 * s


def cycloidal(x: np.ndarray) -> Values:
    """Cycloidal: y = x - sin(2 pi x)/(2 pi) (Norton eq 8.8); continuous acceleration, peak y'' = 2 pi."""
    t = 2.0 * np.pi
    s, c = np.sin(t * x), np.cos(t * x)  # once each: the law is evaluated on large arrays of a population
    return x - s / t, 1.0 - c, t * s, t**2 * c


def _poly(coeffs: dict[int, float]) -> Callable[[np.ndarray], Values]:
    def law(x: np.ndarray) -> Values:
        out = [np.zeros_like(x) for _ in range(4)]
        for n, c in coeffs.items():
            out[0] = out[0] + c * x**n
            out[1] = out[1] + c * n * x ** (n - 1)
            out[2] = out[2] + c * n * (n - 1) * x ** (n - 2)
            out[3] = out[3] + c * n * (n - 1) * (n - 2) * x ** max(n - 3, 0)
        return out[0], out[1], out[2], out[3]

    return law


#: 3-4-5 polynomial y = 10x^3 - 15x^4 + 6x^5 (Norton eq 8.23); zero velocity and acceleration at both ends.
poly345 = _poly({3: 10.0, 4: -15.0, 5: 6.0})
#: 4-5-6-7 polynomial y = 35x^4 - 84x^5 + 70x^6 - 20x^7 (Norton eq 8.25); zero jerk at both ends too.
poly4567 = _poly({4: 35.0, 5: -84.0, 6: 70.0, 7: -20.0})


@dataclass(frozen=True)
class _Piece:
    """y'' = A + B sin(w u) + C cos(w u), u = x - x0, on [x0, x1]."""

    x0: float
    x1: float
    a: float
    b: float
    c: float
    w: float


def _trig_pieces(pieces: tuple[_Piece, ...]) -> Callable[[np.ndarray], Values]:
    """A law whose acceleration is made of sine and constant pieces, integrated exactly piece by piece and
    scaled so that y(1) = 1 (this fixes the peak factor Ca without rounding)."""
    starts = []
    v0 = y0 = 0.0
    for p in pieces:
        starts.append((v0, y0))
        u = p.x1 - p.x0
        v0, y0 = _integrate(p, np.asarray(u), v0, y0)[1:3]
        v0, y0 = float(v0), float(y0)
    scale = 1.0 / y0

    def law(x: np.ndarray) -> Values:
        out = [np.zeros_like(x) for _ in range(4)]
        for p, (v, y) in zip(pieces, starts, strict=True):
            inside = (x >= p.x0) & (x <= p.x1) if p.x1 >= 1.0 else (x >= p.x0) & (x < p.x1)
            j, v1, y1, a = _integrate(p, x - p.x0, v, y)
            for k, val in enumerate((y1, v1, a, j)):
                out[k] = np.where(inside, val * scale, out[k])
        return out[0], out[1], out[2], out[3]

    return law


def _integrate(p: _Piece, u, v0: float, y0: float):
    w = p.w
    s, c = np.sin(w * u), np.cos(w * u)
    acc = p.a + p.b * s + p.c * c
    jerk = p.b * w * c - p.c * w * s
    vel = v0 + p.a * u + p.b / w * (1.0 - c) + p.c / w * s
    disp = y0 + v0 * u + p.a * u**2 / 2.0 + p.b / w * (u - s / w) + p.c / w**2 * (1.0 - c)
    return jerk, vel, disp, acc


_Q = 4.0 * np.pi
#: Modified trapezoid: quarter sines over 1/8, constant acceleration over 1/4 (Rothbart ch. 3; Norton eq 8.15).
modified_trapezoid = _trig_pieces((
    _Piece(0.0, 0.125, 0.0, 1.0, 0.0, _Q),
    _Piece(0.125, 0.375, 1.0, 0.0, 0.0, _Q),
    _Piece(0.375, 0.625, 0.0, 0.0, 1.0, _Q),
    _Piece(0.625, 0.875, -1.0, 0.0, 0.0, _Q),
    _Piece(0.875, 1.0, 0.0, 0.0, -1.0, _Q),
))
#: Modified sine: quarter sines of period 1/2 over the first and last 1/8, a half sine of period 3/2 between
#: (Rothbart ch. 3; Norton eq 8.18).
modified_sine = _trig_pieces((
    _Piece(0.0, 0.125, 0.0, 1.0, 0.0, _Q),
    _Piece(0.125, 0.875, 0.0, 0.0, 1.0, _Q / 3.0),
    _Piece(0.875, 1.0, 0.0, 0.0, -1.0, _Q),
))

#: The laws by name (as written in a problem file).
LAWS: dict[str, Callable[[np.ndarray], Values]] = {
    "uniform": uniform,
    "parabolic": parabolic,
    "harmonic": harmonic,
    "cycloidal": cycloidal,
    "poly345": poly345,
    "poly4567": poly4567,
    "modified_trapezoid": modified_trapezoid,
    "modified_sine": modified_sine,
}


def law(name: str) -> Callable[[np.ndarray], Values]:
    """The motion law called ``name`` (one of :data:`LAWS`)."""
    try:
        return LAWS[name]
    except KeyError:
        raise InputError(f"Unknown motion law {name!r}; expected one of {', '.join(LAWS)}.") from None


def normalised(name: str, x) -> Values:
    """(y, y', y'', y''') of law ``name`` at x in [0, 1] (clipped), each as a float array.

    >>> round(float(normalised("cycloidal", 0.25)[2]), 4)  # peak acceleration factor 2 pi
    6.2832
    """
    arr = np.clip(np.asarray(x, dtype=float), 0.0, 1.0)
    return law(name)(arr)
