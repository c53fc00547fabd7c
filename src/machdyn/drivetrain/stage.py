"""The ``[drivetrain]`` stage: the shaft torques over the cycle, the clutch's engagement, the brake's stops, the
single stroke and the checks of gear teeth and shafts, all on the machine's one drive line (the table itself is
in :mod:`machdyn.drivetrain.schema`)."""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from ..dynamics.driveline import DriveLine, DriveTrain
from ..dynamics.driveline_file import line_of, line_problems
from ..dynamics.equivalent import equivalent_machine
from ..dynamics.stage import FlywheelRun
from ..errors import InputError, ProblemFileError
from ..linkage import analyse, crank_angles
from ..notebook import ShownInNotebook
from ..pipeline import Capability, Outcome, StageContext
from ..problem.build import build_mechanism
from ..results.labels import Label
from .brakes import BrakeTorque, Heating
from .clutch import Engagement, Stop, brake_balance_problem, engage, stop_machine
from .gear_stage import GearCheck, check_teeth, gear_results
from .geometry_tables import (
    ClutchRating,
    heating_of,
    rate_brake,
    rate_clutch,
)
from .schema import DriveTrainSpec
from .shaft_check import ShaftCheck, check_shaft, shaft_results
from .single_stroke import single_stroke, single_stroke_duty

RPM = 30.0 / np.pi


@dataclass(frozen=True)
class DriveTrainRun(ShownInNotebook):
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
    clutch_rating: ClutchRating | None = None     # the clutch's torque from its geometry
    brake_rating: BrakeTorque | None = None       # the brake's torque from its geometry
    heating: Heating | None = None                # the brake drum's heating by the worst stop
    brake_torque: float | None = None             # on the brake's shaft [N*m]
    gear_checks: tuple[GearCheck, ...] = ()       # the teeth of the gear stages that describe them
    shaft_checks: tuple[ShaftCheck, ...] = ()     # the shafts of [[drivetrain.shafts]]
    #: why the single stroke could not be completed (a clutch that does not turn the machine, a brake that does
    #: not stop it within the turn, a motor that does not bring the flywheel back): a design that fails, not input
    single_stroke_failure: str | None = None


def _line(problem: Any) -> DriveLine:
    """The machine's one drive line (``[drivetrain]`` with ``[flywheel]``'s shaft and motor)."""
    return line_of(problem, getattr(problem, "flywheel", None))


def _peak_at_clutch(train: DriveTrain, shaft: int, crank_torque: np.ndarray) -> float:
    return float(np.max(np.abs(train.shaft_torques(crank_torque)[shaft])))


def clutch_rating(table: DriveTrainSpec, line: DriveLine, crank_speed: float) -> ClutchRating:
    """The clutch's slip torque on its shaft: typed, or from its geometry at the shaft's running speed."""
    assert table.clutch is not None
    if table.clutch.geometry is None:
        assert table.clutch.slip_torque is not None
        return ClutchRating(float(table.clutch.slip_torque))
    assert line.clutch_shaft is not None
    speed = crank_speed * float(line.train.speed_ratios[line.clutch_shaft])
    try:
        return rate_clutch(table.clutch.geometry, speed)
    except InputError as exc:
        raise ProblemFileError([("drivetrain.clutch.geometry", str(exc))]) from None


def brake_rating(table: DriveTrainSpec) -> BrakeTorque:
    """The brake's torque on its shaft: typed, or from its geometry (a brake that locks itself is refused)."""
    assert table.brake is not None
    if table.brake.geometry is None:
        assert table.brake.torque is not None
        return BrakeTorque(float(table.brake.torque), 0.0, float(table.brake.torque), False)
    try:
        rating = rate_brake(table.brake.geometry)
    except InputError as exc:
        raise ProblemFileError([("drivetrain.brake.geometry", str(exc))]) from None
    if not rating.torque > 0:
        raise ProblemFileError([("drivetrain.brake.geometry", "gives no braking torque (is its force 0 N?)")])
    return rating


