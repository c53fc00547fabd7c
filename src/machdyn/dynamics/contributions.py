"""What other stages' results give the ``[flywheel]`` stage, as contracts it reads by type.

A result may be a machine of its own reduced to its driving shaft (a cam file: its camshaft is the crank), or
reduced quantities that add to the machine on the crank shaft (a cam on the crank shaft, the linkage a cam's
follower drives). Reduced quantities of a one-degree-of-freedom machine on one shaft add (Uicker, Pennock &
Shigley, *Theory of Machines and Mechanisms*, 4th ed., ch. 17). The capabilities that produce such results
derive their result types from these classes, so the flywheel stage reads them without knowing those
capabilities.
"""

from __future__ import annotations

from .equivalent import EquivalentMachine


class ReducedMachineSource:
    """A stage's result that is a machine reduced to its driving shaft, turning at ``speed`` [rad/s]."""

    speed: float

    def machine(self, positions: int = 720) -> EquivalentMachine:
        """The reduced machine sampled at ``positions`` shaft angles over one turn."""
        raise NotImplementedError


class ShaftContribution:
    """A stage's result whose reduced inertia, potential and damping add to the machine on the crank shaft."""

    def added_to(self, machine: EquivalentMachine, positions: int) -> EquivalentMachine:
        """``machine`` with this result's reduced quantities added at ``positions`` shaft angles."""
        raise NotImplementedError
