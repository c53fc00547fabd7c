"""A three-phase squirrel-cage induction motor with its electrical states: the fifth-order dq model (stator and
rotor flux linkages and the shaft speed) and its steady state, the per-phase equivalent circuit.

Sources
-------
- P. Krause, O. Wasynczuk, S. Sudhoff, S. Pekarek, *Analysis of Electric Machinery and Drive Systems*, 3rd ed.,
  Wiley-IEEE Press 2013, chapter 6 "Symmetrical induction machine": the voltage equations in arbitrary
  reference-frame variables (section 6.5, written with flux linkages as states as in section 6.14, "Computer
  simulation in the arbitrary reference frame"), the torque equation (section 6.6), the stationary and the
  synchronously rotating reference frames (section 6.7) and the steady state from the equivalent circuit
  (section 6.9). (2nd ed., 2002: the same sections in chapter 4.)
- The equivalent circuit's torque through its Thevenin equivalent, breakdown torque and slip: S. J. Chapman,
  *Electric Machinery Fundamentals*, 4th ed., McGraw-Hill 2005, section 6.5 (eqs 6-50, 6-53, 6-54).

The model, all quantities referred to the stator, amplitude-invariant (Park) dq variables, for a reference frame
turning at omega (0: stationary, omega_e: synchronous), the electrical rotor speed omega_r = p omega_m:

    d psi_qs/dt = v_qs - R_s i_qs - omega psi_ds          d psi_qr/dt = -R_r i_qr - (omega - omega_r) psi_dr
    d psi_ds/dt = v_ds - R_s i_ds + omega psi_qs          d psi_dr/dt = -R_r i_dr + (omega - omega_r) psi_qr
    [psi_s; psi_r] = [[L_s, L_m], [L_m, L_r]] [i_s; i_r],  L_s = L_ls + L_m, L_r = L_lr + L_m
    T_e = 3/2 p (psi_ds i_qs - psi_qs i_ds)

with L = X / omega_b (the reactances at the rated frequency omega_b). The supply: phase voltage of peak
sqrt(2/3) V_LL; in the synchronous frame v_qs = sqrt(2/3) V_LL, v_ds = 0; in the stationary frame
v_qs = V cos(omega_e t), v_ds = -V sin(omega_e t). Power into the stator 3/2 (v_qs i_qs + v_ds i_ds) = copper
loss 3/2 (R_s |i_s|^2 + R_r |i_r|^2) + d/dt of the magnetic energy 3/4 (psi_s . i_s + psi_r . i_r) + T_e omega_m.

Validity: linear magnetics (no saturation), no iron loss, no deep-bar effect (constant R_r), a balanced
sinusoidal supply, the stator star-connected (or its delta converted to an equivalent star).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import cached_property
from typing import Literal

import numpy as np

from ..errors import InputError, check_finite

__all__ = ["InductionMachine", "breakdown_of", "equivalent_circuit_torque", "thevenin", "thevenin_torque"]

FRAMES = ("synchronous", "stationary")


def thevenin(voltage, r_s, x_ls, x_m):
    """The Thevenin equivalent of the stator and magnetising branches seen from the rotor, (V_th [V], Z_th [ohm]).

    V_th = V jX_m / (R_s + j(X_ls + X_m)),  Z_th = jX_m (R_s + jX_ls) / (R_s + j(X_ls + X_m))  (Chapman, 4th ed.,
    eqs 6-41 to 6-44, without his approximation X_th ~ X_ls).

    Parameters
    ----------
    voltage : phase voltage V [V] (rms or peak: V_th follows it).
    r_s, x_ls, x_m : stator resistance, stator leakage and magnetising reactances [ohm] at the supply frequency.
    """
    z1 = r_s + 1j * x_ls
    zm = 1j * x_m
    return voltage * zm / (z1 + zm), zm * z1 / (z1 + zm)


def thevenin_torque(slip, v_th, r_th, x_th, r_r, x_lr, pole_pairs, omega_e):
    """Air-gap torque [N*m] at ``slip`` from the Thevenin equivalent (Chapman, 4th ed., eq 6-50):

        T = 3 p V_th^2 (R_r / s) / (omega_e ((R_th + R_r / s)^2 + (X_th + X_lr)^2))

    Parameters
    ----------
    slip : s != 0 (any shape) [-]; v_th : |V_th| [V rms]; r_th, x_th : Thevenin resistance and reactance [ohm];
    r_r, x_lr : rotor resistance and leakage reactance referred to the stator [ohm]; pole_pairs : p [-];
    omega_e : supply angular frequency [rad/s].
    """
    s = np.asarray(slip, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        rr = r_r / s
        t = 3.0 * pole_pairs * v_th ** 2 * rr / (omega_e * ((r_th + rr) ** 2 + (x_th + x_lr) ** 2))
    return np.where(s == 0.0, 0.0, t)


def breakdown_of(v_th, r_th, x_th, r_r, x_lr, pole_pairs, omega_e) -> tuple[float, float]:
    """(breakdown torque T_b [N*m], its slip s_b) from the Thevenin equivalent (Chapman, 4th ed., eqs 6-53 and
    6-54): s_b = R_r / sqrt(R_th^2 + (X_th + X_lr)^2), T_b = 3 p V_th^2 / (2 omega_e (R_th + sqrt(R_th^2 +
    (X_th + X_lr)^2))). Parameters as :func:`thevenin_torque`."""
    root = math.hypot(r_th, x_th + x_lr)
    return 3.0 * pole_pairs * v_th ** 2 / (2.0 * omega_e * (r_th + root)), r_r / root


def equivalent_circuit_torque(slip, phase_voltage, r_s, r_r, x_ls, x_lr, x_m, pole_pairs, omega_e):
    """Air-gap torque [N*m] of the per-phase equivalent circuit at ``slip`` (Steinmetz; Krause 3rd ed. §6.9;
    Chapman 4th ed. eq 6-50):

        T = 3 p V_th^2 (R_r / s) / (omega_e ((R_th + R_r / s)^2 + (X_th + X_lr)^2))

    Parameters
    ----------
    slip : s = (omega_e - p omega_m) / omega_e, s != 0 (any shape) [-]; s < 0 generates.
    phase_voltage : rms phase voltage V [V].
    r_s, r_r : stator and rotor (referred) resistances [ohm].
    x_ls, x_lr, x_m : leakage and magnetising reactances at the supply frequency omega_e [ohm].
    pole_pairs : p [-].
    omega_e : supply angular frequency [rad/s].

    Examples
    --------
    The starting torque of the motor of Chapman, 4th ed., Example 6-5 (460 V, 25 hp, 4 poles, 60 Hz): 107 N*m
    with the exact Thevenin reactance (Chapman prints 104 N*m with his approximation X_th ~ X_1)

    >>> w = 2 * math.pi * 60
    >>> round(float(equivalent_circuit_torque(1.0, 460 / math.sqrt(3), 0.641, 0.332, 1.106, 0.464, 26.3, 2, w)))
    107
    """
    v_th, z_th = thevenin(phase_voltage, r_s, x_ls, x_m)
    return thevenin_torque(slip, abs(v_th), z_th.real, z_th.imag, r_r, x_lr, pole_pairs, omega_e)


def _gear(torque, ratio, efficiency):
    """Crank torque from a motor torque through the gear: loss against the flow of power."""
    t = np.asarray(torque, dtype=float)
    return ratio * np.where(t >= 0.0, t * efficiency, t / efficiency)


@dataclass(frozen=True)
class InductionMachine:
    """A squirrel-cage induction motor by its per-phase equivalent circuit (star, referred to the stator), with
    its electrical states, through a gear of ``ratio`` (motor speed / crank speed) and ``efficiency``.

    stator_resistance, rotor_resistance [ohm]; stator_leakage_reactance, rotor_leakage_reactance,
    magnetizing_reactance [ohm] at ``frequency``; pole_pairs p; line_voltage [V rms, line to line]; frequency
    [Hz] of the supply (rated); rotor_inertia [kg*m^2]; frame: the dq reference frame the states are integrated
    in ("synchronous": constant states in the steady state; "stationary": the phase quantities' frame);
    supply_factor: the supply's frequency and voltage over the rated (constant volts per hertz); phase [rad]:
    the supply's phase at t = 0 (kept continuous through a change of frequency).
    """

    stator_resistance: float
    rotor_resistance: float
    stator_leakage_reactance: float
    rotor_leakage_reactance: float
    magnetizing_reactance: float
    pole_pairs: int
    line_voltage: float
    frequency: float
    ratio: float = 1.0
    efficiency: float = 1.0
    rotor_inertia: float = 0.0
    frame: Literal["synchronous", "stationary"] = "synchronous"
    supply_factor: float = 1.0
    phase: float = 0.0
    name = "induction motor (dq)"
    states = 4

    def __post_init__(self) -> None:
        for what, value, unit in (("stator resistance", self.stator_resistance, "ohm"),
                                  ("rotor resistance", self.rotor_resistance, "ohm"),
                                  ("stator leakage reactance", self.stator_leakage_reactance, "ohm"),
                                  ("rotor leakage reactance", self.rotor_leakage_reactance, "ohm"),
                                  ("magnetizing reactance", self.magnetizing_reactance, "ohm"),
                                  ("line voltage", self.line_voltage, "V"), ("frequency", self.frequency, "Hz"),
                                  ("gear ratio", self.ratio, ""), ("supply factor", self.supply_factor, "")):
            check_finite(f"{what} of the induction motor", value, unit)
            if not value > 0:
                raise InputError(f"The {what} of the induction motor must be > 0 {unit}; got {value:g} {unit}.")
        if int(self.pole_pairs) != self.pole_pairs or self.pole_pairs < 1:
            raise InputError(f"The pole pairs of the induction motor must be an integer >= 1; got "
                             f"{self.pole_pairs!r}.")
        if not 0.0 < self.efficiency <= 1.0:
            raise InputError(f"The gear efficiency of the induction motor must be in (0, 1]; got "
                             f"{self.efficiency:g}.")
        if not self.rotor_inertia >= 0.0:
            raise InputError(f"The rotor inertia of the induction motor must be >= 0 kg*m^2; got "
                             f"{self.rotor_inertia:g} kg*m^2.")
        if self.frame not in FRAMES:
            raise InputError(f"The reference frame of the induction motor must be one of {', '.join(FRAMES)}; "
                             f"got {self.frame!r}.")

    # -- constants -------------------------------------------------------------------------------------------
    @property
    def base_frequency(self) -> float:
        """omega_b = 2 pi f at which the reactances are given [rad/s]."""
        return 2.0 * math.pi * self.frequency

    @property
    def supply_frequency(self) -> float:
        """omega_e of the supply [rad/s] (the rated one times the supply factor)."""
        return self.base_frequency * self.supply_factor

    @property
    def phase_voltage(self) -> float:
        """rms phase voltage V_LL / sqrt 3 times the supply factor [V]."""
        return self.line_voltage / math.sqrt(3.0) * self.supply_factor

    @property
    def inductances(self) -> tuple[float, float, float]:
        """(L_s, L_r, L_m) [H]: self inductances of stator and rotor, magnetising inductance."""
        wb = self.base_frequency
        lm = self.magnetizing_reactance / wb
        return self.stator_leakage_reactance / wb + lm, self.rotor_leakage_reactance / wb + lm, lm

    @property
    def synchronous_speed(self) -> float:
        """Motor shaft speed at zero slip omega_e / p [rad/s]."""
        return self.supply_frequency / self.pole_pairs

    @property
    def no_load_speed(self) -> float:
        """Crank speed at synchronous motor speed [rad/s]."""
        return self.synchronous_speed / self.ratio

    @property
    def inertia(self) -> float:
        """Rotor inertia reduced to the crank i^2 J_r [kg*m^2]."""
        return self.ratio ** 2 * self.rotor_inertia

    def with_supply(self, factor: float, time: float = 0.0) -> InductionMachine:
        """The motor on a supply of ``factor`` times its frequency and voltage (constant volts per hertz) from
        ``time`` [s] on, the supply's phase continuous there."""
        new = replace(self, supply_factor=self.supply_factor * float(factor))
        return replace(new, phase=self.phase + (self.supply_frequency - new.supply_frequency) * time)

    # -- the steady state: the equivalent circuit ----------------------------------------------------------
    def _reactances(self) -> tuple[float, float, float]:
        f = self.supply_factor
        return self.stator_leakage_reactance * f, self.rotor_leakage_reactance * f, self.magnetizing_reactance * f

    def air_gap_torque(self, slip):
        """Motor torque [N*m] in the steady state at ``slip`` (:func:`equivalent_circuit_torque`)."""
        x_ls, x_lr, x_m = self._reactances()
        return equivalent_circuit_torque(slip, self.phase_voltage, self.stator_resistance, self.rotor_resistance,
                                         x_ls, x_lr, x_m, self.pole_pairs, self.supply_frequency)

    def stator_current(self, slip):
        """rms stator current [A] in the steady state at ``slip`` (the equivalent circuit's input impedance)."""
        x_ls, x_lr, x_m = self._reactances()
        s = np.asarray(slip, dtype=float)
        with np.errstate(divide="ignore", invalid="ignore"):
            z2 = np.where(s == 0.0, np.inf, self.rotor_resistance / s) + 1j * x_lr
            zm = 1j * x_m
            parallel = np.where(s == 0.0, zm, zm * z2 / (zm + z2))
        return np.abs(self.phase_voltage / (self.stator_resistance + 1j * x_ls + parallel))

    def slip_at(self, omega):
        """Slip at crank speed ``omega`` [rad/s]."""
        return 1.0 - self.ratio * np.asarray(omega, dtype=float) / self.synchronous_speed

    def torque_at(self, omega):
        """Crank torque [N*m] of the steady state at crank speed omega [rad/s] (any shape)."""
        return _gear(self.air_gap_torque(self.slip_at(omega)), self.ratio, self.efficiency)

    def slope(self, omega):
        """d(crank torque)/d(omega) [N*m*s/rad] of the steady-state curve (central difference of the closed
        form, step 1e-6 of the synchronous speed)."""
        h = 1e-6 * self.no_load_speed
        w = np.asarray(omega, dtype=float)
        return (self.torque_at(w + h) - self.torque_at(w - h)) / (2.0 * h)

    @property
    def breakdown(self) -> tuple[float, float]:
        """(breakdown torque [N*m] of the motor, its slip) of the steady state (:func:`breakdown_of`)."""
        x_ls, x_lr, x_m = self._reactances()
        v_th, z_th = thevenin(self.phase_voltage, self.stator_resistance, x_ls, x_m)
        return breakdown_of(abs(v_th), z_th.real, z_th.imag, self.rotor_resistance, x_lr, self.pole_pairs,
                            self.supply_frequency)

    @property
    def breakdown_torque(self) -> float:
        """Largest crank torque of the steady state [N*m]."""
        return float(_gear(self.breakdown[0], self.ratio, self.efficiency))

    @property
    def starting_torque(self) -> float:
        """Crank torque at standstill in the steady state [N*m]."""
        return float(self.torque_at(0.0))

    # -- the dq model --------------------------------------------------------------------------------------
    @cached_property
    def constants(self) -> tuple[float, ...]:
        """(R_s, R_r, L_s / D, L_r / D, L_m / D, omega_e, V peak, p, frame speed) for the right-hand side, D =
        L_s L_r - L_m^2."""
        ls, lr, lm = self.inductances
        det = ls * lr - lm * lm
        we = self.supply_frequency
        return (self.stator_resistance, self.rotor_resistance, ls / det, lr / det, lm / det, we,
                math.sqrt(2.0) * self.phase_voltage, float(self.pole_pairs),
                we if self.frame == "synchronous" else 0.0)

    def currents(self, psi):
        """(i_qs, i_ds, i_qr, i_dr) [A] from the flux linkages (psi_qs, psi_ds, psi_qr, psi_dr) [Wb] (rows; any
        trailing shape)."""
        _, _, a_s, a_r, a_m, *_ = self.constants
        qs, ds, qr, dr = psi
        return (a_r * qs - a_m * qr, a_r * ds - a_m * dr, a_s * qr - a_m * qs, a_s * dr - a_m * ds)

    def voltages(self, t, on: bool = True):
        """(v_qs, v_ds) [V] of the supply at time t [s] in the model's frame (0 when switched off)."""
        if not on:
            return 0.0 * t, 0.0 * t
        *_, we, v, _, frame = self.constants
        if frame:
            return v + 0.0 * t, 0.0 * t
        return v * np.cos(we * t + self.phase), -v * np.sin(we * t + self.phase)

    def electromagnetic_torque(self, psi):
        """T_e = 3/2 p (psi_ds i_qs - psi_qs i_ds) [N*m] (Krause 3rd ed. §6.6) from the flux linkages."""
        i_qs, i_ds, _, _ = self.currents(psi)
        return 1.5 * self.pole_pairs * (psi[1] * i_qs - psi[0] * i_ds)

    def magnetic_energy(self, psi):
        """3/4 (psi_s . i_s + psi_r . i_r) [J]: the energy stored in the windings' fields."""
        i = self.currents(psi)
        return 0.75 * sum(p * c for p, c in zip(psi, i, strict=True))

    def rates(self, t: float, psi, omega_motor: float, on: bool = True):
        """(d psi / dt (4,), T_e [N*m], power in [W], copper loss [W]) at time t [s], flux linkages psi [Wb] and
        motor shaft speed omega_motor [rad/s]. Switched off, the stator is open (i_s = 0): the rotor's flux
        decays through R_r and the stator's follows it, psi_s = L_m / L_r psi_r."""
        r_s, r_r, a_s, a_r, a_m, we, v, p, w = self.constants
        qs, ds, qr, dr = psi
        slip_w = w - p * omega_motor
        if not on:
            i_qr, i_dr = qr * self._open[0], dr * self._open[0]
            dqr = -r_r * i_qr - slip_w * dr
            ddr = -r_r * i_dr + slip_w * qr
            k = self._open[1]
            return (np.array([k * dqr, k * ddr, dqr, ddr]), 0.0, 0.0, 1.5 * r_r * (i_qr * i_qr + i_dr * i_dr))
        i_qs, i_ds = a_r * qs - a_m * qr, a_r * ds - a_m * dr
        i_qr, i_dr = a_s * qr - a_m * qs, a_s * dr - a_m * ds
        if w:
            v_q, v_d = v, 0.0
        else:
            v_q, v_d = v * math.cos(we * t + self.phase), -v * math.sin(we * t + self.phase)
        rates = np.array([v_q - r_s * i_qs - w * ds, v_d - r_s * i_ds + w * qs,
                          -r_r * i_qr - slip_w * dr, -r_r * i_dr + slip_w * qr])
        torque = 1.5 * p * (ds * i_qs - qs * i_ds)
        power = 1.5 * (v_q * i_qs + v_d * i_ds)
        copper = 1.5 * (r_s * (i_qs * i_qs + i_ds * i_ds) + r_r * (i_qr * i_qr + i_dr * i_dr))
        return rates, torque, power, copper

    @cached_property
    def _open(self) -> tuple[float, float]:
        """(1 / L_r, L_m / L_r) of the open stator."""
        _, lr, lm = self.inductances
        return 1.0 / lr, lm / lr

    def steady_flux(self, slip: float) -> np.ndarray:
        """The flux linkages [Wb] of the steady state at ``slip`` in the synchronous frame: the dq equations'
        right-hand side set to zero (a 4 x 4 linear system), independent of the equivalent circuit."""
        r_s, r_r, a_s, a_r, a_m, we, v, _, _ = self.constants
        sw = slip * we
        # rates = b - A psi with the currents linear in psi
        a = np.array([[r_s * a_r, we, -r_s * a_m, 0.0],
                      [-we, r_s * a_r, 0.0, -r_s * a_m],
                      [-r_r * a_m, 0.0, r_r * a_s, sw],
                      [0.0, -r_r * a_m, -sw, r_r * a_s]])
        return np.linalg.solve(a, np.array([v, 0.0, 0.0, 0.0]))
