"""A scenario of the coupled model integrated in time: start from rest, run-down coasting or braked, a change of
the supply frequency, a load step, or a prescribed crank speed (constant, or at a constant acceleration).

The state (cranks' angles and speeds, the frame's coordinates and rates, and the works of the drives, the loads,
the mounts' dampers and the brake) is integrated with :func:`scipy.integrate.solve_ivp`; the scenario's events at
given times (motor switched off, brake applied, load step, new supply frequency) split the integration, and a
crank coming to rest (below 0.1 % of the largest speed, the motors off) or rolling back under its drive ends it.
Every run is bounded by a budget of evaluations of the equations and of wall-clock time, and refused with a
message before it starts when its drive cannot turn the crank from rest.
"""

from __future__ import annotations

import math
import time
import warnings
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from ..errors import InputError, MachdynError
from ..results.labels import Label
from ..vibration.modes import modes
from . import fast
from .electric import electrical_drives
from .model import CoupledModel
from .torsion import torsional_states

__all__ = ["Scenario", "Transient", "TransientLimitError", "run_scenario"]

METHODS = ("auto", "LSODA", "Radau", "BDF", "DOP853", "RK45")


class TransientLimitError(MachdynError):
    """A transient run stopped at its budget of evaluations or of wall-clock time."""


@dataclass(frozen=True)
class Scenario:
    """What happens in a run (times in s from its start).

    duration : length of the run [s] > 0.
    speed : crank speeds at the start [rad/s] (one value for every crank, or one per crank); 0: from rest.
    angle : crank angles at the start [rad].
    switch_off : time the motors are switched off [s] (their rotors keep turning with the cranks).
    brake_time, brake_torque : a brake on every crank from ``brake_time`` [s], of ``brake_torque`` [N*m] at the
        crank against the motion (smoothed over 1e-3 of the largest speed so that it holds at rest).
    load_time, load_torque : a load torque [N*m] at each crank against its motion, from ``load_time`` [s].
    speed_change_time, speed_factor : at ``speed_change_time`` [s] the supply frequency of an induction motor
        (or the flow to a hydraulic motor) is multiplied by ``speed_factor`` (the motor's torque-speed curve
        shifted by the same slip speed, as under V/f control).
    prescribed : (speed [rad/s], acceleration [rad/s^2]): every crank turns at speed + acceleration t, whatever
        its load (the drive gives the torque it takes); the frame alone is integrated.
    method : "auto" (DOP853, or LSODA, which switches between Adams and BDF by itself, where a steep motor curve
        makes the equations stiff), "Radau" or "BDF" for a stiff model, "DOP853" or "RK45" otherwise.
    rtol : relative tolerance of the integrator.
    samples_per_period : output samples per period of the fastest of the crank's turn and the frame's modes.
    max_evaluations : budget of evaluations of the equations.
    max_seconds : budget of wall-clock time [s].
    """

    duration: float
    speed: Any = 0.0
    angle: Any = 0.0
    switch_off: float | None = None
    brake_time: float | None = None
    brake_torque: float = 0.0
    load_time: float | None = None
    load_torque: float = 0.0
    speed_change_time: float | None = None
    speed_factor: float = 1.0
    prescribed: tuple[float, float] | None = None
    method: str = "auto"
    rtol: float = 1e-8
    samples_per_period: int = 24
    max_evaluations: int = 400_000
    max_seconds: float = 120.0

    def __post_init__(self) -> None:
        if not (math.isfinite(self.duration) and self.duration > 0):
            raise InputError(f"The duration of a transient run must be > 0 s; got {self.duration!r} s.")
        if self.method not in METHODS:
            raise InputError(f"The integration method must be one of {', '.join(METHODS)}; got {self.method!r}.")
        for name in ("switch_off", "brake_time", "load_time", "speed_change_time"):
            t = getattr(self, name)
            if t is not None and not 0 <= t <= self.duration:
                raise InputError(f"The {name.replace('_', ' ')} of a transient run must lie in [0, duration = "
                                 f"{self.duration:g} s]; got {t:g} s.")
        if self.brake_torque < 0 or self.load_torque != self.load_torque:
            raise InputError(f"The brake torque must be >= 0 N*m; got {self.brake_torque:g} N*m.")
        if not self.speed_factor > 0:
            raise InputError(f"The speed factor of a speed change must be > 0; got {self.speed_factor:g}.")
        if not 0 < self.rtol < 1e-2:
            raise InputError(f"The relative tolerance must lie in (0, 0.01); got {self.rtol:g}.")
        if self.max_evaluations < 1000 or not self.max_seconds > 0:
            raise InputError(f"The budget must allow >= 1000 evaluations and > 0 s; got {self.max_evaluations} and "
                             f"{self.max_seconds:g} s.")

    def events(self) -> list[float]:
        """Times at which the equations change, in order."""
        found = {t for t in (self.switch_off, self.brake_time, self.load_time, self.speed_change_time)
                 if t is not None and 0 < t < self.duration}
        return sorted(found)


