"""Periodic curves over a machine cycle: reduced inertia, moments and tabulated crank-effort diagrams.

A cycle may span more than one revolution (a four-stroke engine repeats after 720°, a machine whose torque varies
over three revolutions after 1080°). A :class:`PeriodicCurve` holds the values at nodes over one period and
interpolates them piece by piece:

* ``hermite``: cubic Hermite pieces through the values and their exact slopes (used for the reduced inertia and the
  potential energy, whose derivatives the kinematics give exactly); error O(h^4).
* ``spline``: the periodic cubic spline through the values (the default for smooth tabulated diagrams). Its slopes
  come from :class:`scipy.interpolate.CubicSpline` with periodic end conditions.
* ``linear``: straight pieces, for diagrams drawn as straight segments (triangles, ramps) and for loads that switch
  on and off, where a spline would ring.

Integration rule (chosen for tabulated data): the work and the mean torque are the exact integrals of the
interpolant. For a periodic spline on evenly spaced nodes this equals the periodic trapezoidal sum, exact for
every harmonic below half the number of samples; for linear pieces it is the trapezoidal rule, exact for straight
segments. A plain average of the samples of a closed table that repeats its first angle at the end (0°…360° in
10° steps, 37 values) counts that point twice and is off by about 1 %; here the repeated end point is recognised
and dropped. The extremes of the energy excess, which lie between samples where the torque crosses its mean, are
located on the interpolant, not at the samples (Simpson's rule gives the work only at every second node).

Source of the energy-excess construction: Khurmi & Gupta, *Theory of Machines*, S. Chand, ch. 16
(turning-moment diagram, maximum fluctuation of energy).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError, check_finite

KINDS = ("hermite", "spline", "linear")


@dataclass(frozen=True)
class PeriodicCurve:
    """Values ``y`` [any unit] at nodes ``x`` [rad] over one ``period`` [rad], interpolated piece by piece.

    ``y`` and ``slope`` are shaped (N, M): N design variants (1 for one design) by M nodes. ``slope`` [unit/rad]
    is None for linear pieces. Queries ``phi`` are shaped (N,), (N, K) or (K,) (then shared by all designs).
    """

    x: np.ndarray
    y: np.ndarray
    slope: np.ndarray | None
    period: float
    slope_end: np.ndarray | None = None  # slope at the right end of each piece (default: the next node's)

    def _ends(self):
        """Slopes at the left and right end of every piece, (N, M) each."""
        s = self.slope
        if s is None:
            return None, None
        return s, (np.roll(s, -1, axis=1) if self.slope_end is None else self.slope_end)

    # --- construction -------------------------------------------------------------------------------------
    @classmethod
    def hermite(cls, x, y, slope, period: float) -> PeriodicCurve:
        """Cubic Hermite pieces through values ``y`` and exact slopes ``slope`` at nodes ``x``."""
        x, y = _nodes(x, y, period)
        s = np.broadcast_to(np.atleast_2d(np.asarray(slope, dtype=float)), y.shape).copy()
        return cls(x, y, s, float(period))

    @classmethod
    def spline(cls, x, y, period: float) -> PeriodicCurve:
        """The periodic cubic spline through ``y`` at nodes ``x``."""
        from scipy.interpolate import CubicSpline

        x, y = _nodes(x, y, period)
        if x.size < 3:
            return cls.linear(x, y, period)
        xs = np.append(x, x[0] + period)
        ys = np.concatenate([y, y[:, :1]], axis=1)
        spl = CubicSpline(xs, ys, axis=1, bc_type="periodic")
        return cls(x, y, spl(x, 1), float(period))

    @classmethod
    def linear(cls, x, y, period: float) -> PeriodicCurve:
        """Straight pieces between the nodes (closing from the last node back to the first)."""
        x, y = _nodes(x, y, period)
        return cls(x, y, None, float(period))

    @classmethod
    def smooth_with_jumps(cls, x, y, period: float, jumps) -> PeriodicCurve:
        """Cubic splines through the nodes between jumps; straight pieces across the intervals that hold a jump
        (``jumps``: True for the interval from node k to k+1), e.g. a load switched on and off."""
        from scipy.interpolate import CubicSpline

        x, y = _nodes(x, y, period)
        m = x.size
        jumps = np.asarray(jumps, dtype=bool)
        if not jumps.any():
            return cls.spline(x, y, period)
        xs = np.append(x, x[0] + period)
        h = np.diff(xs)
        secant = (np.roll(y, -1, axis=1) - y) / h
        d0, d1 = secant.copy(), secant.copy()
        first = int(np.flatnonzero(jumps)[0]) + 1  # a node just after a jump starts a smooth run
        order = (np.arange(m) + first) % m
        run: list[int] = []
        for step, k in enumerate(order):
            run.append(int(k))
            ends_run = jumps[k] or step == m - 1
            if not ends_run:
                continue
            nodes = np.array(run)  # nodes of a smooth run; intervals between consecutive ones are smooth
            if nodes.size >= 3:
                xr = x[nodes] + period * np.cumsum(np.r_[0, np.diff(x[nodes]) < 0])  # unwrapped through 2 pi
                spl = CubicSpline(xr, y[:, nodes], axis=1, bc_type="not-a-knot")
                slopes = spl(xr, 1)
                d0[:, nodes[:-1]] = slopes[:, :-1]
                d1[:, nodes[:-1]] = slopes[:, 1:]
            run = []
        return cls(x, y, d0, float(period), d1)

    @classmethod
    def constant(cls, value, period: float = 2.0 * np.pi) -> PeriodicCurve:
        """A constant (one value, or one per design)."""
        v = np.atleast_1d(np.asarray(value, dtype=float))[:, None]
        return cls(np.array([0.0]), v, np.zeros_like(v), float(period))

    @property
    def designs(self) -> int:
        return self.y.shape[0]

    # --- evaluation ---------------------------------------------------------------------------------------
    def _locate(self, phi):
        phi = np.asarray(phi, dtype=float)
        x, period = self.x, self.period
        u = np.mod(phi - x[0], period) + x[0]
        k = np.clip(np.searchsorted(x, u, side="right") - 1, 0, x.size - 1)
        nxt = np.where(k + 1 < x.size, k + 1, 0)
        x1 = np.where(k + 1 < x.size, x[nxt], x[0] + period)
        h = x1 - x[k]
        t = (u - x[k]) / h
        if self.y.shape[0] == 1:
            rows: object = 0
        elif phi.ndim >= 1 and phi.shape[0] == self.y.shape[0]:
            rows = np.arange(self.y.shape[0]).reshape((-1,) + (1,) * (phi.ndim - 1))
        else:  # (K,) queries shared by every design -> (N, K)
            rows = np.arange(self.y.shape[0])[:, None]
        return k, nxt, h, t, rows, phi

    def _pieces(self, phi):
        k, nxt, h, t, rows, phi = self._locate(phi)
        y0, y1 = self.y[rows, k], self.y[rows, nxt]
        left, right = self._ends()
        if left is None:
            d0 = d1 = None
        else:
            d0, d1 = left[rows, k], right[rows, k]
        return y0, y1, d0, d1, h, t, phi

    def __call__(self, phi) -> np.ndarray:
        """Values at ``phi`` [rad]."""
        y0, y1, d0, d1, h, t, _ = self._pieces(phi)
        if d0 is None:
            return y0 + t * (y1 - y0)
        t2, t3 = t * t, t * t * t
        return (2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + t) * h * d0 + (3 * t2 - 2 * t3) * y1 + (t3 - t2) * h * d1

    def derivative(self, phi) -> np.ndarray:
        """Slope d(value)/d(phi) [unit/rad] of the interpolant at ``phi``."""
        y0, y1, d0, d1, h, t, _ = self._pieces(phi)
        if d0 is None:
            return (y1 - y0) / h + 0.0 * t
        t2 = t * t
        return (6 * t2 - 6 * t) * (y0 - y1) / h + (3 * t2 - 4 * t + 1) * d0 + (3 * t2 - 2 * t) * d1

    def _piece_integrals(self) -> np.ndarray:
        x, y = self.x, self.y
        h = np.diff(np.append(x, x[0] + self.period))
        y1 = np.roll(y, -1, axis=1)
        out = h * (y + y1) / 2.0
        left, right = self._ends()
        if left is not None:
            out = out + h * h * (left - right) / 12.0
        return out

    def cycle_integral(self) -> np.ndarray:
        """Integral over one period [unit*rad], one per design (N,)."""
        return self._piece_integrals().sum(axis=1)

    def mean(self) -> np.ndarray:
        """Mean over one period [unit], one per design (N,)."""
        return self.cycle_integral() / self.period

    def integral(self, phi) -> np.ndarray:
        """Integral from the first node ``x[0]`` to ``phi`` [unit*rad] (growing over later periods)."""
        pieces = self._piece_integrals()
        cum = np.concatenate([np.zeros((pieces.shape[0], 1)), np.cumsum(pieces, axis=1)], axis=1)
        total = cum[:, -1]
        y0, y1, d0, d1, h, t, phi = self._pieces(phi)
        k, _, _, _, rows, _ = self._locate(phi)
        turns = np.floor((phi - self.x[0]) / self.period)
        t2, t3, t4 = t * t, t**3, t**4
        if d0 is None:
            part = h * (y0 * (t - t2 / 2) + y1 * t2 / 2)
        else:
            part = h * (
                y0 * (t - t3 + t4 / 2) + y1 * (t3 - t4 / 2)
                + h * d0 * (t2 / 2 - 2 * t3 / 3 + t4 / 4) + h * d1 * (t4 / 4 - t3 / 3)
            )
        tot = total[0] if isinstance(rows, int) else total[rows]
        return turns * tot + cum[rows, k] + part

    def take(self, index) -> PeriodicCurve:
        """The curve of the designs ``index``."""
        s = None if self.slope is None else np.atleast_2d(self.slope[index])
        e = None if self.slope_end is None else np.atleast_2d(self.slope_end[index])
        return PeriodicCurve(self.x, np.atleast_2d(self.y[index]), s, self.period, e)


def _nodes(x, y, period):
    x = np.asarray(x, dtype=float).ravel()
    y = np.atleast_2d(np.asarray(y, dtype=float))
    if y.shape[-1] != x.size:
        raise InputError(f"A curve needs one value per node; got {y.shape[-1]} values for {x.size} nodes.")
    return x, y


def torque_table(angles, torque, *, period: float | None = None, interpolation: str = "spline") -> PeriodicCurve:
    """A crank-effort (turning-moment) diagram from a table: torque [N*m] against crank angle [rad].

    Parameters
    ----------
    angles : crank angles [rad], increasing, covering one cycle; the end of the cycle may repeat the start
        (0 and 360°): it is then dropped, and its torque must equal the first one.
    torque : torque [N*m] at each angle (positive drives the crank).
    period : length of the cycle [rad]; default 2*pi, or the span of ``angles`` if that is longer (720° for a
        four-stroke engine, 1080° for a cycle of three revolutions).
    interpolation : "spline" (periodic cubic spline, for smooth diagrams) or "linear" (straight segments).

    Returns
    -------
    PeriodicCurve of the torque, with ``mean()`` [N*m], ``cycle_integral()`` (work per cycle) [J] and
    ``integral(phi)`` [J].

    Source: Khurmi & Gupta, *Theory of Machines*, ch. 16 (turning-moment diagrams). Valid for tables with at
    least 2 points and a cycle of at least the span of the angles.

    Examples
    --------
    >>> import numpy as np
    >>> table = torque_table(np.radians([0, 90, 180, 270, 360]), [0.0, 100.0, 0.0, -100.0, 0.0],
    ...                      interpolation="linear")
    >>> float(table.mean()[0]), round(float(table.integral(np.pi)), 6)
    (0.0, 157.079633)
    """
    if interpolation not in ("spline", "linear"):
        raise InputError(f"The interpolation of a torque table must be 'spline' or 'linear'; got {interpolation!r}.")
    a = np.asarray(angles, dtype=float).ravel()
    t = np.asarray(torque, dtype=float).ravel()
    check_finite("crank angles of the torque table", a, "rad")
    check_finite("torques of the torque table", t, "N*m")
    if a.size != t.size:
        raise InputError(f"A torque table needs one torque per angle; got {t.size} torques for {a.size} angles.")
    if a.size < 2:
        raise InputError(f"A torque table needs at least 2 points; got {a.size}.")
    if np.any(np.diff(a) <= 0):
        raise InputError("The angles of a torque table must increase strictly; got "
                         f"{np.degrees(a[np.flatnonzero(np.diff(a) <= 0)[0] + 1]):g}° after a larger or equal one.")
    span = a[-1] - a[0]
    if period is None:
        period = max(2.0 * np.pi, span)
        if span > 2.0 * np.pi + 1e-9:
            # a table of several revolutions: the cycle is a whole number of revolutions that covers it
            period = 2.0 * np.pi * np.ceil(span / (2.0 * np.pi) - 1e-9)
    if not period > 0 or span > period * (1 + 1e-12):
        raise InputError(f"The period of a torque table must cover its angles ({np.degrees(span):g}°); "
                         f"got {np.degrees(period):g}°.")
    if np.isclose(span, period, rtol=1e-9, atol=1e-12):
        if not np.isclose(t[-1], t[0], rtol=1e-9, atol=1e-9 * max(1.0, float(np.max(np.abs(t))))):
            raise InputError(
                f"A torque table that closes its cycle must end with the torque it starts with; got {t[0]:g} N*m "
                f"at {np.degrees(a[0]):g}° and {t[-1]:g} N*m at {np.degrees(a[-1]):g}°."
            )
        a, t = a[:-1], t[:-1]
    build = PeriodicCurve.spline if interpolation == "spline" else PeriodicCurve.linear
    return build(a, t, float(period))


def diagram_energy_fluctuation(curve: Curve, mean=None, samples_per_piece: int = 32) -> np.ndarray:
    """Maximum fluctuation of energy ΔE [J] of a turning-moment diagram about its mean (or ``mean`` [N*m]).

    ΔE = max(E) - min(E) with E(phi) = integral of (T - T_mean) dphi over the cycle (Khurmi & Gupta, *Theory of
    Machines*, ch. 16). The extremes are found on the interpolant between the nodes. For samples of a torque over
    evenly spaced crank angles (an analysis's driving torque) use :func:`machdyn.linkage.energy_fluctuation`; this
    one reads a diagram given as a table (:func:`torque_table`) or a reduced machine's moment.

    Examples
    --------
    >>> import numpy as np
    >>> phi = np.linspace(0, 2 * np.pi, 73)
    >>> curve = torque_table(phi, 5000 + 1500 * np.sin(3 * phi))
    >>> round(float(diagram_energy_fluctuation(curve)[0]), 1)   # exact: 1000 J; spline through 5° samples
    1000.0
    """
    grid = fine_grid(curve, samples_per_piece)
    level = curve.mean() if mean is None else np.atleast_1d(np.asarray(mean, dtype=float))
    e = curve.integral(grid[None, :] if curve.designs == 1 else grid) - level[:, None] * (grid - curve.x[0])
    return e.max(axis=-1) - e.min(axis=-1)


def fine_grid(curve: Curve, samples_per_piece: int = 16, min_points: int = 8192) -> np.ndarray:
    """Angles [rad] over one period with at least ``samples_per_piece`` points inside every piece (and every
    node), and at least ``min_points`` over the period (long straight pieces get more), where extremes are
    searched: the error of an extreme found on this grid falls with the square of its spacing."""
    x = np.append(curve.x, curve.x[0] + curve.period)
    lengths = np.diff(x)
    counts = np.maximum(samples_per_piece, np.ceil(min_points * lengths / curve.period)).astype(int)
    # the points of every piece in one go: piece index and position inside the piece for each point
    piece = np.repeat(np.arange(lengths.size), counts)
    inside = np.arange(piece.size) - np.repeat(np.cumsum(counts) - counts, counts)
    return x[piece] + lengths[piece] * inside / counts[piece]


def indicator_crank_effort(crank_angle, pressure, piston_area: float, crank: float, rod: float) -> np.ndarray:
    """Crank effort [N*m] of a slider-crank from the gas pressure read off an indicator diagram.

    T = p A dx/dphi with x the piston's travel from inner dead centre and the exact velocity ratio of a centred
    slider-crank, dx/dphi = r sin(phi) (1 + r cos(phi) / sqrt(l^2 - r^2 sin^2(phi))) (Khurmi &
    Gupta, *Theory of Machines*, ch. 15, crank effort from the piston effort).

    Parameters
    ----------
    crank_angle : crank angles [rad] from inner dead centre at which the pressure is read.
    pressure : gauge gas pressure [Pa] on the piston at those angles (from the indicator diagram).
    piston_area : piston area [m^2] > 0.
    crank : crank radius r [m] > 0.
    rod : connecting-rod length l [m] > r.

    Examples
    --------
    >>> import numpy as np
    >>> round(float(indicator_crank_effort(np.pi / 2, 1.0e6, 0.01, 0.1, 0.4)), 6)   # p A r at 90°
    1000.0
    """
    check_finite("pressure", pressure, "Pa")
    for name, value in (("piston area", piston_area), ("crank radius", crank), ("rod length", rod)):
        if not np.all(np.asarray(value) > 0):
            raise InputError(f"The {name} must be > 0; got {value!r}.")
    if not rod > crank:
        raise InputError(f"The rod length must exceed the crank radius ({crank:g} m); got {rod:g} m.")
    phi = np.asarray(crank_angle, dtype=float)
    s, c = np.sin(phi), np.cos(phi)
    ratio = crank * s * (1.0 + crank * c / np.sqrt(rod * rod - (crank * s) ** 2))
    return np.asarray(pressure, dtype=float) * piston_area * ratio


@dataclass(frozen=True)
class FourierCurve:
    """A smooth periodic curve as its trigonometric interpolant through M evenly spaced samples from phi = 0:
    y(phi) = a0 + sum(a_k cos(k w phi) + b_k sin(k w phi)), w = 2 pi / period, harmonics below the round-off
    level dropped. Exact (to rounding) for the smooth periodic functions of a linkage that turns fully, and
    infinitely differentiable, so an integrator takes long steps through it. Same interface as
    :class:`PeriodicCurve`; ``x``, ``y`` keep the samples."""

    x: np.ndarray
    y: np.ndarray
    a0: np.ndarray
    a: np.ndarray
    b: np.ndarray
    period: float
    slope = None

    @classmethod
    def from_samples(cls, y, period: float, cutoff: float = 1e-14) -> FourierCurve:
        y = np.atleast_2d(np.asarray(y, dtype=float))
        m = y.shape[1]
        c = np.fft.rfft(y, axis=1) / m
        a, b = 2.0 * c.real[:, 1:], -2.0 * c.imag[:, 1:]
        if m % 2 == 0:  # the Nyquist term is not doubled and has no sine part
            a[:, -1] /= 2.0
            b[:, -1] = 0.0
        amp = np.hypot(a, b).max(axis=0)
        scale = max(float(np.max(np.abs(y))), np.finfo(float).tiny)
        keep = np.flatnonzero(amp > cutoff * scale)
        k = int(keep[-1]) + 1 if keep.size else 0
        x = np.arange(m) * (period / m)
        return cls(x, y, c.real[:, 0].copy(), a[:, :k].copy(), b[:, :k].copy(), float(period))

    @property
    def designs(self) -> int:
        return self.y.shape[0]

    @property
    def harmonics(self) -> int:
        return self.a.shape[1]

    @property
    def resolved(self) -> bool:
        """False if the highest harmonics still carry weight (a curve with a kink or jump, not smooth)."""
        m = self.y.shape[1]
        return self.harmonics < int(0.8 * (m // 2))

    def _wave(self) -> np.ndarray:
        return np.arange(1, self.harmonics + 1) * (2.0 * np.pi / self.period)

    def _eval(self, phi, ca, cb, c0):
        phi = np.asarray(phi, dtype=float)
        k = self._wave()
        arg = phi[..., None] * k
        cos, sin = np.cos(arg), np.sin(arg)
        n = self.designs
        if phi.ndim >= 1 and phi.shape[0] == n and n > 1:
            shape = (n,) + (1,) * (phi.ndim - 1)
            return c0.reshape(shape) + np.einsum("n...k,nk->n...", cos, ca) + np.einsum("n...k,nk->n...", sin, cb)
        if n == 1:
            return c0[0] + cos @ ca[0] + sin @ cb[0]
        return c0[:, None] + (cos @ ca.T + sin @ cb.T).T

    def _on_nodes(self, phi) -> bool:
        """True if ``phi`` holds exactly the sample nodes (per design or shared): the curve's values there are
        found by one inverse FFT instead of a sum of cosines and sines."""
        phi = np.asarray(phi)
        if phi.ndim not in (1, 2) or phi.shape[-1] != self.x.size:
            return False
        if phi.ndim == 2 and phi.shape[0] != self.designs and self.designs != 1:
            return False
        return bool(np.array_equal(phi if phi.ndim == 1 else phi[0], self.x)
                    and (phi.ndim == 1 or np.all(phi == phi[:1])))

    def _nodes_eval(self, phi, ca, cb, c0):
        m = self.x.size
        spectrum = np.zeros((self.designs, m // 2 + 1), dtype=complex)
        spectrum[:, 0] = c0 * m
        k = self.harmonics
        spectrum[:, 1:k + 1] = 0.5 * m * (ca - 1j * cb)
        if m % 2 == 0 and k >= m // 2:  # the Nyquist term is not halved
            spectrum[:, m // 2] = m * ca[:, m // 2 - 1]
        out = np.fft.irfft(spectrum, n=m, axis=1)
        if np.ndim(phi) == 1:
            return out[0] if self.designs == 1 else out
        return np.broadcast_to(out, np.shape(phi)).copy()

    def __call__(self, phi) -> np.ndarray:
        if self._on_nodes(phi):
            return self._nodes_eval(phi, self.a, self.b, self.a0)
        return self._eval(phi, self.a, self.b, self.a0)

    def derivative(self, phi) -> np.ndarray:
        k = self._wave()
        if self._on_nodes(phi):
            return self._nodes_eval(phi, self.b * k, -self.a * k, 0.0 * self.a0)
        return self._eval(phi, self.b * k, -self.a * k, 0.0 * self.a0)

    def integral(self, phi) -> np.ndarray:
        """Integral from 0 to ``phi``."""
        k = self._wave()
        phi = np.asarray(phi, dtype=float)
        lin = self._eval(phi, 0.0 * self.a, 0.0 * self.b, self.a0) * phi
        per = self._eval(phi, self.b / -k, self.a / k, (self.b / k).sum(axis=1))
        return lin + per

    def cycle_integral(self) -> np.ndarray:
        return self.a0 * self.period

    def mean(self) -> np.ndarray:
        return self.a0.copy()

    def take(self, index) -> FourierCurve:
        pick = np.atleast_1d(np.arange(self.designs)[index])
        return FourierCurve(self.x, self.y[pick], self.a0[pick], self.a[pick], self.b[pick], self.period)


#: Any periodic curve of the equivalent machine.
Curve = PeriodicCurve | FourierCurve
