"""Screw conveyors: design from duty, power by method (seed 004 textbook rule, ISO 7119, CEMA 350), loads and
verification checks, bending along the screw, the search for the best design, and the ``[screw_conveyor]``
problem kind.

Formula functions compute in SI floats (or NumPy arrays); tables live in ``data/`` (sources in
``data/SOURCES.md``). The problem kind: :func:`validate`, :func:`check`, :func:`run` (:mod:`.kind`).
"""

import warnings

from ..dynamics.motors import smallest_rating
from .beam import beam_column, moment_one_term, one_term_error
from .checks import (
    Check,
    axial_force,
    distributed_loads,
    flight_pressure,
    helix_angle,
    lateral_load,
    pipe_equivalent_stress,
    polar_moment_tube,
    shear_stress_tube,
    span_deflection,
    torque_from_power,
    torsion_angle_distributed,
    twist_rate,
)
from .design import ScrewDesign, design_screw, diameter_for_duty, speed_limit, volume_capacity
from .evaluate import ConveyorResult, evaluate
from .kind import check, run, validate
from .model import ConveyorProblem
from .optimise import best_design
from .plate import flight_edge_moments, flight_moments, plate_coefficient
from .power import power_cema, power_iso7119, power_textbook_360, power_textbook_367
from .problem import load_conveyor_problem, run_conveyor


def select_motor(required_power: float) -> float:
    """Deprecated: :func:`machdyn.dynamics.motors.smallest_rating`, the one IEC 60072-1 motor selection (the
    conveyor's copy was removed in 0.1.0). It warns and delegates, and goes in 0.3.0."""
    warnings.warn("machdyn.conveyor.select_motor is deprecated and goes in 0.3.0: use "
                  "machdyn.dynamics.motors.smallest_rating", DeprecationWarning, stacklevel=2)
    return float(smallest_rating(required_power))


__all__ = [
    "Check", "ConveyorProblem", "ConveyorResult", "ScrewDesign", "axial_force", "beam_column", "best_design",
    "check", "design_screw", "diameter_for_duty", "distributed_loads", "evaluate", "flight_edge_moments",
    "flight_moments", "flight_pressure", "helix_angle", "lateral_load", "load_conveyor_problem", "moment_one_term",
    "one_term_error", "pipe_equivalent_stress", "plate_coefficient", "polar_moment_tube", "power_cema",
    "power_iso7119", "power_textbook_360", "power_textbook_367", "run", "run_conveyor", "select_motor",
    "shear_stress_tube", "span_deflection", "speed_limit", "torque_from_power", "torsion_angle_distributed",
    "twist_rate", "validate", "volume_capacity",
]