@dataclass(frozen=True)
class Transient:
    """A run in time (SI). t (T,); phi, omega, drive_torque (cranks x T); q, dq (3 x T, empty without a frame);
    mount_force (mounts x T) [N] along each mount's line (spring plus damper, positive in compression of the
    line's direction); works (4 x T) [J]: of the drives, of the loads on the machine (process loads, dampers,
    load step: negative when they take energy), of the mounts' dampers (dissipated), of the brake (dissipated);
    energy (T) [J] kinetic plus potential; ended: why the run ended ("duration", "stopped", "rolled back");
    evaluations of the equations; seconds of wall-clock time; electric: the rows of the drives with electrical
    states (:mod:`machdyn.transient.electric`, read by :func:`~machdyn.transient.electric.motor_run`), or None;
    torsion: the rows of the drive line's shafts behind stiff stages (read by
    :func:`~machdyn.transient.torsion.torsion_run`), or None."""

    model: CoupledModel
    scenario: Scenario
    t: np.ndarray
    phi: np.ndarray
    omega: np.ndarray
    drive_torque: np.ndarray
    q: np.ndarray
    dq: np.ndarray
    mount_force: np.ndarray
    works: np.ndarray
    energy: np.ndarray
    ended: str
    evaluations: int
    seconds: float
    electric: dict | None = None
    torsion: dict | None = None

    @property
    def motor_work(self) -> float:
        """Work of the drives over the run [J]."""
        return float(self.works[0, -1])

    @property
    def energy_error(self) -> float:
        """|motor work + load work - mount damping - brake - change of energy| over the largest of the energies
        that flow (relative): the built-in check of a run."""
        w = self.works[:, -1]
        change = float(self.energy[-1] - self.energy[0])
        scale = max(abs(w[0]), abs(w[1]), abs(w[2]), abs(w[3]), abs(change), 1e-300)
        return abs(w[0] + w[1] - w[2] - w[3] - change) / scale

    def point_displacement(self, point) -> np.ndarray:
        """(2 x T) displacement [m] of frame point ``point`` (x, y) [m]."""
        if self.q.shape[0] == 0:
            return np.zeros((2, self.t.size))
        px, py = (float(v) for v in point)
        x, y, b = self.q
        return np.stack([x - b * py, y + b * px])


def _torque_function(drive) -> Callable[[float], float] | None:
    """The drive's crank torque as a function of the crank speed, fast for an induction motor."""
    if drive is None:
        return None
    fast = getattr(drive, "torque_slope", None)
    if fast is not None:
        return lambda w: float(fast(w)[0])
    return lambda w: float(np.asarray(drive.torque_at(w)))


