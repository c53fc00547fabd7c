"""Forward dynamics of the equivalent machine under a real drive: periodic steady state, start-up, free motion.

Equation of motion (Lagrange, one degree of freedom; Uicker, Pennock & Shigley, *Theory of Machines and
Mechanisms*, the chapter on flywheels): J(phi) phi'' + J'(phi)/2 phi'^2 = M_drive(phi') + M(phi, phi'), where J includes
the flywheel and the drive's rotor reduced to the crank.

**Steady state, directly.** With the kinetic energy K = J omega^2 / 2 and phi as the independent variable the
equation becomes dK/dphi = M_drive(omega) + M(phi, omega), omega = sqrt(2K/J), dt/dphi = 1/omega: one equation
per design, whatever the mechanism. The periodic solution K(phi0 + P) = K(phi0) is found by Newton's method on
K(phi0) (shooting over one cycle), with the derivative dK(P)/dK(phi0) integrated alongside (the variational
equation), so a few cycles are integrated, not the hundreds a start-up from rest takes to settle. All design
variants share phi and are integrated together in one call of :func:`scipy.integrate.solve_ivp`.

**Start-up and free motion** integrate the state (phi, omega) in time (:mod:`.motion`).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from ..errors import InputError, MachdynError
from .drives import ConstantSpeed, ConstantTorque, InductionMotor
from .equivalent import EquivalentMachine, _force_moment
from .periodic import collocation_steady
from .tables import FourierCurve, PeriodicCurve, fine_grid

RTOL = 1e-11  # the integrator's relative tolerance: periodicity and energy are checked to 1e-9


class NotSettledError(MachdynError):
    """The simulation did not reach a periodic steady state (or steady running) within its limits."""


#: Evaluations of the equation of motion allowed for one cycle of the steady-state shooting: the examples need
#: at most about 5,000; a machine that nearly stalls (its speed creeping towards zero, where the integrator's
#: steps shrink without end) or runs away is stopped here, within seconds, instead of integrating for minutes.
MAX_EVALUATIONS_PER_CYCLE = 100_000


class EvaluationBudget(Exception):
    """Raised inside an integration that used up its evaluations (see :func:`budgeted`)."""


def budgeted(rhs, limit: int):
    """``rhs`` counting its calls; the ``limit``-th call raises :class:`EvaluationBudget`."""
    calls = [0]

    def counted(*args):
        calls[0] += 1
        if calls[0] > limit:
            raise EvaluationBudget
        return rhs(*args)

    return counted


def _designs(machine: EquivalentMachine, *values) -> int:
    sizes = {machine.designs} | {int(np.size(v)) for v in values if np.ndim(v) > 0}
    sizes.discard(1)
    if len(sizes) > 1:
        raise InputError(f"The design-variant arrays of the machine, flywheel and drive must have one length; got "
                         f"lengths {sorted(sizes)}.")
    return sizes.pop() if sizes else 1


def _added_inertia(flywheel, drive, n) -> np.ndarray:
    fw = np.asarray(flywheel, dtype=float)
    if not np.all(np.isfinite(fw)) or np.any(fw < 0):
        bad = fw[~(np.isfinite(fw) & (fw >= 0))].ravel()[0] if fw.ndim else float(fw)
        raise InputError(f"The flywheel inertia must be >= 0 kg*m^2; got {bad:g} kg*m^2.")
    return np.broadcast_to(fw + np.asarray(getattr(drive, "inertia", 0.0), dtype=float), (n,)).astype(float)


class _Model:
    """The right-hand sides, vectorised over designs. When every curve of the machine is a Fourier series, J,
    J', the position moment and the damping come from one stacked matrix product per call (the fast path)."""

    def __init__(self, machine: EquivalentMachine, drive, added: np.ndarray, n: int):
        self.m, self.drive, self.added, self.n = machine, drive, added, n
        self.speed_dependent = not (isinstance(drive, ConstantTorque) and not machine.forces
                                    and not np.any(machine.damping.y))
        smooth = (machine.inertia, machine.potential, machine.damping)
        self.fast = all(isinstance(c, FourierCurve) for c in smooth) and not machine.forces
        # a moment that is not a Fourier series (a load switched on and off) is evaluated on its own
        self.extra: Any = None if isinstance(machine.moment, FourierCurve) else machine.moment
        if self.fast:
            zero = FourierCurve.from_samples(np.zeros((1, 2)), machine.period)
            self._stack(machine.inertia, machine.potential, machine.moment if self.extra is None else zero,
                        machine.damping)
        self.torque_slope: Any = getattr(drive, "torque_slope", None)
        self.one = bool(self.fast and n == 1 and self.torque_slope is not None
                        and all(np.ndim(v) == 0 for v in drive._constants[:4]))
        if self.one:
            self.c01, self.ca1, self.cb1 = self.c0[:, 0], self.ca[:, 0, :], self.cb[:, 0, :]
            self.added1 = float(added[0])

    def _stack(self, j, v, m, c):
        n = self.n
        kmax = max(x.harmonics for x in (j, v, m, c))
        self.k = np.arange(1, kmax + 1) * (2.0 * np.pi / self.m.period)

        def pad(x):
            out = np.zeros((n, kmax))
            out[:, : x.shape[1]] = x
            return out

        k = self.k
        ja, jb, va, vb = pad(j.a), pad(j.b), pad(v.a), pad(v.b)
        self.c0 = np.stack([np.broadcast_to(j.a0, (n,)), np.zeros(n), np.broadcast_to(m.a0, (n,)),
                            np.broadcast_to(c.a0, (n,))])
        self.ca = np.stack([ja, jb * k, pad(m.a) - vb * k, pad(c.a)])
        self.cb = np.stack([jb, -ja * k, pad(m.b) + va * k, pad(c.b)])

    def curves(self, phi):
        """J (without the added inertia), J', position moment and reduced damping at phi (N,)."""
        m = self.m
        curves = (m.inertia, m.potential, m.moment, m.damping)
        if self.fast and self.extra is None and all(isinstance(c, FourierCurve) and c._on_nodes(phi)
                                                    for c in curves):
            # the sample nodes themselves: one inverse FFT per curve
            return m.inertia(phi), m.inertia.derivative(phi), m.position_moment(phi), m.damping(phi)
        if self.fast:
            phi = np.asarray(phi, dtype=float)
            if phi.ndim == 2:
                arg = phi[..., None] * self.k
                out = (self.c0[..., None] + np.einsum("rnk,nmk->rnm", self.ca, np.cos(arg))
                       + np.einsum("rnk,nmk->rnm", self.cb, np.sin(arg)))
            elif phi.ndim == 0 or np.all(phi == phi.flat[0]):
                arg = float(np.ravel(phi)[0]) * self.k
                out = self.c0 + self.ca @ np.cos(arg) + self.cb @ np.sin(arg)
            else:
                arg = phi[:, None] * self.k
                out = (self.c0 + np.einsum("rnk,nk->rn", self.ca, np.cos(arg))
                       + np.einsum("rnk,nk->rn", self.cb, np.sin(arg)))
            if self.extra is not None:
                shape = out[2].shape
                return out[0], out[1], out[2] + np.broadcast_to(self.extra(phi), shape), out[3]
            return out[0], out[1], out[2], out[3]
        return m.inertia(phi), m.inertia.derivative(phi), m.position_moment(phi), m.damping(phi)

    def _plus_added(self, j):
        j = np.asarray(j)
        return j + self.added.reshape((-1,) + (1,) * (j.ndim - 1)) if j.ndim else j + self.added

    def inertia(self, phi):
        j, dj, _, _ = self.curves(phi)
        return self._plus_added(j), dj

    def drive_torque(self, omega):
        if self.drive is None:
            return 0.0 * omega, 0.0 * omega
        if self.torque_slope is not None:
            return self.torque_slope(omega)
        return self.drive.torque_at(omega), self.drive.slope(omega)

    def _all(self, phi, omega, parts=None):
        j, dj, mp, c = self.curves(phi) if parts is None else parts
        td, dtd = self.drive_torque(omega)
        m, dm = td + mp - c * omega, dtd - c
        for law, ratio in self.m.forces:
            f, df = _force_moment(law, ratio, phi, omega, self.m._speed_step)
            m, dm = m + f, dm + df
        return self._plus_added(j), dj, m, dm

    def moment(self, phi, omega):
        """Total moment (drive + loads) and its omega-derivative."""
        return self._all(phi, omega)[2:]

    def _curves_at(self, phi: float):
        """J, J', position moment and damping at one crank angle shared by all designs (the shooting's)."""
        if self.fast:
            arg = phi * self.k
            out = self.c0 + self.ca @ np.cos(arg) + self.cb @ np.sin(arg)
            if self.extra is not None:
                return out[0], out[1], out[2] + self.extra(np.full(self.n, phi)), out[3]
            return out[0], out[1], out[2], out[3]
        return self.curves(np.full(self.n, phi))

    def _energy_rhs_one(self, phi, y, with_sensitivity):
        """The energy equation of one design with Python floats (the per-call overhead dominates there)."""
        arg = phi * self.k
        out = self.c01 + self.ca1 @ np.cos(arg) + self.cb1 @ np.sin(arg)
        j = float(out[0]) + self.added1
        mp, c = float(out[2]), float(out[3])
        if self.extra is not None:
            mp += float(self.extra(np.array([phi]))[0])
        omega = math.sqrt(max(2.0 * float(y[0]) / j, 1e-300))
        td, dtd = self.torque_slope(omega)
        m = float(td) + mp - c * omega
        if not with_sensitivity:
            return np.array([m, 1.0 / omega])
        return np.array([m, 1.0 / omega, (float(dtd) - c) / (j * omega) * float(y[2])])

    def energy_rhs(self, phi, y, with_sensitivity=True):
        if self.one:
            return self._energy_rhs_one(float(phi), y, with_sensitivity)
        n = self.n
        k = y[:n]
        parts = self._curves_at(float(phi))
        j = parts[0] + self.added
        omega = np.sqrt(np.maximum(2.0 * k / j, 1e-300))
        if self.fast and self.torque_slope is not None:
            td, dtd = self.torque_slope(omega)
            c = parts[3]
            m, dm = td + parts[2] - c * omega, dtd - c
        else:
            _, _, m, dm = self._all(np.full(n, phi), omega, parts)
        if not with_sensitivity:
            return np.concatenate([m, 1.0 / omega])
        s = y[2 * n:]
        return np.concatenate([m, 1.0 / omega, dm / (j * omega) * s])

    def time_rhs(self, t, y):
        n = self.n
        phi, omega = y[:n], y[n:]
        j, dj, m, _ = self._all(phi, omega)
        return np.concatenate([omega, (m - 0.5 * dj * omega * omega) / j])