def check(problem: Any, table: DriveTrainSpec, source: str | None = None) -> list[tuple[str, str]]:
    """Validations ``run`` relies on: a brake from its geometry that does not lock itself, and a clutch that
    carries the largest torque of the cycle at its shaft. (A value of the drive line given twice is the
    ``[flywheel]`` check's: it names both fields.)"""
    if line_problems(problem, getattr(problem, "flywheel", None)):
        return []
    try:
        line = _line(problem)
    except InputError as exc:
        return [("drivetrain.stages", str(exc))]
    if table.brake is not None:
        try:
            brake_rating(table)
        except ProblemFileError as exc:
            return list(exc.problems)
    if table.clutch is None and table.brake is None:
        return []
    try:
        mech = build_mechanism(problem)
        torque = analyse(mech, crank_angles(360), abs(problem.drive.speed)).forces.driving_torque \
            if table.clutch is not None else None
    except (ProblemFileError, InputError):
        return []  # the kind's own check reports them
    try:
        out = brake_problems(table, line, mech)
        if torque is not None:
            out += _clutch_problems(table, line, np.asarray(torque, dtype=float), abs(float(problem.drive.speed)))
    except ProblemFileError as exc:
        return list(exc.problems)
    except InputError:
        return []  # the kind's own check reports them
    return out


def brake_problems(table: DriveTrainSpec, line: DriveLine, mechanism: Any) -> list[tuple[str, str]]:
    """The brake's torque against the loads of the linkage (:func:`~machdyn.drivetrain.clutch.brake_balance_problem`,
    the balance of work over a turn): a brake that cannot stop the machine is refused by ``check`` and by ``run``
    alike, before any stop is integrated."""
    if table.brake is None or getattr(mechanism, "design_count", None) is not None:
        return []
    at_shaft = line.crank if line.brake_shaft is None else line.brake_shaft
    torque = brake_rating(table).torque
    weak = brake_balance_problem(equivalent_machine(mechanism, 360), torque * line.train.speed_ratios[at_shaft])
    field = "drivetrain.brake.torque" if table.brake.geometry is None else "drivetrain.brake.geometry"
    return [] if weak is None else [(field, f"{weak}; got {torque:.4g} N*m on shaft {at_shaft}")]


def _clutch_problems(table: DriveTrainSpec, line: DriveLine, torque: np.ndarray,
                     crank_speed: float) -> list[tuple[str, str]]:
    assert table.clutch is not None and line.clutch_shaft is not None
    shaft = line.clutch_shaft
    peak = _peak_at_clutch(line.train, shaft, torque)
    slip = clutch_rating(table, line, crank_speed).torque
    if slip <= peak:
        if table.clutch.geometry is None:
            return [("drivetrain.clutch.slip_torque",
                     f"must exceed the largest torque the clutch carries on shaft {shaft} over the cycle, "
                     f"{peak:.4g} N*m; got {slip:.4g} N*m")]
        return [("drivetrain.clutch.geometry",
                 f"gives a slip torque of {slip:.4g} N*m, which must exceed the largest torque the clutch carries "
                 f"on shaft {shaft} over the cycle, {peak:.4g} N*m")]
    return []


