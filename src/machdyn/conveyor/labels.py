"""Labels of the screw conveyor's results: result key -> text, SI unit, display unit; and the summary keys."""

from __future__ import annotations

from ..results.labels import Label
from . import power as pw

LABELS: dict[str, Label] = {
    "mass_flow": Label("Throughput (mass)", "kg/s", "t/h", over="scalar", better="target"),
    "volume_flow": Label("Throughput (volume)", "m^3/s", "m^3/h", over="scalar", better="target"),
    "inclination": Label("Inclination", "rad", "deg", over="scalar", better="none"),
    "lift": Label("Lift H", "m", "m", over="scalar", better="none"),
    "inclination_factor": Label("Inclination factor C", "", over="scalar", better="none"),
    "diameter_required": Label("Diameter required", "m", "mm", over="scalar", better="lower"),
    "diameter": Label("Diameter", "m", "mm", over="scalar", better="lower"),
    "pitch": Label("Pitch", "m", "mm", over="scalar", better="none"),
    "speed_limit": Label("Speed limit k/sqrt(D)", "rad/s", "rpm", over="scalar", better="none"),
    "speed": Label("Speed", "rad/s", "rpm", over="scalar", better="none"),
    "capacity": Label("Capacity at this speed", "kg/s", "t/h", over="scalar", better="higher"),
    "filling_actual": Label("Filling at the duty", "", over="scalar", better="target"),
    "shaft_power": Label("Shaft power (selected method)", "W", "kW", over="scalar", better="lower"),
    "drive_efficiency": Label("Drive efficiency", "", over="scalar", better="higher"),
    "motor_power_required": Label("Motor power required", "W", "kW", over="scalar", better="lower"),
    "motor_rating": Label("Motor (IEC rating)", "W", "kW", over="scalar", better="lower"),
    "torque": Label("Screw torque", "N*m", "N*m", over="scalar", better="lower"),
    "helix_angle": Label("Helix angle at R", "rad", "deg", over="scalar", better="none"),
    "axial_force": Label("Axial force", "N", "N", over="scalar", better="lower"),
    "lateral_load": Label("Lateral load per span", "N", "N", over="scalar", better="lower"),
    "p_d": Label("Axial force per length p_d", "N/m", "N/m", over="scalar", better="lower"),
    "p_n": Label("Lateral load per length p_n", "N/m", "N/m", over="scalar", better="lower"),
    "m_0": Label("Torque per length m_0", "N*m/m", "N*m/m", over="scalar", better="lower"),
    "twist_total": Label("Twist over the length", "rad", "rad", over="scalar", better="lower"),
    "screw_mass_per_length": Label("Screw mass per length", "kg/m", "kg/m", over="scalar", better="lower"),
    "screw_mass": Label("Screw mass", "kg", "kg", over="scalar", better="lower"),
    "deflection": Label("Deflection between hangers", "m", "mm", over="scalar", better="lower"),
    "flight_pressure": Label("Flight contact pressure (screw.flight_load)", "Pa", "kPa", over="scalar", better="lower"),
    "pipe_outer_diameter": Label("Pipe outer diameter", "m", "mm", over="scalar", better="none"),
    "pipe_inner_diameter": Label("Pipe inner diameter", "m", "mm", over="scalar", better="none"),
    "flight_thickness": Label("Flight thickness", "m", "mm", over="scalar", better="none"),
    "span_load": Label("Lateral load on a span q", "N/m", "N/m", over="scalar", better="lower"),
    "span_moment_max": Label("Span bending moment, max (beam-column)", "N*m", "N*m", over="scalar", better="lower"),
    "span_deflection_max": Label("Span deflection, max (beam-column)", "m", "mm", over="scalar", better="lower"),
    "span_stress_max": Label("Span equivalent stress, max", "Pa", "MPa", over="scalar", better="lower"),
    "span_axial_ratio": Label("Axial force / Euler load of a span", "", over="scalar", better="lower"),
    "screw_stress_max": Label("Equivalent stress along the screw, max", "Pa", "MPa", over="scalar", better="lower"),
    "bolt_force": Label("Largest base-bolt shear force", "N", "N", over="scalar", better="lower"),
    "bolt_d3_required": Label("Bolt minor diameter required", "m", "mm", over="scalar", better="lower"),
    **{f"power_{m}": Label(f"Shaft power, {pw.LABELS[m]}", "W", "kW", over="scalar", better="lower")
       for m in pw.METHODS},
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
