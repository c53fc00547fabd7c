"""Reports of machdyn results: a self-contained HTML report, tables (pandas) and plots (matplotlib).

- :func:`render_report` builds one HTML document (inline CSS and SVG, no scripts, no external resources) from
  the summary, the warnings and each stage's sections.
- :mod:`machdyn.report.tables`: :func:`~machdyn.report.tables.analysis_frames` (DataFrames with units in the
  headers).
- :mod:`machdyn.report.plots`: plotting functions that take a matplotlib ``ax`` and return it.
- one module per stage (:mod:`.mechanism`, :mod:`.sweep`, :mod:`.rotary_screen` ...) with its ``sections``.

The report formats and plots results; it computes none. Only this package imports matplotlib.
"""

from .html import format_value, render_report
from .mechanism import analysis_figures
from .tables import analysis_frames

__all__ = ["analysis_figures", "analysis_frames", "format_value", "render_report"]