@dataclass(frozen=True)
class SteadyState:
    """The periodic steady state (arrays designs first for several designs; see :func:`steady_state`).

    phi [rad] over one cycle; omega [rad/s], acceleration [rad/s^2], time [s] since phi[0], drive_torque [N*m] at
    the crank, load_moment [N*m] (all loads, reduced), inertia [kg*m^2] (with flywheel and rotor) at each phi.
    delta: (max - min)/mean with mean = (max + min)/2; mean_speed: that mean; time_mean_speed = cycle / period
    [rad/s]; period_time [s]; energy_per_cycle: the drive's work per cycle [J]; peak and RMS (over time) drive
    torque [N*m]; residual: |K(end) - K(start)| / K(start) of the last shooting step, or for a machine solved by
    Fourier collocation (:mod:`machdyn.dynamics.periodic`) the relative amplitude of the upper half of the
    resolved spectrum of K (its truncation error); iterations: shooting steps (0 for collocation).
    """

    machine: EquivalentMachine
    drive: object
    flywheel: np.ndarray
    phi: np.ndarray
    omega: np.ndarray
    acceleration: np.ndarray
    time: np.ndarray
    drive_torque: np.ndarray
    load_moment: np.ndarray
    inertia: np.ndarray
    delta: np.ndarray
    mean_speed: np.ndarray
    time_mean_speed: np.ndarray
    period_time: np.ndarray
    energy_per_cycle: np.ndarray
    peak_drive_torque: np.ndarray
    rms_drive_torque: np.ndarray
    residual: np.ndarray
    iterations: int
    warnings: tuple = ()

    @property
    def mean_power(self) -> np.ndarray:
        """Mean power of the drive [W] = energy per cycle / period."""
        return self.energy_per_cycle / self.period_time

    def speed_curve(self) -> PeriodicCurve:
        """omega(phi) [rad/s] as a periodic Hermite curve (slope epsilon/omega)."""
        w = np.atleast_2d(self.omega)
        return PeriodicCurve.hermite(self.phi, w, np.atleast_2d(self.acceleration) / w, self.machine.period)


