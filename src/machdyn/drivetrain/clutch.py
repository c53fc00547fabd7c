"""A friction clutch that engages a spinning flywheel side to a driven side, and a brake that stops a machine.

Clutch: during slip the clutch passes its slip torque T_c from the faster to the slower side; the driving side
(inertia J1, speed ω1, motor torque T1) slows and the driven side (J2, ω2, load torque T2) speeds up until the
speeds meet. With constant torques the slip ends at

    t_s = (ω1 − ω2) / ((T_c − T1)/J1 + (T_c − T2)/J2),

the common speed is ω = ω1 − (T_c − T1) t_s / J1, and the friction dissipates E = T_c (ω1 − ω2) t_s / 2.
With no motor and no load torque this is Shigley's E = J1 J2 (ω1 − ω2)² / (2 (J1 + J2)).

Brake: a brake torque T_b on a machine of inertia J (constant) with a resisting torque T_r stops it from ω0 in
t = J ω0/(T_b + T_r), over the angle θ = J ω0²/(2 (T_b + T_r)). A linkage, whose reduced inertia and load vary
with the crank angle, is stopped by integrating its equation of motion (:func:`stop_machine`).

Sources
-------
- R. G. Budynas, J. K. Nisbett, *Shigley's Mechanical Engineering Design*, 8th ed., §16-8 "Energy
  considerations": the slip time t1 = I1 I2 (ω1 − ω2) / (T (I1 + I2)) and the energy
  E = I1 I2 (ω1 − ω2)² / (2 (I1 + I2)) of two inertias brought to one speed by a clutch of constant torque T.
- The constant-deceleration stop: Newton's second law for rotation, J dω/dt = −(T_b + T_r).
- Stopping time and overrun of a press: ISO 16092-1:2017, *Machine tools safety — Presses — Part 1: General
  safety requirements*, which requires the stopping performance (time or angle) to be known and monitored.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import InputError
from .population import engagement_arrays  # the closed forms, written once for one design and for N


@dataclass(frozen=True)
class Engagement:
    """A clutch engagement: slip time [s], common speed [rad/s], energy dissipated [J], the angle each side turned
    during the slip [rad], the work of the motor and of the load [J], the driven side's acceleration and the
    driving side's deceleration while the clutch slips [rad/s²]."""

    slip_time: float
    common_speed: float
    dissipated: float
    driving_angle: float
    driven_angle: float
    driving_work: float
    load_work: float
    driven_acceleration: float = 0.0
    driving_deceleration: float = 0.0


def engage(j1: float, w1: float, j2: float, w2: float, slip_torque: float, *, driving_torque: float = 0.0,
           load_torque: float = 0.0) -> Engagement:
    """Engagement of a friction clutch between a driving side (j1, w1) and a driven side (j2, w2) with constant
    torques (Shigley's MED, 8th ed., §16-8, with the motor and load torques added).

    Parameters
    ----------
    j1, j2 : inertias of the driving and the driven side [kg·m²] > 0.
    w1, w2 : their speeds when the clutch closes [rad/s], w1 > w2.
    slip_torque : T_c, the torque the clutch passes while it slips [N·m] > 0.
    driving_torque : T1, the motor's torque on the driving side [N·m] (constant, < T_c).
    load_torque : T2, the resisting torque on the driven side [N·m] (constant, < T_c: else the driven side
        never catches up).

    Returns
    -------
    Engagement
        with the driven side's acceleration α2 = (T_c − T2)/J2 and the driving side's deceleration
        α1 = (T_c − T1)/J1 during the slip.

    Examples
    --------
    Two discs of 4 and 2 kg·m², one at 60 rpm, the other at rest, clutch torque 10 N·m: the common speed is
    2π·(4/6) = 4.19 rad/s and a third of the kinetic energy, 26.3 J, is lost:

    >>> e = engage(4.0, 2 * np.pi, 2.0, 0.0, 10.0)
    >>> round(e.common_speed, 3), round(e.dissipated, 2), round(e.slip_time, 4)
    (4.189, 26.32, 0.8378)
    """
    for name, value in (("j1", j1), ("j2", j2), ("slip torque", slip_torque)):
        if not (np.isfinite(value) and value > 0):
            raise InputError(f"The clutch's {name} must be > 0; got {value!r}.")
    if not w1 > w2:
        raise InputError(f"The driving side must turn faster than the driven side when the clutch closes; got "
                         f"{w1:g} rad/s and {w2:g} rad/s.")
    if load_torque >= slip_torque:
        raise InputError(f"The clutch slips for ever: its slip torque {slip_torque:g} N*m does not exceed the load "
                         f"torque {load_torque:g} N*m it must carry.")
    if driving_torque >= slip_torque:
        raise InputError(f"The motor torque {driving_torque:g} N*m exceeds the clutch's slip torque "
                         f"{slip_torque:g} N*m: the driving side would not slow down and the slip never ends.")
    found = engagement_arrays(j1, w1, j2, w2, slip_torque, driving_torque, load_torque)
    return Engagement(**{name: float(value) for name, value in found.items()})


