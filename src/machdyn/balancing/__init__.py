"""Balancing of planar linkages: mass substitution, crank counterweights, full force balance of the four-bar,
general counterweight optimisation, spring compensation and balance over several operating states.

Every balancing method takes an engine model (:class:`machdyn.linkage.Mechanism`) and returns a
:class:`~machdyn.balancing.frame.BalanceResult`: the balanced model plus a before/after table of the frame loads.
"""
