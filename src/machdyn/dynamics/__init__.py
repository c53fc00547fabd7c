"""Machine dynamics under a real drive: the equivalent one-degree-of-freedom machine, flywheel sizing (classic
and energy-mass), drives and motors, periodic steady state, start-up, and the forces at the real speed.

See ``docs/dynamics.md``. Heavy libraries (scipy) are imported inside the functions that use them.
"""

import warnings

from .drives import (
    ConstantSpeed,
    ConstantTorque,
    HydraulicMotor,
    InductionMotor,
    TorqueSpeedTable,
    kloss_breakdown_slip,
    kloss_torque,
)
from .equivalent import EquivalentMachine, LinearDamper, RotaryDamper, SpeedForce, equivalent_machine
from .flywheel import (
    FlywheelPart,
    FlywheelSizing,
    disc_flywheel,
    flywheel_inertia_classic,
    rim_flywheel,
    rim_speed_limit,
    size_flywheel,
    speed_limits,
)
from .motion import StartUp, Trajectory, simulate, start_up
from .simulate import NotSettledError, SteadyState, steady_state
from .tables import PeriodicCurve, diagram_energy_fluctuation, indicator_crank_effort, torque_table

__all__ = [
    "ConstantSpeed", "ConstantTorque", "EquivalentMachine", "FlywheelPart", "FlywheelSizing", "HydraulicMotor",
    "InductionMotor", "LinearDamper", "NotSettledError", "PeriodicCurve", "RotaryDamper", "SpeedForce", "StartUp",
    "SteadyState", "TorqueSpeedTable", "Trajectory", "diagram_energy_fluctuation", "disc_flywheel",
    "equivalent_machine",
    "flywheel_inertia_classic", "indicator_crank_effort", "kloss_breakdown_slip", "kloss_torque", "rim_flywheel",
    "rim_speed_limit", "simulate", "size_flywheel", "speed_limits", "start_up", "steady_state", "torque_table",
    "energy_fluctuation",
]


def energy_fluctuation(curve, mean=None, samples_per_piece: int = 32):
    """Deprecated name of :func:`diagram_energy_fluctuation` (renamed in 0.1.0 beside
    :func:`machdyn.linkage.energy_fluctuation`, which reads samples); it warns and delegates, and goes in 0.3.0."""
    warnings.warn("machdyn.dynamics.energy_fluctuation is deprecated and goes in 0.3.0: use "
                  "machdyn.dynamics.diagram_energy_fluctuation (a diagram) or machdyn.linkage.energy_fluctuation "
                  "(samples)", DeprecationWarning, stacklevel=2)
    return diagram_energy_fluctuation(curve, mean, samples_per_piece)
