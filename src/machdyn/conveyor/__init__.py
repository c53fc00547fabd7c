"""Screw conveyors: design from duty, power by method (seed 004 textbook rule, ISO 7119, CEMA 350),
loads and verification checks, and the ``[screw_conveyor]`` problem file.

Formula functions compute in SI floats; tables live in ``data/`` (sources in ``data/SOURCES.md``).
"""

from .checks import Check
from .design import ScrewDesign, design_screw, diameter_for_duty, speed_limit, volume_capacity
from .plate import flight_edge_moments, flight_moments, plate_coefficient
from .power import power_cema, power_iso7119, power_textbook_360, power_textbook_367, select_motor
from .problem import ConveyorProblem, ConveyorResult, load_conveyor_problem, run_conveyor

__all__ = [
    "Check", "ConveyorProblem", "ConveyorResult", "ScrewDesign", "design_screw", "diameter_for_duty",
    "flight_edge_moments", "flight_moments", "load_conveyor_problem", "plate_coefficient", "power_cema",
    "power_iso7119", "power_textbook_360", "power_textbook_367", "run_conveyor", "select_motor",
    "speed_limit", "volume_capacity",
]
