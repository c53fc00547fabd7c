"""What a result is called and in which unit it is shown: one registry for every output.

Results are kept in SI (:class:`Label.unit`); each output (the command line's table, ``results.json``, the
report) shows them in :class:`Label.display` (degrees for angles, kW for a conveyor's power). What each result
is called is declared once, in :mod:`machdyn.results.catalogue` (keys made at run time, such as
``joint.B.max_force``, by its patterns).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..units import ureg


@dataclass(frozen=True)
class Label:
    """The text of a result, its SI ``unit`` and the unit it is shown in (``display``; the SI unit if None).

    ``zero_below`` names a result whose magnitude sets the round-off scale of this one: a value smaller than
    1e-9 of it vanishes in exact arithmetic (the mean torque over a loss-free cycle) and is shown as 0.

    A capability declares its results with two more fields, which the catalogue of results
    (:mod:`machdyn.results.catalogue`) reads: ``over``, how the result reduces a series over the crank positions
    (a name of :data:`machdyn.linkage.reductions.REDUCTIONS`: "max_abs", "time_rms", "cycle", ... or "scalar" for
    a figure that is no series' reduction), and ``better``, which way a design is better by it ("lower",
    "higher", "target" for nearest a value the designer sets, "none", or "true" for a yes/no check). Both are ""
    on a label made at run time, whose result the catalogue declares by its pattern.
    """

    text: str
    unit: str = ""
    display: str | None = None
    zero_below: str | None = None
    over: str = ""
    better: str = ""

    @property
    def shown_unit(self) -> str:
        return DEFAULT_DISPLAY.get(self.unit, self.unit) if self.display is None else self.display


#: display units chosen by SI unit when a label does not say
DEFAULT_DISPLAY = {"rad": "deg"}

_SCALES = {("rad", "deg"): 180.0 / math.pi}


def display_factor(unit: str, display: str) -> float:
    """The factor from ``unit`` to ``display`` (1 for equal units)."""
    if unit == display:
        return 1.0
    if (unit, display) in _SCALES:
        return _SCALES[(unit, display)]
    return float(ureg.Quantity(1.0, unit or "dimensionless").to(display or "dimensionless").magnitude)