def _out(x, single):
    x = np.asarray(x)
    return x[0] if single and x.ndim >= 1 and x.shape[0] == 1 else x


def balance_speed(machine: EquivalentMachine, drive, n: int, grid: np.ndarray) -> np.ndarray:
    """The speed [rad/s] at which the drive's torque balances the mean load over a cycle (per design), on the
    stable branch (the drive's surplus falls as the speed rises)."""
    base = np.broadcast_to(machine.moment.mean(), (n,))
    damping = np.broadcast_to(machine.damping.mean(), (n,))  # the mean of -c(phi) omega is -mean(c) omega
    q = np.broadcast_to(grid, (n, grid.size))

    fast_torque = getattr(drive, "torque_slope", None)

    def surplus(w):
        out = (fast_torque(w)[0] if fast_torque is not None else drive.torque_at(w)) + base - damping * w
        if machine.forces:
            ww = w[:, None] + 0.0 * q
            out = out + (machine.speed_moment(q, ww)[0] + machine.damping(q) * ww).mean(axis=1)
        return out

    # start above the drive's no-load speed, where its surplus must be negative for a steady state to exist
    hi = np.broadcast_to(1.01 * np.asarray(getattr(drive, "no_load_speed", 1.0), dtype=float), (n,)).copy()
    for _ in range(80):
        bad = surplus(hi) > 0
        if not np.any(bad):
            break
        hi = np.where(bad, hi * 2.0, hi)
    else:
        raise NotSettledError("The drive's torque exceeds the load at every speed up to "
                              f"{float(np.max(hi)):.3g} rad/s: the machine would run away; there is no steady state.")
    scan = np.linspace(0.0, 1.0, 129)[:, None] * hi[None, :]
    # without speed-dependent point forces the surplus is elementwise in the speed: the whole scan in one call
    values = surplus(scan) if not machine.forces else np.array([surplus(w) for w in scan])
    lo = np.zeros(n)
    up = hi.copy()
    for i in range(n):
        positive = np.flatnonzero(values[:, i] > 0)
        if positive.size == 0:
            lo[i] = np.nan
            continue
        last = positive[-1]
        lo[i], up[i] = scan[last, i], scan[min(last + 1, scan.shape[0] - 1), i]
    if np.any(np.isnan(lo)):
        return lo
    for _ in range(45):  # to 1e-13 of the bracket: the shooting refines it
        mid = 0.5 * (lo + up)
        pos = surplus(mid) > 0
        lo, up = np.where(pos, mid, lo), np.where(pos, up, mid)
    return 0.5 * (lo + up)


