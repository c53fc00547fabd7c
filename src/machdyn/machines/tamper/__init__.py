"""Double tamper of an asphalt paver screed: eccentric shaft + eccentric sleeves, two offset slider-cranks.

Source: Sun Jian, *Structure Analysis and Optimization for Compacting System of Asphalt Paver* (seed paper 000).
Corrections follow ``seed-reproduction.md`` section 000 (cited as "repro 000.x").

- :mod:`.geometry` - eqs 1-4 and Table 1: eccentricities, strokes, phases from the sleeve angles
- :mod:`.slider` - eqs 5-10: exact and series motion of the offset slider-crank beams
- :mod:`.model` - the engine model of the two beams on one shaft; eqs 11-22 and Table 2
- :mod:`.balance` - the 20 stroke/phase states, Table 2 evaluated, and a balance over all states
"""

from .geometry import (
    AUX_SLEEVE_ANGLES,
    MAIN_SLEEVE_ANGLES,
    TABLE1_ECCENTRICITIES,
    Table1Entry,
    beam_phase,
    beam_phase_eq4,
    eccentricity_from_stroke,
    eccentricity_phase,
    eccentricity_phase_eq3,
    phase_at_nominal_strokes,
    resultant_eccentricity,
    sleeve_angle_for_stroke,
    stroke_from_eccentricity,
    table1,
)
from .model import (
    BalanceAnalysis,
    balance_analysis,
    complex_mass_substitution,
    complex_mass_substitution_printed,
    double_tamper,
    sleeve_mass_condition,
)
from .slider import (
    exact_acceleration,
    exact_position,
    exact_velocity,
    series_acceleration,
    series_displacement_from_odc,
    series_position,
    series_velocity,
)

__all__ = [
    "MAIN_SLEEVE_ANGLES",
    "AUX_SLEEVE_ANGLES",
    "TABLE1_ECCENTRICITIES",
    "resultant_eccentricity",
    "eccentricity_phase",
    "eccentricity_phase_eq3",
    "stroke_from_eccentricity",
    "eccentricity_from_stroke",
    "beam_phase",
    "beam_phase_eq4",
    "sleeve_angle_for_stroke",
    "phase_at_nominal_strokes",
    "Table1Entry",
    "table1",
    "exact_position",
    "exact_velocity",
    "exact_acceleration",
    "series_position",
    "series_displacement_from_odc",
    "series_velocity",
    "series_acceleration",
    "double_tamper",
    "complex_mass_substitution",
    "complex_mass_substitution_printed",
    "BalanceAnalysis",
    "balance_analysis",
    "sleeve_mass_condition",
]

