"""The drive of a ``[flywheel.motor]`` table: the motor it names, or the smallest standard motor that carries the
machine; and the thermal check of the motor's duty. The ``[flywheel]`` stage calls these; they read the table's
fields (``kind``, ratings, ``duty``...) and the machine's steady state, nothing of the stage.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .drives import ConstantTorque, HydraulicMotor, InductionMotor
from .duty import motor_duty
from .motion import start_up
from .motors import select_motor, standard_ratings
from .simulate import NotSettledError, steady_state


def choose_drive(motor: Any, machine, flywheel: float, speed: float, mean_torque: float):
    """The drive of the table; for "select", the smallest standard motor whose breakdown torque carries the
    steady state's peak torque with a margin of 1.3, through the table's ``ratio`` where it has one (the drive
    line's), else through the ratio that runs it at its rated speed at the crank's ``speed``. ``flywheel`` [kg·m²]
    is every constant inertia at the crank besides the linkage (flywheel and drive-line shafts)."""
    if motor.kind == "constant_torque":
        return ConstantTorque(mean_torque)
    if motor.kind == "hydraulic":
        # its torque never reverses (p >= 0): the gear's efficiency is a constant factor on it
        return HydraulicMotor(float(motor.displacement or 0), float(motor.flow or 0), float(motor.pressure_limit or 0),
                              motor.volumetric_efficiency, motor.mechanical_efficiency * motor.efficiency,
                              motor.ratio or 1.0, motor.rotor_inertia)
    if motor.kind == "induction":
        rated = float(motor.rated_speed or 0.0)
        ratio = motor.ratio or rated / speed
        return InductionMotor(float(motor.rated_power or 0.0), rated, motor.synchronous_speed, motor.breakdown_ratio,
                              ratio, motor.efficiency, motor.rotor_inertia)
    power = max(mean_torque * speed, standard_ratings()[0])
    # a ratio the drive line (or the table) fixes; else the one that runs the motor at its rated speed
    at = speed if motor.ratio is None else motor.synchronous_speed * (1.0 - motor.rated_slip) / motor.ratio
    choice = select_motor(power, 0.0, at, synchronous_speed=motor.synchronous_speed,
                          rated_slip=motor.rated_slip, breakdown_ratio=motor.breakdown_ratio,
                          gear_efficiency=motor.efficiency, rotor_inertia=motor.rotor_inertia)
    ratings = [r for r in standard_ratings() if r >= choice.motor.rated_power]
    for rating in ratings:
        candidate = InductionMotor(rating, choice.motor.rated_speed, choice.motor.synchronous_speed,
                                   motor.breakdown_ratio, choice.motor.ratio, motor.efficiency, motor.rotor_inertia)
        try:
            ss = steady_state(machine, candidate, flywheel)
        except ValueError:
            continue
        if (float(np.max(ss.drive_torque)) * 1.3 <= float(candidate.breakdown_torque) and not ss.warnings
                and not overloaded(candidate, ss, motor)):
            try:
                run = start_up(machine, candidate, flywheel, steady=ss)
            except ValueError:
                continue  # cannot start the machine from rest
            except NotSettledError:
                pass
            else:
                if motor.starts_per_hour and duty_of(candidate, ss, motor, run).too_many_starts():
                    continue  # its rotor does not stand the starts per hour asked for
            return candidate
    return InductionMotor(ratings[-1], choice.motor.rated_speed, choice.motor.synchronous_speed,
                          motor.breakdown_ratio, choice.motor.ratio, motor.efficiency, motor.rotor_inertia)


def overloaded(drive, steady, motor: Any = None) -> list[str]:
    """The thermal check of the motor's duty: S3 and S6 (``motor.duty``) by :mod:`machdyn.dynamics.duty`; the
    thermal check of an induction motor in continuous duty S1 (IEC 60034-1:2022, 4.2.1): the RMS over
    time of the torque it gives, referred to the crank, must not exceed its rated torque at the crank
    T_r i eta [N*m] (the equivalent-torque method: the winding losses, and so the temperature rise, grow with
    the square of the current, nearly proportional to the torque near rated load; Vogel, Elektrische Antriebe,
    or Pyrhönen, Jokinen & Hrabovcová, Design of Rotating Electrical Machines, 2nd ed. 2014, sec. 10.1)."""
    if getattr(drive, "name", "") != "induction motor":
        return []
    if motor is not None and motor.duty != "S1":
        return duty_of(drive, steady, motor).overload()
    rated = float(np.max(drive.rated_torque * drive.ratio * drive.efficiency))
    rms = float(steady.rms_drive_torque)
    if rms > rated * (1.0 + 1e-9):
        return [f"the induction motor is overloaded for continuous duty S1 (IEC 60034-1): the RMS torque over the "
                f"cycle {rms:.4g} N*m at the crank is {100.0 * rms / rated:.4g} % of its rated torque {rated:.4g} N*m "
                f"at the crank ({float(np.max(drive.rated_power)) / 1000:g} kW); it will overheat. Choose a larger "
                "motor."]
    return []


def duty_of(drive, steady, motor: Any, run=None):
    """The duty of ``drive`` over the steady state (RMS torque against the rating for the table's duty S1, S3 or
    S6, and the starts per hour its rotor stands after ``run``, the start-up), by :func:`.duty.motor_duty`."""
    return motor_duty(drive, float(np.max(steady.rms_drive_torque)), motor.duty, motor.cyclic_duration_factor or 1.0,
                      float(motor.no_load_torque), start_up=run, starts_required=motor.starts_per_hour,
                      rest_cooling=motor.rest_cooling)