def _shifted(drive, factor: float, time: float = 0.0):
    """The drive with its supply frequency (induction motor) or its flow (hydraulic motor) times ``factor``.

    Under constant volts per hertz an induction motor's torque-speed curve moves along the speed axis with the
    synchronous speed, its breakdown torque and the slip speed at a given torque unchanged (B. K. Bose, *Modern
    Power Electronics and AC Drives*, Prentice Hall 2002, the chapter on the control of induction motor drives);
    valid above a few hertz, where the stator resistance is negligible. A hydraulic motor's no-load speed is its
    flow over its displacement."""
    if drive is None or factor == 1.0:
        return drive
    if hasattr(drive, "with_supply"):  # a motor with its electrical states: its supply's frequency and voltage
        return drive.with_supply(factor, time)
    name = getattr(drive, "name", "")
    if name == "induction motor":
        ns = float(drive.synchronous_speed)
        slip_speed = ns - float(drive.rated_speed)
        new_ns = ns * factor
        if new_ns <= slip_speed:
            raise InputError(f"The speed factor {factor:g} leaves the induction motor's synchronous speed "
                             f"{new_ns:.4g} rad/s below its rated slip speed {slip_speed:.4g} rad/s.")
        return replace(drive, synchronous_speed=new_ns, rated_speed=new_ns - slip_speed,
                       rated_power=float(drive.rated_power) * (new_ns - slip_speed) / float(drive.rated_speed))
    if name == "hydraulic motor":
        return replace(drive, flow=float(drive.flow) * factor)
    raise InputError(f"A speed change needs an induction or a hydraulic motor; got a {name or type(drive).__name__}.")


def _static_check(model: CoupledModel, scenario: Scenario, phi0: np.ndarray, drives: list) -> None:
    """A crank started from rest must be turned by its drive: its starting torque must exceed the static load."""
    for k, part in enumerate(model.parts):
        drive = drives[k]
        if drive is None:
            continue
        value, slope = part.channels(float(phi0[k]))
        need = float(slope[1]) - part.loads(float(phi0[k]), 0.0, value)
        if scenario.load_time is not None and scenario.load_time == 0.0:
            need += scenario.load_torque
        start = float(np.asarray(drive.torque_at(0.0)))
        if not start > need:
            raise InputError(
                f"The motor cannot start the crank of '{part.exciter.name}' from rest: its starting torque at the "
                f"crank is {start:.4g} N*m, the static load there is {need:.4g} N*m (crank angle "
                f"{math.degrees(float(phi0[k])):.1f}°). Choose a larger motor or a higher gear ratio, or start it "
                "at another crank angle.")


