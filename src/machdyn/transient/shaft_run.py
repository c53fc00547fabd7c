"""A scenario of a shaft line on its six-degree-of-freedom frame integrated in time (:mod:`.shaft_model`).

The state (shaft angle and speed, the frame's six coordinates and rates, and the works of the drive, the loads, the
mounts' dampers and the brake) is integrated with :func:`scipy.integrate.solve_ivp` through the same
:class:`~machdyn.transient.run.Scenario` as a mechanism's run: start from rest, switch-off, a brake, a load step, a
change of the supply frequency, or the shaft turned at a prescribed speed (constant, or at a constant
acceleration) with the frame alone integrated. Bounded by the scenario's budget of evaluations and seconds.
"""

from __future__ import annotations

import math
import time
import warnings
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import InputError
from ..shafts.frame6 import Frame6, modes6
from .run import Scenario, TransientLimitError, _shifted, _torque_function
from .shaft_model import ShaftFrameModel

__all__ = ["ShaftTransient", "run_shaft_scenario"]


@dataclass(frozen=True)
class ShaftTransient:
    """A run in time (SI): t (T,); phi, omega, drive_torque (1 x T) of the shaft; q, dq (6 x T) the frame's
    translation [m] and rotation vector [rad] and their rates; mount_force (mounts x T) [N] along each mount's
    line; works (4 x T) [J] of the drive, of the loads (negative when they take energy), of the mounts' dampers and
    of the brake; energy (T) [J] kinetic plus the mounts' potential; why it ended; evaluations; seconds."""

    model: ShaftFrameModel
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

    @property
    def motor_work(self) -> float:
        return float(self.works[0, -1])

    @property
    def energy_error(self) -> float:
        """|drive work + load work - dissipation - change of energy| over the largest energy that flows."""
        w = self.works[:, -1]
        change = float(self.energy[-1] - self.energy[0])
        scale = max(*(abs(float(v)) for v in w), abs(change), 1e-300)
        return abs(w[0] + w[1] - w[2] - w[3] - change) / scale

    def point_displacement(self, point) -> np.ndarray:
        """(3 x T) displacement [m] of frame point ``point`` (x, y, z) [m]: u + vartheta x p."""
        return Frame6.point_matrix(point) @ self.q


def _check_start(model: ShaftFrameModel, scenario: Scenario, torque) -> None:
    if torque is None:
        return
    start = torque(0.0)
    need = scenario.load_torque if scenario.load_time == 0.0 else 0.0
    if not start > need:
        raise InputError(f"The motor cannot start the shaft line from rest: its starting torque at the shaft is "
                         f"{start:.4g} N*m against a load of {need:.4g} N*m. Choose a larger motor.")


