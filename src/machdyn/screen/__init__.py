"""Rotary grading screen: slider-crank energy analysis and the energy-storing spring (seed paper 002), and
the ``[rotary_screen]`` problem kind, in one package.

The package has the shape of a kind (as :mod:`machdyn.conveyor`): :mod:`.schema` (the ``[rotary_screen]``
problem file), :mod:`.model` (the screen and the engine's model of it), :mod:`.formulas`, :mod:`.slider`,
:mod:`.ratio` (the paper's equations, corrected), :mod:`.figures` (the energy figures: as printed, by the
formulas corrected, and exact) and :mod:`.kind` (build, check, analysis, the registry's entry). The report draws
the results in :mod:`machdyn.report.rotary_screen`; nothing here draws.

Source: Yuan Rui et al., *Study of Vibration Decreasing and Energy Saving of Rotary Grading Screen* (seed 002,
Trans. CSAM 2013). Corrections follow ``seed-reproduction.md`` section 002 (cited as "repro 002.x").

The screen is modelled as a centred slider-crank: crank A-B (radius R, mass m1, centroid S1 at l_AS1 from A),
rod B-C (length L, mass m2, centroid S2 at l_BS2 from B and l_CS2 from C), slider C (mass m3), a counterweight
m_e at radius r_e opposite the crank pin, crank speed omega. The screen moves horizontally, so gravity does no
work and is left out.

**Crank angle.** The paper's alpha is the angle between the crank A->B and the x axis, with the slider on the
+x side of A (eq 1: S = L + R[cos alpha - ...] is largest at alpha = 0) and alpha = omega t increasing
counter-clockwise (eq 2: v = dS/dt). The engine's slider-crank has its slide line along +x through the crank
centre and measures its crank angle counter-clockwise from +x, so **alpha = the engine's crank angle** and
omega = the engine's ``speed``; the paper's S is the slider's x coordinate (the engine's slide displacement).

Every function takes and returns SI floats or numpy arrays (m, kg, rad, rad/s, J, N/m, N m, W).
"""

from .figures import energy_figures
from .formulas import (
    energy_range,
    fluctuation_power,
    input_torque,
    pr_eq20,
    pr_first_order,
    pr_printed,
    rotating_mass,
    slider_acceleration_series,
    slider_position_exact,
    slider_position_series,
    slider_velocity_exact,
    slider_velocity_series,
    spring_displacement_exact,
    spring_displacement_series,
    spring_energy,
    spring_stiffness,
    t1,
    t1_max,
    t1_max_with_lambda,
    t2,
    t3,
    t3_printed,
    total_energy,
    translating_mass,
    w1_range_eq20,
    w1_range_printed,
    w1_ratio_eq20,
    w1_ratio_first_order,
    w1_ratio_printed,
)
from .model import PAPER_SCREEN, RotaryScreen, link_ratio

__all__ = [
    "RotaryScreen",
    "PAPER_SCREEN",
    "link_ratio",
    "slider_position_series",
    "slider_velocity_series",
    "slider_acceleration_series",
    "slider_position_exact",
    "slider_velocity_exact",
    "rotating_mass",
    "translating_mass",
    "t1",
    "t1_max",
    "t1_max_with_lambda",
    "t2",
    "t3",
    "t3_printed",
    "total_energy",
    "energy_range",
    "fluctuation_power",
    "spring_stiffness",
    "spring_displacement_series",
    "spring_displacement_exact",
    "spring_energy",
    "w1_ratio_eq20",
    "w1_ratio_first_order",
    "w1_ratio_printed",
    "w1_range_eq20",
    "w1_range_printed",
    "pr_printed",
    "pr_first_order",
    "pr_eq20",
    "input_torque",
    "energy_figures",
]
