"""machdyn: analysis and design of machine mechanisms and bulk-material machinery.

The planar linkage engine lives in :mod:`machdyn.linkage`; screw conveyors in :mod:`machdyn.conveyor`.
Everything computes in SI floats; units are parsed and printed at the boundary by :mod:`machdyn.units`.
"""

__version__ = "0.1.0"
