"""``[transient]`` in a shaft-line file: the shaft line (its masses, cylinders and linkages, the crank-angle-dependent
inertia and the inertia torques of :mod:`machdyn.shafts`) driven by a motor through a scenario, together with its
frame's six degrees of freedom on the mounts of ``[frame]`` (:mod:`machdyn.shafts.frame6`).

The motor and the drive line's inertia are given in ``[transient.drive]`` (a shaft-line file has no
``[flywheel]``); the frame, its mounts and points are those of ``[frame]``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..dynamics.drive_choice import choose_drive
from ..dynamics.drives import InductionMotor
from ..dynamics.stage import MotorTable
from ..errors import InputError, ProblemFileError
from ..pipeline import Outcome, StageContext
from ..problem.fields import Inertia
from ..problem.schema import Spec
from ..results.labels import Label
from ..shafts.frame6 import modes6
from ..shafts.model import ShaftLine
from ..shafts.model import build as build_line
from .passage import AmplitudeCurve, Passage, amplitude_curve, capture, passages
from .run import Scenario, TransientLimitError, balance_scalars, passage_results
from .shaft_model import shaft_frame_model
from .shaft_run import ShaftTransient, run_shaft_scenario

__all__ = ["ShaftDriveSpec", "ShaftTransientRun", "check_shaft_transient", "is_shaft_line", "run_shaft_transient"]

#: The relative tolerance of the energy balance a run must close to (its own check).
ENERGY_TOLERANCE = 1e-6
#: Evaluations of the equations per period of the fastest motion (shaft turn or frame mode).
EVALUATIONS_PER_PERIOD = 250
RPM = 30.0 / math.pi


class ShaftDriveSpec(Spec):
    """``[transient.drive]`` of a shaft-line file: the inertia turning with the shaft about its axis besides the
    shaft line's masses (crankshaft, flywheel, coupling), and ``[transient.drive.motor]`` (an induction motor by its
    rated data, or a hydraulic motor; the keys of ``[flywheel.motor]``)."""

    inertia: Inertia = 0.0
    motor: MotorTable | None = None


@dataclass(frozen=True)
class FrameModes6:
    """The natural frequencies [Hz] and mass-normalised mode shapes of the frame on its mounts."""

    frequencies: np.ndarray
    shapes: np.ndarray

    @property
    def angular_frequencies(self) -> np.ndarray:
        return 2.0 * math.pi * self.frequencies


@dataclass(frozen=True)
class ShaftTransientRun:
    """Everything ``[transient]`` computed for a shaft line on its six-degree-of-freedom frame (SI)."""

    table: Any
    run: ShaftTransient
    modes: FrameModes6
    curve: AmplitudeCurve
    passages: tuple[Passage, ...]
    point: tuple[float, float, float]
    point_name: str
    captured: bool
    final_speed: float
    free_speed: float
    line: ShaftLine
    shaft: tuple[float, float]
    direction: None = None


def is_shaft_line(problem: Any) -> bool:
    """True for a validated shaft-line problem."""
    return hasattr(problem, "shaft_line")


def check_shaft_transient(problem: Any, table: Any) -> list[tuple[str, str]]:
    """What ``check`` can tell of ``[transient]`` in a shaft-line file without running it."""
    found: list[tuple[str, str]] = []
    drive = table.drive
    motor = drive.motor if drive is not None else None
    if motor is None and table.prescribed_speed is None and not table.start_speed > 0:
        found.append(("transient.drive.motor", "a shaft line needs a motor ([transient.drive.motor]), a "
                                               "prescribed_speed or a start_speed"))
    if motor is not None and motor.kind not in ("induction", "hydraulic"):
        found.append(("transient.drive.motor.kind", f"must be \"induction\" or \"hydraulic\" for a shaft line (the "
                                                    f"motor is given by its data, not chosen); got \"{motor.kind}\""))
    if problem.frame is None:
        found.append(("transient", "a shaft line runs in time on its frame: give [frame] with its [[frame.mounts]]"))
    for key in ("twin", "direction"):
        if getattr(table, key) is not None:
            found.append((f"transient.{key}", "applies to a mechanism on a planar frame, not to a shaft line"))
    if table.rigid:
        found.append(("transient.rigid", "a shaft line runs on its frame; remove rigid"))
    points = [p.name for p in problem.frame.points] if problem.frame is not None else []
    if table.point is not None and table.point not in points:
        found.append(("transient.point", f"no point '{table.point}' in [[frame.points]]; points: "
                                         f"{', '.join(points) or 'none'}"))
    if not found:
        estimate = _estimated_evaluations(problem, table)
        if estimate > table.max_evaluations:
            found.append(("transient.duration", f"a run of {table.duration:g} s would take about {estimate:,.0f} "
                                                f"evaluations of the equations of motion, over its budget "
                                                f"max_evaluations = {table.max_evaluations:,}; shorten the run or "
                                                "raise max_evaluations"))
    return found


def _motor(table: Any):
    """The drive of ``[transient.drive.motor]`` at the shaft (its ``ratio`` = motor speed / shaft speed, 1 if not
    given), or None."""
    drive = table.drive
    if drive is None or drive.motor is None:
        return None
    m = drive.motor
    if m.kind == "induction":
        return InductionMotor(float(m.rated_power or 0.0), float(m.rated_speed or 0.0), m.synchronous_speed,
                              m.breakdown_ratio, m.ratio or 1.0, m.efficiency, m.rotor_inertia)
    return choose_drive(m, None, 0.0, 1.0, 0.0)


def _estimated_evaluations(problem: Any, table: Any) -> float:
    """The evaluations a run will take: the duration over the period of the fastest of the shaft's speed (the
    motor's no-load speed, the start or prescribed speed) and the frame's modes."""
    speed = abs(table.start_speed)
    if table.prescribed_speed is not None:
        speed = max(speed, abs(table.prescribed_speed),
                    abs(table.prescribed_speed + table.prescribed_acceleration * table.duration))
    try:
        motor = _motor(table)
        if motor is not None:
            speed = max(speed, float(np.asarray(getattr(motor, "no_load_speed", 0.0))))
        line, problems = build_line(problem)
        if line is not None and line.frame is not None:
            speed = max(speed, 2.0 * math.pi * float(np.max(modes6(line.frame)[0])))
    except InputError:
        pass  # the motor's or the frame's own check says what is wrong
    return EVALUATIONS_PER_PERIOD * table.duration * speed / (2.0 * math.pi)


def _free_speed(motor: Any, load: float) -> float:
    """The speed [rad/s] at which the motor's torque falls to ``load`` [N*m] (its no-load speed without a load):
    where a rigidly mounted shaft line without losses settles; NaN if it never does below 3 x the no-load speed."""
    if motor is None:
        return float("nan")
    top = 3.0 * float(np.asarray(getattr(motor, "no_load_speed", 0.0)) or 1000.0)
    grid = np.linspace(0.0, top, 3001)
    surplus = np.asarray(motor.torque_at(grid), dtype=float) - load
    change = np.flatnonzero((surplus[:-1] > 0) & (surplus[1:] <= 0))
    if not change.size:
        return float("nan")
    i = int(change[0])
    return float(grid[i] + (grid[i + 1] - grid[i]) * surplus[i] / (surplus[i] - surplus[i + 1]))


def run_shaft_transient(ctx: StageContext, scenario: Scenario) -> Outcome:
    """The stage for a shaft-line file: build the model from the shaft line, ``[frame]`` and
    ``[transient.drive]``, run the scenario and sum it up."""
    table = ctx.table
    problems = check_shaft_transient(ctx.problem, table)
    if problems:
        raise ProblemFileError(problems)
    line, problems = build_line(ctx.problem)
    if line is None or line.frame is None:
        raise ProblemFileError(problems or [("frame", "missing")])
    fs = ctx.problem.frame
    motor = _motor(table)
    inertia = float(table.drive.inertia) if table.drive is not None else 0.0
    model = shaft_frame_model(line, line.frame, tuple(fs.shaft), motor, inertia, positions=table.positions)
    points = {p.name: (float(p.position[0]), float(p.position[1]), float(p.position[2])) for p in fs.points}
    name = table.point or next(iter(points), "origin")
    point = points.get(name, (0.0, 0.0, 0.0))
    try:
        run = run_shaft_scenario(model, scenario)
    except TransientLimitError as exc:
        return Outcome(failed_checks=(str(exc).rstrip("."),))
    except InputError as exc:
        if not str(exc).startswith("The motor cannot start"):
            raise
        return Outcome(failed_checks=(str(exc).rstrip("."),))
    frequencies, shapes = modes6(line.frame)
    md = FrameModes6(frequencies, shapes)
    curve = amplitude_curve(run, point)  # type: ignore[arg-type]
    found = tuple(passages(run, md.angular_frequencies, point, None, table.band))  # type: ignore[arg-type]
    load = table.load_torque if table.load_time is not None and table.load_time == 0.0 else 0.0
    free = _free_speed(motor, load)
    motors_on = table.switch_off is None and table.prescribed_speed is None and motor is not None
    if motors_on and math.isfinite(free):
        captured, final = capture(run, md.angular_frequencies, free, table.band)  # type: ignore[arg-type]
    else:
        captured, final = False, abs(float(run.omega[0, -1]))
    return outcome_of(ShaftTransientRun(table, run, md, curve, found, point, name, captured, final, free, line,
                                        (float(fs.shaft[0]), float(fs.shaft[1]))))


def outcome_of(r: ShaftTransientRun) -> Outcome:
    """Scalars, labels, series, summary and checks of a shaft line's run."""
    run = r.run
    u = run.point_displacement(r.point)
    amp = np.sqrt(np.sum(u * u, axis=0))
    values: dict[str, Any] = {
        **balance_scalars(run, r.final_speed, r.captured),
        "transient.peak_amplitude": float(amp.max()),
        "transient.peak_rotation": float(np.sqrt(np.sum(run.q[3:] ** 2, axis=0)).max()),
        "transient.peak_mount_force": float(np.abs(run.mount_force).max()),
    }
    labels: dict[str, Label] = {}
    for m, f in zip(run.model.frame.mounts, run.mount_force, strict=True):
        key = f"transient.mount.{m.name}.peak_force"
        values[key] = float(np.abs(f).max())
        labels[key] = Label(f"Transient: largest dynamic force of mount {m.name}", "N", over="max_abs",
                            better="lower")
    if math.isfinite(r.free_speed):
        values["transient.free_speed"] = r.free_speed
        if run.scenario.prescribed is None and r.table.start_speed == 0.0:
            reached = np.flatnonzero(np.abs(run.omega[0]) >= 0.95 * r.free_speed)
            if reached.size:
                values["transient.time_to_speed"] = float(run.t[reached[0]])
    if run.ended == "stopped":
        values["transient.stop_time"] = float(run.t[-1])
    found, passage_labels = passage_results(r.passages, with_frequency=True)
    values |= found
    labels |= passage_labels
    failed: list[str] = []
    warnings: list[str] = []
    if run.energy_error > ENERGY_TOLERANCE:
        failed.append(f"the energy balance of the transient run closes only to {run.energy_error:.3g} (relative), "
                      f"more than {ENERGY_TOLERANCE:g}: tighten rtol")
    if run.ended == "rolled back":
        failed.append(f"the shaft rolls back under its motor at t = {run.t[-1]:.4g} s: the motor cannot turn the "
                      "shaft line over")
    if r.captured:
        warnings.append(f"The motor is captured by a resonance of the frame: the shaft runs at "
                        f"{r.final_speed * RPM:.4g} rpm instead of {r.free_speed * RPM:.4g} rpm (Sommerfeld effect).")
    if any(not p.completed for p in r.passages) and not r.captured:
        warnings.append("The run ends inside the band of a frame mode; lengthen it to see the whole passage.")
    every = max(1, run.t.size // 20_000)
    cols: dict[str, tuple[Any, str]] = {"time": (run.t[::every], "s"), "shaft_angle": (run.phi[0, ::every], "rad"),
                                        "speed": (run.omega[0, ::every], "rad/s"),
                                        "drive_torque": (run.drive_torque[0, ::every], "N*m")}
    for i, name in enumerate(("frame_x", "frame_y", "frame_z")):
        cols[name] = (run.q[i, ::every], "m")
    for i, name in enumerate(("frame_rx", "frame_ry", "frame_rz")):
        cols[name] = (run.q[3 + i, ::every], "rad")
    cols[f"displacement_{r.point_name}"] = (amp[::every], "m")
    for m, f in zip(run.model.frame.mounts, run.mount_force, strict=True):
        cols[f"mount_force_{m.name}"] = (f[::every], "N")
    cols["energy"] = (run.energy[::every], "J")
    series: dict[str, Any] = {"transient": cols}
    if r.curve.speed.size:
        series["transient_amplitude"] = {"speed": (r.curve.speed, "rad/s"), "time": (r.curve.time, "s"),
                                         "amplitude": (r.curve.amplitude, "m"),
                                         "mount_force": (r.curve.mount_force, "N")}
    summary = ("transient.final_speed", "transient.captured", "transient.peak_amplitude", "transient.peak_rotation",
               "transient.peak_mount_force", "transient.passage_peak_amplitude", "transient.passage_time",
               "transient.time_to_speed", "transient.stop_time", "transient.energy_error")
    return Outcome(results=r, scalars=values, labels=labels, series=series,
                   summary=tuple(k for k in summary if k in values), warnings=tuple(warnings),
                   failed_checks=tuple(failed))
