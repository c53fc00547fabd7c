"""The HTML report: self-contained, escaped, complete, and quick to render."""

from __future__ import annotations

import re

import numpy as np
import pytest

from machdyn.report import format_value, render_report
from machdyn.report.mechanism import analysis_sections, torque_harmonics
from machdyn.results.linkage import analysis_scalars, linkage_scalars

NASTY = '<script>alert("x")</script> & <b>bold</b>'


def _sections(analysis, shaking_about):
    """The report sections of an analysis, with the harmonics the results stage gives (6 orders)."""
    designs = np.ndim(analysis.forces.driving_torque) == 2
    scalars = {} if designs else linkage_scalars(analysis, harmonic_orders=6)[0]
    return analysis_sections(analysis, shaking_about=shaking_about, harmonics=torque_harmonics(scalars))


def _render(analysis=None, extra=(), shaking_about=(0.0, 0.0), **kw):
    args = dict(
        title=f"Report {NASTY}",
        problem_text=f"[mechanism]\nname = '{NASTY}'\n",
        summary_rows=[(f"quantity {NASTY}", 1.23456789, "N*m"), ("text value", NASTY, ""), ("n", 3, "")],
        warnings=[f"warning {NASTY}"],
        sections=[*(_sections(analysis, shaking_about) if analysis is not None else []), *extra],
    )
    args.update(kw)
    return render_report(**args)


def test_self_contained(any_analysis):
    html = _render(any_analysis)
    assert html.startswith("<!DOCTYPE html>")
    assert not re.search(r"""(src|href)\s*=\s*["']?\s*(https?:)?//""", html, re.I)
    assert not re.search(r"<(script|link|iframe|img|object|embed)\b", html, re.I)
    assert "@import" not in html and "url(http" not in html
    # every local reference points to an id in the same document
    ids = set(re.findall(r'\bid="([^"]+)"', html))
    for ref in re.findall(r'href="#([^"]+)"', html) + re.findall(r"url\(#([^)]+)\)", html):
        assert ref in ids, ref


def test_user_text_is_escaped(four_bar_analysis):
    html = _render(four_bar_analysis)
    assert "<script>" not in html and "<b>bold</b>" not in html
    escaped = "&lt;script&gt;alert(&#34;x&#34;)&lt;/script&gt; &amp; &lt;b&gt;bold&lt;/b&gt;"
    # title (twice), problem text, summary quantity and value, warning
    assert html.count(escaped) >= 6


def test_contents(four_bar_analysis):
    html = _render(four_bar_analysis)
    for section in ("summary", "warnings", "diagnostics", "plots", "input"):
        assert f'id="{section}"' in html
    assert "1.235" in html and "N·m" in html  # summary row, 4 significant digits
    assert "Grashof type" in html and "Transmission angle, minimum" in html and "Time ratio" in html
    for key in ("mechanism", "motion", "joints", "torque", "shaking", "energy", "harmonics"):
        assert f'id="fig-{key}"' in html
    assert html.count("<svg") == 7
    assert "<?xml" not in html and "<!DOCTYPE svg" not in html
    ids = re.findall(r'\bid="([^"]+)"', html)
    assert len(ids) == len(set(ids)), "element ids must be unique across the inline SVGs"


def test_without_analysis_and_with_extra_sections():
    extra = "<table class='conveyor'><tr><td>capacity</td><td>12.5</td></tr></table>"
    html = _render(None, warnings=[], extra=[("Capacity", extra), ("Screw conveyor", "<p>fill 30 %</p>")])
    assert "<svg" not in html and 'id="diagnostics"' not in html
    assert extra in html  # trusted fragments go in as they are
    assert "<h2>Screw conveyor</h2>" in html and "<p>fill 30 %</p>" in html
    assert 'href="#screw-conveyor"' in html, "every section has a link in the navigation"
    assert "No warnings." in html


def test_design_variants_are_reported(sweep_analysis):
    html = _render(sweep_analysis)
    assert html.count("<svg") >= 6
    assert "Design variant 0" in html


def test_scalars_as_summary_rows(slider_crank_analysis):
    rows = [(k, v["value"], v["unit"]) for k, v in analysis_scalars(slider_crank_analysis).items()]
    html = _render(slider_crank_analysis, summary_rows=rows)
    assert "driving_torque.max_abs" in html and "stroke.slider" in html


@pytest.mark.parametrize(
    ("value", "text"),
    [(1.23456789, "1.235"), (1234.5678, "1235"), (0.00123456, "0.001235"), (1.5e-7, "1.5e-07"), (2.0, "2"),
     (float("nan"), "n/a"), (None, "–"), (True, "yes"), (7, "7"), ([1.0, 2.5], "1, 2.5"), ("abc", "abc"),
     (-0.5, "-0.5"), (3.2e7, "3.2e+07")],
)
def test_format_value(value, text):
    assert format_value(value) == text


def test_units_are_displayed_with_dots_and_superscripts():
    from machdyn.report.html import pretty_unit

    assert pretty_unit("kg*m^2") == "kg·m²"
    assert pretty_unit("m/s^2") == "m/s²"
    assert pretty_unit("N*m") == "N·m"
    assert pretty_unit("m^-1") == "m⁻¹"


def test_shaking_moment_point_is_used(slider_crank_analysis):
    html = _render(slider_crank_analysis, shaking_about=(0.1, -0.02))
    assert "Shaking moment about (0.1, -0.02) m" in html
