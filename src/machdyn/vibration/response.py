"""Steady-state response of a frame on mounts to the mechanism's periodic shaking loads.

The mechanism's frame force and shaking moment are periodic in the crank angle; their harmonics
(:func:`machdyn.linkage.harmonics`) are loads Re(Q_k e^{i k Omega t}) on the frame. Each order is solved
on its own (linear system, superposition):

    (K - (k Omega)^2 M + i k Omega C) q_k = Q_k

(Rao, *Mechanical Vibrations*, 5th ed., 2011, §6.14, harmonic response of multi-degree-of-freedom systems).
The mechanism is taken as driven at constant crank speed and the frame's motion as too small to change the
mechanism's loads (the usual decoupling of a machine from its foundation; Harris' *Shock and Vibration
Handbook*, 6th ed., ch. 30).

RMS values of a periodic response are exact sums over the orders: rms = sqrt(sum |a_k|^2 / 2) (Parseval).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError, check_finite
from ..linkage import harmonics
from .frame import Frame
from .modes import check_supported, modes

__all__ = [
    "Comparison",
    "FrameResponse",
    "ShakingLoads",
    "compare",
    "check_resonance",
    "harmonic_loads",
    "reduction_percent",
    "shaking_loads",
    "steady_state",
    "transmissibility",
]


def transmissibility(frequency_ratio, damping_ratio):
    """Force (and motion) transmissibility of a single-degree-of-freedom isolator.

    T = sqrt(1 + (2 zeta r)^2) / sqrt((1 - r^2)^2 + (2 zeta r)^2), the ratio of the force amplitude through
    spring and damper to the applied force amplitude (Rao, *Mechanical Vibrations*, 5th ed., 2011, eq. (9.94);
    Thomson & Dahleh, *Theory of Vibration with Applications*, 5th ed., eq. (3.5-3)).

    Parameters
    ----------
    frequency_ratio : r = omega / omega_n [-] >= 0
    damping_ratio : zeta [-] >= 0

    Examples
    --------
    >>> round(float(transmissibility(2.0, 0.0)), 6)
    0.333333
    >>> round(float(transmissibility(np.sqrt(2.0), 0.3)), 6)
    1.0
    """
    r = np.asarray(frequency_ratio, dtype=float)
    z = np.asarray(damping_ratio, dtype=float)
    check_finite("frequency ratio", r)
    check_finite("damping ratio", z)
    if np.any(r < 0) or np.any(z < 0):
        raise InputError(f"The frequency ratio and damping ratio must be >= 0; got {r.min():g} and {z.min():g}.")
    num = 1.0 + (2 * z * r) ** 2
    den = (1.0 - r**2) ** 2 + (2 * z * r) ** 2
    if np.any(den == 0):
        raise InputError("An undamped isolator at resonance (r = 1, zeta = 0) has unbounded transmissibility.")
    return np.sqrt(num / den)


def reduction_percent(before, after):
    """Reduction (before - after) / before x 100 [%] of a vibration level, as seed 002 reports it.

    Seed 002 (Yuan Rui et al.), §4: vibration velocity 0.5129 -> 0.3546 cm/s is a 30.86 % reduction (the
    paper prints 30.89 %, see ``seed-reproduction.md`` 002.1 item 13).

    Parameters
    ----------
    before : level before the change (any unit) > 0
    after : level after the change (same unit) >= 0

    Examples
    --------
    >>> round(float(reduction_percent(0.5129, 0.3546)), 4)
    30.8637
    """
    b = np.asarray(before, dtype=float)
    a = np.asarray(after, dtype=float)
    check_finite("level before", b)
    check_finite("level after", a)
    if np.any(b <= 0):
        raise InputError(f"The level before must be > 0 to give a reduction in %; got {b.min():g}.")
    return (b - a) / b * 100.0


@dataclass(frozen=True)
class ShakingLoads:
    """Harmonic loads on the frame at its reference point: load(t) = Re(Q_k exp(i k Omega t)).

    ``crank_speed`` Omega [rad/s]; ``orders`` k; complex amplitudes ``force_x``, ``force_y`` [N] and
    ``moment`` [N m] (counter-clockwise) about the frame's reference point, one per order. The phase refers to
    crank angle 0 at t = 0.
    """

    crank_speed: float
    orders: np.ndarray
    force_x: np.ndarray
    force_y: np.ndarray
    moment: np.ndarray

    def __post_init__(self) -> None:
        if not (np.isfinite(self.crank_speed) and self.crank_speed > 0):
            raise InputError(f"The crank speed of shaking loads must be > 0 rad/s; got {self.crank_speed!r}.")
        for name in ("orders", "force_x", "force_y", "moment"):
            arr = np.atleast_1d(np.asarray(getattr(self, name)))
            if not np.all(np.isfinite(arr)):
                raise InputError(f"The {name} of shaking loads must be finite; got {arr}.")
            object.__setattr__(self, name, arr)
        n = self.orders.size
        if any(getattr(self, k).shape != (n,) for k in ("force_x", "force_y", "moment")):
            raise InputError("The shaking loads need one force_x, force_y and moment per order.")
        if np.any(self.orders <= 0):
            raise InputError(f"The orders of shaking loads must be > 0; got {self.orders}.")

    @property
    def angular_frequencies(self) -> np.ndarray:
        """k Omega [rad/s]."""
        return self.orders * self.crank_speed

    @property
    def frequencies(self) -> np.ndarray:
        """k Omega / 2 pi [Hz]."""
        return self.angular_frequencies / (2 * np.pi)

    def vector(self) -> np.ndarray:
        """Generalised forces (n_orders x 3) on (x, y, theta)."""
        return np.stack([self.force_x, self.force_y, self.moment], axis=-1).astype(complex)

    def scaled(self, factor: float) -> ShakingLoads:
        return ShakingLoads(self.crank_speed, self.orders, self.force_x * factor, self.force_y * factor,
                            self.moment * factor)


def harmonic_loads(angular_frequency, force_x=0.0, force_y=0.0, moment=0.0) -> ShakingLoads:
    """One harmonic load Re(Q e^{i w t}) on the frame's reference point.

    Parameters
    ----------
    angular_frequency : w [rad/s] > 0
    force_x, force_y : complex amplitudes [N] (e.g. a rotating unbalance m e w^2 along y)
    moment : complex amplitude [N m], counter-clockwise
    """
    return ShakingLoads(float(angular_frequency), np.array([1]), np.array([force_x], dtype=complex),
                        np.array([force_y], dtype=complex), np.array([moment], dtype=complex))


def shaking_loads(analysis, *, orders: int = 6, origin=(0.0, 0.0), angle: float = 0.0,
                  design: int | None = None) -> ShakingLoads:
    """The harmonics of a mechanism's frame force and shaking moment as loads on the frame.

    Parameters
    ----------
    analysis : a constant-speed :class:`machdyn.linkage.Analysis` over one full revolution (evenly spaced crank
        angles, as ``crank_angles`` makes them)
    orders : number of harmonic orders (1..orders) kept
    origin : (x, y) [m] of the mechanism's origin in frame coordinates
    angle : rotation [rad] of the mechanism's axes relative to the frame's
    design : which design variant of a sweep (None for a single design)
    """
    forces = analysis.forces
    kin = analysis.kinematics
    fx, fy = (np.asarray(v, dtype=float) for v in forces.frame_force)
    mz = np.asarray(forces.shaking_moment((0.0, 0.0)), dtype=float)
    speed = np.asarray(kin.speed, dtype=float)
    phi = np.asarray(kin.crank_angle, dtype=float)
    if fx.ndim == 2:
        designs = fx.shape[0]
        if design is None and designs != 1:
            raise InputError(f"The analysis holds {designs} designs; give design= to pick one.")
        d = 0 if design is None else int(design)
        if not 0 <= d < designs:
            raise InputError(f"The design index must be between 0 and {designs - 1}; got {design}.")
        fx, fy, mz = fx[d], fy[d], mz[d]
        speed = speed[d] if speed.ndim and speed.shape[0] == designs else speed
        phi = phi[d] if phi.ndim == 2 else phi
    if speed.size > 1 and not np.allclose(speed, speed.ravel()[0]):
        raise InputError("Shaking loads need a constant crank speed; the analysis has a varying speed.")
    if np.any(np.asarray(getattr(kin, "acceleration", 0.0)) != 0):
        raise InputError("Shaking loads need a constant crank speed; the analysis has a crank acceleration.")
    omega = float(np.ravel(speed)[0])
    if not omega > 0:
        raise InputError(f"Shaking loads need a crank speed > 0 rad/s; got {omega:g} rad/s.")
    ox, oy = (float(v) for v in origin)
    c, s = np.cos(angle), np.sin(angle)
    gx, gy = c * fx - s * fy, s * fx + c * fy
    moment = mz + ox * gy - oy * gx
    parts = [harmonics(v, phi, orders) for v in (gx, gy, moment)]
    qx, qy, qm = (p.amplitude * np.exp(1j * p.phase) for p in parts)
    return ShakingLoads(omega, parts[0].orders, qx, qy, qm)


def _direction_vector(direction) -> np.ndarray | None:
    if direction is None:
        return None
    check_finite("measuring direction", direction, "rad")
    return np.array([np.cos(direction), np.sin(direction)])


def _rms(amplitudes: np.ndarray) -> float:
    """RMS of sum_k Re(a_k e^{i w_k t}) with distinct w_k: sqrt(sum |a_k|^2 / 2); a (n,) or (n, 2)."""
    return float(np.sqrt(0.5 * np.sum(np.abs(amplitudes) ** 2)))


@dataclass(frozen=True)
class FrameResponse:
    """Steady-state response of a frame: complex amplitudes ``coordinates`` (n_orders x 3) of (x, y, theta)
    for each order of ``loads``; derived quantities at any frame point and in every mount."""

    frame: Frame
    loads: ShakingLoads
    coordinates: np.ndarray

    @property
    def angular_frequencies(self) -> np.ndarray:
        return self.loads.angular_frequencies

    def displacement(self, point) -> np.ndarray:
        """Complex amplitudes (n_orders x 2) [m] of the displacement (ux, uy) of frame point ``point``."""
        return self.coordinates @ Frame.point_matrix(point).T

    def velocity(self, point) -> np.ndarray:
        """Complex amplitudes (n_orders x 2) [m/s]: i w u."""
        return 1j * self.angular_frequencies[:, None] * self.displacement(point)

    def acceleration(self, point) -> np.ndarray:
        """Complex amplitudes (n_orders x 2) [m/s^2]: -w^2 u."""
        return -(self.angular_frequencies[:, None] ** 2) * self.displacement(point)

    def _quantity(self, quantity: str, point) -> np.ndarray:
        table = {"displacement": self.displacement, "velocity": self.velocity, "acceleration": self.acceleration}
        if quantity not in table:
            raise InputError(f"The quantity must be one of {', '.join(table)}; got {quantity!r}.")
        return table[quantity](point)

    def amplitudes(self, point, quantity: str = "velocity", direction=None) -> np.ndarray:
        """Amplitude per order at ``point``: along ``direction`` [rad] or, with None, of the vector
        (sqrt(|ax|^2 + |ay|^2), the amplitude of the largest excursion only for a straight-line motion)."""
        a = self._quantity(quantity, point)
        d = _direction_vector(direction)
        return np.abs(a @ d) if d is not None else np.sqrt(np.sum(np.abs(a) ** 2, axis=-1))

    def rms(self, point, quantity: str = "velocity", direction=None, band=None) -> float:
        """RMS [SI] over a revolution of ``quantity`` at ``point``: along ``direction`` [rad], or with None
        of the vector (sqrt(rms_x^2 + rms_y^2)). With ``band`` (low, high) [Hz] only the orders inside it count,
        as a band-limited measurement would see them (ISO 10816-1: 10...1000 Hz)."""
        a = self._quantity(quantity, point)
        if band is not None:
            low, high = (float(v) for v in band)
            f = self.loads.frequencies
            a = a[(f >= low) & (f <= high)]
        d = _direction_vector(direction)
        return _rms(a @ d if d is not None else a)

    def rms_velocity(self, point, direction=None, band=None) -> float:
        """RMS velocity [m/s] at ``point`` (see :meth:`rms`)."""
        return self.rms(point, "velocity", direction, band)

    def rms_acceleration(self, point, direction=None, band=None) -> float:
        """RMS acceleration [m/s^2] at ``point`` (see :meth:`rms`)."""
        return self.rms(point, "acceleration", direction, band)

    def time_history(self, point, quantity: str = "acceleration", samples: int = 360):
        """(t [s], x component, y component) over one crank revolution, ``samples`` points."""
        if int(samples) < 4:
            raise InputError(f"A time history needs at least 4 samples; got {samples}.")
        period = 2 * np.pi / self.loads.crank_speed
        t = np.arange(int(samples)) * period / int(samples)
        a = self._quantity(quantity, point)
        phase = np.exp(1j * np.outer(t, self.angular_frequencies))
        values = (phase @ a).real
        return t, values[:, 0], values[:, 1]

    def mount_deflection(self, name: str) -> np.ndarray:
        """Complex deflection amplitudes (n_orders,) [m] of mount ``name`` along its line."""
        return self.coordinates @ self.frame.mount(name).influence

    def mount_force(self, name: str) -> np.ndarray:
        """Complex amplitudes (n_orders,) [N] of the force mount ``name`` passes to the foundation along its
        line: (k + i w c) delta (spring plus damper)."""
        m = self.frame.mount(name)
        return (m.stiffness + 1j * self.angular_frequencies * m.damping) * self.mount_deflection(name)

    def transmitted_force_rms(self, name: str) -> float:
        """RMS [N] of the dynamic force mount ``name`` passes to the foundation."""
        return _rms(self.mount_force(name))

    def transmitted_force_peak(self, name: str, samples: int = 720) -> float:
        """Largest |force| [N] of mount ``name`` over a revolution (orders added with their phases)."""
        period = 2 * np.pi / self.loads.crank_speed
        t = np.arange(int(samples)) * period / int(samples)
        return float(np.max(np.abs((np.exp(1j * np.outer(t, self.angular_frequencies)) @ self.mount_force(name)).real)))

    def input_energy_per_cycle(self) -> np.ndarray:
        """Work [J] the loads do on the frame over one period of each order: pi Re(i Q^H q)."""
        q = self.coordinates
        return np.pi * np.real(1j * np.sum(np.conj(self.loads.vector()) * q, axis=-1))

    def dissipated_energy_per_cycle(self) -> np.ndarray:
        """Energy [J] the mount dampers dissipate over one period of each order: sum pi w c |delta|^2."""
        w = self.angular_frequencies
        total = np.zeros_like(w, dtype=float)
        for m in self.frame.mounts:
            total += np.pi * w * m.damping * np.abs(self.coordinates @ m.influence) ** 2
        return total


#: The largest dynamic magnification of a frame mode accepted [-]: 1 / (2 zeta) = 1000 at resonance means a modal
#: damping ratio of 0.05 %, below that of any real structure (welded steel about 0.2-1 %; Harris' Shock and
#: Vibration Handbook, 6th ed., table 37.1), so beyond it the model lacks the damping that bounds the response.
MAX_MAGNIFICATION = 1.0e3


def check_resonance(frame: Frame, angular_frequencies, orders) -> None:
    """Raise :class:`~machdyn.errors.InputError` if an order of the excitation is so close to an undamped (or
    nearly undamped) mode of ``frame`` that the response is unbounded or not physical, naming the order, the
    mode and the margin.

    The magnification of mode j at w is D = 1 / sqrt((1 - r^2)^2 + (2 zeta_j r)^2), r = w / omega_j (Rao,
    *Mechanical Vibrations*, 5th ed., 2011, eq. (3.30)); it is refused above :data:`MAX_MAGNIFICATION`.

    Parameters
    ----------
    frame : the frame on its mounts
    angular_frequencies : w_k of the orders [rad/s]
    orders : k of each frequency [-]

    Examples
    --------
    >>> from machdyn.vibration.frame import Frame, Mount
    >>> f = Frame(100.0, 1.0, (Mount("v", (0, 0), np.pi / 2, 1e5), Mount("h", (0, 0), 0.0, 1e5),
    ...                        Mount("t", (1, 0), np.pi / 2, 1e5), Mount("t2", (-1, 0), np.pi / 2, 1e5)))
    >>> check_resonance(f, [20.0], [1])   # 20 rad/s against modes from 31.6 rad/s: D = 1.7
    >>> try:
    ...     check_resonance(f, [31.6227766 * (1 + 1e-6)], [1])
    ... except InputError as exc:
    ...     print(str(exc)[:77])
    Order 1 at 5.033 Hz is within 0.0001 % of mode 1 of frame 'frame' (5.033 Hz,
    """
    md = modes(frame)
    w = np.asarray(angular_frequencies, dtype=float)
    for k, wk in zip(np.atleast_1d(orders), np.atleast_1d(w), strict=True):
        for j, (wn, zeta) in enumerate(zip(md.angular_frequencies, md.damping_ratios, strict=True), start=1):
            if not wn > 0:
                continue
            r = wk / wn
            den = np.hypot(1.0 - r * r, 2.0 * zeta * r)
            if den * MAX_MAGNIFICATION < 1.0:
                shown = "unbounded" if den == 0 else f"{1.0 / den:.3g}"
                raise InputError(
                    f"Order {int(k)} at {wk / (2 * np.pi):.4g} Hz is within {100 * abs(r - 1):.3g} % of mode {j} of "
                    f"frame '{frame.name}' ({wn / (2 * np.pi):.4g} Hz, damping ratio {zeta:.3g}): the dynamic "
                    f"magnification {shown} exceeds {MAX_MAGNIFICATION:g}, beyond which the model lacks the damping "
                    "that bounds a real frame's response. Give the mounts' damping, or move the mode away from "
                    "the order.")


def steady_state(frame: Frame, loads: ShakingLoads) -> FrameResponse:
    """Steady-state response of ``frame`` to the harmonic ``loads``: (K - w^2 M + i w C) q = Q per order.

    Rao, *Mechanical Vibrations*, 5th ed. (2011), §6.14 (and eq. (3.25)-(3.28) for one degree of freedom).

    Parameters
    ----------
    frame : a supported :class:`~machdyn.vibration.frame.Frame`
    loads : :class:`ShakingLoads` (from :func:`shaking_loads` or :func:`harmonic_loads`)

    Examples
    --------
    A 100 kg mass on a 1e5 N/m spring driven by 100 N at 20 rad/s moves 100 / (1e5 - 100 * 400) m:

    >>> from machdyn.vibration.frame import Frame, Mount
    >>> f = Frame(100.0, 1.0, (Mount("v", (0, 0), np.pi / 2, 1e5), Mount("h", (0, 0), 0.0, 1e5),
    ...                        Mount("t", (1, 0), np.pi / 2, 1e5), Mount("t2", (-1, 0), np.pi / 2, 1e5)))
    >>> r = steady_state(f, harmonic_loads(20.0, force_x=100.0))
    >>> round(float(abs(r.displacement((0, 0))[0, 0])) * 1e3, 6)
    1.666667
    """
    check_supported(frame)
    check_resonance(frame, loads.angular_frequencies, loads.orders)
    m, k, c = frame.mass_matrix(), frame.stiffness_matrix(), frame.damping_matrix()
    q = np.empty((loads.orders.size, 3), dtype=complex)
    for i, (w, rhs) in enumerate(zip(loads.angular_frequencies, loads.vector(), strict=True)):
        dyn = k - w**2 * m + 1j * w * c
        if np.linalg.cond(dyn) > 1e14:
            raise InputError(f"Order {loads.orders[i]} at {w / (2 * np.pi):.4g} Hz hits an undamped natural "
                             f"frequency of frame '{frame.name}': the response is unbounded. Add damping.")
        q[i] = np.linalg.solve(dyn, rhs)
    return FrameResponse(frame, loads, q)


@dataclass(frozen=True)
class Comparison:
    """RMS levels at named points for two variants and the reduction in % ((before - after) / before)."""

    quantity: str
    points: tuple[str, ...]
    before: np.ndarray
    after: np.ndarray
    mounts: tuple[str, ...] = ()
    force_before: np.ndarray | None = None
    force_after: np.ndarray | None = None

    @property
    def reduction(self) -> np.ndarray:
        """(before - after) / before x 100 [%] per point."""
        return reduction_percent(self.before, self.after)

    @property
    def mean_reduction(self) -> float:
        """Reduction [%] of the mean level over the points (as seed 000 averages its measuring points)."""
        return float(reduction_percent(np.mean(self.before), np.mean(self.after)))


def compare(before: FrameResponse, after: FrameResponse, points: dict, quantity: str = "acceleration",
            direction=None) -> Comparison:
    """RMS ``quantity`` at named frame ``points`` {name: (x, y) [m]} and RMS mount forces, before and after.

    Both responses must be of frames with the same mounts (names); the loads may differ (e.g. unbalanced and
    balanced mechanism) and so may the frames' stiffnesses.
    """
    if not points:
        raise InputError("A comparison needs at least one named point; got none.")
    names = tuple(points)
    b = np.array([before.rms(points[n], quantity, direction) for n in names])
    a = np.array([after.rms(points[n], quantity, direction) for n in names])
    mounts_b = [m.name for m in before.frame.mounts]
    mounts_a = [m.name for m in after.frame.mounts]
    common = tuple(n for n in mounts_b if n in mounts_a)
    fb = np.array([before.transmitted_force_rms(n) for n in common])
    fa = np.array([after.transmitted_force_rms(n) for n in common])
    return Comparison(quantity, names, b, a, common, fb, fa)
