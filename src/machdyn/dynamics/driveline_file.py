"""The drive line of a problem file: read once from ``[drivetrain]`` (stages, shaft inertias, clutch and brake
shafts) and ``[flywheel]`` (the flywheel's shaft and the motor), with every value given twice refused.

A value has one home:

- a stage's ratio and efficiency, and the inertia on each shaft: ``[[drivetrain.stages]]`` (the motor shaft's
  inertia, rotor and pulley: ``drivetrain.motor_inertia``);
- the motor's speed ratio and efficiency to the crank are then the product of the stages' — giving
  ``flywheel.motor.ratio`` or ``flywheel.motor.efficiency`` as well is refused, naming both fields;
- the flywheel's shaft: ``flywheel.shaft`` (a shaft's name or number); ``flywheel.speed_ratio`` is for a file
  with no ``[drivetrain]`` and is refused beside one;
- the flywheel's ``inertia`` is its own, about its shaft; the run refers it to the crank (J r²).

``check`` and ``run`` call :func:`line_problems` alike, so they agree on what is valid. The ``[drivetrain]`` table
is read by its field names (it belongs to the drive-train capability, which imports this package, not the other
way round).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .driveline import CRANK, MOTOR, DriveLine, DriveTrain, Stage


def shaft_names(drivetrain: Any) -> tuple[str, ...]:
    """A name per shaft: "motor", each stage's ``shaft`` name (or "shaft k"), "crank" for the last."""
    stages = list(drivetrain.stages)
    inner = [str(getattr(s, "shaft", "") or f"shaft {k + 1}") for k, s in enumerate(stages[:-1])]
    return (MOTOR, *inner, CRANK)


def resolve_shaft(value: int | str, drivetrain: Any) -> int:
    """The index of the shaft ``value`` names (a number 0 .. n, "motor", "crank", or a stage's ``shaft`` name);
    ValueError listing the names where none matches."""
    names = shaft_names(drivetrain)
    last = len(names) - 1
    if isinstance(value, bool):
        raise ValueError(f"must name a shaft; got {value!r}")
    if isinstance(value, int):
        if not 0 <= value <= last:
            raise ValueError(f"must be a shaft number 0 (the motor) to {last} (the crank); got {value}")
        return value
    aliases = {name: k for k, name in enumerate(names)}
    final = getattr(list(drivetrain.stages)[-1], "shaft", "")
    if final:
        aliases[str(final)] = last  # the last stage's output is the crank shaft, under either name
    if value in aliases:
        return aliases[value]
    known = ", ".join(f"{k} = \"{n}\"" for n, k in sorted(aliases.items(), key=lambda item: item[1]))
    raise ValueError(f"names no shaft of [drivetrain] (its shafts: {known}); got \"{value}\"")


def _train(drivetrain: Any, motor: Any) -> DriveTrain:
    stages = tuple(Stage(s.ratio, s.efficiency, s.kind, s.name, getattr(s, "torsional_stiffness", None),
                         float(getattr(s, "torsional_damping", 0.0))) for s in drivetrain.stages)
    rotor = float(drivetrain.motor_inertia)
    if "motor_inertia" not in drivetrain.model_fields_set and motor is not None:
        rotor = float(motor.rotor_inertia)  # given once, in [flywheel.motor]: the motor shaft's inertia
    return DriveTrain(stages, (rotor, *(float(s.inertia) for s in drivetrain.stages)))


def line_of(problem: Any, flywheel: Any = None) -> DriveLine:
    """The drive line of ``problem`` (with its ``[flywheel]`` table ``flywheel``, or None); assumes
    :func:`line_problems` found nothing."""
    drivetrain = getattr(problem, "drivetrain", None)
    if drivetrain is None:
        return DriveLine.crank_only(float(flywheel.speed_ratio) if flywheel is not None else 1.0)
    train = _train(drivetrain, flywheel.motor if flywheel is not None else None)
    n = len(train.stages)
    fly = n
    if flywheel is not None and flywheel.shaft is not None:
        fly = resolve_shaft(flywheel.shaft, drivetrain)
    clutch = brake = None
    if drivetrain.clutch is not None:
        clutch = n - 1 if drivetrain.clutch.shaft is None else resolve_shaft(drivetrain.clutch.shaft, drivetrain)
    if drivetrain.brake is not None:
        brake = n if drivetrain.brake.shaft is None else resolve_shaft(drivetrain.brake.shaft, drivetrain)
    return DriveLine(train, shaft_names(drivetrain), fly, clutch, brake)


def _product(values: list[float], sign: str) -> str:
    text = f" {sign} ".join(f"{v:g}" for v in values)
    return text if len(values) == 1 else f"{text} = {float(np.prod(values)):.6g}"


