"""``[transient.motor]``: the motor of a transient run with its electrical states (``model = "induction-dq"``),
given by its per-phase equivalent circuit; its results (peak electromagnetic torque and stator current of the
run, the electrical energy balance) for the catalogue.

The gear ratio and efficiency to the crank and the rotor's inertia stay those of the drive line (``[drivetrain]``
or ``[flywheel.motor]``): the table replaces only the motor's torque-speed curve by its electrical model.
"""

from __future__ import annotations

import math
from typing import Any, Literal

from pydantic import Field

from ..problem.fields import PositiveFrequency, Resistance, Voltage
from ..problem.schema import Spec
from ..results.labels import Label
from .electric import MotorRun
from .induction import InductionMachine

__all__ = ["MOTOR_LABELS", "MotorSpec", "dq_motor", "motor_checks", "motor_scalars"]

#: The relative tolerance of the electrical energy balance of a run (its own check).
ELECTRICAL_TOLERANCE = 1e-6


class MotorSpec(Spec):
    """``[transient.motor]``: a three-phase squirrel-cage induction motor by its per-phase equivalent circuit
    (star equivalent, rotor quantities referred to the stator, reactances at ``frequency``)."""

    model: Literal["induction-dq"]
    stator_resistance: Resistance
    rotor_resistance: Resistance
    stator_leakage_reactance: Resistance
    rotor_leakage_reactance: Resistance
    magnetizing_reactance: Resistance
    pole_pairs: int = Field(ge=1, le=50, strict=True)
    line_voltage: Voltage
    frequency: PositiveFrequency
    reference_frame: Literal["synchronous", "stationary"] = "synchronous"


def dq_motor(spec: MotorSpec, drive: Any) -> InductionMachine:
    """The :class:`InductionMachine` of ``spec`` through the gear of the run's ``drive`` (its ratio, efficiency
    and rotor inertia: the drive line's)."""
    return InductionMachine(spec.stator_resistance, spec.rotor_resistance, spec.stator_leakage_reactance,
                            spec.rotor_leakage_reactance, spec.magnetizing_reactance, spec.pole_pairs,
                            spec.line_voltage, spec.frequency, float(getattr(drive, "ratio", 1.0)),
                            float(getattr(drive, "efficiency", 1.0)), float(getattr(drive, "rotor_inertia", 0.0)),
                            spec.reference_frame)


MOTOR_LABELS = {
    "transient.motor_peak_torque": Label("Transient motor: peak electromagnetic torque (motor shaft)", "N*m",
                                         over="max_abs", better="lower"),
    "transient.motor_peak_current": Label("Transient motor: peak stator phase current (amplitude)", "A",
                                          over="max_abs", better="lower"),
    "transient.motor_breakdown_torque": Label("Transient motor: breakdown torque of its steady state "
                                              "(motor shaft)", "N*m", over="scalar", better="higher"),
    "transient.motor_starting_torque": Label("Transient motor: starting torque of its steady state (motor shaft)",
                                             "N*m", over="scalar", better="higher"),
    "transient.motor_electrical_input": Label("Transient motor: electrical energy into the stator", "J",
                                              over="scalar", better="lower"),
    "transient.motor_copper_loss": Label("Transient motor: copper loss (stator and rotor)", "J",
                                         over="scalar", better="lower"),
    "transient.motor_switching_loss": Label("Transient motor: magnetic energy lost at the switch-off", "J",
                                            over="scalar", better="lower"),
    "transient.motor_magnetic_energy_change": Label("Transient motor: change of the magnetic energy", "J",
                                                    over="scalar", better="none"),
    "transient.motor_gear_loss": Label("Transient motor: loss in the gear to the crank", "J",
                                       over="scalar", better="lower"),
    "transient.motor_energy_error": Label("Transient motor: electrical energy balance error (relative)", "",
                                          over="scalar", better="lower"),
}

MOTOR_SUMMARY = ("transient.motor_peak_torque", "transient.motor_peak_current", "transient.motor_energy_error")


def energy_error(motor: MotorRun, run: Any) -> float:
    """|electrical input - copper - switching loss - change of magnetic energy - gear loss - the drive's work at
    the crank| / electrical input, the drive's work at the crank being the run's own balance of kinetic and
    potential energy, loads, mounts and brake."""
    w = run.works[:, -1]
    mechanical = float(run.energy[-1] - run.energy[0]) - float(w[1]) + float(w[2]) + float(w[3])
    gear = motor.air_gap_work - float(w[0])
    out = (motor.electrical_input - motor.copper_loss - motor.switching_loss - motor.magnetic_energy_change - gear
           - mechanical)
    return abs(out) / max(abs(motor.electrical_input), 1e-300)


def motor_scalars(motor: MotorRun, run: Any) -> dict[str, float]:
    """The catalogue's values of the run's motor (SI)."""
    return {"transient.motor_peak_torque": motor.peak_torque,
            "transient.motor_peak_current": motor.peak_current,
            "transient.motor_breakdown_torque": motor.breakdown_torque,
            "transient.motor_starting_torque": motor.starting_torque,
            "transient.motor_electrical_input": motor.electrical_input,
            "transient.motor_copper_loss": motor.copper_loss,
            "transient.motor_switching_loss": motor.switching_loss,
            "transient.motor_magnetic_energy_change": motor.magnetic_energy_change,
            "transient.motor_gear_loss": motor.air_gap_work - float(run.works[0, -1]),
            "transient.motor_energy_error": energy_error(motor, run)}


def motor_checks(motor: MotorRun, run: Any, free_speed: float, mean_load: float) -> list[str]:
    """The run's failed checks of its motor: an electrical energy balance that does not close; a motor whose
    breakdown torque is below the machine's mean load (it can never run the machine at speed)."""
    failed = []
    error = energy_error(motor, run)
    if error > ELECTRICAL_TOLERANCE:
        failed.append(f"the electrical energy balance of the motor closes only to {error:.3g} (relative), more than "
                      f"{ELECTRICAL_TOLERANCE:g}: tighten rtol")
    if not math.isfinite(free_speed):
        m = motor.motor
        at_crank = float(m.ratio) * float(m.efficiency) * motor.breakdown_torque  # type: ignore[attr-defined]
        failed.append(f"the induction motor's breakdown torque at the crank, {at_crank:.4g} N*m, is below the "
                      f"machine's mean load there, {mean_load:.4g} N*m: it cannot run the machine up to speed "
                      "(choose a larger motor or a higher gear ratio)")
    return failed


def motor_series(motor: MotorRun) -> dict[str, tuple[Any, str]]:
    """Columns of the motor's CSV: time, electromagnetic torque, stator current amplitude, its dq components."""
    every = max(1, motor.t.size // 20_000)
    s = slice(None, None, every)
    return {"time": (motor.t[s], "s"), "electromagnetic_torque": (motor.torque[s], "N*m"),
            "stator_current": (motor.current[s], "A"), "i_qs": (motor.currents[0, s], "A"),
            "i_ds": (motor.currents[1, s], "A")}
