"""The limits on the work one problem file may ask for, in one place (documented in docs/explore.md).

Each is checked before the work starts, by ``machdyn check`` as by ``machdyn run``, and refused with the field
that sets it; none depends on the machine except the number of local worker processes
(:func:`machdyn.studies.exploration.execution.worker_limit`).
"""

from __future__ import annotations

#: Values of one result held in memory at once by a one-quantity sweep or an optimisation (designs x crank
#: positions): about 32 MB per result array, a few hundred MB for a whole analysis. An exploration has no such
#: limit: it works partition by partition.
MAX_HELD_VALUES = 4_000_000

#: Dyads of a custom mechanism (``mechanism.dyads``).
MAX_DYADS = 64


def held_values_error(designs: int, positions: int) -> str | None:
    """Why ``designs`` x ``positions`` values per result are refused, or None."""
    if designs * positions <= MAX_HELD_VALUES:
        return None
    return (f"{designs:,} designs x {positions:,} crank positions make {designs * positions:,} values per result "
            f"held in memory at once; at most {MAX_HELD_VALUES:,} (lower it, or drive.positions; a [sweep] with "
            f"[[sweep.quantities]] explores any number of designs partition by partition)")