def line_problems(problem: Any, flywheel: Any) -> list[tuple[str, str]]:
    """Every value of the drive line given twice or naming no shaft, as (path, message) pairs: the message names
    both fields and says where the value belongs. Empty for a file without ``[flywheel]``."""
    if flywheel is None:
        return []
    drivetrain = getattr(problem, "drivetrain", None)
    given = flywheel.model_fields_set
    motor_given = flywheel.motor.model_fields_set
    found: list[tuple[str, str]] = []
    if drivetrain is None:
        if flywheel.shaft is not None and flywheel.shaft not in (CRANK, 0):
            found.append(("flywheel.shaft", f"names a shaft of [drivetrain], but the file has no [drivetrain]; got "
                                            f"{flywheel.shaft!r}. Without a drive train the flywheel is on the crank "
                                            "shaft, or on a shaft turning flywheel.speed_ratio times as fast"))
        elif flywheel.shaft is not None and float(flywheel.speed_ratio) != 1.0:
            found.append(("flywheel.shaft", f"flywheel.shaft = {flywheel.shaft!r} (the crank shaft) and "
                                            f"flywheel.speed_ratio = {flywheel.speed_ratio:g} both give the "
                                            "flywheel's shaft; give one of them"))
        return found
    ratios = [float(s.ratio) for s in drivetrain.stages]
    efficiencies = [float(s.efficiency) for s in drivetrain.stages]
    train_ratios = np.cumprod(ratios[::-1])[::-1]  # shafts 0 .. n-1 relative to the crank
    if "speed_ratio" in given:
        r = float(flywheel.speed_ratio)
        match = [k for k, v in enumerate([*train_ratios, 1.0]) if np.isclose(v, r, rtol=1e-6)]
        names = shaft_names(drivetrain)
        where = (f"name its shaft instead: flywheel.shaft = \"{names[match[-1]]}\" (the shaft turning {r:g} times "
                 "the crank)") if match else \
            (f"name its shaft instead with flywheel.shaft (no shaft turns {r:g} times the crank; they turn "
             f"{', '.join(f'{v:g}' for v in [*train_ratios, 1.0])} times as fast)")
        inertia = ""
        if flywheel.inertia is not None:
            inertia = (f"; flywheel.inertia is the flywheel's own, about that shaft: a value meant at the crank is "
                       f"divided by {r:g}² = {r * r:g} there")
        found.append(("flywheel.speed_ratio",
                      f"flywheel.speed_ratio = {r:g} and drivetrain.stages[*].ratio both give the speed of the "
                      f"flywheel's shaft; give it once: remove flywheel.speed_ratio and {where}{inertia}"))
    if flywheel.shaft is not None:
        try:
            resolve_shaft(flywheel.shaft, drivetrain)
        except ValueError as exc:
            found.append(("flywheel.shaft", str(exc)))
    if "ratio" in motor_given:
        found.append(("flywheel.motor.ratio",
                      f"flywheel.motor.ratio = {flywheel.motor.ratio:g} and drivetrain.stages[*].ratio "
                      f"({_product(ratios, '×')}) both give the motor's speed / crank speed; give it once: remove "
                      "flywheel.motor.ratio (the drive train's stages set it)"))
    if "efficiency" in motor_given:
        found.append(("flywheel.motor.efficiency",
                      f"flywheel.motor.efficiency = {flywheel.motor.efficiency:g} and drivetrain.stages[*].efficiency "
                      f"({_product(efficiencies, '×')}) both give the efficiency from the motor to the crank; give "
                      "it once: remove flywheel.motor.efficiency (each stage's efficiency belongs to its stage)"))
    clutch = drivetrain.clutch
    if clutch is not None and "motor_torque" in clutch.model_fields_set:
        found.append(("drivetrain.clutch.motor_torque",
                      f"drivetrain.clutch.motor_torque = {clutch.motor_torque:g} N*m and [flywheel.motor] both give "
                      "the motor's torque; give it once: remove drivetrain.clutch.motor_torque (the clutch and the "
                      "single stroke take the torque of the [flywheel.motor] motor)"))
    if "rotor_inertia" in motor_given and "motor_inertia" in drivetrain.model_fields_set:
        found.append(("flywheel.motor.rotor_inertia",
                      f"flywheel.motor.rotor_inertia = {flywheel.motor.rotor_inertia:g} kg*m^2 and "
                      f"drivetrain.motor_inertia = {drivetrain.motor_inertia:g} kg*m^2 both give the inertia on the "
                      "motor shaft; give it once, as drivetrain.motor_inertia (rotor and what turns with it)"))
    return found


def motor_on_line(motor: Any, line: DriveLine) -> Any:
    """The ``[flywheel.motor]`` table with the ratio and efficiency of a declared drive line and no rotor inertia
    of its own (the line's motor shaft carries it); the table itself where the file has no ``[drivetrain]``."""
    if not line.declared:
        return motor
    return motor.model_copy(update={"ratio": line.motor_ratio, "efficiency": line.motor_efficiency,
                                    "rotor_inertia": 0.0})
