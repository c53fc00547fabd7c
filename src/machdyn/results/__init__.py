"""The results stage: every scalar result in SI with its label and unit, and the one summary builder.

:mod:`.labels` is the registry of what each result is called and how it is shown; :mod:`.store` holds the
results of a run; :mod:`.summary` builds the summary table that the command line, the report and the Python API
all show; :mod:`.linkage` computes the scalar results of a linkage analysis.
"""

from __future__ import annotations

from .catalogue import label_for
from .labels import Label
from .store import Results, collect
from .summary import Summary, SummaryRow, summarise

__all__ = ["Label", "Results", "Summary", "SummaryRow", "collect", "label_for", "summarise"]