def _stall_message(machine, drive, n, mean_speed_guess, grid):
    q = np.broadcast_to(grid, (n, grid.size))
    w = np.broadcast_to(np.where(np.isfinite(mean_speed_guess), mean_speed_guess, 1.0), (n,))[:, None] + 0.0 * q
    j = machine.inertia(q)
    need = -machine.moment_at(q, w) + 0.5 * machine.inertia.derivative(q) * w * w
    mean_need = -(machine.moment.mean() + machine.speed_moment(q, w)[0].mean(axis=1))
    del j
    bd = np.broadcast_to(np.asarray(getattr(drive, "breakdown_torque", np.nan), dtype=float), (n,))
    return (f"peak load torque {float(np.max(need)):.4g} N*m and mean load torque {float(np.max(mean_need)):.4g} N*m "
            f"at the crank, against the drive's breakdown torque {float(np.min(bd)):.4g} N*m at the crank")


def steady_state(
    machine: EquivalentMachine,
    drive,
    flywheel=0.0,
    *,
    mean_speed: float | None = None,
    tolerance: float = 1e-10,
    max_iterations: int = 30,
    rtol: float = RTOL,
) -> SteadyState:
    """The periodic steady state of ``machine`` driven by ``drive`` with a ``flywheel`` [kg*m^2] on the crank.

    Parameters
    ----------
    machine : :class:`~machdyn.dynamics.equivalent.EquivalentMachine`.
    drive : a drive of :mod:`machdyn.dynamics.drives`. With :class:`ConstantSpeed` the speed is imposed (the
        kinetostatic case). With a :class:`ConstantTorque` drive and no speed-dependent load every speed repeats
        if the work per cycle balances; ``mean_speed`` [rad/s] then picks the one with (max + min)/2 equal to it.
    flywheel : flywheel inertia [kg*m^2] >= 0 (one per design allowed).
    tolerance : periodicity |K(end) - K(start)| / K(start) required of the shooting.
    max_iterations : Newton steps before :class:`NotSettledError`.

    Raises
    ------
    InputError : negative inertia; a drive that cannot carry the mean load (naming the peak and mean load torque
        and the breakdown torque); a machine that stalls in the cycle.
    NotSettledError : the shooting does not converge.
    """
    from scipy.integrate import solve_ivp

    n = _designs(machine, flywheel, *(getattr(drive, f, 0.0) for f in ("torque", "rated_power", "flow")))
    added = _added_inertia(flywheel, drive, n)
    if np.any(machine.inertia.y + added.min() <= 0):
        raise InputError("The reduced moment of inertia with the flywheel must be > 0 kg*m^2 at every crank angle; "
                         f"got {float(np.min(machine.inertia.y) + added.min()):g} kg*m^2.")
    period = machine.period
    grid = np.append(machine.inertia.x, machine.inertia.x[0] + period) if machine.inertia.x.size > 1 else \
        np.linspace(0.0, period, 721)
    if machine.moment.x.size > grid.size - 1:
        grid = np.append(machine.moment.x, machine.moment.x[0] + period)
    phi0 = float(grid[0])
    if isinstance(drive, ConstantSpeed):
        return _constant_speed(machine, drive, added, n, grid)
    model = _Model(machine, drive, added, n)
    j0 = model.inertia(np.full(n, phi0))[0]

    if not model.speed_dependent:
        k0 = _neutral_start(model, machine, drive, n, grid, mean_speed, rtol)
        iterations, spectral = 0, None
    else:
        w_bar = balance_speed(machine, drive, n, grid[:-1])
        if np.any(~np.isfinite(w_bar)):
            raise InputError("The drive cannot carry the load of the machine at any speed: "
                             + _stall_message(machine, drive, n, w_bar, grid[:-1]) + ".")
        k0 = 0.5 * j0 * w_bar**2
        spectral = None
        if model.fast and model.extra is None and grid.size - 1 == machine.inertia.x.size:
            spectral = collocation_steady(model, n, grid[:-1], w_bar, tolerance)
        # LSODA: Adams steps (about half the evaluations of DOP853 at these tolerances on this smooth equation),
        # switching to BDF by itself where a steep drive characteristic makes the equation stiff
        method = "LSODA"
        iterations = 0
        # Newton's steps far from the solution need no more accuracy than they deliver: the integration tolerance
        # tightens with the residual, and the cycle is sampled once the next step will be the last
        near, loose = False, 1e-7
        for step_number in range(1, max_iterations + 1):
            if spectral is not None:
                break
            iterations = step_number
            y0 = np.concatenate([k0, np.zeros(n), np.ones(n)])
            sol = _solve(solve_ivp, lambda p, y: model.energy_rhs(p, y), (phi0, phi0 + period), y0,
                         rtol if near else loose, model, n, machine, drive, grid, t_eval=grid if near else None,
                         method=method)
            kend, send = sol.y[:n, -1], sol.y[2 * n:, -1]
            res = kend - k0
            if near and np.all(np.abs(res) <= tolerance * k0):
                break
            r = float(np.max(np.abs(res) / k0))
            near = near or r <= 1e-5
            loose = max(rtol, min(loose, 1e-6 * r * r))
            k0 = np.maximum(k0 - res / (send - 1.0), 0.05 * k0)
        else:
            raise NotSettledError(
                f"The periodic steady state was not found in {max_iterations} shooting steps: the energy at the start "
                f"of the cycle still changes by {float(np.max(np.abs(res) / k0)):.3g} (relative) per cycle.")
    phi = grid[:-1]
    if spectral is not None:
        k, time, period_time, residual = spectral
    else:
        if iterations == 0:
            y0 = np.concatenate([k0, np.zeros(n)])
            sol = _solve(solve_ivp, lambda p, y: model.energy_rhs(p, y, False), (phi0, phi0 + period), y0, rtol,
                         model, n, machine, drive, grid, t_eval=grid)
        k, time = sol.y[:n], sol.y[n:2 * n]
        residual = np.abs(k[:, -1] - k[:, 0]) / k[:, 0]
        period_time = time[:, -1]
        k, time = k[:, :-1], time[:, :-1]
    q = np.broadcast_to(phi, (n, phi.size))
    j, dj = model.inertia(q)
    j = np.broadcast_to(j, q.shape)
    omega = np.sqrt(2.0 * k / j)
    td = np.broadcast_to(model.drive_torque(omega)[0], q.shape)
    load = machine.moment_at(q, omega)
    acc = (td + load - 0.5 * dj * omega**2) / j
    result = _steady_result(machine, drive, added, phi, omega, acc, time, td, load, j, period_time, residual,
                            iterations)
    return replace(result, warnings=_overload(drive, omega))


