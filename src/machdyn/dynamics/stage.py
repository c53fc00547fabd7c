"""The ``[flywheel]`` capability: a flywheel (given, or sized for a coefficient of speed fluctuation), the drive
(``[flywheel.motor]``), the periodic steady state at the real speed, the start-up and the forces at the real speed.

The crank's nominal speed is the problem's ``[drive] speed`` (the table that also sets the crank positions of the
constant-speed analysis); ``[flywheel]`` adds the machine's dynamics under a real drive.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Literal

import numpy as np
from pydantic import Field, model_validator

from ..errors import InputError, ProblemFileError
from ..notebook import ShownInNotebook
from ..pipeline import Capability, Outcome, StageContext
from ..problem.fields import (
    AngularVelocity,
    Density,
    Inertia,
    LinearDamping,
    Power,
    Pressure,
    RotaryDamping,
    Stress,
    Torque,
)
from ..problem.fields import PositiveVelocity as Speed
from ..problem.fields import Volume as Displacement
from ..problem.fields import VolumeFlow as Flow
from ..problem.schema import Spec
from ..results.labels import Label
from .contributions import ReducedMachineSource, ShaftContribution
from .drive_choice import choose_drive, duty_of, overloaded
from .driveline import DriveLine
from .driveline_file import line_of, line_problems, motor_on_line
from .drives import InductionMotor
from .equivalent import LinearDamper, RotaryDamper, equivalent_machine
from .flywheel import disc_flywheel, rim_flywheel, rim_speed_limit, size_flywheel
from .motion import start_up
from .motor_flywheel import flywheel_for_drive
from .realspeed import forces_at_speed
from .simulate import NotSettledError, steady_state


class MotorTable(Spec):
    """``[flywheel.motor]``: the drive. ``kind`` = "select" picks an induction motor from the IEC 60072-1
    ratings; "induction" takes its rated data; "constant_torque" balances the mean load at the nominal speed;
    "hydraulic" a hydraulic motor fed with a constant flow."""

    kind: Literal["select", "induction", "constant_torque", "hydraulic"] = "select"
    rated_power: Power | None = None
    rated_speed: AngularVelocity | None = None
    synchronous_speed: AngularVelocity = 50.0 * np.pi  # 1500 rpm
    breakdown_ratio: float = Field(2.5, gt=1.0, allow_inf_nan=False)
    rated_slip: float = Field(0.04, gt=0.0, lt=1.0, allow_inf_nan=False)
    ratio: float | None = Field(None, gt=0.0, allow_inf_nan=False)
    efficiency: float = Field(1.0, gt=0.0, le=1.0, allow_inf_nan=False)
    rotor_inertia: Inertia = 0.0
    displacement: Displacement | None = None
    flow: Flow | None = None
    pressure_limit: Pressure | None = None
    volumetric_efficiency: float = Field(0.95, gt=0.0, lt=1.0, allow_inf_nan=False)
    mechanical_efficiency: float = Field(0.9, gt=0.0, le=1.0, allow_inf_nan=False)
    # duty of an induction motor (IEC 60034-1): S1 continuous, S3 intermittent, S6 with intermittent load
    duty: Literal["S1", "S3", "S6"] = "S1"
    cyclic_duration_factor: float | None = Field(None, gt=0.0, le=1.0, allow_inf_nan=False)
    no_load_torque: Torque = 0.0  # S6: the torque at the crank in the no-load periods
    rest_cooling: float = Field(1.0, gt=0.0, le=1.0, allow_inf_nan=False)  # S3: cooling at rest / running
    starts_per_hour: float | None = Field(None, ge=0.0, allow_inf_nan=False)

    @model_validator(mode="after")
    def _complete(self):
        if self.duty != "S1" and self.cyclic_duration_factor is None:
            raise ValueError(f"duty {self.duty} needs cyclic_duration_factor (the share of the cycle under load, "
                             "in (0, 1])")
        if self.kind in ("constant_torque", "hydraulic") and (self.duty != "S1" or self.starts_per_hour is not None):
            raise ValueError(f"duty and starts_per_hour apply to an induction motor (kind = \"select\" or "
                             f"\"induction\"); got kind = \"{self.kind}\"")
        if self.no_load_torque < 0:
            raise ValueError(f"no_load_torque must be >= 0; got {self.no_load_torque:g} N*m")
        if self.kind == "induction" and (self.rated_power is None or self.rated_speed is None):
            raise ValueError("an induction motor needs rated_power and rated_speed")
        if self.kind == "hydraulic" and None in (self.displacement, self.flow, self.pressure_limit):
            raise ValueError("a hydraulic motor needs displacement, flow and pressure_limit")
        return self


class DamperTable(Spec):
    """``[[flywheel.dampers]]``: a viscous load. Rotary on ``body`` (coefficient in N*m*s/rad), or linear between
    ``point_1`` and ``point_2`` (``linear_coefficient`` in N*s/m)."""

    name: str
    body: str | None = None
    relative_to: str = "ground"
    coefficient: RotaryDamping | None = None
    point_1: str | None = None
    point_2: str | None = None
    linear_coefficient: LinearDamping | None = None

    @model_validator(mode="after")
    def _one_kind(self):
        rotary = self.body is not None and self.coefficient is not None
        linear = None not in (self.point_1, self.point_2, self.linear_coefficient)
        if rotary == linear:
            raise ValueError("give either body and coefficient (rotary) or point_1, point_2 and linear_coefficient "
                             "(linear)")
        return self


class FlywheelTable(Spec):
    """``[flywheel]``: either ``delta`` (the coefficient of speed fluctuation to size for) or ``inertia`` (the
    flywheel's own moment of inertia about its shaft, ``shaft``)."""

    delta: float | None = Field(None, gt=0.0, lt=1.0, allow_inf_nan=False)
    inertia: Inertia | None = None
    method: Literal["exact", "classic"] = "exact"
    # size for a constant-torque drive (the classic assumption) or for the chosen motor's torque-speed curve
    size_for: Literal["constant_torque", "motor"] = "constant_torque"
    # the flywheel's shaft: a shaft of [drivetrain] by name or number (default: the crank shaft); without a
    # drive train, a faster shaft is given by its speed / crank speed, speed_ratio
    shaft: int | str | None = None
    speed_ratio: float = Field(1.0, gt=0.0, allow_inf_nan=False)
    positions: int = Field(720, ge=16, le=100_000, strict=True)
    shape: Literal["disc", "rim"] = "disc"
    width_ratio: float = Field(0.2, gt=0.0, allow_inf_nan=False)
    width_to_thickness: float = Field(2.0, gt=0.0, allow_inf_nan=False)
    density: Density = 7850.0
    allowable_stress: Stress = 100e6
    rim_speed_limit: Speed | None = None
    rim_speed: Speed | None = None  # mean rim speed of a rim design (default 0.8 x the limit)
    start_up: bool = Field(True, strict=True)
    motor: MotorTable = MotorTable.model_validate({})
    dampers: list[DamperTable] = []

    @model_validator(mode="after")
    def _one_of(self):
        if (self.delta is None) == (self.inertia is None):
            raise ValueError("give exactly one of delta (to size the flywheel) and inertia")
        return self


LABELS = {
    "flywheel.inertia": Label("Flywheel: moment of inertia, referred to the crank", "kg*m^2", over="scalar",
                              better="lower"),
    "flywheel.own_inertia": Label("Flywheel: moment of inertia about its own shaft", "kg*m^2", over="scalar",
                                  better="lower"),
    "flywheel.shaft_speed_ratio": Label("Flywheel: its shaft's speed / crank speed", "", over="scalar", better="none"),
    "flywheel.line_inertia": Label("Drive line: shaft inertias referred to the crank (motor rotor included), "
                                   "besides the flywheel", "kg*m^2", over="scalar", better="none"),
    "flywheel.inertia_exact": Label("Flywheel sized by the energy-mass (Wittenbauer) method", "kg*m^2", over="scalar",
                                    better="lower"),
    "flywheel.inertia_classic": Label("Flywheel sized by ΔE/(ω²δ) less the mean reduced inertia", "kg*m^2",
                                      over="scalar", better="lower"),
    "flywheel.method_difference": Label("Flywheel: classic / exact − 1", "", over="scalar", better="none"),
    "flywheel.inertia_constant_torque": Label("Flywheel sized for a constant-torque drive", "kg*m^2", over="scalar",
                                              better="lower"),
    "flywheel.inertia_for_motor": Label("Flywheel sized for the chosen motor's torque-speed curve", "kg*m^2",
                                        over="scalar", better="lower"),
    "flywheel.motor_slip_saving": Label("Flywheel: saving by sizing for the motor's slip (1 − motor / constant "
                                        "torque)", "", over="scalar", better="higher"),
    "flywheel.sizing_energy_fluctuation": Label("Flywheel sizing: maximum fluctuation of energy ΔE", "J",
                                                over="cycle", better="lower"),
    "flywheel.target_delta": Label("Coefficient of speed fluctuation: target", "", over="scalar", better="none"),
    "flywheel.delta": Label("Coefficient of speed fluctuation: simulated", "", over="cycle", better="lower"),
    "flywheel.mean_speed": Label("Crank speed: (max + min)/2, steady state", "rad/s", "rpm", over="cycle",
                                 better="none"),
    "flywheel.min_speed": Label("Crank speed: minimum, steady state", "rad/s", "rpm", over="min", better="none"),
    "flywheel.max_speed": Label("Crank speed: maximum, steady state", "rad/s", "rpm", over="max", better="none"),
    "flywheel.peak_drive_torque": Label("Drive torque at the crank: peak", "N*m", over="max_abs", better="lower"),
    "flywheel.rms_drive_torque": Label("Drive torque at the crank: RMS over time", "N*m", over="time_rms",
                                       better="lower"),
    "flywheel.energy_per_cycle": Label("Drive: energy per cycle", "J", over="cycle", better="lower"),
    "flywheel.mean_power": Label("Drive: mean power", "W", over="time_mean", better="lower"),
    "flywheel.time_to_steady": Label("Start-up: time to steady running (within 1 % of the speed)", "s", over="scalar",
                                     better="lower"),
    "flywheel.diameter": Label("Flywheel: outer diameter", "m", "mm", over="scalar", better="lower"),
    "flywheel.width": Label("Flywheel: width", "m", "mm", over="scalar", better="lower"),
    "flywheel.mass": Label("Flywheel: mass", "kg", over="scalar", better="lower"),
    "flywheel.rim_speed": Label("Flywheel: rim speed at the highest speed", "m/s", over="max", better="lower"),
    "flywheel.rim_speed_limit": Label("Flywheel: rim speed limit", "m/s", over="scalar", better="none"),
    "flywheel.motor_rated_power": Label("Motor: rated power", "W", "kW", over="scalar", better="lower"),
    "flywheel.motor_breakdown_torque": Label("Motor: breakdown torque at the crank", "N*m", over="scalar",
                                             better="none"),
    "flywheel.gear_ratio": Label("Motor: gear ratio (motor / crank speed)", "", over="scalar", better="none"),
    "flywheel.motor_rms_load": Label("Motor: RMS torque over the cycle / rated torque (duty S1)", "", over="time_rms",
                                     better="lower"),
    "flywheel.motor_duty_load": Label("Motor: equivalent torque of its duty (S1, S3 or S6) / rated torque", "",
                                      over="scalar", better="lower"),
    "flywheel.motor_duty_rated_torque": Label("Motor: torque it may carry while loaded in its duty, at the crank",
                                              "N*m", over="scalar", better="none"),
    "flywheel.motor_start_rotor_loss": Label("Motor: rotor loss of one start (run-up with the flywheel)", "J",
                                             over="scalar", better="lower"),
    "flywheel.motor_starts_per_hour": Label("Motor: starts per hour it stands (by the rotor heat of a start)", "",
                                            over="scalar", better="higher"),
    "flywheel.torque_peak_constant_speed": Label("Driving torque into the linkage: peak at constant speed", "N*m",
                                                 over="max_abs", better="lower"),
    "flywheel.torque_peak_real_speed": Label("Driving torque into the linkage: peak at the real speed", "N*m",
                                             over="max_abs", better="lower"),
    "flywheel.joint_force_change": Label("Largest change of a joint's peak force at the real speed", "",
                                         over="scalar", better="lower"),
}

SUMMARY = ("flywheel.inertia", "flywheel.own_inertia", "flywheel.shaft_speed_ratio", "flywheel.line_inertia",
           "flywheel.inertia_constant_torque", "flywheel.motor_slip_saving",
           "flywheel.target_delta", "flywheel.delta", "flywheel.method_difference",
           "flywheel.mean_speed", "flywheel.peak_drive_torque", "flywheel.mean_power", "flywheel.motor_rated_power",
           "flywheel.motor_rms_load", "flywheel.motor_duty_load", "flywheel.motor_starts_per_hour",
           "flywheel.time_to_steady", "flywheel.diameter", "flywheel.mass", "flywheel.rim_speed")


def speed_loads(table: FlywheelTable) -> tuple:
    out: list[Any] = []
    for d in table.dampers:
        if d.body is not None:
            out.append(RotaryDamper(d.name, d.body, float(d.coefficient or 0.0), d.relative_to))
        else:
            out.append(LinearDamper(d.name, str(d.point_1), str(d.point_2), float(d.linear_coefficient or 0.0)))
    return tuple(out)


def check_flywheel(problem: Any, table: FlywheelTable, source: str | None = None) -> list[tuple[str, str]]:
    """The validations of ``[flywheel]`` that need more than its schema, so that ``check`` and ``run`` agree: a
    crank turning forwards, and a motor whose data describe a real induction motor (its drive object builds)."""
    found: list[tuple[str, str]] = list(line_problems(problem, table))
    drive = getattr(problem, "drive", None)  # a cam file turns its camshaft at the cam's own speed
    speed = float(drive.speed) if drive is not None else 1.0
    if not speed > 0:
        found.append(("drive.speed", f"must be > 0 for [flywheel] (the crank turns counter-clockwise); got "
                                     f"{speed:g} rad/s"))
    motor = table.motor
    if motor.kind in ("select", "induction") and not motor.synchronous_speed > 0:
        found.append(("flywheel.motor.synchronous_speed", f"must be > 0 rad/s; got {motor.synchronous_speed:g} rad/s"))
    elif motor.kind == "induction":
        try:
            InductionMotor(float(motor.rated_power or 0.0), float(motor.rated_speed or 0.0), motor.synchronous_speed,
                           motor.breakdown_ratio, motor.ratio or 1.0, motor.efficiency, motor.rotor_inertia)
        except InputError as exc:
            text = str(exc).rstrip(".")
            found.append(("flywheel.motor", text[:1].lower() + text[1:]))
    return found


#: The largest relative departure of the steady mean crank speed from the nominal ``[drive] speed`` accepted: the
#: constant-speed analysis (joint forces, driving torque, shaking) is made at the nominal speed, and its inertia
#: loads grow with the square of the speed (1.2^2 = 1.44 at the limit).
SPEED_TOLERANCE = 0.2


def _off_speed(steady, nominal: float) -> list[str]:
    """A failed check when the machine under its drive settles far from its nominal speed (a load that drives it,
    a drive too slow or too fast for it): the results at the nominal speed would not describe it."""
    mean = float(steady.mean_speed)
    if abs(mean / nominal - 1.0) <= SPEED_TOLERANCE:
        return []
    why = ("a load drives the machine faster than its drive (a process load of the wrong sign or window?)"
           if mean > nominal else "the drive does not hold the machine near its nominal speed")
    rpm = 30.0 / np.pi
    return [f"the steady mean crank speed {mean * rpm:.4g} rpm is {mean / nominal:.3g} times the nominal "
            f"{nominal * rpm:.4g} rpm of [drive] (more than {100 * SPEED_TOLERANCE:g} % off): {why}, and the "
            "constant-speed results at the nominal speed do not describe it"]


def run_flywheel(ctx: StageContext) -> Outcome:
    """The stage: size or take the flywheel, choose or take the drive, steady state, start-up, real-speed forces."""
    table: FlywheelTable = ctx.table
    mech = ctx.mechanism
    problems = line_problems(ctx.problem, table)
    if problems:
        raise ProblemFileError(problems)
    line = line_of(ctx.problem, table)
    added = line.shaft_inertia  # every shaft of the drive line, at the crank: it turns with the flywheel
    motor_table = motor_on_line(table.motor, line)
    cam = ctx.result_of("cam", ReducedMachineSource)
    if cam is not None:  # a cam machine: the camshaft is the crank, its reduced machine comes from the cam
        speed = float(cam.speed)
        machine = cam.machine(table.positions)
        linked = ctx.result_of("follower_linkage", ShaftContribution)
        if linked is not None:  # the linkage the follower drives adds its reduced quantities at the camshaft
            machine = linked.added_to(machine, table.positions)
    else:
        speed = float(ctx.problem.drive.speed)
        if not speed > 0:
            raise ProblemFileError([("drive.speed", f"must be > 0 for [flywheel] (the crank turns "
                                                    f"counter-clockwise); got {speed:g} rad/s")])
        machine = equivalent_machine(mech, table.positions, speed_loads=speed_loads(table))
        shaft_cam = ctx.result_of("shaft_cam", ShaftContribution)
        if shaft_cam is not None:  # a cam on the crank shaft: its reduced quantities add to the linkage's
            machine = shaft_cam.added_to(machine, table.positions)
    target = table.delta if table.delta is not None else 0.02
    sizing = size_flywheel(machine, speed, target)
    if table.inertia is not None:
        flywheel = line.at_crank(float(table.inertia), line.flywheel_shaft)
    else:
        # the sizing asks for a constant inertia at the crank; the drive line's shafts give part of it
        flywheel = max(float(sizing.exact[0] if table.method == "exact" else sizing.classic[0]) - added, 0.0)
    mean_torque = float(sizing.drive_torque[0])
    size_failed = None
    try:
        drive = choose_drive(motor_table, machine, flywheel + added, speed, mean_torque)
        for_motor = None
        if table.delta is not None and table.size_for == "motor" and table.motor.kind != "constant_torque" \
                and flywheel > 0:
            try:
                for_motor = flywheel_for_drive(machine, drive, table.delta, flywheel + added, added=added)
                flywheel = for_motor.inertia
            except InputError as exc:
                # a design outcome, not bad input: the file is valid, no flywheel meets delta with this motor;
                # the constant-torque flywheel is kept and the design fails its check
                size_failed = f"flywheel sized for the motor (size_for = \"motor\"): {str(exc).rstrip('.')}"
        steady = steady_state(machine, drive, flywheel + added,
                              mean_speed=speed if table.motor.kind == "constant_torque" else None)
    except ProblemFileError:
        raise
    except InputError as exc:
        if not str(exc).startswith(_CANNOT_CARRY):
            raise
        # a drive too small for the machine is a design that fails, not bad input: say so with the figures
        return Outcome(results=None, scalars={"flywheel.inertia": flywheel}, summary=("flywheel.inertia",),
                       failed_checks=(str(exc).rstrip("."),))
    warnings = list(steady.warnings)
    failed: list[str] = [*steady.warnings, *overloaded(drive, steady, table.motor), *_off_speed(steady, speed)]
    if size_failed is not None:
        failed.append(size_failed)
    run = None
    if table.start_up and table.motor.kind != "constant_torque":
        try:
            run = start_up(machine, drive, flywheel + added, steady=steady)
        except NotSettledError as exc:
            warnings.append(str(exc))
        except ValueError as exc:  # the drive cannot start the machine or it rolls back: a design check fails
            failed.append(str(exc))
    real = forces_at_speed(steady) if cam is None else None
    values: dict[str, Any] = {
        "flywheel.inertia": flywheel,
        "flywheel.own_inertia": line.about_shaft(flywheel, line.flywheel_shaft),
        "flywheel.shaft_speed_ratio": line.ratio(line.flywheel_shaft),
        "flywheel.sizing_energy_fluctuation": float(sizing.energy_fluctuation[0]),
        "flywheel.delta": float(steady.delta),
        "flywheel.mean_speed": float(steady.mean_speed),
        "flywheel.min_speed": float(np.min(steady.omega)),
        "flywheel.max_speed": float(np.max(steady.omega)),
        "flywheel.peak_drive_torque": float(steady.peak_drive_torque),
        "flywheel.rms_drive_torque": float(steady.rms_drive_torque),
        "flywheel.energy_per_cycle": float(steady.energy_per_cycle),
        "flywheel.mean_power": float(steady.mean_power),
    }
    if real is not None:
        values |= {"flywheel.torque_peak_constant_speed": float(real.torque_peak[1]),
                   "flywheel.torque_peak_real_speed": float(real.torque_peak[0]),
                   "flywheel.joint_force_change": real.largest_change()[1]}
    if table.delta is not None:
        values |= {"flywheel.target_delta": table.delta, "flywheel.inertia_exact": float(sizing.exact[0]),
                   "flywheel.inertia_classic": float(sizing.classic[0]),
                   "flywheel.method_difference": float(sizing.difference[0])}
        if steady.delta > table.delta * 1.05:
            failed.append(f"simulated coefficient of speed fluctuation {float(steady.delta):.4g} exceeds the target "
                          f"{table.delta:g} by more than 5 %")
    if for_motor is not None:
        values |= {"flywheel.inertia_constant_torque": for_motor.constant_torque,
                   "flywheel.inertia_for_motor": for_motor.inertia,
                   "flywheel.motor_slip_saving": for_motor.saving}
    if line.declared:
        values["flywheel.line_inertia"] = added
    if not line.declared and table.inertia is not None and line.flywheel_shaft != line.crank:
        r = line.ratio(line.flywheel_shaft)
        warnings.append(f"flywheel.inertia = {float(table.inertia):.6g} kg*m^2 is the flywheel's own, about its shaft "
                        f"turning flywheel.speed_ratio = {r:g} times the crank: {flywheel:.6g} kg*m^2 at the crank. "
                        f"(Earlier versions took it as referred to the crank; for that meaning give "
                        f"{float(table.inertia) / r**2:.6g} kg*m^2.)")
    if run is not None:
        values["flywheel.time_to_steady"] = float(run.time_to_steady)
    duty = None
    if hasattr(drive, "breakdown_torque") and drive.name == "induction motor":
        values |= {"flywheel.motor_rated_power": float(drive.rated_power),
                   "flywheel.motor_breakdown_torque": float(drive.breakdown_torque),
                   "flywheel.gear_ratio": float(drive.ratio),
                   "flywheel.motor_rms_load": float(steady.rms_drive_torque)
                   / float(np.max(drive.rated_torque * drive.ratio * drive.efficiency))}
        duty = duty_of(drive, steady, motor_table, run)
        values |= {"flywheel.motor_duty_load": duty.load_ratio,
                   "flywheel.motor_duty_rated_torque": duty.rated_for_duty}
        if run is not None and np.isfinite(duty.starts_allowed):
            values |= {"flywheel.motor_start_rotor_loss": duty.start_loss,
                       "flywheel.motor_starts_per_hour": duty.starts_allowed}
        elif table.motor.starts_per_hour is not None:
            warnings.append("flywheel.motor.starts_per_hour is not checked: the start-up was not simulated "
                            "([flywheel] start_up = false, or it did not settle)")
        failed += duty.too_many_starts()
    part = None
    if flywheel > 0:
        limit = table.rim_speed_limit or rim_speed_limit(table.allowable_stress, table.density, table.shape)
        # on a shaft turning i times the crank, the part carries J / i^2 at i times the speed
        i = line.ratio(line.flywheel_shaft)
        wmax = float(np.max(steady.omega)) * i
        own = line.about_shaft(flywheel, line.flywheel_shaft)
        if table.shape == "disc":
            part = disc_flywheel(own, wmax, width_ratio=table.width_ratio, density=table.density,
                                 rim_speed_limit=limit)
        else:
            part = rim_flywheel(own, float(steady.mean_speed) * i, wmax, rim_speed=table.rim_speed or 0.8 * limit,
                                width_to_thickness=table.width_to_thickness, density=table.density,
                                rim_speed_limit=limit)
        values |= {"flywheel.diameter": part.diameter, "flywheel.width": part.width, "flywheel.mass": part.mass,
                   "flywheel.rim_speed": part.rim_speed, "flywheel.rim_speed_limit": part.rim_speed_limit}
        if not part.within_limit:
            failed.append(f"flywheel rim speed {part.rim_speed:.4g} m/s exceeds the limit {part.rim_speed_limit:.4g} "
                          "m/s")
    result = FlywheelRun(table, machine, sizing, drive, flywheel, steady, run, real, part, duty, line)
    series = {"flywheel_cycle": _cycle_columns(result)}
    if run is not None:
        tr = run.trajectory
        series["start_up"] = {"time": (tr.t, "s"), "crank_angle": (tr.phi, "rad"), "speed": (tr.omega, "rad/s"),
                              "drive_torque": (tr.drive_torque, "N*m")}
    present = tuple(k for k in SUMMARY if k in values)
    return Outcome(results=result, scalars=values, series=series, summary=present, warnings=tuple(warnings),
                   failed_checks=tuple(failed))


#: the starts of the messages of :func:`~machdyn.dynamics.simulate.steady_state` for a drive too weak for the load:
#: one that cannot carry its mean load, and one under which the machine stalls (or creeps near a stall) in the
#: cycle, e.g. against a damper; both are designs that fail (exit 3), never bad input, as ``check`` cannot find them
#: without the simulation
_CANNOT_CARRY = ("The drive cannot carry the load", "No standard motor up to", "The machine stalls",
                 "The machine nearly stalls")


def _cycle_columns(r) -> dict[str, tuple[Any, str]]:
    s = r.steady
    out = {
        "crank_angle": (s.phi, "rad"),
        "reduced_inertia": (r.machine.inertia(s.phi), "kg*m^2"),
        "load_moment": (s.load_moment, "N*m"),
        "speed": (s.omega, "rad/s"),
        "acceleration": (s.acceleration, "rad/s^2"),
        "time": (s.time, "s"),
        "drive_torque": (s.drive_torque, "N*m"),
    }
    if r.real is not None:  # a linkage's kinetostatics at the real speed (a cam machine has none)
        out["linkage_torque_real_speed"] = (r.real.real.driving_torque, "N*m")
        out["linkage_torque_constant_speed"] = (r.real.constant.driving_torque, "N*m")
    return out


@dataclass(frozen=True)
class FlywheelRun(ShownInNotebook):
    """Everything the ``[flywheel]`` stage computed (SI), for the report and the Python API."""

    table: Any
    machine: Any
    sizing: Any
    drive: Any
    flywheel: float
    steady: Any
    start_up: Any
    real: Any
    part: Any
    duty: Any = None  # the induction motor's duty check (machdyn.dynamics.duty.DutyCheck), None for other drives
    line: DriveLine = DriveLine.crank_only()  # the drive line: flywheel[, shafts, clutch, brake] (flywheel at crank)

    @property
    def line_inertia(self) -> float:
        """The drive line's shafts referred to the crank [kg·m²]: the steady state counts them with the flywheel."""
        return self.line.shaft_inertia


CAPABILITY = Capability(
    table="flywheel",
    schema=FlywheelTable,
    run=run_flywheel,
    step="flywheel and drive",
    kinds=("mechanism", "rotary_screen", "cam"),
    labels=LABELS,
    report="machdyn.report.dynamics:sections",
    check=check_flywheel,
    after=("shaft_cam", "follower_linkage"),
    result_type=FlywheelRun,
)