def run(ctx: StageContext) -> Outcome:
    """Stage of ``[drivetrain]``."""
    table: DriveTrainSpec = ctx.table
    flywheel = ctx.result_of("flywheel", FlywheelRun)  # None: no [flywheel], or no steady state
    line = flywheel.line if flywheel is not None else _line(ctx.problem)
    train = line.train
    forces = flywheel.real.real if flywheel is not None else ctx.analysis.forces
    torque = np.asarray(forces.driving_torque, dtype=float)
    if torque.ndim != 1:
        raise InputError("[drivetrain] analyses a single design; the file describes several.")
    crank_speed = float(np.mean(np.abs(np.ravel(ctx.analysis.kinematics.speed))))
    nominal = np.asarray(ctx.analysis.forces.driving_torque, dtype=float)
    problems = _clutch_problems(table, line, nominal, crank_speed) if table.clutch is not None else []
    problems += brake_problems(table, line, ctx.mechanism)
    if problems:  # what check finds at the nominal speed: bad input
        raise ProblemFileError(problems)
    # At the real speed under the flywheel's drive the clutch may carry more than check could see: a failed check.
    overloaded = [f"clutch: {message}" for _path, message in _clutch_problems(table, line, torque, crank_speed)] \
        if table.clutch is not None and flywheel is not None else []
    shaft_torques = train.shaft_torques(torque)
    if flywheel is not None:
        # Upstream of the flywheel the shafts carry the motor's torque, not the linkage's peaks.
        f = line.flywheel_shaft
        steady = flywheel.steady
        phi = np.asarray(forces.kinematics.crank_angle, dtype=float)
        motor = np.interp(np.mod(phi, 2 * np.pi), np.mod(np.ravel(steady.phi), 2 * np.pi),
                          np.ravel(steady.drive_torque), period=2 * np.pi)
        shaft_torques[:f] = train.shaft_torques(motor)[:f]
    machine = flywheel.machine if flywheel is not None else equivalent_machine(ctx.mechanism, 360)
    fly_inertia = float(flywheel.flywheel) if flywheel is not None else 0.0
    ratios = train.speed_ratios
    n = len(train.stages)

    engagement, shaft, rating = None, line.clutch_shaft, None
    if table.clutch is not None:
        assert shaft is not None
        rating = clutch_rating(table, line, crank_speed)
        drive_side, driven_side = _sides(line, shaft, fly_inertia)  # at the crank
        linkage = float(np.mean(machine.inertia(np.linspace(0, 2 * np.pi, 361)[:-1])))
        to_clutch = ratios[shaft] ** 2  # inertias at the crank, taken to the clutch shaft
        engagement = engage(drive_side / to_clutch, crank_speed * ratios[shaft], (driven_side + linkage) / to_clutch,
                            0.0, rating.torque,
                            driving_torque=_motor_at_clutch(line, flywheel, crank_speed, table.clutch.motor_torque))

    stops: list[Stop] = []
    worst, braking, heating = None, None, None
    if table.brake is not None:
        braking = brake_rating(table)
        # the brake stops what the clutch (if any) leaves joined to the crank
        extra = _sides(line, shaft, fly_inertia)[1] if shaft is not None else line.shaft_inertia + fly_inertia
        at_shaft = n if line.brake_shaft is None else line.brake_shaft
        brake_at_crank = braking.torque * ratios[at_shaft]
        angles = table.brake.at or list(np.linspace(0.0, 2 * np.pi, 12, endpoint=False))
        for a in angles:
            stops.append(stop_machine(machine, extra, crank_speed, brake_at_crank, float(a)))
        worst = max(stops, key=lambda s: s.angle)
        if table.brake.heating is not None:
            try:
                heating = heating_of(table.brake.heating, brake_at_crank * worst.angle)
            except InputError as exc:
                raise ProblemFileError([("drivetrain.brake.heating", str(exc))]) from None

    stroke, stroke_failure = None, None
    if table.single_stroke is not None:
        assert rating is not None and braking is not None
        try:
            stroke = _single_stroke(table, line, machine, flywheel, fly_inertia, crank_speed, rating.torque,
                                    braking.torque)
        except ProblemFileError:
            raise
        except InputError as exc:  # the file is valid (check said so); this design cannot make its single stroke
            stroke_failure = str(exc).rstrip(".")
    duty = None
    if stroke is not None and flywheel is not None and hasattr(flywheel.drive, "rated_torque"):
        assert table.clutch is not None
        duty = single_stroke_duty(stroke, flywheel.drive, table.clutch.strokes_per_minute)
    gears = tuple(check_teeth(k, s.teeth, s.ratio, shaft_torques, ratios, crank_speed)
                  for k, s in enumerate(table.stages) if s.teeth is not None)
    done = DriveTrainRun(train, np.asarray(forces.kinematics.crank_angle, dtype=float), shaft_torques, shaft,
                         engagement, tuple(stops), worst, crank_speed, stroke, duty, rating, braking, heating,
                         braking.torque if braking is not None else None, gears,
                         _check_shafts(table, shaft_torques, crank_speed * ratios), stroke_failure)
    done_outcome = _outcome(done, table)
    if overloaded:
        done_outcome = replace(done_outcome, failed_checks=(*overloaded, *done_outcome.failed_checks))
    return done_outcome