@dataclass(frozen=True)
class Stop:
    """A stop: time [s] and crank angle [rad] from the brake's application to rest, the crank angle where it
    came to rest [rad], and the time histories (t [s], crank angle [rad], speed [rad/s])."""

    time: float
    angle: float
    rest_angle: float
    t: np.ndarray
    phi: np.ndarray
    omega: np.ndarray
    #: True when the stop was integrated over its first ``max_turns`` turns only and its rest found by the
    #: energy balance from there (an upper bound: the speed-dependent loads that also brake are left out).
    estimated: bool = False


def stop_constant(inertia: float, speed: float, brake_torque: float, resisting_torque: float = 0.0) -> Stop:
    """Stop of a machine of constant inertia by a constant brake torque: t = J ω0/(T_b + T_r), θ = J ω0²/(2(T_b +
    T_r)) (Newton's second law for rotation).

    Parameters
    ----------
    inertia : J [kg·m²] > 0; speed : ω0 [rad/s] > 0; brake_torque : T_b [N·m] > 0;
    resisting_torque : T_r [N·m] of the load (>= −T_b: a load that drives harder than the brake brakes never
        stops).

    Returns
    -------
    Stop

    Examples
    --------
    A 2 kg·m² rotor at 1500 rpm braked by 100 N·m stops in 3.14 s after 39.3 turns:

    >>> s = stop_constant(2.0, 1500 * np.pi / 30, 100.0)
    >>> round(s.time, 3), round(s.angle / (2 * np.pi), 2)
    (3.142, 39.27)
    """
    net = brake_torque + resisting_torque
    if not (inertia > 0 and speed > 0 and brake_torque > 0):
        raise InputError(f"A stop needs an inertia, a speed and a brake torque > 0; got {inertia!r}, {speed!r}, "
                         f"{brake_torque!r}.")
    if net <= 0:
        raise InputError(f"The brake torque {brake_torque:g} N*m does not overcome the driving load "
                         f"{-resisting_torque:g} N*m: the machine never stops.")
    time = inertia * speed / net
    t = np.linspace(0.0, time, 50)
    omega = speed - net / inertia * t
    phi = speed * t - 0.5 * net / inertia * t**2
    return Stop(float(time), float(phi[-1]), float(phi[-1]), t, phi, omega)


def mean_load_moment_at_rest(machine: Any, samples: int = 720) -> float:
    """The mean over one crank turn of the reduced moment of a machine's loads at rest, M̄ = (1/2π) ∮ M(φ, 0) dφ
    [N·m] (positive drives the crank): the work its loads do per turn divided by 2π, the speed-dependent loads
    (dampers) left out as they vanish at rest. ``samples`` evenly spaced crank angles (the rectangle rule, exact
    for a trigonometric polynomial of degree < ``samples``)."""
    phi = np.linspace(0.0, 2 * np.pi, samples, endpoint=False)
    return float(np.mean(np.ravel(machine.moment_at(phi, np.zeros_like(phi)))))


def brake_balance_problem(machine: Any, brake_torque: float) -> str | None:
    """Why a brake torque T_b [N·m] at the crank cannot stop a machine, or None: by the balance of work over a
    turn, a brake that does not exceed the loads' mean driving moment M̄ (:func:`mean_load_moment_at_rest`)
    absorbs less per turn than the loads put in, so the machine does not come to rest (and a brake that is
    closed on a machine at rest cannot hold it against them)."""
    mean = mean_load_moment_at_rest(machine)
    if brake_torque > mean:
        return None
    return (f"the brake's {brake_torque:.4g} N*m at the crank does not exceed the mean driving moment of the loads "
            f"over a turn, {mean:.4g} N*m: the loads put more work into each turn than the brake takes out, so it "
            f"never stops the machine")


