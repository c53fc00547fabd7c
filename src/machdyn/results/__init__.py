"""The results stage: every scalar result in SI with its label and unit, and the one summary builder.

:mod:`.catalogue` declares every result once (key, label, SI and display unit, reductions, producer) and maps
the old names to the keys; :mod:`.labels` holds :class:`Label` and the display units; :mod:`.store` holds the
results of a run; :mod:`.summary` builds the summary table that the command line, the report and the Python API
all show; :mod:`.linkage` computes the scalar results of a linkage analysis; :mod:`.population` evaluates a
population of designs for sweeps, explorations and the optimiser under the catalogue's keys.
"""

from __future__ import annotations

from .catalogue import label_for
from .labels import Label
from .store import Results, collect
from .summary import Summary, SummaryRow, summarise

__all__ = ["Label", "Results", "Summary", "SummaryRow", "collect", "label_for", "summarise"]
