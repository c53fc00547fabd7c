"""The ``[transient]`` capability: the machine in time — its drive (from ``[flywheel]``), the mechanism and the
frame on its mounts (from ``[frame]``) simulated together through a scenario; speed, frame motion and mount forces
over time, every passage through a mode of the frame, capture, and the energy balance of the run.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any, Literal

import numpy as np
from pydantic import Field, model_validator

from ..dynamics.driveline_file import line_of
from ..dynamics.drives import ConstantSpeed
from ..dynamics.simulate import balance_speed
from ..dynamics.stage import FlywheelRun
from ..errors import InputError, ProblemFileError
from ..notebook import ShownInNotebook
from ..pipeline import Capability, Outcome, StageContext
from ..problem.fields import Angle, AngularAcceleration, AngularVelocity, Point, Time, Torque
from ..problem.schema import Name, Spec
from ..results.labels import Label
from ..vibration.modes import Modes, modes
from ..vibration.study import build_frame
from .electric import MotorRun, motor_run
from .model import Exciter, carried_frame, coupled_model
from .motor_table import MOTOR_LABELS, MOTOR_SUMMARY, MotorSpec, dq_motor, motor_checks, motor_scalars, motor_series
from .passage import AmplitudeCurve, Passage, amplitude_curve, capture, passages
from .run import Scenario, Transient, TransientLimitError, balance_scalars, passage_results, run_scenario
from .shaft_stage import ShaftDriveSpec, ShaftTransientRun, check_shaft_transient, is_shaft_line, run_shaft_transient
from .torsion import TorsionRun, torsion_run, torsional_line
from .torsion_results import (
    TORSION_LABELS,
    TORSION_SUMMARY,
    torsion_checks,
    torsion_labels,
    torsion_scalars,
    torsion_series,
)

__all__ = ["CAPABILITY", "TransientRun", "TransientTable", "TwinSpec", "check_transient", "run_transient",
           "scenario_of"]

#: The relative tolerance of the energy balance a run must close to (its own check).
ENERGY_TOLERANCE = 1e-6


class TwinSpec(Spec):
    """``[transient.twin]``: a second exciter, the same mechanism with the same drive and flywheel, on the frame at
    ``origin`` (frame coordinates), turning the other way with ``mirror`` (counter-rotating exciters), started
    at ``start_angle``."""

    origin: Point
    mirror: bool = Field(True, strict=True)
    start_angle: Angle = 0.0


class TransientTable(Spec):
    """``[transient]``: a scenario of the machine in time. The drive and flywheel are those of ``[flywheel]``;
    the frame and its mounts those of ``[frame]`` (``rigid = true``, or a file without ``[frame]``: a rigid
    ground); ``[transient.motor]`` replaces the drive's torque-speed curve by an induction motor's electrical
    model (through the same gear)."""

    duration: Time
    start_speed: AngularVelocity = 0.0
    start_angle: Angle = 0.0
    switch_off: Time | None = None
    brake_time: Time | None = None
    brake_torque: Torque = 0.0
    load_time: Time | None = None
    load_torque: Torque = 0.0
    speed_change_time: Time | None = None
    speed_factor: float = Field(1.0, gt=0.0, le=10.0, allow_inf_nan=False)
    prescribed_speed: AngularVelocity | None = None
    prescribed_acceleration: AngularAcceleration = 0.0
    rigid: bool = Field(False, strict=True)
    method: Literal["auto", "LSODA", "Radau", "BDF", "DOP853", "RK45"] = "auto"
    rtol: float = Field(1e-8, gt=0.0, lt=1e-2, allow_inf_nan=False)  # DOP853 closes the energy balance to ~1e-8
    positions: int = Field(256, ge=32, le=4096, strict=True)
    band: float = Field(0.1, gt=0.0, lt=0.5, allow_inf_nan=False)
    point: Name | None = None
    direction: Angle | None = None
    samples_per_period: int = Field(24, ge=4, le=1000, strict=True)
    max_evaluations: int = Field(400_000, ge=1000, le=100_000_000, strict=True)
    max_seconds: Time = 120.0
    twin: TwinSpec | None = None
    motor: MotorSpec | None = None
    drive: ShaftDriveSpec | None = None  # a shaft-line file's motor and drive-line inertia

    @model_validator(mode="after")
    def _consistent(self):
        for name in ("switch_off", "brake_time", "load_time", "speed_change_time"):
            t = getattr(self, name)
            if t is not None and t > self.duration:
                raise ValueError(f"{name} ({t:g} s) must lie within the duration ({self.duration:g} s)")
        if self.brake_time is not None and not self.brake_torque > 0:
            raise ValueError(f"brake_time needs brake_torque > 0 N*m; got {self.brake_torque:g} N*m")
        if self.brake_torque < 0:
            raise ValueError(f"brake_torque must be >= 0 N*m; got {self.brake_torque:g} N*m")
        if self.speed_change_time is not None and self.speed_factor == 1.0:
            raise ValueError("speed_change_time needs speed_factor (the new supply frequency / the old), not 1")
        if self.prescribed_speed is None and self.prescribed_acceleration != 0.0:
            raise ValueError("prescribed_acceleration needs prescribed_speed (the speed at the start)")
        if self.prescribed_speed is not None and self.motor is not None:
            raise ValueError("[transient.motor] drives the crank; a prescribed_speed leaves it nothing to do: give "
                             "one of them")
        if self.prescribed_speed is not None and self.prescribed_speed < 0:
            raise ValueError(f"prescribed_speed must be >= 0 rad/s; got {self.prescribed_speed:g} rad/s")
        return self


LABELS = {
    "transient.final_speed": Label("Transient: crank speed at the end (mean over the last turn)", "rad/s", "rpm",
                                   over="cycle", better="none"),
    "transient.free_speed": Label("Transient: speed the drive holds on a rigid frame", "rad/s", "rpm", over="cycle",
                                  better="none"),
    "transient.captured": Label("Transient: drive captured by a frame resonance (1 = yes, Sommerfeld effect)", "",
                                over="scalar", better="lower"),
    "transient.peak_amplitude": Label("Transient: largest frame displacement at the point", "m", "mm", over="max_abs",
                                      better="lower"),
    "transient.peak_mount_force": Label("Transient: largest dynamic mount force", "N", over="max_abs", better="lower"),
    "transient.peak_rotation": Label("Transient: largest rotation of the frame (six degrees of freedom)", "rad",
                                     "mrad", over="max_abs", better="lower"),
    "transient.passage_peak_amplitude": Label("Transient: largest displacement in a resonance passage", "m",
                                              "mm", over="max_abs", better="lower"),
    "transient.passage_peak_mount_force": Label("Transient: largest mount force in a resonance passage", "N",
                                                over="max_abs", better="lower"),
    "transient.passage_time": Label("Transient: time spent within the band of the frame's modes", "s", over="scalar",
                                    better="lower"),
    "transient.steady_amplitude": Label("Transient: displacement at the point over the last turn under the motor",
                                        "m", "mm", over="range", better="lower"),
    "transient.time_to_speed": Label("Transient: time to 95 % of the speed the drive holds on a rigid frame", "s",
                                     over="scalar", better="lower"),
    "transient.stop_time": Label("Transient: time at which the crank comes to rest", "s", over="scalar", better="none"),
    "transient.motor_work": Label("Transient: work of the drive", "J", over="scalar", better="none"),
    "transient.load_work": Label("Transient: work done on the process loads and dampers of the mechanism", "J",
                                 over="scalar", better="none"),
    "transient.mount_dissipation": Label("Transient: energy dissipated in the mounts", "J", over="scalar",
                                         better="none"),
    "transient.brake_dissipation": Label("Transient: energy dissipated in the brake", "J", over="scalar",
                                         better="none"),
    "transient.energy_change": Label("Transient: change of kinetic plus potential energy", "J", over="scalar",
                                     better="none"),
    "transient.energy_error": Label("Transient: energy balance error (relative)", "", over="scalar", better="lower"),
    "transient.evaluations": Label("Transient: evaluations of the equations of motion", "", over="count",
                                   better="none"),
    "transient.phase_difference": Label("Transient: phase of the crank less the twin's over the last turn "
                                        "(synchronised exciters)", "rad", "deg", over="cycle", better="none"),
    **MOTOR_LABELS,
    **TORSION_LABELS,
}

SUMMARY = ("transient.final_speed", "transient.captured", "transient.phase_difference", "transient.peak_amplitude",
           "transient.peak_mount_force",
           "transient.passage_peak_amplitude", "transient.passage_time", "transient.time_to_speed",
           "transient.stop_time", "transient.energy_error")


@dataclass(frozen=True)
class TransientRun(ShownInNotebook):
    """Everything the ``[transient]`` stage computed (SI), for the report and the Python API."""

    table: Any
    run: Transient
    modes: Modes | None
    curve: AmplitudeCurve
    passages: tuple[Passage, ...]
    point: tuple[float, float]
    point_name: str
    direction: float | None
    captured: bool
    final_speed: float
    free_speed: float
    motor: MotorRun | None = None  # the electrical side of an induction motor's dq model ([transient.motor])
    mean_load: float = float("nan")  # the machine's mean load at the crank [N*m] (for the motor's check)
    torsion: TorsionRun | None = None  # the drive line's shafts behind torsionally stiff stages
    crank_inertia: float = float("nan")  # the crank's rigid group with the mechanism's mean inertia [kg*m^2]


def _frame_and_point(ctx: StageContext, table: TransientTable):
    frame_table = getattr(ctx.problem, "frame", None)
    if frame_table is None or table.rigid:
        return None, (0.0, 0.0), "origin", None, (0.0, 0.0), 0.0
    speed = float(getattr(getattr(ctx.problem, "drive", None), "speed", 1.0))
    frame = build_frame(frame_table, abs(speed) / (2.0 * math.pi))
    points = dict(frame_table.points)
    name = table.point or next(iter(points))
    if name not in points:
        raise ProblemFileError([("transient.point", f"no point '{name}' in [frame.points]; points: "
                                                    f"{', '.join(points)}")])
    direction = table.direction if table.direction is not None else frame_table.direction
    return (frame, tuple(points[name]), name, direction, tuple(frame_table.mechanism_origin),
            float(frame_table.mechanism_angle))


def scenario_of(table: TransientTable) -> Scenario:
    """The :class:`Scenario` of a validated ``[transient]`` table."""
    prescribed = None
    if table.prescribed_speed is not None:
        prescribed = (float(table.prescribed_speed), float(table.prescribed_acceleration))
    return Scenario(duration=table.duration, speed=table.start_speed, angle=table.start_angle,
                    switch_off=table.switch_off, brake_time=table.brake_time, brake_torque=table.brake_torque,
                    load_time=table.load_time, load_torque=table.load_torque,
                    speed_change_time=table.speed_change_time, speed_factor=table.speed_factor,
                    prescribed=prescribed, method=table.method, rtol=table.rtol,
                    samples_per_period=table.samples_per_period, max_evaluations=table.max_evaluations,
                    max_seconds=table.max_seconds)


def run_transient(ctx: StageContext) -> Outcome:
    """The stage: build the coupled model from the mechanism, ``[flywheel]``'s drive and ``[frame]``, run the
    scenario, and sum it up."""
    table: TransientTable = ctx.table
    if is_shaft_line(ctx.problem):  # a shaft line on its frame in space: its own model (six degrees of freedom)
        return run_shaft_transient(ctx, scenario_of(table))
    fly = ctx.result_of("flywheel", FlywheelRun)
    if fly is None and table.prescribed_speed is None:
        return Outcome(failed_checks=("[transient] has no drive: [flywheel] found no steady state for its motor, "
                                      "so the machine cannot be run in time",))
    frame, point, point_name, direction, origin, angle = _frame_and_point(ctx, table)
    drive = None if fly is None else fly.drive
    if table.motor is not None and drive is not None:  # the motor's electrical model, through the line's gear
        drive = dq_motor(table.motor, drive)
    # the flywheel with every shaft of the one drive line, at the crank (as the steady state counts them)
    flywheel = 0.0 if fly is None else float(fly.flywheel) + fly.line_inertia
    machine = None if fly is None else fly.machine
    line = None
    if fly is not None:  # stiff stages: the shafts behind them turn on their own, the crank keeps its group
        found_problems = _torsion_problems(ctx.problem)
        if found_problems:
            raise ProblemFileError(found_problems)
        line, crank_group = torsional_line(fly.line, float(fly.flywheel))
        flywheel = crank_group if line is not None else flywheel
    exciters = [Exciter(ctx.mechanism, drive, flywheel, origin, angle, name="crank", machine=machine,
                        torsion=line)]
    scenario = scenario_of(table)
    if table.twin is not None:
        exciters.append(Exciter(ctx.mechanism, drive, flywheel, tuple(table.twin.origin), angle, table.twin.mirror,
                                name="twin", machine=machine, torsion=line))
        scenario = replace(scenario, angle=(table.start_angle, table.twin.start_angle))
    model = coupled_model(exciters, frame, positions=table.positions)
    try:
        run = run_scenario(model, scenario)
    except TransientLimitError as exc:
        # stopped at its budget, saying how far it came: the other results stand, this one failed (a file that
        # check accepts runs to 0 or 3; a run that would plainly take too long is refused by check already)
        return Outcome(failed_checks=(str(exc).rstrip("."),))
    except InputError as exc:
        if not str(exc).startswith("The motor cannot start"):
            raise
        # a motor too small to start the machine is a design that fails, not bad input (as [flywheel] has it)
        return Outcome(failed_checks=(str(exc).rstrip("."),))
    md = modes(carried_frame(model)) if frame is not None else None
    frequencies = md.angular_frequencies if md is not None else np.zeros(0)
    curve = amplitude_curve(run, point, direction)
    found = tuple(passages(run, frequencies, point, direction, table.band))
    free = _free_speed(fly, drive)
    motors_on = table.switch_off is None and table.prescribed_speed is None
    captured, final = capture(run, frequencies, free, table.band) if motors_on else (False, _last_speed(run))
    mean_load = float("nan") if fly is None else -float(np.ravel(fly.machine.moment.mean())[0])
    crank_inertia = float(model.parts[0].c0[0] + model.parts[0].added)
    result = TransientRun(table, run, md, curve, found, point, point_name, direction, captured, final, free,
                          motor_run(run), mean_load, torsion_run(run), crank_inertia)
    outcome = _outcome(result)
    curve_speed = float(getattr(getattr(fly, "drive", None), "synchronous_speed", float("nan")))
    if table.motor is not None and drive is not None and abs(drive.synchronous_speed / curve_speed - 1.0) > 0.02:
        # the gear was chosen for [flywheel.motor]'s synchronous speed: the crank runs at another speed here
        rpm = 30.0 / math.pi
        outcome = replace(outcome, warnings=(*outcome.warnings, (
            f"[transient.motor] turns at {drive.synchronous_speed * rpm:.5g} rpm synchronous "
            f"({table.motor.frequency:g} Hz, {table.motor.pole_pairs} pole pairs), [flywheel.motor] at "
            f"{curve_speed * rpm:.5g} rpm: the gear chosen for the one turns the crank at another speed with the "
            "other; give both the same motor")))
    return outcome


def _free_speed(fly, drive) -> float:
    """The speed at which the drive balances the mean load on a rigid frame [rad/s] (NaN without a drive)."""
    if fly is None or drive is None or isinstance(drive, ConstantSpeed):
        return float("nan")
    grid = np.linspace(0.0, fly.machine.period, 361)[:-1]
    try:
        return float(balance_speed(fly.machine, drive, 1, grid)[0])
    except (InputError, ValueError):
        return float("nan")


def _last_speed(run: Transient) -> float:
    return abs(float(run.omega[0, -1]))


def _outcome(r: TransientRun) -> Outcome:
    run = r.run
    amp = np.hypot(*run.point_displacement(r.point)) if r.direction is None else np.abs(
        math.cos(r.direction) * run.point_displacement(r.point)[0]
        + math.sin(r.direction) * run.point_displacement(r.point)[1])
    values: dict[str, Any] = balance_scalars(run, r.final_speed, r.captured)
    if math.isfinite(r.free_speed):
        values["transient.free_speed"] = r.free_speed
    if run.phi.shape[0] > 1:
        turn = np.abs(run.phi[0] - run.phi[0, -1]) <= 2.0 * math.pi
        values["transient.phase_difference"] = float(np.angle(np.mean(np.exp(1j * (run.phi[0] - run.phi[1])[turn]))))
    if run.q.shape[0]:
        # the last turn under the motor: before the switch-off, or at the end of the run
        end = run.t.size - 1 if run.scenario.switch_off is None else int(np.searchsorted(run.t,
                                                                                          run.scenario.switch_off))
        end = min(end, run.t.size - 1)
        last = (np.abs(run.phi[0] - run.phi[0, end]) <= 2.0 * math.pi) & (run.t <= run.t[end])
        values |= {"transient.peak_amplitude": float(amp.max()),
                   "transient.peak_mount_force": float(np.abs(run.mount_force).max()),
                   "transient.steady_amplitude": float(amp[last].max())}
    speed = np.abs(run.omega[0])
    if run.scenario.prescribed is None and r.table.start_speed == 0.0 and math.isfinite(r.free_speed):
        reached = np.flatnonzero(speed >= 0.95 * r.free_speed)
        if reached.size:
            values["transient.time_to_speed"] = float(run.t[reached[0]])
    if run.ended == "stopped":
        values["transient.stop_time"] = float(run.t[-1])
    found, labels = passage_results(r.passages)
    values |= found
    warnings: list[str] = []
    failed: list[str] = []
    if run.energy_error > ENERGY_TOLERANCE:
        failed.append(f"the energy balance of the transient run closes only to {run.energy_error:.3g} (relative), "
                      f"more than {ENERGY_TOLERANCE:g}: tighten rtol")
    if run.ended == "rolled back":
        failed.append(f"the crank rolls back under its drive at t = {run.t[-1]:.4g} s: the motor cannot turn the "
                      "machine over (choose a larger motor or a higher gear ratio)")
    if r.captured:
        warnings.append(f"The drive is captured by a resonance of the frame: the crank runs at "
                        f"{r.final_speed * 30 / math.pi:.4g} rpm instead of {r.free_speed * 30 / math.pi:.4g} rpm, "
                        "and the motor's power goes into shaking the frame (Sommerfeld effect). Choose a stronger "
                        "motor, more damping in the mounts, or stiffer mounts.")
    if any(not p.completed for p in r.passages) and not r.captured:
        warnings.append("The run ends inside the band of a frame mode; lengthen it to see the whole passage.")
    series = {"transient": _columns(r, amp)}
    if r.motor is not None:
        values |= motor_scalars(r.motor, run)
        failed += motor_checks(r.motor, run, r.free_speed, r.mean_load)
        series["transient_motor"] = motor_series(r.motor)
    if r.torsion is not None:
        values |= torsion_scalars(r.torsion, r.crank_inertia)
        labels |= torsion_labels(r.torsion)
        failed += torsion_checks(r.torsion)
        series["transient_shafts"] = torsion_series(r.torsion)
        if run.scenario.switch_off is None and r.table.start_speed == 0.0 and "transient.time_to_speed" not in values \
                and math.isfinite(r.free_speed):
            warnings.append(f"The induction motor did not bring the crank to 95 % of its speed "
                            f"({r.free_speed * 30 / math.pi:.4g} rpm) within the run; lengthen it to see the start "
                            "end.")
    if r.curve.speed.size:
        series["transient_amplitude"] = {"speed": (r.curve.speed, "rad/s"), "time": (r.curve.time, "s"),
                                         "amplitude": (r.curve.amplitude, "m"),
                                         "mount_force": (r.curve.mount_force, "N")}
    return Outcome(results=r, scalars=values, labels=labels, series=series,
                   summary=tuple(k for k in (*SUMMARY, *MOTOR_SUMMARY, *TORSION_SUMMARY) if k in values),
                   warnings=tuple(warnings),
                   failed_checks=tuple(failed))


def _columns(r: TransientRun, amp) -> dict[str, tuple[Any, str]]:
    run = r.run
    every = max(1, run.t.size // 20_000)  # the CSV keeps at most about 20,000 rows
    out: dict[str, tuple[Any, str]] = {"time": (run.t[::every], "s"), "crank_angle": (run.phi[0, ::every], "rad"),
                                       "speed": (run.omega[0, ::every], "rad/s"),
                                       "drive_torque": (run.drive_torque[0, ::every], "N*m")}
    if run.model.frame is not None:
        out |= {"frame_x": (run.q[0, ::every], "m"), "frame_y": (run.q[1, ::every], "m"),
                "frame_rotation": (run.q[2, ::every], "rad"), f"displacement_{r.point_name}": (amp[::every], "m")}
        for m, f in zip(run.model.frame.mounts, run.mount_force, strict=True):
            out[f"mount_force_{m.name}"] = (f[::every], "N")
    out["energy"] = (run.energy[::every], "J")
    return out


def check_transient(problem, table: TransientTable, source: str | None = None) -> list[tuple[str, str]]:
    """What ``check`` can tell without running: a drive to run the machine, and the point to watch."""
    if is_shaft_line(problem):
        return check_shaft_transient(problem, table)
    found: list[tuple[str, str]] = []
    if table.drive is not None:
        found.append(("transient.drive", "is a shaft line's motor; a mechanism's drive is [flywheel.motor]"))
    if table.prescribed_speed is None and getattr(problem, "flywheel", None) is None:
        found.append(("transient", "needs [flywheel] with its [flywheel.motor] (the drive that turns the machine), "
                                   "or prescribed_speed"))
    frame_table = getattr(problem, "frame", None)
    if table.point is not None:
        points = dict(frame_table.points) if frame_table is not None else {}
        if table.point not in points:
            found.append(("transient.point", f"no point '{table.point}' in [frame.points]; points: "
                                             f"{', '.join(points) or 'none (no [frame])'}"))
    if table.prescribed_speed is not None and (frame_table is None or table.rigid):
        found.append(("transient.prescribed_speed", "a prescribed crank speed on a rigid frame leaves nothing to "
                                                    "run; give [frame] (and rigid = false)"))
    fly = getattr(problem, "flywheel", None)
    if table.motor is not None and fly is not None and fly.motor.kind not in ("select", "induction"):
        found.append(("transient.motor", f"an induction motor's electrical model stands in for the induction motor of "
                                         f"[flywheel.motor] (its gear and rotor); got kind = \"{fly.motor.kind}\" "
                                         "there: give kind = \"induction\" (or \"select\") with the same motor"))
    found += _torsion_problems(problem)
    estimate = _estimated_evaluations(problem, table)
    if estimate > table.max_evaluations:
        found.append(("transient.duration", f"a run of {table.duration:g} s would take about {estimate:,.0f} "
                                            f"evaluations of the equations of motion, over its budget "
                                            f"max_evaluations = {table.max_evaluations:,}; shorten the run or raise "
                                            "max_evaluations"))
    return found


def _torsion_problems(problem) -> list[tuple[str, str]]:
    """A stiff stage of ``[drivetrain]`` with no inertia before it (a spring needs a mass on both sides), as
    ``run`` would find it."""
    drivetrain, fly = getattr(problem, "drivetrain", None), getattr(problem, "flywheel", None)
    if drivetrain is None or fly is None:
        return []
    stiff = [k for k, s in enumerate(drivetrain.stages) if getattr(s, "torsional_stiffness", None) is not None]
    if not stiff:
        return []
    try:
        line = line_of(problem, fly)
        # a flywheel still to be sized counts as present (its inertia is found by the run)
        flywheel = line.at_crank(float(fly.inertia), line.flywheel_shaft) if fly.inertia is not None else 1.0
        torsional_line(line, flywheel)
    except InputError as exc:
        text = str(exc).rstrip(".")
        return [(f"drivetrain.stages[{stiff[0]}].torsional_stiffness", text[:1].lower() + text[1:])]
    except ValueError:
        return []  # a drive line given twice: [flywheel]'s own check names it
    return []


#: Evaluations of the equations per period of the fastest motion (crank turn or frame mode): DOP853 at the default
#: tolerance takes about 165 on the rotary screen's run-up.
EVALUATIONS_PER_PERIOD = 200


def _estimated_evaluations(problem, table: TransientTable) -> float:
    """The evaluations a run will take, from the duration and the fastest of the crank's speed (10 % above its
    nominal ``[drive] speed``, or the prescribed or start speed), the frame's modes (without the mechanism's
    masses: the upper estimate) and the drive line's stiff stages."""
    drive = getattr(problem, "drive", None)
    speed = 1.1 * abs(float(getattr(drive, "speed", 0.0)))
    speed = max(speed, abs(table.start_speed))
    if table.prescribed_speed is not None:
        speed = max(abs(table.prescribed_speed), abs(table.prescribed_speed + table.prescribed_acceleration
                                                     * table.duration))
    frame_table = getattr(problem, "frame", None)
    if frame_table is not None and not table.rigid:
        try:
            speed = max(speed, float(np.max(modes(build_frame(frame_table, max(speed, 1e-9) / (2.0 * math.pi)))
                                            .angular_frequencies)))
        except InputError:
            pass  # [frame]'s own check reports an unsupported frame
    if table.prescribed_speed is None:
        speed = max(speed, _spring_speed(problem))
    return EVALUATIONS_PER_PERIOD * table.duration * speed / (2.0 * math.pi)


def _spring_speed(problem) -> float:
    """sqrt(K / J) [rad/s] of the stiffest spring of the drive line against the inertia before it (a lower
    estimate of its frequency; 0 for a rigid line or one ``check`` refuses elsewhere)."""
    fly = getattr(problem, "flywheel", None)
    if getattr(problem, "drivetrain", None) is None or fly is None:
        return 0.0
    try:
        line = line_of(problem, fly)
        flywheel = line.at_crank(float(fly.inertia), line.flywheel_shaft) if fly.inertia is not None else 0.0
        torsion, _ = torsional_line(line, flywheel)
    except (InputError, ValueError):
        return 0.0
    if torsion is None:
        return 0.0
    return max(math.sqrt(k / j) for k, j in zip(torsion.stiffness, torsion.inertias, strict=True))


CAPABILITY = Capability(
    table="transient",
    schema=TransientTable,
    run=run_transient,
    step="machine in time",
    kinds=("mechanism", "rotary_screen", "shaft_line"),
    labels=LABELS,
    report="machdyn.report.transient_drive:sections",
    check=check_transient,
    after=("flywheel", "frame"),
    result_type=(TransientRun, ShaftTransientRun),
)