def _check_shafts(table: DriveTrainSpec, shaft_torques: np.ndarray, speeds: np.ndarray) -> tuple[ShaftCheck, ...]:
    checks = []
    for i, s in enumerate(table.shafts):
        try:
            checks.append(check_shaft(s, shaft_torques[s.shaft], float(speeds[s.shaft])))
        except InputError as exc:
            raise ProblemFileError([(f"drivetrain.shafts[{i}]", str(exc))]) from None
    return tuple(checks)


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


def _motor_at_clutch(line: DriveLine, flywheel: FlywheelRun | None, crank_speed: float, constant: float) -> float:
    """The motor's torque [N·m] on the clutch shaft while the clutch slips: that of ``[flywheel.motor]`` at the
    running speed, through the stages before the clutch only (motor torque × ratio × their efficiency); else the
    clutch table's constant ``motor_torque``."""
    drive = flywheel.drive if flywheel is not None else None
    if drive is None or not hasattr(drive, "torque_at") or line.clutch_shaft is None:
        return float(constant)
    at_crank = float(np.ravel(drive.torque_at(crank_speed))[0])  # motor × ratio × every stage's efficiency
    c = line.clutch_shaft
    after = line.efficiency_between(c, line.crank)  # the stages after the clutch do not act while it slips
    return at_crank / line.ratio(c) / (after if at_crank >= 0 else 1.0 / after)


def _sides(line: DriveLine, clutch: int, fly_inertia: float) -> tuple[float, float]:
    """The inertias [kg·m², at the crank] on the clutch's driving side (shafts 0 .. clutch) and on its driven
    side (the shafts after it, the linkage not included), the flywheel ``fly_inertia`` (at the crank) on the side
    of its shaft."""
    drive = line.inertia_between(0, clutch)
    driven = line.inertia_between(clutch + 1, line.crank)
    if line.flywheel_shaft <= clutch:
        return drive + fly_inertia, driven
    return drive, driven + fly_inertia


