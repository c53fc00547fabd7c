"""The planar linkage engine: exact kinematics, kinetostatics and energy, vectorised over crank positions
and design variants. See :mod:`machdyn.linkage.model` for the model and its conventions."""

from .analysis import Analysis, analyse
from .builders import double_slider_crank, four_bar, inverted_slider_crank, six_bar, slider_crank
from .diagnostics import Diagnostics, diagnose
from .energy import Energy, WorkBalance, energy
from .grashof import grashof_type
from .harmonics import Harmonics, harmonics
from .kinematics import kinematics
from .kinetostatics import kinetostatics
from .model import (
    PRP,
    RPR,
    RRP,
    RRR,
    Body,
    BodyTorque,
    Crank,
    Guide,
    Mechanism,
    PointForce,
    PointMass,
    Spring,
    joints,
    stack_designs,
)
from .motion import Kinematics, SlideMotion, angle_ranges, crank_angles
from .reactions import Forces, Joint, Reaction
from .state import BodyState, PointState
from .sweep import SweepResult, sweep

__all__ = [
    "PRP", "RPR", "RRP", "RRR", "Analysis", "Body", "BodyState", "BodyTorque", "Crank", "Diagnostics", "Energy",
    "Forces", "Guide", "Harmonics", "Joint", "Kinematics", "Mechanism", "PointForce", "PointMass", "PointState",
    "Reaction", "SlideMotion", "Spring", "SweepResult", "WorkBalance", "analyse", "angle_ranges", "crank_angles",
    "diagnose", "double_slider_crank", "energy", "four_bar", "grashof_type", "harmonics", "inverted_slider_crank",
    "joints", "kinematics", "kinetostatics", "six_bar", "slider_crank", "stack_designs", "sweep",
]

# Textbook-facing additions: loads on a built model, inverse position, crank and piston effort, the total centre
# of mass and the maximum fluctuation of energy.
from .effort import CrankEffort, PistonEffort, crank_effort, piston_effort  # noqa: E402
from .fluctuation import energy_fluctuation  # noqa: E402
from .inverse import InversePosition, inverse_position  # noqa: E402
from .loading import with_loads  # noqa: E402
from .mass_centre import MassCentre, inertial_force, mass_centre  # noqa: E402

__all__ += [
    "CrankEffort", "InversePosition", "MassCentre", "PistonEffort", "crank_effort", "energy_fluctuation",
    "inertial_force", "inverse_position", "mass_centre", "piston_effort", "with_loads",
]
