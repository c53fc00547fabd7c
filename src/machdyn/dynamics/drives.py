"""Drives of a machine: the torque a source puts on the crank shaft as a function of the crank speed.

Every drive gives, at the crank shaft, ``torque(omega)`` [N*m] and its slope ``slope(omega)`` [N*m*s/rad] at
crank speed omega [rad/s], the inertia of its rotating parts reduced to the crank (``inertia`` [kg*m^2]), the
largest torque it can give (``breakdown_torque``) and its torque at standstill (``starting_torque``). A gear
between motor and crank of ``ratio`` i = motor speed / crank speed multiplies the motor torque by i (times the
gear efficiency while the motor drives, divided by it while the machine drives the motor) and its rotor inertia
by i^2 (kinetic energy at the same crank speed).

Parameters may be arrays of N design variants (one motor per design).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ..errors import InputError, check_finite, check_positive


def _arr(v) -> np.ndarray:
    return np.asarray(v, dtype=float)


def _gear(motor_torque, ratio, efficiency):
    """Crank-side torque from a motor torque through a gear (efficiency counts against the power flow)."""
    t = _arr(motor_torque)
    return ratio * np.where(t >= 0.0, t * efficiency, t / efficiency)


def _gear_slope(motor_torque, motor_slope, ratio, efficiency):
    return ratio * ratio * np.where(_arr(motor_torque) >= 0.0, motor_slope * efficiency, motor_slope / efficiency)


def _check_gear(ratio, efficiency, rotor_inertia, what):
    check_positive(f"gear ratio of the {what}", ratio)
    check_positive(f"gear efficiency of the {what}", efficiency)
    if np.any(_arr(efficiency) > 1.0):
        raise InputError(f"The gear efficiency of the {what} must be <= 1; got {float(np.max(efficiency)):g}.")
    check_positive(f"rotor inertia of the {what}", rotor_inertia, "kg*m^2", allow_zero=True)


@dataclass(frozen=True)
class ConstantSpeed:
    """An ideal speed source: the crank turns at ``speed`` [rad/s] whatever the load (the kinetostatic case)."""

    speed: float

    def __post_init__(self):
        check_positive("speed of the constant-speed drive", self.speed, "rad/s")

    inertia = 0.0
    name = "constant speed"


@dataclass(frozen=True)
class ConstantTorque:
    """A constant torque [N*m] on the crank at every speed (a weight-driven or an ideally regulated drive)."""

    torque: float
    name = "constant torque"

    def __post_init__(self):
        check_finite("torque of the constant-torque drive", self.torque, "N*m")

    @property
    def inertia(self):
        return 0.0

    def torque_at(self, omega):
        return _arr(self.torque) + 0.0 * _arr(omega)

    def slope(self, omega):
        return 0.0 * _arr(omega)

    @property
    def breakdown_torque(self):
        return _arr(self.torque)

    @property
    def starting_torque(self):
        return _arr(self.torque)


def kloss_torque(slip, breakdown_torque, breakdown_slip):
    """Torque of an induction motor by the Kloss formula, T = 2 T_b / (s/s_b + s_b/s) [N*m].

    Parameters
    ----------
    slip : s = 1 - n/n_s, the slip (0 at synchronous speed, 1 at standstill, < 0 above synchronous speed).
    breakdown_torque : T_b, the breakdown (pull-out) torque [N*m] > 0.
    breakdown_slip : s_b, the slip at breakdown torque, 0 < s_b.

    Source: the Kloss formula of induction-machine theory, e.g. A. Binder, *Elektrische Maschinen und
    Antriebe*, Springer (chapter on the induction machine); rated quantities as in IEC 60034-1. Neglects the
    stator resistance: a good fit near the rated point and up to breakdown; the starting torque of real cage
    motors (deep bars) is usually larger than Kloss predicts. Valid for -1 < s <= 1.

    Examples
    --------
    >>> round(float(kloss_torque(0.2, 100.0, 0.2)), 6)   # at breakdown slip: the breakdown torque
    100.0
    >>> round(float(kloss_torque(-0.2, 100.0, 0.2)), 6)  # generating above synchronous speed
    -100.0
    """
    s = _arr(slip)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = 2.0 * breakdown_torque / (s / breakdown_slip + breakdown_slip / s)
    return np.where(s == 0.0, 0.0, t)


def kloss_breakdown_slip(rated_slip, breakdown_ratio):
    """Breakdown slip s_b = s_r (λ + sqrt(λ^2 - 1)) from the rated slip s_r and λ = T_b / T_r (Kloss formula at
    the rated point, stable branch s_r < s_b).

    Parameters
    ----------
    rated_slip : s_r = 1 - n_r/n_s, 0 < s_r < 1.
    breakdown_ratio : λ = T_b / T_r > 1.

    Source: as :func:`kloss_torque` (solving T_r = 2 T_b / (s_r/s_b + s_b/s_r) for s_b).

    Examples
    --------
    >>> round(float(kloss_breakdown_slip(0.04, 2.5)), 6)
    0.191652
    """
    lam = _arr(breakdown_ratio)
    return _arr(rated_slip) * (lam + np.sqrt(lam * lam - 1.0))


@dataclass(frozen=True)
class InductionMotor:
    """A three-phase cage induction motor on the Kloss characteristic, through a gear of ``ratio``.

    rated_power [W], rated_speed and synchronous_speed [rad/s] of the motor shaft, breakdown_ratio = breakdown
    torque / rated torque (catalogue value, typically 2-3.5), ratio = motor speed / crank speed, efficiency of
    the gear, rotor_inertia [kg*m^2] of the motor.
    """

    rated_power: float
    rated_speed: float
    synchronous_speed: float
    breakdown_ratio: float = 2.5
    ratio: float = 1.0
    efficiency: float = 1.0
    rotor_inertia: float = 0.0
    name = "induction motor"

    def __post_init__(self):
        check_positive("rated power of the induction motor", self.rated_power, "W")
        check_positive("rated speed of the induction motor", self.rated_speed, "rad/s")
        check_positive("synchronous speed of the induction motor", self.synchronous_speed, "rad/s")
        if np.any(_arr(self.rated_speed) >= _arr(self.synchronous_speed)):
            raise InputError(
                f"The rated speed of the induction motor must be below its synchronous speed "
                f"({np.max(self.synchronous_speed):g} rad/s); got {np.max(self.rated_speed):g} rad/s."
            )
        if np.any(_arr(self.breakdown_ratio) <= 1.0):
            raise InputError(f"The breakdown-torque ratio of the induction motor must be > 1; got "
                             f"{np.min(self.breakdown_ratio):g}.")
        _check_gear(self.ratio, self.efficiency, self.rotor_inertia, "induction motor")

    @property
    def rated_torque(self):
        """Rated torque of the motor shaft, T_r = P_r / omega_r [N*m]."""
        return _arr(self.rated_power) / _arr(self.rated_speed)

    @property
    def rated_slip(self):
        return 1.0 - _arr(self.rated_speed) / _arr(self.synchronous_speed)

    @property
    def breakdown_slip(self):
        return kloss_breakdown_slip(self.rated_slip, self.breakdown_ratio)

    def _motor(self, omega):
        slip = 1.0 - self.ratio * _arr(omega) / self.synchronous_speed
        tb, sb = self.breakdown_ratio * self.rated_torque, self.breakdown_slip
        return slip, tb, sb

    def torque_at(self, omega):
        """Torque on the crank [N*m] at crank speed omega [rad/s]."""
        slip, tb, sb = self._motor(omega)
        return _gear(kloss_torque(slip, tb, sb), self.ratio, self.efficiency)

    def slope(self, omega):
        """d(crank torque)/d(omega) [N*m*s/rad]."""
        slip, tb, sb = self._motor(omega)
        x = slip / sb
        # dT/ds = 2 T_b (1/s_b)(1 - x^-2)... written without dividing by s: T = 2 T_b x/(x^2 + 1)
        dt_ds = 2.0 * tb * (1.0 - x * x) / ((x * x + 1.0) ** 2) / sb
        dm = -dt_ds / self.synchronous_speed  # per rad/s of motor speed
        return _gear_slope(kloss_torque(slip, tb, sb), dm, self.ratio, self.efficiency)

    @cached_property
    def _constants(self):
        def num(v):
            a = _arr(v)
            return float(a) if a.ndim == 0 else a

        i, ns, sb = num(self.ratio), num(self.synchronous_speed), num(self.breakdown_slip)
        tb = num(self.breakdown_ratio * self.rated_torque)
        # crank torque = a x / (x^2 + 1) with x = (1 - i omega / ns) / sb; slope = b (1 - x^2) / (x^2 + 1)^2
        return (i / (ns * sb), 1.0 / sb, 2.0 * tb * i, -2.0 * tb * i * i / (sb * ns), _arr(self.efficiency),
                bool(np.all(_arr(self.efficiency) == 1.0)))

    def torque_slope(self, omega):
        """Crank torque [N*m] and its slope [N*m*s/rad] at crank speed omega, in one call (the simulation's)."""
        p, q, a, b, eta, lossless = self._constants
        x = q - p * omega
        x2 = x * x
        d = 1.0 / (x2 + 1.0)
        t, s = a * x * d, b * (1.0 - x2) * d * d
        if lossless:
            return t, s
        g = np.where(t >= 0.0, eta, 1.0 / eta)
        return t * g, s * g

    @property
    def inertia(self):
        return _arr(self.ratio) ** 2 * _arr(self.rotor_inertia)

    @property
    def breakdown_torque(self):
        """Largest crank torque the motor gives [N*m]."""
        return _gear(self.breakdown_ratio * self.rated_torque, self.ratio, self.efficiency)

    @property
    def starting_torque(self):
        """Crank torque at standstill by the Kloss formula [N*m]."""
        return self.torque_at(0.0)

    @property
    def no_load_speed(self):
        """Crank speed at synchronous motor speed [rad/s]."""
        return _arr(self.synchronous_speed) / _arr(self.ratio)


@dataclass(frozen=True)
class TorqueSpeedTable:
    """A motor given by its torque-speed curve: ``speeds`` [rad/s] of the motor shaft (increasing) and
    ``torques`` [N*m]; monotone cubic (PCHIP) interpolation inside, the end torques held outside."""

    speeds: tuple
    torques: tuple
    ratio: float = 1.0
    efficiency: float = 1.0
    rotor_inertia: float = 0.0
    name = "torque-speed table"

    def __post_init__(self):
        s, t = _arr(self.speeds).ravel(), _arr(self.torques).ravel()
        check_finite("speeds of the torque-speed table", s, "rad/s")
        check_finite("torques of the torque-speed table", t, "N*m")
        if s.size != t.size or s.size < 2:
            raise InputError(f"A torque-speed table needs at least 2 speeds and one torque per speed; got {s.size} "
                             f"speeds and {t.size} torques.")
        if np.any(np.diff(s) <= 0):
            i = int(np.flatnonzero(np.diff(s) <= 0)[0]) + 1
            raise InputError(f"The speeds of a torque-speed table must increase strictly; got speeds[{i}] = "
                             f"{s[i]:g} rad/s after speeds[{i - 1}] = {s[i - 1]:g} rad/s.")
        if s[0] < 0:
            raise InputError(f"The speeds of a torque-speed table must be >= 0 rad/s; got {s[0]:g} rad/s.")
        _check_gear(self.ratio, self.efficiency, self.rotor_inertia, "torque-speed table motor")

    @cached_property
    def _curve(self):
        from scipy.interpolate import PchipInterpolator

        curve = PchipInterpolator(_arr(self.speeds), _arr(self.torques), extrapolate=False)
        return curve, curve.derivative()

    def _motor(self, omega):
        """Motor torque and slope at crank speed omega: PCHIP inside the table; above its last speed the last
        slope continues (a motor past synchronous speed generates); below the first speed the first torque."""
        curve, slope = self._curve
        lo, hi = self.speeds[0], self.speeds[-1]
        m = self.ratio * _arr(omega)
        inside = np.clip(m, lo, hi)
        t, d = curve(inside), slope(inside)
        end_slope = float(slope(hi))
        t = np.where(m > hi, float(curve(hi)) + end_slope * (m - hi), t)
        d = np.where(m > hi, end_slope, np.where(m < lo, 0.0, d))
        return t, d

    def torque_at(self, omega):
        return _gear(self._motor(omega)[0], self.ratio, self.efficiency)

    def slope(self, omega):
        t, d = self._motor(omega)
        return _gear_slope(t, d, self.ratio, self.efficiency)

    @property
    def inertia(self):
        return _arr(self.ratio) ** 2 * _arr(self.rotor_inertia)

    @property
    def breakdown_torque(self):
        grid = np.linspace(self.speeds[0], self.speeds[-1], 512)
        return _gear(np.max(self._curve[0](grid)), self.ratio, self.efficiency)

    @property
    def starting_torque(self):
        return self.torque_at(0.0)


@dataclass(frozen=True)
class HydraulicMotor:
    """A hydraulic motor fed with a constant flow through a relief valve (as on a paver's tamper drive).

    displacement [m^3 per revolution], flow [m^3/s] from the pump, pressure_limit [Pa] of the relief valve,
    volumetric_efficiency at the pressure limit (internal leakage proportional to pressure), mechanical (torque)
    efficiency, ratio = motor speed / crank speed, rotor_inertia [kg*m^2].

    Model: with D = displacement / 2 pi [m^3/rad] and leakage conductance C = (1 - eta_v) Q / p_max, the flow
    balance Q = D omega_m + C p gives p = (Q - D omega_m) / C, limited to 0 <= p <= p_max by the relief valve;
    torque T = eta_m D p. Source: N. D. Manring, *Hydraulic Control Systems*, Wiley 2005 (chapter on pumps and
    motors: motor torque T = eta_m V_d p / 2 pi, laminar leakage Q_L = C p); valid while the pump delivers its
    flow.
    """

    displacement: float
    flow: float
    pressure_limit: float
    volumetric_efficiency: float = 0.95
    mechanical_efficiency: float = 0.9
    ratio: float = 1.0
    rotor_inertia: float = 0.0
    name = "hydraulic motor"

    def __post_init__(self):
        check_positive("displacement of the hydraulic motor", self.displacement, "m^3")
        check_positive("flow to the hydraulic motor", self.flow, "m^3/s")
        check_positive("pressure limit of the hydraulic motor", self.pressure_limit, "Pa")
        for what, v in (("volumetric", self.volumetric_efficiency), ("mechanical", self.mechanical_efficiency)):
            if not np.all((_arr(v) > 0) & (_arr(v) < 1 + 1e-15)):
                raise InputError(f"The {what} efficiency of the hydraulic motor must be in (0, 1]; got {v!r}.")
        if np.any(_arr(self.volumetric_efficiency) >= 1.0):
            raise InputError("The volumetric efficiency of the hydraulic motor must be < 1 (some leakage is "
                             f"needed to model the pressure build-up); got {self.volumetric_efficiency!r}.")
        _check_gear(self.ratio, 1.0, self.rotor_inertia, "hydraulic motor")

    @property
    def _d(self):
        return _arr(self.displacement) / (2.0 * np.pi)

    @property
    def _leak(self):
        return (1.0 - _arr(self.volumetric_efficiency)) * _arr(self.flow) / _arr(self.pressure_limit)

    def pressure(self, omega):
        """Motor pressure [Pa] at crank speed omega [rad/s]."""
        p = (self.flow - self._d * self.ratio * _arr(omega)) / self._leak
        return np.clip(p, 0.0, self.pressure_limit)

    def torque_at(self, omega):
        return self.ratio * self.mechanical_efficiency * self._d * self.pressure(omega)

    def slope(self, omega):
        p = (self.flow - self._d * self.ratio * _arr(omega)) / self._leak
        inside = (p > 0.0) & (p < self.pressure_limit)
        return np.where(inside, -self.ratio**2 * self.mechanical_efficiency * self._d**2 / self._leak, 0.0)

    @property
    def inertia(self):
        return _arr(self.ratio) ** 2 * _arr(self.rotor_inertia)

    @property
    def breakdown_torque(self):
        return self.ratio * self.mechanical_efficiency * self._d * _arr(self.pressure_limit)

    @property
    def starting_torque(self):
        return self.torque_at(0.0)

    @property
    def no_load_speed(self):
        """Crank speed at which the whole flow passes the motor at zero pressure [rad/s]."""
        return _arr(self.flow) / (self._d * self.ratio)


Drive = ConstantSpeed | ConstantTorque | InductionMotor | TorqueSpeedTable | HydraulicMotor