def run_scenario(model: CoupledModel, scenario: Scenario) -> Transient:
    """Integrate ``model`` through ``scenario``.

    Raises
    ------
    InputError : a drive that cannot start its crank from rest (naming its starting torque and the load).
    TransientLimitError : the run used up its evaluations or its wall-clock time (naming how far it came).
    """
    from scipy.integrate import solve_ivp

    n, frame = model.cranks, model.frame
    has_frame = frame is not None
    nq = 3 if has_frame else 0
    phi0 = np.broadcast_to(np.asarray(scenario.angle, dtype=float), (n,)).copy()
    w0 = np.broadcast_to(np.asarray(scenario.speed, dtype=float), (n,)).copy()
    if not np.all(np.isfinite(w0)) or not np.all(np.isfinite(phi0)):
        raise InputError(f"The start angles and speeds must be finite; got {phi0} rad and {w0} rad/s.")
    prescribed = scenario.prescribed
    if prescribed is not None and not has_frame:
        raise InputError("A prescribed crank speed on a rigid frame leaves nothing to integrate; give a frame.")
    drives = [p.exciter.drive for p in model.parts]
    if prescribed is None and np.any(w0 == 0.0):
        _static_check(model, scenario, phi0, drives)
    reference = max(float(np.max(np.abs(w0))), *(float(np.asarray(getattr(d, "no_load_speed", 0.0)))
                                                 for d in drives if d is not None), 1.0)
    if prescribed is not None:
        reference = max(reference, abs(prescribed[0]) + abs(prescribed[1]) * scenario.duration)
    brake_width = 1e-3 * reference
    counter = {"calls": 0, "start": time.perf_counter()}
    budget = scenario.max_evaluations
    state: dict[str, Any] = {"torques": [_torque_function(d) for d in drives], "brake": 0.0, "load": 0.0,
                             "on": True}

    def check_budget(t: float) -> None:
        counter["calls"] += 1
        if counter["calls"] > budget:
            raise TransientLimitError(
                f"The transient run used its budget of {budget:,} evaluations at t = {t:.4g} s of "
                f"{scenario.duration:g} s: the model is too stiff or too fast for this duration (a frame mode far "
                "above the crank speed, a very steep motor curve). Shorten the run, soften what is stiff, or "
                "raise max_evaluations.")
        if counter["calls"] % 2000 == 0 and time.perf_counter() - counter["start"] > scenario.max_seconds:
            raise TransientLimitError(
                f"The transient run was stopped after {scenario.max_seconds:g} s of computing at t = {t:.4g} s of "
                f"{scenario.duration:g} s; it would take about "
                f"{(time.perf_counter() - counter['start']) * scenario.duration / max(t, 1e-9):.3g} s in all.")

    def crank_forces(t, phis, omegas, values, on):
        drive_t = np.zeros(n)
        load_t = np.zeros(n)
        for k, part in enumerate(model.parts):
            w = float(omegas[k])
            fn = state["torques"][k]
            if fn is not None and on:
                drive_t[k] = fn(w)
            load_t[k] = part.loads(float(phis[k]), w, values[k]) - state["load"] * math.tanh(w / brake_width)
        return drive_t, load_t

    def rhs_free(t, y):
        check_budget(t)
        phis, omegas = y[:n], y[n:2 * n]
        q, dq = y[2 * n:2 * n + nq], y[2 * n + nq:2 * n + 2 * nq]
        mass, force, values, slopes = model.matrices(phis, omegas, q, dq)
        drive_t, load_t = crank_forces(t, phis, omegas, values, state["on"])
        brake_t = -state["brake"] * np.tanh(omegas / brake_width)
        g_c, g_f = model.gravity_terms(q, values, slopes)
        rhs = force.copy()
        rhs[:n] += drive_t + load_t + brake_t + g_c - np.array([s[1] for s in slopes])
        mount_loss = 0.0
        if has_frame:
            rhs[n:] += -model.stiffness @ q - model.damping @ dq + g_f
            mount_loss = float(dq @ model.damping @ dq)
        acc = np.linalg.solve(mass, rhs)
        works = [float(drive_t @ omegas), float(load_t @ omegas), mount_loss, -float(brake_t @ omegas)]
        return np.concatenate([omegas, acc[:n], dq, acc[n:], works])

    speed0, rate = prescribed if prescribed is not None else (0.0, 0.0)

    def profile(t):
        return (phi0 + speed0 * t + 0.5 * rate * t * t, np.full(n, speed0 + rate * t), np.full(n, rate))

    def rhs_prescribed(t, y, torque_only=False):
        if not torque_only:
            check_budget(t)
        phis, omegas, alphas = profile(t)
        q, dq = y[:3], y[3:6]
        mass, force, values, slopes = model.matrices(phis, omegas, q, dq)
        _, load_t = crank_forces(t, phis, omegas, values, False)
        g_c, g_f = model.gravity_terms(q, values, slopes)
        rhs_q = force[n:] - model.stiffness @ q - model.damping @ dq + g_f - mass[n:, :n] @ alphas
        ddq = np.linalg.solve(mass[n:, n:], rhs_q)
        # the torque the drive gives to hold the prescribed motion: the crank rows solved for it
        drive_t = (mass[:n, :n] @ alphas + mass[:n, n:] @ ddq - force[:n] - load_t - g_c
                   + np.array([s[1] for s in slopes]))
        if torque_only:
            return drive_t
        works = [float(drive_t @ omegas), float(load_t @ omegas), float(dq @ model.damping @ dq), 0.0]
        return np.concatenate([dq, ddq, works])

    if prescribed is None:
        y0 = np.concatenate([phi0, w0, np.zeros(2 * nq), np.zeros(4)])
        rhs = rhs_free
        if fast.usable(model):
            rhs = fast.right_hand_side(model, state, check_budget, brake_width)
    else:
        y0 = np.zeros(2 * nq + 4)
        rhs = rhs_prescribed
        if fast.usable(model):
            rhs = rhs_prescribed = fast.prescribed_right_hand_side(model, profile, state, check_budget, brake_width)
    drive_list = list(drives)
    torsion = torsional_states(model, y0.size) if prescribed is None else None
    atol = _tolerances(y0, n, nq, prescribed is not None, reference, model)
    if torsion is not None:  # the drive line's shafts behind stiff stages, each group on its own
        rhs = torsion.wrap(rhs, state)
        y0 = np.concatenate([y0, torsion.initial(phi0, w0)])
        atol = np.concatenate([atol, torsion.tolerances(reference)])
    electric = electrical_drives(drive_list, y0.size, n, torsion) if prescribed is None else None
    if electric is not None:  # the motors' flux linkages integrated with the machine
        rhs = electric.wrap(rhs, state)
        y0 = np.concatenate([y0, electric.initial()])
        atol = np.concatenate([atol, electric.tolerances()])
    fastest = reference
    if frame is not None:
        fastest = max(fastest, float(np.max(modes(frame).angular_frequencies)))
    if torsion is not None:
        fastest = max(fastest, torsion.fastest(model))
    step = 2.0 * math.pi / fastest / max(int(scenario.samples_per_period), 4)
    samples = int(min(max(scenario.duration / step, 200), 400_000))
    t_out = np.linspace(0.0, scenario.duration, samples + 1)
    method = scenario.method
    if method == "auto":
        # the motor's electrical states are stiff; a stiff stage's spring is a fast oscillation, which DOP853
        # follows with the works' balance closed to 1e-8 (LSODA's Adams steps leave 1e-6 on a slow machine)
        method = "LSODA" if electric is not None else _method(model, scenario, reference, fastest)
    cuts = [0.0, *scenario.events(), scenario.duration]
    pieces_t: list[np.ndarray] = []
    pieces_y: list[np.ndarray] = []
    ended = "duration"
    y = y0

    def stopped(t, y):  # a crank come to rest (below 0.1 % of the reference speed, the motors off) or rolling back
        # (under its drive)
        return float(np.min(y[n:2 * n])) + (-1e-3 * reference if not state["on"] else 1e-3 * reference)

    stopped.terminal = True  # type: ignore[attr-defined]
    stopped.direction = -1  # type: ignore[attr-defined]
    segments = []
    for start, end in zip(cuts[:-1], cuts[1:], strict=True):
        _apply_events(scenario, start, state, drive_list)
        if electric is not None:
            y = electric.enter(y, state)
        segments.append((start, dict(state)))
        mask = (t_out >= start) & (t_out <= end)
        t_eval = t_out[mask]
        if t_eval.size == 0 or t_eval[0] > start:
            t_eval = np.concatenate([[start], t_eval])
        if t_eval[-1] < end:
            t_eval = np.concatenate([t_eval, [end]])
        events = [stopped] if prescribed is None and (state["on"] or np.any(y[n:2 * n] > 1e-3 * reference)) else None
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UserWarning)
            sol = solve_ivp(rhs, (start, end), y, method=method, rtol=scenario.rtol, atol=atol, t_eval=t_eval,
                            events=events)
        if not sol.success or not np.all(np.isfinite(sol.y)):
            raise TransientLimitError(f"The time integration failed at t = {sol.t[-1] if sol.t.size else start:.4g}"
                                      f" s: {sol.message}")
        keep = slice(1, None) if pieces_t else slice(None)
        pieces_t.append(sol.t[keep])
        pieces_y.append(sol.y[:, keep])
        y = sol.y[:, -1]
        if sol.status == 1:
            te, ye = sol.t_events[0][0], sol.y_events[0][0]
            pieces_t.append(np.array([te]))
            pieces_y.append(ye[:, None])
            ended = "stopped" if not state["on"] else "rolled back"
            break
    t_all = np.concatenate(pieces_t)
    y_all = np.concatenate(pieces_y, axis=1)
    held = None
    if prescribed is not None:
        held = np.stack([rhs_prescribed(ti, y_all[:, i], True) for i, ti in enumerate(t_all)], axis=-1)
    return _result(model, scenario, t_all, y_all, n, nq, profile if prescribed else None, held, segments, ended,
                   counter, electric, torsion)


