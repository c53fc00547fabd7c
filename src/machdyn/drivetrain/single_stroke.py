"""The single-stroke cycle of a press: clutch in, stroke, clutch out and brake, then the flywheel's recovery.

Everything is reduced to the crank shaft (speeds in crank rad/s, torques at the crank). The driving side — motor
rotor, pulleys, flywheel, every shaft up to the clutch — is one inertia J₁ turning at ω₁ under the motor's torque
T_m(ω₁); the driven side is the linkage machine (reduced inertia J(φ), the reduced moment of its loads M(φ, ω),
seed 003 eqs 18–19) plus the shafts after the clutch, J₂(φ) = J(φ) + J_x, turning at ω₂ = φ'. The crank starts
at rest at the start angle with the flywheel at its running speed ω₀.

- **slip** (ω₁ ≠ ω₂): the clutch passes its slip torque T_c from the faster side to the slower one:
  J₁ ω₁' = T_m − T_c·s,  J₂ ω₂' = M − ½ J₂' ω₂² + T_c·s,  s = sign(ω₁ − ω₂);
- **locked** (ω₁ = ω₂ = ω): (J₁ + J₂) ω' = T_m + M − ½ J₂' ω², as long as the torque the clutch must pass,
  T = T_m − J₁ ω', stays within ±T_c (else it slips again);
- **braking**, from the brake angle on: the clutch is open, J₂ ω₂' = M − ½ J₂' ω₂² − T_b until ω₂ = 0, while the
  motor alone speeds the flywheel up again, J₁ ω₁' = T_m(ω₁), until ω₁ is back at ω₀ (the recovery).

Without a given brake angle, the brake is applied where the crank comes to rest at the start angle one turn on
(found by Brent's method). The shortest time between strokes is the stroke's time plus the recovery, which
bounds the strokes per minute the drive can make.

Sources
-------
- Clutch slip with constant torques and the energy dissipated: R. G. Budynas, J. K. Nisbett, *Shigley's
  Mechanical Engineering Design*, 8th ed., §16-8 (see :mod:`machdyn.drivetrain.clutch`).
- The machine's equation of motion with a variable reduced inertia: seed 003 eqs 18–19; a clutch and brake in a
  press's single-stroke mode and its stopping performance: ISO 16092-1:2017, §5.3 (stopping time and angle are
  to be known and monitored).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..dynamics.duty import DutyCheck, motor_duty
from ..errors import InputError
from .clutch import Stop, stop_machine

#: the flywheel counts as back at speed within this share of its running speed
RECOVERED = 1e-3


@dataclass(frozen=True)
class SingleStroke:
    """One single stroke (SI, crank-shaft units): time histories ``t``, crank angle ``phi``, crank speed
    ``omega``, driving-side speed ``omega_drive``, the torque the clutch passes ``clutch_torque`` (0 once it is
    open) and the motor's torque ``motor_torque`` (at the crank), each sample's ``phase`` (``"slip"``,
    ``"locked"``, ``"braking"``, ``"recovery"``), and the figures a press designer checks; ``idle_torque`` is the
    motor's torque at the running speed, between strokes."""

    t: np.ndarray
    phi: np.ndarray
    omega: np.ndarray
    omega_drive: np.ndarray
    clutch_torque: np.ndarray
    motor_torque: np.ndarray
    phase: np.ndarray
    running_speed: float
    start_angle: float
    brake_angle: float
    rest_angle: float
    slip_time: float
    clutch_energy: float
    brake_energy: float
    stroke_time: float
    stop_time: float
    stop_angle: float
    lowest_drive_speed: float
    recovery_time: float
    motor_work: float
    load_work: float
    idle_torque: float

    @property
    def overrun(self) -> float:
        """How far [rad] the crank comes to rest past the start angle one turn on (negative: short of it)."""
        return self.rest_angle - (self.start_angle + 2 * np.pi)

    def motor_rms(self, period: float | None = None) -> float:
        """The RMS [N·m, at the crank] of the motor's torque over one period [s] of repeated single strokes: the
        stroke and the flywheel's recovery as simulated, then the motor idling at ``idle_torque`` for the rest of
        the period (None: strokes back to back, the period is the stroke plus the recovery). The thermal load of
        a motor with a varying load is the RMS of its torque over the cycle (IEC 60034-1:2022, 4.2.1 and Annex A;
        the RMS-torque method of motor selection, e.g. Groschopp, *Motor sizing basics*, part 3).

        Valid for a period at least the stroke plus the recovery (shorter is refused: the drive cannot make it)."""
        busy = self.stroke_time + self.recovery_time
        period = busy if period is None else float(period)
        if not period >= busy * (1.0 - 1e-12) or not period > 0:
            raise InputError(f"A single stroke and its recovery take {busy:.4g} s; a period of {period!r} s is "
                             "shorter.")
        upto = self.t <= busy + 1e-12
        squared = float(np.trapezoid(self.motor_torque[upto] ** 2, self.t[upto]))
        squared += self.idle_torque**2 * max(0.0, period - float(self.t[upto][-1]))
        return float(np.sqrt(squared / period))

    @property
    def strokes_per_minute(self) -> float:
        """The most single strokes a minute the drive can make (stroke plus recovery)."""
        total = self.stroke_time + self.recovery_time
        return 60.0 / total if np.isfinite(total) and total > 0 else 0.0


