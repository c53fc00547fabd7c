"""Labels of the screw conveyor's results: result key -> text, SI unit, display unit; and the summary keys."""

from __future__ import annotations

from ..results.labels import Label
from . import power as pw

LABELS: dict[str, Label] = {
    "mass_flow": Label("Throughput (mass)", "kg/s", "t/h"),
    "volume_flow": Label("Throughput (volume)", "m^3/s", "m^3/h"),
    "inclination": Label("Inclination", "rad", "deg"),
    "lift": Label("Lift H", "m", "m"),
    "inclination_factor": Label("Inclination factor C", ""),
    "diameter_required": Label("Diameter required", "m", "mm"),
    "diameter": Label("Diameter", "m", "mm"),
    "pitch": Label("Pitch", "m", "mm"),
    "speed_limit": Label("Speed limit k/sqrt(D)", "rad/s", "rpm"),
    "speed": Label("Speed", "rad/s", "rpm"),
    "capacity": Label("Capacity at this speed", "kg/s", "t/h"),
    "filling_actual": Label("Filling at the duty", ""),
    "shaft_power": Label("Shaft power (selected method)", "W", "kW"),
    "drive_efficiency": Label("Drive efficiency", ""),
    "motor_power_required": Label("Motor power required", "W", "kW"),
    "motor_rating": Label("Motor (IEC rating)", "W", "kW"),
    "torque": Label("Screw torque", "N*m", "N*m"),
    "helix_angle": Label("Helix angle at R", "rad", "deg"),
    "axial_force": Label("Axial force", "N", "N"),
    "lateral_load": Label("Lateral load per span", "N", "N"),
    "p_d": Label("Axial force per length p_d", "N/m", "N/m"),
    "p_n": Label("Lateral load per length p_n", "N/m", "N/m"),
    "m_0": Label("Torque per length m_0", "N*m/m", "N*m/m"),
    "twist_total": Label("Twist over the length", "rad", "rad"),
    "screw_mass_per_length": Label("Screw mass per length", "kg/m", "kg/m"),
    "screw_mass": Label("Screw mass", "kg", "kg"),
    "deflection": Label("Deflection between hangers", "m", "mm"),
    "flight_pressure": Label("Flight contact pressure (screw.flight_load)", "Pa", "kPa"),
    "pipe_outer_diameter": Label("Pipe outer diameter", "m", "mm"),
    "pipe_inner_diameter": Label("Pipe inner diameter", "m", "mm"),
    "flight_thickness": Label("Flight thickness", "m", "mm"),
    "span_load": Label("Lateral load on a span q", "N/m", "N/m"),
    "span_moment_max": Label("Span bending moment, max (beam-column)", "N*m", "N*m"),
    "span_deflection_max": Label("Span deflection, max (beam-column)", "m", "mm"),
    "span_stress_max": Label("Span equivalent stress, max", "Pa", "MPa"),
    "span_axial_ratio": Label("Axial force / Euler load of a span", ""),
    "screw_stress_max": Label("Equivalent stress along the screw, max", "Pa", "MPa"),
    "bolt_force": Label("Largest base-bolt shear force", "N", "N"),
    "bolt_d3_required": Label("Bolt minor diameter required", "m", "mm"),
    **{f"power_{m}": Label(f"Shaft power, {pw.LABELS[m]}", "W", "kW") for m in pw.METHODS},
}

#: The summary table, in order (keys a run does not have are left out).
SUMMARY: tuple[str, ...] = (
    "mass_flow", "diameter", "pitch", "speed", "capacity", "filling_actual", "shaft_power", "motor_rating",
    "torque", "axial_force", "deflection", "span_stress_max",
)


def label_of(key: str) -> Label:
    """The label of a result key, including the per-check utilisation keys made at run time."""
    if key in LABELS:
        return LABELS[key]
    if key.startswith("check_") and key.endswith("_utilisation"):
        return Label("Utilisation: " + key.removeprefix("check_").removesuffix("_utilisation").replace("_", " "), "")
    return Label(key.replace("_", " "), "")
