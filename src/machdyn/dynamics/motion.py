"""Motion in time of the equivalent machine: free motion and the start-up from rest to steady running.

The state (phi, omega) is integrated with :func:`scipy.integrate.solve_ivp` (DOP853) from the equation of
:mod:`.simulate`; the start-up runs until the speed stays within a tolerance of the periodic steady state at the
same crank angle.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .drives import ConstantSpeed
from .equivalent import EquivalentMachine
from .simulate import (
    RTOL,
    EvaluationBudget,
    NotSettledError,
    SteadyState,
    _added_inertia,
    _designs,
    _Model,
    _out,
    _stall_message,
    budgeted,
    steady_state,
)

#: Evaluations of the equation of motion allowed for a start-up from rest (the examples need at most about
#: 25,000 for all their start-ups together): a start-up that creeps near a stall is stopped within seconds.
MAX_START_UP_EVALUATIONS = 400_000


@dataclass(frozen=True)
class Trajectory:
    """A motion in time: t [s], phi [rad], omega [rad/s] (designs first), the drive torque [N*m] and the
    kinetic plus potential energy [J] of the machine with its flywheel (from the machine's curves)."""

    t: np.ndarray
    phi: np.ndarray
    omega: np.ndarray
    drive_torque: np.ndarray
    energy: np.ndarray


def simulate(machine: EquivalentMachine, drive, flywheel=0.0, *, duration: float, phi0=0.0, omega0=0.0,
             samples: int = 400, rtol: float = RTOL) -> Trajectory:
    """Integrate the machine in time from (phi0 [rad], omega0 [rad/s]) over ``duration`` [s].

    ``drive`` None leaves the machine free (no drive torque, no drive inertia).
    """
    from scipy.integrate import solve_ivp

    if not duration > 0:
        raise InputError(f"The duration of a simulation must be > 0 s; got {duration!r}.")
    if isinstance(drive, ConstantSpeed):
        raise InputError("A constant-speed drive imposes the motion; use steady_state for it.")
    n = _designs(machine, flywheel, phi0, omega0)
    added = _added_inertia(flywheel, drive, n)
    model = _Model(machine, drive, added, n)
    y0 = np.concatenate([np.broadcast_to(phi0, (n,)), np.broadcast_to(omega0, (n,))]).astype(float)
    t_eval = np.linspace(0.0, duration, samples)
    sol = solve_ivp(model.time_rhs, (0.0, duration), y0, method="DOP853", rtol=rtol,
                    atol=1e-12 * max(1.0, float(np.max(np.abs(y0)))), t_eval=t_eval)
    if not sol.success:
        raise NotSettledError(f"The time integration failed: {sol.message}")
    return _trajectory(machine, model, sol.t, sol.y, n)


def _trajectory(machine, model, t, y, n):
    phi, omega = y[:n], y[n:]
    j = model.inertia(phi)[0]
    td = np.broadcast_to(model.drive_torque(omega)[0], phi.shape)
    e = 0.5 * j * omega**2 + machine.potential(phi)
    s = machine.single
    return Trajectory(t, _out(phi, s), _out(omega, s), _out(td, s), _out(e, s))


@dataclass(frozen=True)
class StartUp:
    """A start-up from rest: the trajectory, the steady state it runs into and the time to steady running [s]
    (the first time after which the speed stays within ``tolerance`` * mean speed of the steady-state speed at
    the same crank angle)."""

    trajectory: Trajectory
    steady: SteadyState
    time_to_steady: np.ndarray
    tolerance: float


def start_up(machine: EquivalentMachine, drive, flywheel=0.0, *, phi0: float = 0.0, tolerance: float = 0.01,
             max_time: float | None = None, steady: SteadyState | None = None, samples_per_cycle: int = 100,
             rtol: float = 1e-9) -> StartUp:
    """Start the machine from rest at crank angle ``phi0`` [rad] and run it until it is in steady running.

    Raises InputError if the drive cannot start it (naming its starting torque and the load's static torque at
    phi0) or if it rolls back; :class:`NotSettledError` if it is not in steady running after ``max_time`` [s]
    (default: 500 steady-state periods).
    """
    from scipy.integrate import solve_ivp

    if isinstance(drive, ConstantSpeed):
        raise InputError("A constant-speed drive has no start-up; give a motor (constant torque, induction, table or "
                         "hydraulic).")
    if not 0 < tolerance < 1:
        raise InputError(f"The tolerance of steady running must be in (0, 1); got {tolerance!r}.")
    steady = steady or steady_state(machine, drive, flywheel)
    n = _designs(machine, flywheel)
    added = _added_inertia(flywheel, drive, n)
    model = _Model(machine, drive, added, n)
    q0 = np.full(n, float(phi0))
    static = machine.position_moment(q0)
    start = np.broadcast_to(drive.torque_at(0.0), (n,))
    if np.any(start + static <= 0):
        i = int(np.flatnonzero(start + static <= 0)[0])
        grid = np.broadcast_to(steady.phi, (n, steady.phi.size))
        peak = float(np.max(-machine.position_moment(grid)))
        raise InputError(
            f"The drive cannot start the machine at crank angle {np.degrees(phi0):.1f}°: its starting torque "
            f"{start[i]:.4g} N*m at the crank does not exceed the load's static torque {-static[i]:.4g} N*m there "
            f"(peak static load over the cycle {peak:.4g} N*m; breakdown torque "
            f"{float(np.min(getattr(drive, 'breakdown_torque', np.nan))):.4g} N*m).")
    curve = steady.speed_curve()
    period_t = float(np.max(steady.period_time))
    limit = max_time if max_time is not None else 500.0 * period_t
    wm = np.atleast_1d(steady.mean_speed)

    def rollback(t, y):
        return float(np.min(y[n:])) + 1e-9 * float(np.max(wm))

    rollback.terminal = True  # type: ignore[attr-defined]
    rollback.direction = -1  # type: ignore[attr-defined]
    ts, ys = [np.zeros(1)], [np.concatenate([q0, np.zeros(n)])[:, None]]
    t0, y0 = 0.0, ys[0][:, 0]
    settled_at = np.full(n, np.nan)
    chunk = 5.0 * period_t
    rhs = budgeted(model.time_rhs, MAX_START_UP_EVALUATIONS)
    while t0 < limit:
        t1 = min(t0 + chunk, limit)
        t_eval = np.linspace(t0, t1, int(samples_per_cycle * (t1 - t0) / period_t) + 2)[1:]
        try:
            sol = solve_ivp(rhs, (t0, t1), y0, method="DOP853", rtol=rtol, atol=1e-10 * float(np.max(wm)),
                            t_eval=t_eval, events=rollback)
        except EvaluationBudget:
            raise NotSettledError(
                f"The start-up was stopped after {MAX_START_UP_EVALUATIONS:,} steps of the integrator at {t0:.4g} s "
                f"without reaching steady running: the machine creeps near a stall or accelerates without end "
                f"({_stall_message(machine, drive, n, wm, steady.phi)}).") from None
        if sol.status == 1:
            raise InputError(
                f"The machine rolls back after {sol.t[-1]:.3g} s of start-up: the drive's torque at low speed does not "
                f"carry it over its peak load ({_stall_message(machine, drive, n, wm, steady.phi)}).")
        ts.append(sol.t)
        ys.append(sol.y)
        t0, y0 = float(sol.t[-1]), sol.y[:, -1]
        t_all, y_all = np.concatenate(ts), np.concatenate(ys, axis=1)
        off = np.abs(y_all[n:] - curve(y_all[:n])) > tolerance * wm[:, None]
        # settled: off nowhere during the last cycle
        last = t_all >= t0 - period_t
        if t0 >= period_t and not np.any(off[:, last]):
            for i in range(n):
                bad = np.flatnonzero(off[i])
                settled_at[i] = t_all[bad[-1] + 1] if bad.size else 0.0
            traj = _trajectory(machine, model, t_all, y_all, n)
            return StartUp(traj, steady, _out(settled_at, machine.single), tolerance)
    raise NotSettledError(
        f"The machine did not reach steady running within {limit:.4g} s ({limit / period_t:.0f} steady-state "
        f"periods): its speed still differs from the steady state by more than {tolerance:.1%} of the mean speed.")