def stop_machine(machine: Any, extra_inertia: float, speed: float, brake_torque: float, start_angle: float,
                 *, max_turns: float = 200.0) -> Stop:
    """Stop of a linkage machine (its reduced inertia J(φ), the reduced moment of its loads M(φ, ω)) with an
    extra constant inertia on the crank (flywheel and drive train, reflected) by a brake torque on the crank,
    applied at the crank angle ``start_angle`` [rad] and speed ``speed`` [rad/s].

    (J(φ) + J_x) ω' = M(φ, ω) − ½ J'(φ) ω² − T_b   (the equation of motion of the equivalent machine, seed 003
    eqs 18–19; the machine's moment is that of :class:`~machdyn.dynamics.equivalent.EquivalentMachine`),
    integrated by :func:`scipy.integrate.solve_ivp` until ω = 0, over at most ``max_turns`` crank turns. A stop
    longer than that is finished by the energy balance from the state reached: the kinetic energy ½ J̄ ω² [J]
    (J̄ the mean inertia over a turn) taken out by the net torque T_b − M̄ [N·m] (:func:`mean_load_moment_at_rest`)
    over the angle ½ J̄ ω²/(T_b − M̄) in the time J̄ ω/(T_b − M̄), and the stop is marked ``estimated``.

    Parameters
    ----------
    machine : an :class:`~machdyn.dynamics.equivalent.EquivalentMachine` of one design.
    extra_inertia : J_x [kg·m²] >= 0.
    speed : ω0 [rad/s] > 0.
    brake_torque : T_b [N·m] > 0, on the crank; it must exceed the loads' mean moment M̄
        (:func:`brake_balance_problem`), or the machine never stops (refused).
    start_angle : φ0 [rad].
    max_turns : the most crank turns integrated (bounds the time of the computation).

    Returns
    -------
    Stop
    """
    from scipy.integrate import solve_ivp

    if not (speed > 0 and brake_torque > 0 and extra_inertia >= 0):
        raise InputError(f"A stop needs a speed and a brake torque > 0 and an extra inertia >= 0; got {speed!r}, "
                         f"{brake_torque!r}, {extra_inertia!r}.")
    weak = brake_balance_problem(machine, brake_torque)
    if weak is not None:
        raise InputError(f"The brake cannot stop the machine: {weak}.")

    def rate(_t: float, y: np.ndarray) -> list[float]:
        phi, w = y
        j = float(np.ravel(machine.inertia(phi))[0]) + extra_inertia
        dj = float(np.ravel(machine.inertia.derivative(phi))[0])
        m = float(np.ravel(machine.moment_at(phi, w))[0])
        return [w, (m - 0.5 * dj * w * w - brake_torque) / j]

    def at_rest(_t: float, y: np.ndarray) -> float:
        return y[1]

    def turned_out(_t: float, y: np.ndarray) -> float:
        return (y[0] - start_angle) - 2 * np.pi * max_turns

    at_rest.terminal = True  # type: ignore[attr-defined]
    at_rest.direction = -1  # type: ignore[attr-defined]
    turned_out.terminal = True  # type: ignore[attr-defined]
    turned_out.direction = 1  # type: ignore[attr-defined]
    j0 = float(np.ravel(machine.inertia(start_angle))[0]) + extra_inertia
    horizon = 10.0 * j0 * speed / brake_torque + 1.0  # ten times the constant-inertia stop: ample
    sol = solve_ivp(rate, (0.0, horizon), [start_angle, speed], events=(at_rest, turned_out), rtol=1e-9,
                    atol=1e-9, max_step=horizon / 200)
    if sol.status == 1 and sol.t_events[0].size:
        t_end = float(sol.t_events[0][0])
        phi_end = float(sol.y_events[0][0][0])
        return Stop(t_end, phi_end - start_angle, float(np.mod(phi_end, 2 * np.pi)), sol.t, sol.y[0], sol.y[1])
    # Still turning after max_turns (or the horizon): the rest of the stop by the energy balance.
    phi1, w1, t1 = float(sol.y[0, -1]), float(sol.y[1, -1]), float(sol.t[-1])
    turn = np.linspace(0.0, 2 * np.pi, 720, endpoint=False)
    j_mean = float(np.mean(np.ravel(machine.inertia(turn)))) + extra_inertia
    net = brake_torque - mean_load_moment_at_rest(machine)
    w1 = max(w1, 0.0)
    t_end = t1 + j_mean * w1 / net
    phi_end = phi1 + 0.5 * j_mean * w1 * w1 / net
    return Stop(t_end, phi_end - start_angle, float(np.mod(phi_end, 2 * np.pi)), np.append(sol.t, t_end),
                np.append(sol.y[0], phi_end), np.append(sol.y[1], 0.0), estimated=True)