def _overload(drive, omega) -> tuple[str, ...]:
    """A warning if an induction motor runs beyond its breakdown slip (on the unstable, overloaded branch)."""
    if not isinstance(drive, InductionMotor):
        return ()
    breakdown_speed = np.asarray(drive.synchronous_speed * (1.0 - drive.breakdown_slip) / drive.ratio)
    low = np.min(omega, axis=-1)
    if np.any(low < breakdown_speed):
        return (f"The induction motor runs beyond its breakdown slip: the crank speed falls to "
                f"{float(np.min(low)):.4g} rad/s, below the breakdown speed {float(np.max(breakdown_speed)):.4g} "
                "rad/s; it is overloaded and will overheat. Choose a larger motor.",)
    return ()


def _solve(solve_ivp, rhs, span, y0, rtol, model, n, machine, drive, grid, t_eval=None, method="DOP853"):
    """One cycle of the energy equation; a speed that reaches zero (K <= 0 at a step) is a stall."""
    atol = 1e-14 * max(1.0, float(np.max(np.abs(y0))))
    with np.errstate(over="ignore"), warnings.catch_warnings():
        # LSODA warns where it cannot continue past a stall; the stall is reported below
        warnings.simplefilter("ignore", UserWarning)
        try:
            sol = solve_ivp(budgeted(rhs, MAX_EVALUATIONS_PER_CYCLE), span, y0, method=method, rtol=rtol, atol=atol,
                            t_eval=t_eval)
        except EvaluationBudget:
            raise InputError(
                f"The machine nearly stalls: one cycle of its motion needed more than {MAX_EVALUATIONS_PER_CYCLE:,} "
                "steps of the integrator (its speed creeps towards zero somewhere in the cycle); "
                + _stall_message(machine, drive, n, np.nan, grid[:-1])
                + ". Choose a larger motor, a higher gear ratio or a larger flywheel.") from None
    low = sol.y[:n] <= 1e-12 * np.max(np.abs(y0[:n]))
    if np.any(low) or not sol.success or not np.all(np.isfinite(sol.y)):
        cols = np.flatnonzero(low.any(axis=0))
        where = float(sol.t[cols[0]]) if cols.size else float(sol.t[-1])
        raise InputError(
            f"The machine stalls: its speed falls to zero at crank angle {np.degrees(where):.1f}° in the cycle; "
            + _stall_message(machine, drive, n, np.nan, grid[:-1])
            + ". Choose a larger motor, a higher gear ratio or a larger flywheel.")
    return sol


