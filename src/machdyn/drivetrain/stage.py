"""The ``[drivetrain]`` table of a mechanism problem file: the stages between motor and crank, a clutch that
engages the flywheel side to the crank, and a brake that stops the crank side.

```toml
[drivetrain]
motor_inertia = "0.02 kg*m^2"     # shaft 0: the motor's rotor and what turns with it

[[drivetrain.stages]]             # from the motor to the crank, one shaft after each stage
kind = "belt"
ratio = 4.0                       # input speed / output speed
efficiency = 0.95
inertia = "1.2 kg*m^2"            # what sits on the stage's output shaft (pulley, flywheel rim, gear)

[[drivetrain.stages]]
kind = "gear"
ratio = 9.0
efficiency = 0.97
inertia = "0.3 kg*m^2"            # the last stage's output shaft is the crank shaft

[drivetrain.clutch]
shaft = 1                         # the clutch joins shaft 1 (and all before it) to the stage after it
slip_torque = "900 N*m"           # on that shaft
strokes_per_minute = 20           # single strokes: for the clutch's heat

[drivetrain.brake]
torque = "2500 N*m"               # on the crank shaft
max_angle = "45 deg"              # a stop longer than this fails the design check (exit 3)
max_time = "0.3 s"
```

With ``[flywheel]`` the flywheel (its inertia reduced to the crank) sits on the clutch's driving side, and the
shaft torques are those at the real speed.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any, Literal

import numpy as np
from pydantic import Field, model_validator

from ..dynamics.equivalent import equivalent_machine
from ..dynamics.stage import FlywheelRun
from ..errors import InputError, ProblemFileError
from ..linkage import analyse, crank_angles
from ..pipeline import Capability, Outcome, StageContext
from ..problem.build import build_mechanism
from ..problem.fields import Angle, Inertia, Time, Torque
from ..problem.schema import Spec
from ..results.labels import Label
from .clutch import Engagement, Stop, brake_balance_problem, engage, stop_machine
from .single_stroke import single_stroke, single_stroke_duty
from .train import DriveTrain, Stage

RPM = 30.0 / np.pi


class StageTable(Spec):
    kind: Literal["gear", "belt", "chain"] = "gear"
    ratio: float = Field(gt=0.0, allow_inf_nan=False)
    efficiency: float = Field(1.0, gt=0.0, le=1.0, allow_inf_nan=False)
    inertia: Inertia = 0.0
    name: str = ""


class ClutchTable(Spec):
    shaft: int | None = Field(None, ge=0)
    slip_torque: Torque
    motor_torque: Torque = 0.0
    strokes_per_minute: float | None = Field(None, gt=0.0, allow_inf_nan=False)


class BrakeTable(Spec):
    torque: Torque
    shaft: int | None = Field(None, ge=0)
    at: list[Angle] = []
    max_angle: Angle | None = None
    max_time: Time | None = None


class SingleStrokeTable(Spec):
    """``[drivetrain.single_stroke]``: simulate one stroke of a press in single-stroke mode."""

    start: Angle                      # the crank angle at rest between strokes (e.g. top dead centre)
    brake_at: Angle | None = None     # where the clutch opens and the brake closes; default: found so that the
                                      # crank comes to rest at ``start`` one turn on


class DriveTrainSpec(Spec):
    """The ``[drivetrain]`` table."""

    motor_inertia: Inertia = 0.0
    stages: list[StageTable] = Field(min_length=1)
    clutch: ClutchTable | None = None
    brake: BrakeTable | None = None
    single_stroke: SingleStrokeTable | None = None

    @model_validator(mode="after")
    def _shafts(self):
        last = len(self.stages)
        if self.clutch is not None and self.clutch.shaft is not None and self.clutch.shaft >= last:
            raise ValueError(f"clutch.shaft must name a shaft before the crank shaft (0 to {last - 1}); got "
                             f"{self.clutch.shaft}")
        if self.brake is not None and self.brake.shaft is not None and self.brake.shaft > last:
            raise ValueError(f"brake.shaft must be 0 to {last} (the crank shaft); got {self.brake.shaft}")
        if self.clutch is not None and not self.clutch.slip_torque > 0:
            raise ValueError(f"clutch.slip_torque must be > 0 N*m; got {self.clutch.slip_torque:g} N*m")
        if self.brake is not None and not self.brake.torque > 0:
            raise ValueError(f"brake.torque must be > 0 N*m; got {self.brake.torque:g} N*m")
        if self.single_stroke is not None and (self.clutch is None or self.brake is None):
            raise ValueError("single_stroke needs both a [drivetrain.clutch] and a [drivetrain.brake]")
        stroke = self.single_stroke
        if stroke is not None and stroke.brake_at is not None and not (
                stroke.start < stroke.brake_at < stroke.start + 2 * np.pi):
            raise ValueError(f"single_stroke.brake_at must lie within the stroke, after start "
                             f"({np.degrees(stroke.start):g} deg) and less than a turn later; got "
                             f"{np.degrees(stroke.brake_at):g} deg")
        return self


@dataclass(frozen=True)
class DriveTrainRun:
    """What ``[drivetrain]`` computed: the train, the crank-side inertia, the shaft torques over the cycle
    (shafts first), the clutch engagement (at the clutch shaft), the worst stop and every stop computed."""

    train: DriveTrain
    crank_angle: np.ndarray
    shaft_torques: np.ndarray
    clutch_shaft: int | None
    engagement: Engagement | None
    stops: tuple[Stop, ...]
    worst_stop: Stop | None
    crank_speed: float
    single_stroke: Any = None
    single_stroke_duty: Any = None  # the motor's duty over repeated single strokes (a DutyCheck), if rated
    #: why the single stroke could not be completed (a clutch that does not turn the machine, a brake that does
    #: not stop it within the turn, a motor that does not bring the flywheel back): a design that fails, not input
    single_stroke_failure: str | None = None


def train_of(table: DriveTrainSpec) -> DriveTrain:
    stages = tuple(Stage(s.ratio, s.efficiency, s.kind, s.name) for s in table.stages)
    return DriveTrain(stages, (table.motor_inertia, *(s.inertia for s in table.stages)))


def flywheel_shaft(train: DriveTrain, speed_ratio: float) -> int:
    """The shaft of the train that turns ``speed_ratio`` times faster than the crank (where ``[flywheel]``
    puts the flywheel); an error naming the ratios where none does."""
    ratios = train.speed_ratios
    match = np.flatnonzero(np.isclose(ratios, speed_ratio, rtol=1e-6))
    if match.size == 0:
        raise InputError(f"[flywheel] speed_ratio = {speed_ratio:g} matches no shaft of [drivetrain], whose shafts "
                         f"turn {', '.join(f'{r:g}' for r in ratios)} times as fast as the crank.")
    return int(match[-1])


def _clutch_shaft(table: DriveTrainSpec) -> int:
    assert table.clutch is not None
    return len(table.stages) - 1 if table.clutch.shaft is None else table.clutch.shaft


def _peak_at_clutch(train: DriveTrain, shaft: int, crank_torque: np.ndarray) -> float:
    return float(np.max(np.abs(train.shaft_torques(crank_torque)[shaft])))


def check(problem: Any, table: DriveTrainSpec, source: str | None = None) -> list[tuple[str, str]]:
    """Validations ``run`` relies on: the clutch carries the largest torque of the cycle at its shaft."""
    try:
        train = train_of(table)
    except InputError as exc:
        return [("drivetrain.stages", str(exc))]
    flywheel = getattr(problem, "flywheel", None)
    if flywheel is not None:
        try:
            flywheel_shaft(train, float(flywheel.speed_ratio))
        except InputError as exc:
            return [("drivetrain.stages", str(exc))]
    if table.clutch is None and table.brake is None:
        return []
    try:
        mech = build_mechanism(problem)
        out = brake_problems(table, train, mech)
        if table.clutch is not None:
            torque = analyse(mech, crank_angles(360), abs(problem.drive.speed)).forces.driving_torque
            out += _clutch_problems(table, train, np.asarray(torque, dtype=float))
    except (ProblemFileError, InputError):
        return []  # the kind's own check reports them
    return out


def brake_problems(table: DriveTrainSpec, train: DriveTrain, mechanism: Any) -> list[tuple[str, str]]:
    """The brake's torque against the loads of the linkage (:func:`~machdyn.drivetrain.clutch.brake_balance_problem`,
    the balance of work over a turn): a brake that cannot stop the machine is refused by ``check`` and by ``run``
    alike, before any stop is integrated."""
    if table.brake is None or getattr(mechanism, "design_count", None) is not None:
        return []
    at_shaft = len(train.stages) if table.brake.shaft is None else table.brake.shaft
    if not 0 <= at_shaft <= len(train.stages):
        return []  # the table's own rule reports it
    weak = brake_balance_problem(equivalent_machine(mechanism, 360), table.brake.torque * train.speed_ratios[at_shaft])
    return [] if weak is None else [("drivetrain.brake.torque", f"{weak}; got {table.brake.torque:.4g} N*m on "
                                                                 f"shaft {at_shaft}")]


def _clutch_problems(table: DriveTrainSpec, train: DriveTrain, torque: np.ndarray) -> list[tuple[str, str]]:
    assert table.clutch is not None
    shaft = _clutch_shaft(table)
    peak = _peak_at_clutch(train, shaft, torque)
    if table.clutch.slip_torque <= peak:
        return [("drivetrain.clutch.slip_torque",
                 f"must exceed the largest torque the clutch carries on shaft {shaft} over the cycle, "
                 f"{peak:.4g} N*m; got {table.clutch.slip_torque:.4g} N*m")]
    return []


def run(ctx: StageContext) -> Outcome:
    """Stage of ``[drivetrain]``."""
    table: DriveTrainSpec = ctx.table
    train = train_of(table)
    flywheel = ctx.result_of("flywheel", FlywheelRun)  # None: no [flywheel], or no steady state
    forces = flywheel.real.real if flywheel is not None else ctx.analysis.forces
    torque = np.asarray(forces.driving_torque, dtype=float)
    if torque.ndim != 1:
        raise InputError("[drivetrain] analyses a single design; the file describes several.")
    crank_speed = float(np.mean(np.abs(np.ravel(ctx.analysis.kinematics.speed))))
    nominal = np.asarray(ctx.analysis.forces.driving_torque, dtype=float)
    problems = _clutch_problems(table, train, nominal) if table.clutch is not None else []
    problems += brake_problems(table, train, ctx.mechanism)
    if problems:  # what check finds at the nominal speed: bad input
        raise ProblemFileError(problems)
    # At the real speed under the flywheel's drive the clutch may carry more than check could see: a failed check.
    overloaded = [f"clutch: {message}" for _path, message in _clutch_problems(table, train, torque)] \
        if table.clutch is not None and flywheel is not None else []
    shaft_torques = train.shaft_torques(torque)
    if flywheel is not None:
        # Upstream of the flywheel the shafts carry the motor's torque, not the linkage's peaks.
        f = flywheel_shaft(train, float(flywheel.table.speed_ratio))
        steady = flywheel.steady
        phi = np.asarray(forces.kinematics.crank_angle, dtype=float)
        motor = np.interp(np.mod(phi, 2 * np.pi), np.mod(np.ravel(steady.phi), 2 * np.pi),
                          np.ravel(steady.drive_torque), period=2 * np.pi)
        shaft_torques[:f] = train.shaft_torques(motor)[:f]
    machine = flywheel.machine if flywheel is not None else equivalent_machine(ctx.mechanism, 360)
    fly_inertia = float(flywheel.flywheel) if flywheel is not None else 0.0
    ratios = train.speed_ratios
    n = len(train.stages)

    engagement, shaft = None, None
    if table.clutch is not None:
        shaft = _clutch_shaft(table)
        j = np.asarray(train.shaft_inertia)
        scale = ratios / ratios[shaft]  # speeds relative to the clutch shaft
        j1 = float(np.sum(j[: shaft + 1] * scale[: shaft + 1] ** 2) + fly_inertia / ratios[shaft] ** 2)
        linkage = float(np.mean(machine.inertia(np.linspace(0, 2 * np.pi, 361)[:-1])))
        j2 = float(np.sum(j[shaft + 1:] * scale[shaft + 1:] ** 2) + linkage / ratios[shaft] ** 2)
        engagement = engage(j1, crank_speed * ratios[shaft], j2, 0.0, table.clutch.slip_torque,
                            driving_torque=table.clutch.motor_torque)

    stops: list[Stop] = []
    worst = None
    if table.brake is not None:
        start = 0 if shaft is None else shaft + 1
        j = np.asarray(train.shaft_inertia)
        extra = float(np.sum(j[start:] * ratios[start:] ** 2))  # reflected to the crank
        if shaft is None:
            extra += fly_inertia
        at_shaft = n if table.brake.shaft is None else table.brake.shaft
        brake_at_crank = table.brake.torque * ratios[at_shaft]
        angles = table.brake.at or list(np.linspace(0.0, 2 * np.pi, 12, endpoint=False))
        for a in angles:
            stops.append(stop_machine(machine, extra, crank_speed, brake_at_crank, float(a)))
        worst = max(stops, key=lambda s: s.angle)

    stroke, stroke_failure = None, None
    if table.single_stroke is not None:
        try:
            stroke = _single_stroke(table, train, machine, flywheel, fly_inertia, crank_speed)
        except ProblemFileError:
            raise
        except InputError as exc:  # the file is valid (check said so); this design cannot make its single stroke
            stroke_failure = str(exc).rstrip(".")
    duty = None
    if stroke is not None and flywheel is not None and hasattr(flywheel.drive, "rated_torque"):
        assert table.clutch is not None
        duty = single_stroke_duty(stroke, flywheel.drive, table.clutch.strokes_per_minute)
    done = DriveTrainRun(train, np.asarray(forces.kinematics.crank_angle, dtype=float), shaft_torques, shaft,
                         engagement, tuple(stops), worst, crank_speed, stroke, duty, stroke_failure)
    done_outcome = _outcome(done, table)
    if overloaded:
        done_outcome = replace(done_outcome, failed_checks=(*overloaded, *done_outcome.failed_checks))
    return done_outcome


def idle_speed(motor: Any, nominal: float) -> float:
    """The speed [rad/s, crank units] the flywheel side runs at between single strokes: where the motor's torque
    falls to zero (an induction motor's synchronous speed through the drive), or the nominal speed for a drive
    whose torque does not fall with the speed."""
    from scipy.optimize import brentq

    def torque(w: float) -> float:
        return float(np.ravel(motor(w))[0])

    if not torque(nominal) > 0:
        return nominal
    high = nominal
    for _ in range(8):
        high *= 1.25
        if torque(high) <= 0:
            return float(brentq(torque, nominal, high, xtol=1e-12 * nominal))
    return nominal


def _single_stroke(table: DriveTrainSpec, train: DriveTrain, machine: Any, flywheel: FlywheelRun | None,
                   fly_inertia: float, crank_speed: float) -> Any:
    """The single stroke of ``[drivetrain.single_stroke]``, everything reduced to the crank shaft: the motor of
    ``[flywheel.motor]`` (or the clutch table's constant ``motor_torque``) on the driving side."""
    assert table.clutch is not None and table.brake is not None and table.single_stroke is not None
    shaft = _clutch_shaft(table)
    ratios = train.speed_ratios
    j = np.asarray(train.shaft_inertia)
    drive_side = float(np.sum(j[: shaft + 1] * ratios[: shaft + 1] ** 2) + fly_inertia)
    driven_side = float(np.sum(j[shaft + 1:] * ratios[shaft + 1:] ** 2))
    drive = flywheel.drive if flywheel is not None else None
    if drive is not None and hasattr(drive, "torque_at"):
        motor = drive.torque_at
    else:
        constant = float(table.clutch.motor_torque * ratios[shaft])
        if not constant > 0:
            raise ProblemFileError([("drivetrain.single_stroke", "needs a motor to bring the flywheel back to "
                                     "speed: a [flywheel.motor] or drivetrain.clutch.motor_torque > 0 N*m")])

        def motor(_w: float) -> float:
            return constant
    at_brake = len(train.stages) if table.brake.shaft is None else table.brake.shaft
    return single_stroke(machine, motor, drive_inertia=drive_side, driven_inertia=driven_side,
                         speed=idle_speed(motor, crank_speed),
                         slip_torque=float(table.clutch.slip_torque * ratios[shaft]),
                         brake_torque=float(table.brake.torque * ratios[at_brake]),
                         start_angle=float(table.single_stroke.start), brake_angle=table.single_stroke.brake_at)


def _outcome(done: DriveTrainRun, table: DriveTrainSpec) -> Outcome:
    scalars: dict[str, Any] = {
        "drivetrain.ratio": done.train.total_ratio,
        "drivetrain.efficiency": done.train.efficiency,
        "drivetrain.reflected_inertia": done.train.reflected_inertia(),
    }
    labels: dict[str, Label] = {}
    for k, t in enumerate(done.shaft_torques):
        where = "motor shaft" if k == 0 else ("crank shaft" if k == len(done.train.stages) else f"shaft {k}")
        scalars[f"drivetrain.shaft_{k}.torque.max_abs"] = float(np.max(np.abs(t)))
        labels[f"drivetrain.shaft_{k}.torque.max_abs"] = Label(f"Drive train: peak torque, {where}", "N*m")
    failed = []
    e = done.engagement
    if e is not None:
        assert table.clutch is not None and done.clutch_shaft is not None
        ratio = done.train.speed_ratios[done.clutch_shaft]
        scalars.update({
            "clutch.slip_time": e.slip_time,
            "clutch.energy": e.dissipated,
            "clutch.crank_speed_after": e.common_speed / ratio,
            "clutch.speed_drop": 1.0 - e.common_speed / (done.crank_speed * ratio),
        })
        if table.clutch.strokes_per_minute is not None:
            scalars["clutch.heat_power"] = e.dissipated * table.clutch.strokes_per_minute / 60.0
    s = done.worst_stop
    if s is not None:
        assert table.brake is not None
        scalars.update({"brake.stop_time": s.time, "brake.stop_angle": s.angle})
        if table.brake.max_angle is not None and s.angle > table.brake.max_angle:
            failed.append(f"brake: the crank overruns {np.degrees(s.angle):.1f}° after the brake is applied, more "
                          f"than brake.max_angle = {np.degrees(table.brake.max_angle):.1f}°")
        if table.brake.max_time is not None and s.time > table.brake.max_time:
            failed.append(f"brake: the stop takes {s.time:.3g} s, more than brake.max_time = "
                          f"{table.brake.max_time:.3g} s")
    k = done.single_stroke
    if k is not None:
        scalars.update({
            "single_stroke.brake_angle": float(np.mod(k.brake_angle, 2 * np.pi)), "single_stroke.overrun": k.overrun,
            "single_stroke.slip_time": k.slip_time, "single_stroke.stroke_time": k.stroke_time,
            "single_stroke.stop_time": k.stop_time, "single_stroke.stop_angle": k.stop_angle,
            "single_stroke.clutch_energy": k.clutch_energy, "single_stroke.brake_energy": k.brake_energy,
            "single_stroke.speed_drop": 1.0 - k.lowest_drive_speed / k.running_speed,
            "single_stroke.recovery_time": k.recovery_time,
            "single_stroke.strokes_per_minute": k.strokes_per_minute,
        })
        if table.brake is not None and table.brake.max_angle is not None and k.stop_angle > table.brake.max_angle:
            failed.append(f"single stroke: the crank runs {np.degrees(k.stop_angle):.1f}° after the brake closes, "
                          f"more than brake.max_angle = {np.degrees(table.brake.max_angle):.1f}°")
        if table.brake is not None and table.brake.max_time is not None and k.stop_time > table.brake.max_time:
            failed.append(f"single stroke: the stop takes {k.stop_time:.3g} s, more than brake.max_time = "
                          f"{table.brake.max_time:.3g} s")
        if done.single_stroke_duty is not None:
            d = done.single_stroke_duty
            scalars["single_stroke.motor_rms_torque"] = d.load_rms
            scalars["single_stroke.motor_load"] = d.load_ratio
            failed += [f"single stroke: {text}" for text in d.overload()]
        wanted = table.clutch.strokes_per_minute if table.clutch is not None else None
        if wanted is not None and k.strokes_per_minute < wanted:
            failed.append(f"single stroke: the drive manages {k.strokes_per_minute:.3g} strokes a minute (stroke "
                          f"{k.stroke_time:.3g} s, flywheel back to speed after {k.recovery_time:.3g} s more), fewer "
                          f"than clutch.strokes_per_minute = {wanted:g}")
    series = {"drivetrain_torques": {"crank_angle": (done.crank_angle, "rad"),
                                     **{f"shaft_{k}": (t, "N*m") for k, t in enumerate(done.shaft_torques)}}}
    if k is not None:
        series["single_stroke"] = {"time": (k.t, "s"), "crank_angle": (k.phi, "rad"), "crank_speed": (k.omega, "rad/s"),
                                   "drive_side_speed": (k.omega_drive, "rad/s"),
                                   "clutch_torque": (k.clutch_torque, "N*m"), "motor_torque": (k.motor_torque, "N*m")}
    summary = tuple(key for key in scalars if not key.startswith("drivetrain.shaft_")) + \
        ("drivetrain.shaft_0.torque.max_abs",)
    if done.single_stroke_failure is not None:
        failed.append(f"single stroke: {done.single_stroke_failure}")
    estimated = [st for st in done.stops if st.estimated]
    warnings = (f"brake: {len(estimated)} of the {len(done.stops)} stops last longer than the turns integrated; "
                "their rest is found by the energy balance from there (an upper bound on the angle and time)",
                ) if estimated else ()
    return Outcome(results=done, scalars=scalars, labels=labels, series=series, summary=summary,
                   warnings=warnings, failed_checks=tuple(failed))


LABELS = {
    "drivetrain.ratio": Label("Drive train: motor speed / crank speed", ""),
    "drivetrain.efficiency": Label("Drive train: efficiency", ""),
    "drivetrain.reflected_inertia": Label("Drive train: shaft inertias reflected to the crank", "kg*m^2"),
    "clutch.slip_time": Label("Clutch: slip time of an engagement", "s"),
    "clutch.energy": Label("Clutch: energy dissipated per engagement", "J"),
    "clutch.crank_speed_after": Label("Clutch: crank speed when the slip ends", "rad/s", "rpm"),
    "clutch.speed_drop": Label("Clutch: relative speed drop of the driving side (fraction)", ""),
    "clutch.heat_power": Label("Clutch: mean heat power at the stroke rate", "W"),
    "brake.stop_time": Label("Brake: stopping time, worst application angle", "s"),
    "brake.stop_angle": Label("Brake: stopping angle of the crank, worst application angle", "rad", "deg"),
    "single_stroke.brake_angle": Label("Single stroke: crank angle where the clutch opens and the brake closes",
                                       "rad", "deg"),
    "single_stroke.overrun": Label("Single stroke: crank at rest past the start angle (negative: short of it)",
                                   "rad", "deg"),
    "single_stroke.slip_time": Label("Single stroke: clutch slip time", "s"),
    "single_stroke.stroke_time": Label("Single stroke: time from clutch in to the crank at rest", "s"),
    "single_stroke.stop_time": Label("Single stroke: stopping time after the brake closes", "s"),
    "single_stroke.stop_angle": Label("Single stroke: stopping angle after the brake closes", "rad", "deg"),
    "single_stroke.clutch_energy": Label("Single stroke: energy dissipated in the clutch", "J"),
    "single_stroke.brake_energy": Label("Single stroke: energy dissipated in the brake", "J"),
    "single_stroke.speed_drop": Label("Single stroke: largest speed drop of the flywheel side, relative to its "
                                      "speed between strokes", ""),
    "single_stroke.recovery_time": Label("Single stroke: time for the motor to bring the flywheel back after the "
                                         "stop", "s"),
    "single_stroke.strokes_per_minute": Label("Single stroke: most strokes a minute the drive can make", ""),
    "single_stroke.motor_rms_torque": Label("Single stroke: RMS of the motor's torque (at the crank) over a period "
                                            "of strokes at the rate asked for", "N*m"),
    "single_stroke.motor_load": Label("Single stroke: motor's RMS torque / its rated S1 torque", ""),
}

CAPABILITY = Capability(
    table="drivetrain",
    schema=DriveTrainSpec,
    run=run,
    step="drive train, clutch and brake",
    kinds=("mechanism",),
    labels=LABELS,
    report="machdyn.report.drivetrain:sections",
    check=check,
    after=("flywheel",),
    result_type=DriveTrainRun,
)
