"""The pipelines of the problem kinds machdyn ships (linkage, rotary screen, screw conveyor) and of the
``[sweep]`` capability; each is registered by one line in :mod:`machdyn.kinds`."""