def _neutral_start(model, machine, drive, n, grid, mean_speed, rtol):
    """K at the start for a drive and loads that do not depend on speed: the cycle must balance, and the level
    is set by ``mean_speed``."""
    from scipy.optimize import brentq

    phi = grid
    q = np.broadcast_to(phi, (n, phi.size))
    work = (machine.moment.integral(q) - machine.moment.integral(np.zeros((n, 1)))
            - (machine.potential(q) - machine.potential(np.zeros((n, 1))))
            + np.broadcast_to(np.asarray(drive.torque, dtype=float), (n,))[:, None] * (phi - phi[0]))
    scale = np.abs(machine.moment.y).mean(axis=1) * machine.period + np.abs(np.asarray(drive.torque)) * machine.period
    unbalanced = np.abs(work[:, -1]) > 1e-9 * np.maximum(scale, 1e-300)
    if np.any(unbalanced):
        i = int(np.flatnonzero(unbalanced)[0])
        given = float(np.broadcast_to(np.asarray(drive.torque, dtype=float), (n,))[i])
        balancing = given - work[i, -1] / machine.period
        raise InputError(
            f"With a constant drive torque and no speed-dependent load the work per cycle must balance for a steady "
            f"state; the drive torque {given:.6g} N*m and the loads leave {work[i, -1]:.6g} J per cycle (the "
            f"balancing drive torque is {balancing:.6g} N*m).")
    if mean_speed is None or not mean_speed > 0:
        raise InputError("A constant-torque drive with no speed-dependent load needs the mean speed (mean_speed > 0 "
                         f"rad/s) to fix its steady state; got {mean_speed!r}.")
    j = np.broadcast_to(model.inertia(q)[0], q.shape)
    k0 = np.empty(n)
    for i in range(n):
        lowest = max(0.0, float(np.max(-work[i])))

        def mid(k, i=i):
            w = np.sqrt(2.0 * (k + work[i]) / j[i])
            return 0.5 * (w.max() + w.min()) - mean_speed

        if mid(lowest) > 0:
            # even the least energy that keeps the crank turning gives a faster mean: the machine cannot run
            # through the cycle at mean_speed (it would stop and swing back)
            raise InputError(
                f"mean_speed: the machine cannot turn through its cycle at a mean speed of {mean_speed:g} rad/s; "
                f"at that speed it stops at some crank angle (the lowest mean speed that passes the cycle is "
                f"{mid(lowest) + mean_speed:.6g} rad/s). Add a flywheel or raise the mean speed.")
        hi = max(lowest, 1.0) * 2.0
        while mid(hi) < 0:
            hi *= 2.0
        k0[i] = brentq(mid, lowest, hi, xtol=1e-14 * hi, rtol=4 * np.finfo(float).eps)
    return k0


