"""Reports of machdyn results: a self-contained HTML report, tables (pandas) and plots (matplotlib).

- :func:`render_report` builds one HTML document (inline CSS and SVG, no scripts, no external resources).
- :mod:`machdyn.report.tables`: :func:`~machdyn.report.tables.analysis_frames` (DataFrames with units in
  the headers) and :func:`~machdyn.report.tables.analysis_scalars` (every scalar with its unit).
- :mod:`machdyn.report.plots`: plotting functions that take a matplotlib ``ax`` and return it.

Only this package imports matplotlib; the analysis modules do not.
"""

from .html import analysis_figures, format_value, render_report
from .tables import analysis_frames, analysis_scalars, summary_rows

__all__ = [
    "analysis_figures",
    "analysis_frames",
    "analysis_scalars",
    "format_value",
    "render_report",
    "summary_rows",
]
