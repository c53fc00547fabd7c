"""The validated screw-conveyor problem: frozen, every quantity an SI float.

Made by :func:`machdyn.conveyor.schema.validate` from a problem file, or directly in Python.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Any


@dataclass(frozen=True)
class Coupling:
    """Elastic-pin coupling of the drive (seed 004, eqs 2.97-2.98); SI."""

    rated_torque: float  # [N·m]
    pins: int
    pin_circle_diameter: float  # D0 [m]
    pin_diameter: float  # d_c [m]
    bushing_length: float  # l3 [m]
    pin_lever: float  # l0 [m]
    allowable_bushing_stress: float  # [Pa]
    allowable_pin_stress: float  # [Pa]


@dataclass(frozen=True)
class BaseBolts:
    """Four bolts of the motor base under the belt pull (seed 004, eqs 2.72-2.80); SI."""

    belt_force: float  # [N]
    belt_preload: float  # [N]
    lever: float  # [m]
    spacing_a: float  # [m]
    spacing_b: float  # [m]
    allowable_tensile_stress: float  # [Pa]
    friction: float
    safety: float
    bolt: str | None = None


@dataclass(frozen=True)
class DesignSearch:
    """The grid of candidate designs the ``[screw_conveyor.optimise]`` table asks for."""

    objective: str  # "power" or "cost"
    diameters: tuple[float, ...]  # [m]
    pitch_ratios: tuple[float, ...]  # S/D
    speed_fractions: tuple[float, ...]  # n as a fraction of k/sqrt(D)
    fillings: tuple[float, ...]
    motor_mass_per_kw: float  # [kg/kW] of the cost proxy


@dataclass(frozen=True)
class ConveyorProblem:
    """A validated screw-conveyor problem in SI floats (kg/s, kg/m³, m, rad, rad/s, Pa, W; the speed
    coefficient k of n = k/√D in rpm·m^0.5, as tabulated).

    ``mass_flow`` is None when the file describes an existing screw (diameter, speed, filling) whose capacity
    is the duty. ``lift`` and ``torque`` are None unless given directly.
    """

    name: str
    description: str
    mass_flow: float | None
    length: float
    inclination: float
    lift: float | None
    torque: float | None
    power_method: str
    methods: tuple[str, ...]
    material_name: str
    bulk_density: float
    filling: float
    speed_coefficient: float
    resistance: float
    cema_material_factor: float | None
    friction_coefficient: float
    diameter: float | None
    speed: float | None
    pitch_ratio: float
    inclination_factor: float
    pipe_outer_diameter: float | None
    pipe_wall: float | None
    flight_thickness: float | None
    hanger_spacing: float
    force_radius_ratio: float
    lateral_load_factor: float
    hanger_bearing: str
    flight_type: str
    paddles: int
    drive_efficiency: float
    coupling_service_factor: float
    shear_modulus: float
    elastic_modulus: float
    poisson_ratio: float
    steel_density: float
    allowable_shear_stress: float
    allowable_stress: float
    allowable_twist: float
    max_deflection: float
    coupling: Coupling | None = None
    base_bolts: BaseBolts | None = None
    search: DesignSearch | None = None
    source: str | None = None
    #: "annulus": the pipe's section deducted from the capacity (CEMA 350); "circle": the whole D² (seed 004).
    capacity_section: str = "annulus"
    #: "per_pitch": each flight turn carries the axial force of its own pitch, F_a·S/L, on the material's
    #: cross-section; "one_turn": the whole axial force on one turn's whole face (seed 004, eq 2.56).
    flight_load: str = "per_pitch"

    @property
    def lift_height(self) -> float:
        """The lift H [m]: given directly, or L·sin β."""
        return self.lift if self.lift is not None else self.length * math.sin(self.inclination)

    def replace(self, **changes: Any) -> ConveyorProblem:
        """A copy with some fields changed."""
        return dataclasses.replace(self, **changes)
