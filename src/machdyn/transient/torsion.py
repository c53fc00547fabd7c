"""Torsional stiffness and damping between the shafts of the drive line in a transient run.

A stage of the drive line with a ``torsional_stiffness`` k [N*m/rad] (and ``torsional_damping`` c [N*m*s/rad])
passes k (theta_in / i - theta_out) + c (omega_in / i - omega_out) to its output shaft
(:class:`~machdyn.dynamics.driveline.Stage`). The stiff stages cut the line into rigid groups of shafts; each group
upstream of the crank's becomes a degree of freedom of its own, its angle psi_g referred to the crank (a shaft of
speed ratio r to the crank turns r psi_g), its inertia J_g = sum J_k r_k^2 (equal kinetic energy), and the spring
after it referred to the crank as K = k r_out^2, C = c r_out^2, r_out the ratio of the stage's output shaft
(equal potential energy and dissipation: Den Hartog, *Mechanical Vibrations*, 4th ed., McGraw-Hill 1956, §5.5,
geared systems reduced to one speed; W. T. Thomson, *Theory of Vibration with Applications*, the equivalent
torsional system of a geared line). Lagrange's equations of the chain:

    J_0 psi_0''  = T_drive(psi_0') - S_0
    J_g psi_g''  = S_(g-1) - S_g
    crank row    : the drive torque of the rigid model replaced by S_last
    S_g          = K_g (psi_g - psi_(g+1)) + C_g (psi_g' - psi_(g+1)')        (psi after the last: the crank)

With one stiff stage and no load the twist oscillates at omega_n = sqrt(K (J_0 + J_c) / (J_0 J_c)) (the
two-inertia system; Den Hartog §5.4), J_c the crank's inertia.

The drive's torque at the crank (gear ratio and the efficiency of the whole line, as for the rigid line: the
motor's torque takes every stage's loss) acts on the motor's group at its speed; the springs are loss-free, their
dampers dissipate. The shafts upstream of a stiff stage turn about axes fixed in the frame; the coupling of their
spin with the frame's rotation (of the order of their inertia times the frame's rotation rate) is left out, so
on a frame they enter only the crank and not the frame's rows.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError

__all__ = ["TorsionalLine", "TorsionalStates", "TorsionRun", "torsion_run", "torsional_line", "torsional_states"]

#: integrals per crank after its groups' states: the drive's work, the springs' dampers' dissipation
INTEGRALS = 2


@dataclass(frozen=True)
class TorsionalLine:
    """The drive line upstream of the crank's rigid group, referred to the crank: ``inertias`` [kg*m^2] of each
    group (the motor's first), ``stiffness`` [N*m/rad] and ``damping`` [N*m*s/rad] of the spring after each group
    (the last joins the crank's group), ``output_ratio`` the speed ratio to the crank of each spring's output
    shaft (its torque there is S / r_out), ``names`` of the stiff stages, ``stages`` their indices (0 from the
    motor)."""

    inertias: tuple[float, ...]
    stiffness: tuple[float, ...]
    damping: tuple[float, ...]
    output_ratio: tuple[float, ...]
    names: tuple[str, ...]
    stages: tuple[int, ...]

    def __post_init__(self) -> None:
        sizes = {len(self.inertias), len(self.stiffness), len(self.damping), len(self.output_ratio),
                 len(self.names), len(self.stages)}
        if len(sizes) != 1 or not self.inertias:
            raise InputError(f"A torsional line needs one inertia, stiffness, damping, ratio and name per stiff "
                             f"stage; got {len(self.inertias)} inertias and {len(self.stiffness)} springs.")
        for name, j in zip(self.names, self.inertias, strict=True):
            if not j > 0:
                raise InputError(f"The shafts before the stiff stage '{name}' have no inertia (got {j:g} kg*m^2 "
                                 "referred to the crank): a spring needs a mass on both sides. Give the motor "
                                 "shaft's inertia (drivetrain.motor_inertia) or the stage shafts' inertia.")
        for name, k, c in zip(self.names, self.stiffness, self.damping, strict=True):
            if not (np.isfinite(k) and k > 0) or not (np.isfinite(c) and c >= 0):
                raise InputError(f"The stage '{name}' needs a torsional stiffness > 0 and damping >= 0; got {k!r} "
                                 f"N*m/rad and {c!r} N*m*s/rad.")

    @property
    def groups(self) -> int:
        """Rigid groups upstream of the crank's."""
        return len(self.inertias)

    def natural_frequency(self, crank_inertia: float) -> float:
        """omega_n = sqrt(K (J_0 + J_c) / (J_0 J_c)) [rad/s] of a line with one stiff stage (Den Hartog, 4th ed.,
        §5.4), ``crank_inertia`` J_c [kg*m^2] the crank's group with the mechanism's mean inertia."""
        if self.groups != 1:
            raise InputError("The two-inertia natural frequency needs a line with one stiff stage.")
        j0, k = self.inertias[0], self.stiffness[0]
        return float(np.sqrt(k * (j0 + crank_inertia) / (j0 * crank_inertia)))


def torsional_line(line, flywheel_at_crank: float = 0.0) -> tuple[TorsionalLine | None, float]:
    """(the :class:`TorsionalLine` of a :class:`~machdyn.dynamics.driveline.DriveLine`, or None when no stage is
    stiff; the inertia of the crank's rigid group referred to the crank [kg*m^2], its shafts' and the flywheel's if
    it sits there). ``flywheel_at_crank`` [kg*m^2] is the flywheel's inertia referred to the crank, on the line's
    ``flywheel_shaft``."""
    stages = line.train.stages
    r = line.train.speed_ratios
    inertia = np.asarray(line.train.shaft_inertia, dtype=float) * r ** 2
    inertia[line.flywheel_shaft] += float(flywheel_at_crank)
    cuts = [k for k, s in enumerate(stages) if s.torsional_stiffness is not None]
    if not cuts:
        return None, float(inertia.sum())
    bounds = [0, *(k + 1 for k in cuts)]
    groups = [float(inertia[a:b].sum()) for a, b in zip(bounds[:-1], bounds[1:], strict=True)]
    crank_group = float(inertia[bounds[-1]:].sum())
    stiff = tuple(float(stages[k].torsional_stiffness) * r[k + 1] ** 2 for k in cuts)  # type: ignore[arg-type]
    damp = tuple(float(stages[k].torsional_damping) * r[k + 1] ** 2 for k in cuts)
    names = tuple(stages[k].name or f"stage {k + 1}" for k in cuts)
    return TorsionalLine(tuple(groups), stiff, damp, tuple(float(r[k + 1]) for k in cuts), names,
                         tuple(cuts)), crank_group


class TorsionalStates:
    """The groups' angles and speeds of the cranks with a :class:`TorsionalLine` (``exciter.torsion``), in the
    state vector from ``offset`` on, and the right-hand side that integrates them with the machine."""

    def __init__(self, lines: dict[int, TorsionalLine], offset: int, cranks: int) -> None:
        self.lines = lines
        self.offset = offset
        self.cranks = cranks
        self.starts: dict[int, int] = {}
        at = offset
        for k, line in lines.items():
            self.starts[k] = at
            at += 2 * line.groups + INTEGRALS
        self.end = at
        self.spring = [0.0] * cranks
        self.readers = [(lambda _w, k=k: self.spring[k]) for k in range(cranks)]
        self.source: list = []

    @property
    def size(self) -> int:
        return self.end - self.offset

    def speed_row(self, k: int) -> int:
        """The row of the motor's group's speed (crank-referred) of crank ``k``."""
        return self.starts[k] + self.lines[k].groups

    def initial(self, phi0, w0) -> np.ndarray:
        """Every group at the crank's angle and speed (no twist)."""
        out = []
        for k, line in self.lines.items():
            out += [float(phi0[k])] * line.groups + [float(w0[k])] * line.groups + [0.0] * INTEGRALS
        return np.array(out)

    def tolerances(self, reference: float) -> np.ndarray:
        out: list[float] = []
        for line in self.lines.values():
            out += [1e-10] * line.groups + [1e-10 * reference] * line.groups + [1e-9] * INTEGRALS
        return np.array(out)

    def fastest(self, model) -> float:
        """The largest of the springs' frequencies sqrt(K (1/J_up + 1/J_down)) [rad/s], the crank's side with its
        mean inertia: the output's sampling and the integrator's pace."""
        top = 0.0
        for k, line in self.lines.items():
            part = model.parts[k]
            down = [*line.inertias[1:], float(part.c0[0] + part.added)]
            for j_up, j_down, stiff in zip(line.inertias, down, line.stiffness, strict=True):
                top = max(top, float(np.sqrt(stiff * (1.0 / j_up + 1.0 / max(j_down, 1e-300)))))
        return top

    def springs(self, line: TorsionalLine, psi, omega, phi: float, w: float) -> np.ndarray:
        """S_g [N*m] referred to the crank."""
        nxt_psi = np.append(psi[1:], phi)
        nxt_w = np.append(omega[1:], w)
        return np.asarray(line.stiffness) * (psi - nxt_psi) + np.asarray(line.damping) * (omega - nxt_w)

    def wrap(self, rhs, state: dict):
        """f(t, y) with the groups' rows from the machine's ``rhs``: the crank's drive torque becomes the last
        spring's, the drive's torque acts on the motor's group."""
        n, offset = self.cranks, self.offset

        def f(t, y):
            current = state["torques"]
            if current is not self.readers:
                self.source = current  # the drives' torques (a speed change or the motor's electrical states)
            on = state["on"]
            extra = np.empty(self.size)
            for k, line in self.lines.items():
                g, base = line.groups, self.starts[k]
                psi, omega = y[base:base + g], y[base + g:base + 2 * g]
                s = self.springs(line, psi, omega, float(y[k]), float(y[n + k]))
                fn = self.source[k]
                drive = fn(float(omega[0])) if on and fn is not None else 0.0
                inflow = np.concatenate([[drive], s[:-1]])
                i = base - offset
                extra[i:i + g] = omega
                extra[i + g:i + 2 * g] = (inflow - s) / np.asarray(line.inertias)
                nxt_w = np.append(omega[1:], float(y[n + k]))
                extra[i + 2 * g] = drive * float(omega[0])
                extra[i + 2 * g + 1] = float(np.sum(np.asarray(line.damping) * (omega - nxt_w) ** 2))
                self.spring[k] = float(s[-1])
            state["torques"] = self.readers
            state["on"] = True  # the springs turn the crank whether the motor is on or off
            try:
                out = rhs(t, y[:offset])
            finally:
                state["on"] = on
            return np.concatenate([out, extra])

        return f


def torsional_states(model, offset: int) -> TorsionalStates | None:
    """The :class:`TorsionalStates` of the model's exciters that carry a torsional line, or None."""
    lines = {k: p.exciter.torsion for k, p in enumerate(model.parts) if getattr(p.exciter, "torsion", None)}
    return TorsionalStates(lines, offset, model.cranks) if lines else None


@dataclass(frozen=True)
class TorsionRun:
    """The drive line's torsion in a run of crank k (SI): t (T,), psi and omega (groups x T) referred to the
    crank, shaft_torque (stiff stages x T) [N*m] each at its own output shaft, drive_work and damper_loss [J] at the
    end, the groups' kinetic and the springs' potential energy (T,) [J], and the relative error of the line's
    balance: drive work = change of the line's energy + damper loss + the work the last spring does on the
    crank."""

    line: TorsionalLine
    t: np.ndarray
    psi: np.ndarray
    omega: np.ndarray
    shaft_torque: np.ndarray
    drive_work: float
    damper_loss: float
    energy: np.ndarray
    energy_error: float

    @property
    def peak_torques(self) -> np.ndarray:
        """Largest |torque| [N*m] through each stiff stage, at its output shaft."""
        return np.max(np.abs(self.shaft_torque), axis=1)


def torsion_run(run, k: int = 0) -> TorsionRun | None:
    """The :class:`TorsionRun` of crank ``k`` of a :class:`~machdyn.transient.run.Transient`, or None."""
    torsion = run.torsion
    if torsion is None or k not in torsion["lines"]:
        return None
    line: TorsionalLine = torsion["lines"][k]
    rows = torsion["rows"][k]
    g = line.groups
    psi, omega = rows[:g], rows[g:2 * g]
    nxt_psi = np.vstack([psi[1:], run.phi[k][None, :]])
    nxt_w = np.vstack([omega[1:], run.omega[k][None, :]])
    k_ref, c_ref = np.asarray(line.stiffness)[:, None], np.asarray(line.damping)[:, None]
    springs = k_ref * (psi - nxt_psi) + c_ref * (omega - nxt_w)
    energy = 0.5 * np.sum(np.asarray(line.inertias)[:, None] * omega ** 2, axis=0) + \
        0.5 * np.sum(k_ref * (psi - nxt_psi) ** 2, axis=0)
    drive, loss = float(rows[2 * g, -1]), float(rows[2 * g + 1, -1])
    into_crank = float(run.works[0, -1])
    error = abs(drive - (energy[-1] - energy[0]) - loss - into_crank) / max(abs(drive), abs(into_crank),
                                                                            abs(loss), 1e-300)
    return TorsionRun(line, run.t, psi, omega, springs / np.asarray(line.output_ratio)[:, None], drive, loss, energy,
                      error)
