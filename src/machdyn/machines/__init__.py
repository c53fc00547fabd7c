"""Seed machines: thin layers over the linkage engine for the machines of the founding papers.

- :mod:`machdyn.machines.tamper` - asphalt paver double tamper (seed 000)
- :mod:`machdyn.machines.compactor` - four-bar compaction mechanism with an "Archimedes lever" (seed 003)

The rotary grading screen (seed 002) is a problem kind of its own, gathered in one package: :mod:`machdyn.screen`.

Each formula function takes and returns SI floats or numpy arrays; the docstrings name the paper's equation
and, where the paper is wrong, the correction applied.
"""

#: The package's public API is its modules (``from machdyn.machines import compactor``).
__all__ = [
    "compactor", "tamper"
]