def _method(model: CoupledModel, scenario: Scenario, reference: float, fastest: float) -> str:
    """DOP853 (an explicit Runge-Kutta method of order 8, few evaluations per step on these smooth equations and an
    energy balance to 1e-8), or LSODA where a steep motor curve makes the crank's equation stiff: its rate
    |dT/domega| / J above twice the fastest frequency of the motion (a hydraulic motor on a light shaft: DOP853
    then takes twice LSODA's evaluations, held at its stability limit)."""
    rate = 0.0
    for part in model.parts:
        drive = part.exciter.drive
        if drive is None or not hasattr(drive, "slope"):
            continue
        speeds = np.linspace(0.0, 1.2 * reference, 25)
        slope = float(np.max(np.abs(np.asarray(drive.slope(speeds), dtype=float))))
        inertia = float(part.c0[0] - np.sum(np.hypot(part.ca[0], part.cb[0])) + part.added)
        rate = max(rate, slope / max(inertia, 1e-300))
    return "LSODA" if rate > 2.0 * fastest else "DOP853"


def _apply_events(scenario: Scenario, start: float, state: dict, drives: list) -> None:
    """The scenario's state from ``start`` on."""
    state["on"] = scenario.switch_off is None or start < scenario.switch_off
    state["brake"] = scenario.brake_torque if scenario.brake_time is not None and start >= scenario.brake_time else 0.0
    state["load"] = scenario.load_torque if scenario.load_time is not None and start >= scenario.load_time else 0.0
    if scenario.speed_change_time is not None and start >= scenario.speed_change_time and not state.get("changed"):
        state["changed"] = True
        for k, d in enumerate(drives):
            drives[k] = _shifted(d, scenario.speed_factor, start)
        state["torques"] = [_torque_function(d) for d in drives]