def _single_stroke(table: DriveTrainSpec, line: DriveLine, machine: Any, flywheel: FlywheelRun | None,
                   fly_inertia: float, crank_speed: float, slip_torque: float, brake_torque: float) -> Any:
    """The single stroke of ``[drivetrain.single_stroke]``, everything reduced to the crank shaft: the motor of
    ``[flywheel.motor]`` (or the clutch table's constant ``motor_torque``) on the driving side."""
    assert table.clutch is not None and table.brake is not None and table.single_stroke is not None
    assert line.clutch_shaft is not None
    shaft = line.clutch_shaft
    ratios = line.train.speed_ratios
    drive_side, driven_side = _sides(line, shaft, fly_inertia)
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
    at_brake = line.crank if line.brake_shaft is None else line.brake_shaft
    return single_stroke(machine, motor, drive_inertia=drive_side, driven_inertia=driven_side,
                         speed=idle_speed(motor, crank_speed),
                         slip_torque=float(slip_torque * ratios[shaft]),
                         brake_torque=float(brake_torque * ratios[at_brake]),
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
    gear_values, gear_labels = gear_results(done.gear_checks)
    scalars.update(gear_values)
    labels.update(gear_labels)
    for g in done.gear_checks:
        failed += g.failures()
    shaft_values, shaft_labels = shaft_results(done.shaft_checks)
    scalars.update(shaft_values)
    labels.update(shaft_labels)
    for c in done.shaft_checks:
        failed += c.failures()
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
        scalars.update(_clutch_scalars(done, table))
    s = done.worst_stop
    if s is not None:
        assert table.brake is not None
        scalars.update({"brake.stop_time": s.time, "brake.stop_angle": s.angle})
        brake_scalars, brake_failed = _brake_scalars(done, table)
        scalars.update(brake_scalars)
        failed += brake_failed
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
    summary = tuple(key for key in scalars if not key.startswith(("drivetrain.shaft_", "drivetrain.stage_"))) + \
        ("drivetrain.shaft_0.torque.max_abs",)
    if done.single_stroke_failure is not None:
        failed.append(f"single stroke: {done.single_stroke_failure}")
    estimated = [st for st in done.stops if st.estimated]
    warnings = (f"brake: {len(estimated)} of the {len(done.stops)} stops last longer than the turns integrated; "
                "their rest is found by the energy balance from there (an upper bound on the angle and time)",
                ) if estimated else ()
    return Outcome(results=done, scalars=scalars, labels=labels, series=series, summary=summary,
                   warnings=warnings, failed_checks=tuple(failed))


def _clutch_scalars(done: DriveTrainRun, table: DriveTrainSpec) -> dict[str, float]:
    e, rating = done.engagement, done.clutch_rating
    assert e is not None and rating is not None and table.clutch is not None
    out = {"clutch.torque": rating.torque, "clutch.driven_acceleration": e.driven_acceleration,
           "clutch.driving_deceleration": e.driving_deceleration}
    geometry = table.clutch.geometry
    if geometry is not None and geometry.kind == "centrifugal":
        out["clutch.engagement_speed"] = rating.engagement_speed
    elif geometry is not None:
        out.update({"clutch.axial_force": rating.force, "clutch.max_pressure": rating.max_pressure})
    return out


def _brake_scalars(done: DriveTrainRun, table: DriveTrainSpec) -> tuple[dict[str, float], list[str]]:
    brake, rating, heating = table.brake, done.brake_rating, done.heating
    assert brake is not None and rating is not None and done.worst_stop is not None
    out = {"brake.torque": rating.torque}
    failed: list[str] = []
    if brake.geometry is not None:
        out.update({"brake.lever_force": rating.lever_force, "brake.torque_reverse": rating.torque_reverse})
        if brake.geometry.kind == "internal_shoe":
            out["brake.max_pressure"] = rating.max_pressure
            limit = brake.geometry.max_allowed_pressure
            if limit is not None and rating.max_pressure > limit:
                failed.append(f"brake: the lining pressure {rating.max_pressure / 1e6:.4g} MPa exceeds "
                              f"brake.geometry.max_allowed_pressure = {limit / 1e6:.4g} MPa")
    if heating is not None:
        assert brake.heating is not None
        out.update({"brake.stop_energy": heating.rise_per_stop * brake.heating.mass * brake.heating.specific_heat,
                    "brake.temperature_rise": heating.rise_per_stop,
                    "brake.temperature_rise_steady": heating.steady_peak_rise})
        limit = brake.heating.max_temperature_rise
        if limit is not None and heating.steady_peak_rise > limit:
            failed.append(f"brake: the drum heats {heating.steady_peak_rise:.4g} K above its surroundings "
                          f"{'after many stops' if brake.heating.stops_per_hour else 'in one stop'}, more than "
                          f"brake.heating.max_temperature_rise = {limit:.4g} K")
    return out, failed


LABELS = {
    "drivetrain.ratio": Label("Drive train: motor speed / crank speed", "", over="scalar", better="none"),
    "drivetrain.efficiency": Label("Drive train: efficiency", "", over="scalar", better="higher"),
    "drivetrain.reflected_inertia": Label("Drive train: shaft inertias reflected to the crank", "kg*m^2",
                                          over="scalar", better="none"),
    "clutch.slip_time": Label("Clutch: slip time of an engagement", "s", over="scalar", better="lower"),
    "clutch.energy": Label("Clutch: energy dissipated per engagement", "J", over="scalar", better="lower"),
    "clutch.crank_speed_after": Label("Clutch: crank speed when the slip ends", "rad/s", "rpm", over="scalar",
                                      better="higher"),
    "clutch.speed_drop": Label("Clutch: relative speed drop of the driving side (fraction)", "", over="scalar",
                               better="lower"),
    "clutch.heat_power": Label("Clutch: mean heat power at the stroke rate", "W", over="scalar", better="lower"),
    "clutch.torque": Label("Clutch: slip torque on its shaft", "N*m", over="scalar", better="none"),
    "clutch.driven_acceleration": Label("Clutch: driven side's acceleration while the clutch slips (at the clutch "
                                        "shaft)", "rad/s^2", over="scalar", better="none"),
    "clutch.driving_deceleration": Label("Clutch: driving side's deceleration while the clutch slips (at the "
                                         "clutch shaft)", "rad/s^2", over="scalar", better="none"),
    "clutch.axial_force": Label("Clutch: axial force on the friction faces", "N", over="scalar", better="lower"),
    "clutch.max_pressure": Label("Clutch: largest pressure on the friction faces", "Pa", "MPa", over="scalar",
                                 better="lower"),
    "clutch.engagement_speed": Label("Clutch: speed at which the centrifugal shoes touch the drum", "rad/s", "rpm",
                                     over="scalar", better="none"),
    "brake.torque": Label("Brake: braking torque on its shaft", "N*m", over="scalar", better="higher"),
    "brake.lever_force": Label("Brake: actuating force at the lever (or on each shoe or pad)", "N", over="scalar",
                               better="lower"),
    "brake.torque_reverse": Label("Brake: braking torque with the drum turning the other way", "N*m", over="scalar",
                                  better="higher"),
    "brake.max_pressure": Label("Brake: largest lining pressure of the self-energising shoe", "Pa", "MPa",
                                over="scalar", better="lower"),
    "brake.stop_energy": Label("Brake: energy turned into heat by the worst stop", "J", over="scalar", better="lower"),
    "brake.temperature_rise": Label("Brake: temperature rise of the drum per stop", "K", over="scalar", better="lower"),
    "brake.temperature_rise_steady": Label("Brake: largest temperature rise of the drum after many stops", "K",
                                           over="scalar", better="lower"),
    "brake.stop_time": Label("Brake: stopping time, worst application angle", "s", over="scalar", better="lower"),
    "brake.stop_angle": Label("Brake: stopping angle of the crank, worst application angle", "rad", "deg",
                              over="scalar", better="lower"),
    "single_stroke.brake_angle": Label("Single stroke: crank angle where the clutch opens and the brake closes",
                                       "rad", "deg", over="scalar", better="none"),
    "single_stroke.overrun": Label("Single stroke: crank at rest past the start angle (negative: short of it)",
                                   "rad", "deg", over="scalar", better="target"),
    "single_stroke.slip_time": Label("Single stroke: clutch slip time", "s", over="scalar", better="lower"),
    "single_stroke.stroke_time": Label("Single stroke: time from clutch in to the crank at rest", "s", over="scalar",
                                       better="lower"),
    "single_stroke.stop_time": Label("Single stroke: stopping time after the brake closes", "s", over="scalar",
                                     better="lower"),
    "single_stroke.stop_angle": Label("Single stroke: stopping angle after the brake closes", "rad", "deg",
                                      over="scalar", better="lower"),
    "single_stroke.clutch_energy": Label("Single stroke: energy dissipated in the clutch", "J", over="scalar",
                                         better="lower"),
    "single_stroke.brake_energy": Label("Single stroke: energy dissipated in the brake", "J", over="scalar",
                                        better="lower"),
    "single_stroke.speed_drop": Label("Single stroke: largest speed drop of the flywheel side, relative to its "
                                      "speed between strokes", "", over="scalar", better="lower"),
    "single_stroke.recovery_time": Label("Single stroke: time for the motor to bring the flywheel back after the "
                                         "stop", "s", over="scalar", better="lower"),
    "single_stroke.strokes_per_minute": Label("Single stroke: most strokes a minute the drive can make", "",
                                              over="scalar", better="higher"),
    "single_stroke.motor_rms_torque": Label("Single stroke: RMS of the motor's torque (at the crank) over a period "
                                            "of strokes at the rate asked for", "N*m", over="time_rms", better="lower"),
    "single_stroke.motor_load": Label("Single stroke: motor's RMS torque / its rated S1 torque", "", over="scalar",
                                      better="lower"),
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