def run_shaft_scenario(model: ShaftFrameModel, scenario: Scenario, frame_start=None) -> ShaftTransient:
    """Integrate ``model`` through ``scenario`` (one shaft: ``speed`` and ``angle`` scalars), the frame starting
    at rest at ``frame_start`` (6,) [m, rad] (None: at its static equilibrium).

    Raises InputError for a drive that cannot start the shaft from rest, TransientLimitError when the run uses up
    its evaluations or seconds."""
    from scipy.integrate import solve_ivp

    theta0 = float(np.ravel(scenario.angle)[0])
    w0 = float(np.ravel(scenario.speed)[0])
    if not (math.isfinite(theta0) and math.isfinite(w0)):
        raise InputError(f"The start angle and speed must be finite; got {theta0} rad and {w0} rad/s.")
    prescribed = scenario.prescribed
    drive = model.drive
    if prescribed is None and drive is None and w0 == 0.0 and frame_start is None:
        raise InputError("A shaft line at rest without a motor does not move: give a motor, a start speed or a "
                         "prescribed speed.")
    state: dict[str, Any] = {"torque": _torque_function(drive), "brake": 0.0, "load": 0.0, "on": True}
    if prescribed is None and w0 == 0.0:
        _check_start(model, scenario, state["torque"])
    reference = max(abs(w0), float(np.asarray(getattr(drive, "no_load_speed", 0.0))) if drive is not None else 0.0,
                    1.0)
    if prescribed is not None:
        reference = max(reference, abs(prescribed[0]) + abs(prescribed[1]) * scenario.duration)
    width = 1e-3 * reference
    counter = {"calls": 0, "start": time.perf_counter()}
    k_mat, c_mat = model.stiffness, model.damping

    def check_budget(t: float) -> None:
        counter["calls"] += 1
        if counter["calls"] > scenario.max_evaluations:
            raise TransientLimitError(
                f"The transient run used its budget of {scenario.max_evaluations:,} evaluations at t = {t:.4g} s of "
                f"{scenario.duration:g} s: the model is too stiff or too fast for this duration. Shorten the run, "
                "soften what is stiff, or raise max_evaluations.")
        if counter["calls"] % 2000 == 0 and time.perf_counter() - counter["start"] > scenario.max_seconds:
            raise TransientLimitError(
                f"The transient run was stopped after {scenario.max_seconds:g} s of computing at t = {t:.4g} s of "
                f"{scenario.duration:g} s.")

    def shaft_torques(w: float) -> tuple[float, float, float]:
        fn = state["torque"]
        drive_t = fn(w) if fn is not None and state["on"] else 0.0
        return drive_t, -state["load"] * math.tanh(w / width), -state["brake"] * math.tanh(w / width)

    def rhs_free(t, y):
        check_budget(t)
        q, dq = y[2:8], y[8:14]
        ds = np.concatenate([[y[1]], dq])
        mass, force = model.matrices(float(y[0]), q, ds)
        drive_t, load_t, brake_t = shaft_torques(float(y[1]))
        force[0] += drive_t + load_t + brake_t
        force[1:] -= k_mat @ q + c_mat @ dq
        acc = np.linalg.solve(mass, force)
        w = float(y[1])
        works = [drive_t * w, load_t * w, float(dq @ c_mat @ dq), -brake_t * w]
        return np.concatenate([[w, acc[0]], dq, acc[1:], works])

    speed0, rate = prescribed if prescribed is not None else (0.0, 0.0)

    def profile(t):
        return theta0 + speed0 * t + 0.5 * rate * t * t, speed0 + rate * t

    def rhs_prescribed(t, y, torque_only=False):
        if not torque_only:
            check_budget(t)
        theta, w = profile(t)
        q, dq = y[:6], y[6:12]
        ds = np.concatenate([[w], dq])
        mass, force = model.matrices(theta, q, ds)
        _, load_t, _ = shaft_torques(w)
        rhs_q = force[1:] - k_mat @ q - c_mat @ dq - mass[1:, 0] * rate
        ddq = np.linalg.solve(mass[1:, 1:], rhs_q)
        drive_t = float(mass[0, 0] * rate + mass[0, 1:] @ ddq - force[0] - load_t)
        if torque_only:
            return drive_t
        return np.concatenate([dq, ddq, [drive_t * w, load_t * w, float(dq @ c_mat @ dq), 0.0]])

    fastest = max(reference, 2.0 * math.pi * float(np.max(modes6(model.frame)[0])))
    step = 2.0 * math.pi / fastest / max(int(scenario.samples_per_period), 4)
    samples = int(min(max(scenario.duration / step, 200), 400_000))
    t_out = np.linspace(0.0, scenario.duration, samples + 1)
    if prescribed is None:
        y = np.concatenate([[theta0, w0], np.zeros(16)])
        rhs = rhs_free
        atol = np.concatenate([[1e-10, 1e-10 * reference], np.full(6, 1e-13), np.full(6, 1e-13 * reference),
                               np.full(4, 1e-9)])
    else:
        y = np.zeros(16)
        rhs = rhs_prescribed
        atol = np.concatenate([np.full(6, 1e-13), np.full(6, 1e-13 * reference), np.full(4, 1e-9)])
    if frame_start is not None:
        offset = 2 if prescribed is None else 0
        y[offset:offset + 6] = np.asarray(frame_start, dtype=float)
    method = "DOP853" if scenario.method == "auto" else scenario.method
    cuts = [0.0, *scenario.events(), scenario.duration]
    pieces_t: list[np.ndarray] = []
    pieces_y: list[np.ndarray] = []
    segments: list[tuple[float, dict]] = []
    ended = "duration"
    drive_now = [drive]

    def stopped(t, y):  # the shaft come to rest (motor off) or rolling back under its drive
        return float(y[1]) + (-1e-3 * reference if not state["on"] else 1e-3 * reference)

    stopped.terminal = True  # type: ignore[attr-defined]
    stopped.direction = -1  # type: ignore[attr-defined]
    for start, end in zip(cuts[:-1], cuts[1:], strict=True):
        _apply(scenario, start, state, drive_now)
        segments.append((start, dict(state)))
        t_eval = t_out[(t_out >= start) & (t_out <= end)]
        if t_eval.size == 0 or t_eval[0] > start:
            t_eval = np.concatenate([[start], t_eval])
        if t_eval[-1] < end:
            t_eval = np.concatenate([t_eval, [end]])
        events = [stopped] if prescribed is None and (state["on"] or y[1] > 1e-3 * reference) else None
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
            pieces_t.append(np.array([sol.t_events[0][0]]))
            pieces_y.append(sol.y_events[0][0][:, None])
            ended = "stopped" if not state["on"] else "rolled back"
            break
    t_all = np.concatenate(pieces_t)
    y_all = np.concatenate(pieces_y, axis=1)
    if prescribed is None:
        theta, omega = y_all[0], y_all[1]
        q, dq, works = y_all[2:8], y_all[8:14], y_all[14:]
        starts = np.array([s for s, _ in segments])
        torque = np.zeros_like(omega)
        for i, ti in enumerate(t_all):
            seg = segments[max(int(np.searchsorted(starts, ti, side="left")) - 1, 0)][1]
            fn = seg["torque"]
            torque[i] = fn(float(omega[i])) if fn is not None and seg["on"] else 0.0
    else:
        theta, omega = (np.array(v) for v in zip(*(profile(ti) for ti in t_all), strict=True))
        q, dq, works = y_all[:6], y_all[6:12], y_all[12:]
        torque = np.array([rhs_prescribed(ti, y_all[:, i], True) for i, ti in enumerate(t_all)])
    energy = np.array([model.energy(float(theta[i]), q[:, i], np.concatenate([[omega[i]], dq[:, i]]))
                       for i in range(t_all.size)])
    b = model.frame.influence_matrix()
    rates = np.array([m.stiffness for m in model.frame.mounts])
    dampers = np.array([m.damping for m in model.frame.mounts])
    force = rates[:, None] * (b @ q) + dampers[:, None] * (b @ dq)
    return ShaftTransient(model, scenario, t_all, theta[None, :], omega[None, :], torque[None, :], q, dq, force,
                          works, energy, ended, int(counter["calls"]), time.perf_counter() - counter["start"])


def _apply(scenario: Scenario, start: float, state: dict, drive: list) -> None:
    """The scenario's state from ``start`` on."""
    state["on"] = scenario.switch_off is None or start < scenario.switch_off
    state["brake"] = scenario.brake_torque if scenario.brake_time is not None and start >= scenario.brake_time else 0.0
    state["load"] = scenario.load_torque if scenario.load_time is not None and start >= scenario.load_time else 0.0
    if scenario.speed_change_time is not None and start >= scenario.speed_change_time and not state.get("changed"):
        state["changed"] = True
        drive[0] = _shifted(drive[0], scenario.speed_factor)
        state["torque"] = _torque_function(drive[0])
