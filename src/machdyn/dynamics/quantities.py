"""Quantity fields of the ``[flywheel]`` table (text with a unit in, an SI float out)."""

from ..problem.fields import quantity

Power = quantity("W", "power", ">0")
Speed = quantity("m/s", "speed", ">0")
Density = quantity("kg/m^3", "density", ">0")
Stress = quantity("Pa", "stress", ">0")
Displacement = quantity("m^3", "volume", ">0")
Flow = quantity("m^3/s", "flow", ">0")
Pressure = quantity("Pa", "pressure", ">0")
RotaryDamping = quantity("N*m*s/rad", "rotary_damping", ">=0")
LinearDamping = quantity("N*s/m", "linear_damping", ">=0")
