"""Seed machines: thin layers over the linkage engine for the machines of the founding papers.

- :mod:`machdyn.machines.tamper` - asphalt paver double tamper (seed 000)
- :mod:`machdyn.machines.rotary_screen` - rotary grading screen with an energy-storing spring (seed 002)
- :mod:`machdyn.machines.compactor` - four-bar compaction mechanism with an "Archimedes lever" (seed 003)

Each formula function takes and returns SI floats or numpy arrays; the docstrings name the paper's equation
and, where the paper is wrong, the correction applied.
"""
