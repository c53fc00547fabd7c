"""Rich display in Jupyter: a run, its results, its summary, each stage of it and every study's and capability's
result show themselves as HTML (a summary table with units, and their plots as inline SVG).

The HTML is made by :mod:`machdyn.report.notebook`, loaded by its name only when a notebook shows an object:
no analysis imports the report (which draws with matplotlib), and ``machdyn check`` never draws.
"""

from __future__ import annotations

from importlib import import_module


class ShownInNotebook:
    """A result that Jupyter shows as HTML (``_repr_html_``, IPython's rich display protocol)."""

    __slots__ = ()

    def _repr_html_(self) -> str:
        return str(import_module("machdyn.report.notebook").html_of(self))