def _tolerances(y0, n, nq, prescribed, reference, model):
    """Absolute tolerances: angles to 1e-10 rad, speeds to 1e-10 of the reference speed, the frame's coordinates
    to 1e-12 m, works to 1e-9 J."""
    if prescribed:
        return np.concatenate([np.full(nq, 1e-13), np.full(nq, 1e-13 * reference), np.full(4, 1e-9)])
    return np.concatenate([np.full(n, 1e-10), np.full(n, 1e-10 * reference), np.full(nq, 1e-13),
                           np.full(nq, 1e-13 * reference), np.full(4, 1e-9)])


def _result(model, scenario, t, y, n, nq, profile, held, segments, ended, counter, electric=None, torsion=None):
    rows = twists = None
    if profile is None:
        phi, omega = y[:n], y[n:2 * n]
        q, dq = y[2 * n:2 * n + nq], y[2 * n + nq:2 * n + 2 * nq]
        works = y[2 * n + 2 * nq:2 * n + 2 * nq + 4]
        torque = np.zeros_like(omega)
        starts = np.array([s for s, _ in segments])
        for i, ti in enumerate(t):
            # at an event time the value before it (the segment that ends there)
            state = segments[max(int(np.searchsorted(starts, ti, side="left")) - 1, 0)][1]
            if state["on"]:
                for k in range(n):
                    fn = state["torques"][k]
                    torque[k, i] = fn(float(omega[k, i])) if fn is not None else 0.0
        if electric is not None:  # the motors' electromagnetic torque at the crank, from their flux linkages
            rows = {"index": list(electric.index), "drives": [electric.drives[k] for k in electric.index],
                    "rows": y[electric.offset:]}
            for j, k in enumerate(electric.index):
                motor = electric.drives[k]
                te = motor.electromagnetic_torque(y[electric.offset + electric.width * j:][:4])
                torque[k] = motor.ratio * np.where(te >= 0.0, te * motor.efficiency, te / motor.efficiency)
        if torsion is not None:  # the crank is driven by the last stiff stage's spring
            twists = {"lines": dict(torsion.lines),
                      "rows": {k: y[torsion.starts[k]:torsion.starts[k] + 2 * line.groups + 2]
                               for k, line in torsion.lines.items()}}
            for k, line in torsion.lines.items():
                g, base = line.groups, torsion.starts[k]
                torque[k] = (line.stiffness[-1] * (y[base + g - 1] - phi[k])
                             + line.damping[-1] * (y[base + 2 * g - 1] - omega[k]))
    else:
        phi, omega, _ = (np.stack(v, axis=-1) for v in zip(*(profile(ti) for ti in t), strict=True))
        q, dq = y[:3], y[3:6]
        works = y[6:10]
        torque = held
    energy = np.array([model.energy(phi[:, i], omega[:, i], q[:, i], dq[:, i]) for i in range(t.size)])
    if model.frame is not None:
        b = model.frame.influence_matrix()
        rates = np.array([m.stiffness for m in model.frame.mounts])
        dampers = np.array([m.damping for m in model.frame.mounts])
        force = rates[:, None] * (b @ q) + dampers[:, None] * (b @ dq)
    else:
        force = np.zeros((0, t.size))
    return Transient(model, scenario, t, phi, omega, torque, q, dq, force, works, energy, ended, counter["calls"],
                     time.perf_counter() - counter["start"], rows, twists)