def _machine_terms(machine: Any, extra: float):
    def j(phi: float) -> float:
        return float(np.ravel(machine.inertia(phi))[0]) + extra

    def dj(phi: float) -> float:
        return float(np.ravel(machine.inertia.derivative(phi))[0])

    def m(phi: float, w: float) -> float:
        return float(np.ravel(machine.moment_at(phi, w))[0])

    return j, dj, m


def single_stroke(machine: Any, motor_torque: Any, *, drive_inertia: float, driven_inertia: float, speed: float,
                  slip_torque: float, brake_torque: float, start_angle: float, brake_angle: float | None = None,
                  max_time: float = 120.0) -> SingleStroke:
    """Simulate one single stroke (see the module's equations), integrated by :func:`scipy.integrate.solve_ivp`
    phase by phase with events at the switches.

    Parameters
    ----------
    machine : an :class:`~machdyn.dynamics.equivalent.EquivalentMachine` of one design (J(φ), M(φ, ω)).
    motor_torque : T_m(ω) [N·m] at the crank for a driving-side speed ω [rad/s] (a drive's ``torque_at``).
    drive_inertia : J₁ [kg·m²] > 0, the driving side reduced to the crank (flywheel included).
    driven_inertia : J_x [kg·m²] >= 0, the shafts after the clutch reduced to the crank.
    speed : ω₀ [rad/s] > 0, the driving side's running speed (crank units) before the stroke.
    slip_torque : T_c [N·m] > 0 at the crank; brake_torque : T_b [N·m] > 0 at the crank.
    start_angle : the crank angle [rad] at rest before the stroke.
    brake_angle : the crank angle [rad] (start < angle < start + 2π) where the clutch opens and the brake closes;
        None: the angle that brings the crank to rest at the start angle one turn on.
    max_time : a stroke or a recovery longer than this [s] is refused (the clutch cannot turn the machine, or
        the motor cannot bring the flywheel back).
    """
    from scipy.integrate import solve_ivp
    from scipy.optimize import brentq

    if not (drive_inertia > 0 and speed > 0 and slip_torque > 0 and brake_torque > 0 and driven_inertia >= 0):
        raise InputError("A single stroke needs a driving inertia, a speed, a slip torque and a brake torque > 0; "
                         f"got {drive_inertia!r}, {speed!r}, {slip_torque!r}, {brake_torque!r}.")
    j2, dj2, m = _machine_terms(machine, driven_inertia)
    j1 = drive_inertia
    end_angle = start_angle + 2 * np.pi

    def tm(w: float) -> float:
        return float(np.ravel(motor_torque(w))[0])

    # ---- clutch in: slip, then locked (possibly slipping again), up to one turn -------------------------
    def slip_rhs(_t, y, sign):
        phi, w2, w1 = y
        tc = slip_torque * sign
        return [w2, (m(phi, w2) - 0.5 * dj2(phi) * w2 * w2 + tc) / j2(phi), (tm(w1) - tc) / j1]

    def locked_rhs(_t, y):
        phi, w = y
        acc = (tm(w) + m(phi, w) - 0.5 * dj2(phi) * w * w) / (j1 + j2(phi))
        return [w, acc]

    def locked_torque(phi: float, w: float) -> float:
        return tm(w) - j1 * (tm(w) + m(phi, w) - 0.5 * dj2(phi) * w * w) / (j1 + j2(phi))

    def turned(_t, y, *_):
        return y[0] - end_angle

    turned.terminal = True  # type: ignore[attr-defined]
    turned.direction = 1  # type: ignore[attr-defined]

    def met(_t, y, _sign):
        return y[2] - y[1]

    met.terminal = True  # type: ignore[attr-defined]

    def overloaded(_t, y):
        return abs(locked_torque(y[0], y[1])) - slip_torque

    overloaded.terminal = True  # type: ignore[attr-defined]
    overloaded.direction = 1  # type: ignore[attr-defined]

    ts, ys, phases = [], [], []
    segments: list[tuple[Any, bool]] = []  # each phase's solution (dense) and whether the clutch was locked
    torques: list[np.ndarray] = []          # the torque the clutch passes, per sample
    t0, state = 0.0, np.array([start_angle, 0.0, speed])
    slip_time = None
    for _ in range(50):  # slip and lock alternate a few times at most
        if t0 > max_time:
            raise InputError(f"The clutch does not turn the machine through a stroke within {max_time:g} s: its slip "
                             f"torque {slip_torque:g} N*m (at the crank) is too small for the load.")
        sign = 1.0 if state[2] >= state[1] else -1.0
        sol = solve_ivp(slip_rhs, (t0, t0 + max_time), state, args=(sign,), events=(turned, met), rtol=1e-9,
                        atol=1e-10, max_step=0.01, dense_output=True)
        segments.append((sol, False))
        torques.append(np.full(sol.t.size, slip_torque * sign))
        ts.append(sol.t)
        ys.append(sol.y)
        phases += ["slip"] * sol.t.size
        t0, state = float(sol.t[-1]), sol.y[:, -1].copy()
        if sol.t_events[0].size:
            break
        if not sol.t_events[1].size:
            raise InputError(f"The clutch does not turn the machine through a stroke within {max_time:g} s.")
        if slip_time is None:
            slip_time = t0
        w = 0.5 * (state[1] + state[2])
        needed = locked_torque(state[0], w)
        if abs(needed) > slip_torque:  # the clutch cannot hold: it keeps slipping, the side it cannot keep up
            state[1] = state[2] = w    # with falling behind
            state[2] += np.sign(needed) * 1e-9 * speed
            continue
        sol = solve_ivp(locked_rhs, (t0, t0 + max_time), [state[0], w], events=(turned, overloaded), rtol=1e-9,
                        atol=1e-10, max_step=0.01, dense_output=True)
        segments.append((sol, True))
        torques.append(np.array([locked_torque(p, w) for p, w in zip(sol.y[0], sol.y[1], strict=True)]))
        ts.append(sol.t)
        ys.append(np.vstack([sol.y, sol.y[1]]))
        phases += ["locked"] * sol.t.size
        t0 = float(sol.t[-1])
        state = np.array([sol.y[0, -1], sol.y[1, -1], sol.y[1, -1]])
        if sol.t_events[0].size:
            break
        state[2] += np.sign(locked_torque(state[0], state[1])) * 1e-9 * speed  # slips again
    if state[0] < end_angle - 1e-9:
        raise InputError("The clutch slips and locks without end: the single stroke does not complete a turn.")
    t_in = np.concatenate(ts)
    y_in = np.concatenate(ys, axis=1)
    phase_in = np.array(phases)
    slip_time = float(t0 if slip_time is None else slip_time)

    def engaged_at(angle: float) -> tuple[float, float, float]:
        """(t, ω₂, ω₁) where the engaged run first reaches the crank angle ``angle``, from the dense output."""
        for sol, locked in segments:
            phis = sol.y[0]
            above = np.flatnonzero(phis >= angle)
            if not above.size:
                continue
            k = int(above[0])
            if k == 0:
                t = float(sol.t[0])
            else:
                dense = sol.sol
                t = float(brentq(lambda tt, f=dense: f(tt)[0] - angle, sol.t[k - 1], sol.t[k], xtol=1e-14))
            y = sol.sol(t)
            return (t, float(y[1]), float(y[1] if locked else y[2]))
        raise InputError(f"The engaged run does not reach the crank angle {np.degrees(angle):g}°.")

    def stop_from(angle: float) -> Stop:
        """The brake's stop from the engaged run's state at the crank angle ``angle``."""
        _t, w2, _w1 = engaged_at(angle)
        return stop_machine(machine, driven_inertia, max(w2, 1e-12), brake_torque, angle)

    if brake_angle is None:
        lo, hi = start_angle + np.pi, end_angle - 1e-6

        def miss(angle: float) -> float:
            return float(stop_from(angle).phi[-1]) - end_angle

        if miss(lo) > 0:
            raise InputError(f"The brake torque {brake_torque:g} N*m (at the crank) cannot stop the crank within "
                             "half a turn: no brake angle brings it to rest at the start angle.")
        brake_angle = float(brentq(miss, lo, hi, xtol=1e-9))
    elif not start_angle < brake_angle < end_angle:
        raise InputError(f"The brake angle must lie within the stroke, between {np.degrees(start_angle):g}° and "
                         f"{np.degrees(end_angle):g}°; got {np.degrees(brake_angle):g}°.")
    t_b, w2_b, w1_b = engaged_at(brake_angle)
    stop = stop_from(brake_angle)
    keep = t_in <= t_b
    t_stop = t_b + stop.t
    stop_time = stop.time

    # ---- clutch out: the motor alone brings the driving side back to speed --------------------------------
    def drive_rhs(_t, y):
        return [tm(y[0]) / j1]

    def back(_t, y):
        return y[0] - speed * (1.0 - RECOVERED)

    back.terminal = True  # type: ignore[attr-defined]
    back.direction = 1  # type: ignore[attr-defined]
    if w1_b >= speed * (1.0 - RECOVERED):
        rec_t, rec_w = np.array([t_b]), np.array([w1_b])
    else:
        rec = solve_ivp(drive_rhs, (t_b, t_b + max_time), [w1_b], events=back, rtol=1e-9, atol=1e-10,
                        max_step=max_time / 2000)
        if rec.status != 1:
            raise InputError(f"The motor does not bring the flywheel back to {speed:g} rad/s (crank) within "
                             f"{max_time:g} s after a stroke.")
        rec_t, rec_w = rec.t, rec.y[0]
    stroke_end = float(t_stop[-1])
    recovery_end = float(rec_t[-1])
    w1_during_stop = np.interp(t_stop, rec_t, rec_w) if rec_t.size > 1 else np.full(t_stop.size, w1_b)
    tail = rec_t > stroke_end

    t = np.concatenate([t_in[keep], t_stop, rec_t[tail]])
    phi = np.concatenate([y_in[0][keep], stop.phi, np.full(int(tail.sum()), stop.phi[-1])])
    omega = np.concatenate([y_in[1][keep], stop.omega, np.zeros(int(tail.sum()))])
    omega_drive = np.concatenate([y_in[2][keep], w1_during_stop, rec_w[tail]])
    phase = np.concatenate([phase_in[keep], np.full(t_stop.size, "braking"), np.full(int(tail.sum()), "recovery")])
    engaged = int(keep.sum())
    clutch = np.concatenate([np.concatenate(torques)[keep], np.zeros(t.size - engaged)])

    slip_mask = phase[:engaged] == "slip"
    t_e = t[:engaged]
    rel = np.abs(omega_drive[:engaged] - omega[:engaged])
    clutch_energy = float(np.trapezoid(np.where(slip_mask, slip_torque * rel, 0.0), t_e))
    brake_energy = float(brake_torque * (stop.phi[-1] - brake_angle))
    # work of the motor on the driving side and of the machine's loads on the crank, over the stroke
    motor = np.array([tm(w) for w in omega_drive])
    motor_power = motor * omega_drive
    load_power = np.array([m(p, w) * w for p, w in zip(phi, omega, strict=True)])
    upto = t <= stroke_end
    motor_work = float(np.trapezoid(motor_power[upto], t[upto]))
    load_work = float(np.trapezoid(load_power[upto], t[upto]))
    return SingleStroke(
        t=t, phi=phi, omega=omega, omega_drive=omega_drive, clutch_torque=clutch, motor_torque=motor, phase=phase,
        running_speed=speed,
        start_angle=float(start_angle), brake_angle=float(brake_angle), rest_angle=float(stop.phi[-1]),
        slip_time=slip_time, clutch_energy=clutch_energy, brake_energy=brake_energy, stroke_time=stroke_end,
        stop_time=stop_time, stop_angle=float(stop.phi[-1] - brake_angle),
        lowest_drive_speed=float(np.min(omega_drive)), recovery_time=max(0.0, recovery_end - stroke_end),
        motor_work=motor_work, load_work=load_work, idle_torque=tm(speed),
    )


def single_stroke_duty(stroke: SingleStroke, drive: Any, strokes_per_minute: float | None) -> DutyCheck:
    """The thermal duty of the induction motor ``drive`` (:class:`~machdyn.dynamics.drives.InductionMotor`) that
    drives a press in single-stroke mode: the RMS of its torque over one period of strokes at
    ``strokes_per_minute`` [1/min] (None, or more than the drive can make: strokes back to back), against its
    rated torque in continuous duty S1 — the motor runs all the time, its load varying with each stroke
    (IEC 60034-1:2022, 4.2.1; :meth:`SingleStroke.motor_rms`, :func:`machdyn.dynamics.duty.motor_duty`)."""
    busy = stroke.stroke_time + stroke.recovery_time
    period = 60.0 / strokes_per_minute if strokes_per_minute else None
    if period is not None and period < busy:
        period = None
    return motor_duty(drive, stroke.motor_rms(period))
