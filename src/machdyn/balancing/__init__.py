"""Balancing of planar linkages: mass substitution, crank counterweights, full force balance of the four-bar,
general counterweight optimisation, spring compensation and balance over several operating states.

Every balancing method takes an engine model (:class:`machdyn.linkage.Mechanism`) and returns a
:class:`~machdyn.balancing.frame.BalanceResult`: the balanced model plus a before/after table of the frame loads.
"""

#: The package's public API is its modules (``from machdyn.balancing import berkof_lowen``).
__all__ = [
    "berkof_lowen", "counterweights", "frame", "general", "methods", "robust", "springs", "stage", "substitution"
]