def balance_scalars(run, final_speed: float, captured: bool) -> dict[str, float]:
    """The results every ``[transient]`` run reports from its time history ``run`` (a :class:`Transient` or a
    shaft line's run: ``works`` [J] of the drive, the loads, the mounts and the brake over time, ``energy`` [J],
    ``energy_error``, ``evaluations``): the final speed [rad/s], capture (1/0) and the energy balance's terms."""
    w = run.works[:, -1]
    return {
        "transient.final_speed": final_speed,
        "transient.captured": float(captured),
        "transient.motor_work": float(w[0]),
        "transient.load_work": float(-w[1]),
        "transient.mount_dissipation": float(w[2]),
        "transient.brake_dissipation": float(w[3]),
        "transient.energy_change": float(run.energy[-1] - run.energy[0]),
        "transient.energy_error": run.energy_error,
        "transient.evaluations": float(run.evaluations),
    }


def passage_results(passages, with_frequency: bool = False) -> tuple[dict[str, float], dict[str, Any]]:
    """The results of a run's resonance passages (:class:`~machdyn.transient.passage.Passage`): the largest
    amplitude [m] and mount force [N] of any, the time in their bands [s], and each passage's own figures
    (``transient.passage_<i>.*``) with their labels; ``with_frequency`` names each mode's frequency [Hz] too."""
    if not passages:
        return {}, {}
    values = {"transient.passage_peak_amplitude": max(p.peak_amplitude for p in passages),
              "transient.passage_peak_mount_force": max(p.peak_mount_force for p in passages),
              "transient.passage_time": sum(p.time_in_band for p in passages)}
    labels = {}
    for i, p in enumerate(passages, start=1):
        key = f"transient.passage_{i}"
        hz = f", {p.frequency / (2 * math.pi):.3g} Hz" if with_frequency else ""
        what = f"passage {i} (mode {p.mode}{hz}, {p.direction})"
        for field, value, text, unit in (("time", p.time, "time of crossing", "s"),
                                         ("peak_amplitude", p.peak_amplitude, "peak displacement", "m"),
                                         ("peak_mount_force", p.peak_mount_force, "peak mount force", "N"),
                                         ("time_in_band", p.time_in_band, "time within the band", "s")):
            values[f"{key}.{field}"] = float(value)
            labels[f"{key}.{field}"] = Label(f"Transient: {what}, {text}", unit, "mm" if unit == "m" else None)
    return values, labels
