"""Quantity fields of the vibration tables (text with a unit in, SI float out), in the style of
:mod:`machdyn.problem.fields`."""

from ..problem.fields import quantity

PositiveMass = quantity("kg", "mass", ">0")
PositiveInertia = quantity("kg*m^2", "inertia", ">0")
Damping = quantity("N*s/m", "damping", ">=0")
PositiveStiffness = quantity("N/m", "stiffness", ">0")
PositiveLength = quantity("m", "length", ">0")
Frequency = quantity("Hz", "frequency", ">=0")
Velocity = quantity("m/s", "velocity", ">0")