def _constant_speed(machine, drive, added, n, grid):
    phi = grid[:-1]
    q = np.broadcast_to(phi, (n, phi.size))
    w = float(drive.speed)
    omega = np.full(q.shape, w)
    j = np.broadcast_to(machine.inertia(q) + added[:, None], q.shape)
    dj = machine.inertia.derivative(q)
    load = machine.moment_at(q, omega)
    td = -load + 0.5 * dj * w * w
    time = (phi - phi[0]) / w + 0.0 * q
    return _steady_result(machine, drive, added, phi, omega, np.zeros(q.shape), time, td, load, j,
                          np.full(n, machine.period / w), np.zeros(n), 0)


def _steady_result(machine, drive, added, phi, omega, acc, time, td, load, j, period_time, residual, iterations):
    period = machine.period
    h = np.diff(np.append(phi, phi[0] + period))
    # the extremes of the speed lie between the nodes: search them on the Hermite curve through omega and its
    # slope epsilon/omega (error O(h^4))
    curve = PeriodicCurve.hermite(phi, omega, acc / omega, period)
    fine = fine_grid(curve, 16, 0)
    w_fine = curve(np.broadcast_to(fine, (omega.shape[0], fine.size)) if omega.shape[0] > 1 else fine)
    w_fine = np.atleast_2d(w_fine)
    wmax, wmin = np.maximum(w_fine.max(axis=1), omega.max(axis=1)), np.minimum(w_fine.min(axis=1), omega.min(axis=1))
    steady = np.ptp(omega, axis=1) == 0  # an imposed constant speed: no fluctuation at all
    wmax, wmin = np.where(steady, omega[:, 0], wmax), np.where(steady, omega[:, 0], wmin)
    mid = 0.5 * (wmax + wmin)
    energy = (td * h).sum(axis=1)
    rms = np.sqrt((td * td / omega * h).sum(axis=1) / period_time)
    s = machine.single
    return SteadyState(
        machine, drive, _out(added, s), phi, _out(omega, s), _out(acc, s), _out(time, s), _out(td, s),
        _out(load, s), _out(j, s), _out((wmax - wmin) / mid, s), _out(mid, s), _out(period / period_time, s),
        _out(period_time, s), _out(energy, s), _out(np.abs(td).max(axis=1), s), _out(rms, s), _out(residual, s),
        iterations,
    )
