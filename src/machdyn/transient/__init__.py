"""The machine in time: the motor, the mechanism with its position-dependent inertia and the frame on its mounts
simulated together — start, stop, passage through the mounts' resonances, capture by a resonance (the Sommerfeld
effect) and the self-synchronisation of several exciters on one frame.

See ``docs/transient.md``. scipy is imported inside the functions that integrate.
"""

from .model import CoupledModel, Exciter, carried_frame, coupled_model
from .run import Scenario, Transient, TransientLimitError, run_scenario

__all__ = ["CoupledModel", "Exciter", "Scenario", "Transient", "TransientLimitError", "carried_frame", "coupled_model",
           "run_scenario"]
