"""The machine in time: the motor, the mechanism with its position-dependent inertia and the frame on its mounts
simulated together — start, stop, passage through the mounts' resonances, capture by a resonance (the Sommerfeld
effect) and the self-synchronisation of several exciters on one frame; optionally an induction motor's electrical
states (:mod:`machdyn.transient.induction`) and torsionally stiff stages of the drive line
(:mod:`machdyn.transient.torsion`).

See ``docs/transient.md``. scipy is imported inside the functions that integrate.
"""

from .electric import MotorRun, motor_run
from .induction import InductionMachine
from .model import CoupledModel, Exciter, carried_frame, coupled_model
from .run import Scenario, Transient, TransientLimitError, run_scenario
from .torsion import TorsionalLine, TorsionRun, torsion_run, torsional_line

__all__ = ["CoupledModel", "Exciter", "InductionMachine", "MotorRun", "Scenario", "TorsionRun", "TorsionalLine",
           "Transient", "TransientLimitError", "carried_frame", "coupled_model", "motor_run", "run_scenario",
           "torsion_run", "torsional_line"]
