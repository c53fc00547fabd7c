"""Jupyter shows a run, its stages, its results and the studies' results as HTML: a table with units and the
plots inline. The docs notebook is executed as a user would run it (nbclient, a real kernel)."""

from __future__ import annotations

from pathlib import Path

import nbformat
from nbclient import NotebookClient

from machdyn.reading import load_problem
from machdyn.runner import run_problem

ROOT = Path(__file__).resolve().parents[2]
TABLE = '<table class="machdyn-summary"><thead><tr><th>'


def _html(cell) -> str:
    return "".join(o.get("data", {}).get("text/html", "") for o in cell.outputs)


def test_the_quickstart_notebook_runs_and_shows_its_tables_with_units_and_plots():
    path = ROOT / "docs" / "notebooks" / "quickstart.ipynb"
    nb = nbformat.read(path, as_version=4)
    NotebookClient(nb, timeout=120, kernel_name="python3",
                   resources={"metadata": {"path": str(path.parent)}}).execute()
    run_cell, results_cell = (c for c in nb.cells if c.cell_type == "code")
    run = _html(run_cell)
    assert TABLE + "quantity</th><th>value</th><th>unit</th>" in run
    assert "<td>Driving torque, max |T|</td>" in run and "<td>N·m</td>" in run  # the value's unit beside it
    assert "<svg" in run and "&lt;svg" not in run  # the report's plots inline, not escaped
    results = _html(results_cell)
    assert "<code>transmission_angle.worst</code>" in results and "<td>deg</td>" in results  # display units


def test_a_stage_of_a_sweep_shows_its_results_plot_and_table_unescaped():
    """The stage's sections are the report's: the sweep's plot and table were escaped after its scatter."""
    text = (ROOT / "examples" / "four_bar.toml").read_text(encoding="utf-8").replace("positions = 360",
                                                                                      "positions = 72")
    text += '\n[sweep]\nparameter = "mechanism.crank.length"\nvalues = ["30 mm", "40 mm", "50 mm"]\n'
    run = run_problem(load_problem(text))
    html = run.stage("sweep")._repr_html_()
    assert TABLE + "key</th>" in html and "<code>sweep.regular_count</code>" in html
    assert "<svg" in html and "&lt;svg" not in html and "<td>regular</td>" in html
    assert run.summary._repr_html_().startswith("<style>") and TABLE in run.summary._repr_html_()
