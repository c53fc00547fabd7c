"""The HTML report opens in headless Chromium without console errors and with its plots.

Chromium prints every console message (errors, uncaught exceptions, warnings) as an ``INFO:CONSOLE`` line
on stderr with ``--enable-logging=stderr``; the report has no scripts, so any such line is a failure. A
page that does log an error checks that the detection works. The test is skipped only where no Chromium
executable can be found (set ``MACHDYN_CHROMIUM`` to its path to choose one).
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from machdyn.report import render_report
from machdyn.report.mechanism import analysis_sections, torque_harmonics
from machdyn.results.linkage import analysis_scalars, linkage_scalars

CANDIDATES = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable", "chrome")


def _chromium() -> str | None:
    env = os.environ.get("MACHDYN_CHROMIUM")
    if env:
        return env if Path(env).exists() else shutil.which(env)
    for name in CANDIDATES:
        found = shutil.which(name)
        if found:
            return found
    return None


CHROMIUM = _chromium()
_WHY = (
    f"MACHDYN_CHROMIUM={os.environ['MACHDYN_CHROMIUM']!r} is not an executable"
    if os.environ.get("MACHDYN_CHROMIUM")
    else f"no Chromium on PATH (looked for {', '.join(CANDIDATES)})"
)
pytestmark = pytest.mark.skipif(
    CHROMIUM is None,
    reason=f"Chromium cannot be found: {_WHY}; install it with `apt-get install -y chromium`.",
)
CONSOLE = re.compile(r":(?:INFO|WARNING|ERROR|FATAL):CONSOLE[^\]]*\]\s*(.*)")


def _open(path: Path, profile: Path) -> tuple[str, list[str]]:
    """Load ``path`` in headless Chromium; return the DOM after load and the console messages."""
    cmd = [
        CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
        "--disable-background-networking", "--disable-component-update", "--disable-sync",
        f"--user-data-dir={profile}", "--enable-logging=stderr", "--v=0", "--dump-dom", path.as_uri(),
    ]
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, f"chromium failed ({proc.returncode}): {proc.stderr[-2000:]}"
    messages = [m.group(1) for m in CONSOLE.finditer(proc.stderr)]
    return proc.stdout, messages


def test_console_errors_are_detected(tmp_path):
    page = tmp_path / "bad.html"
    page.write_text(
        "<!DOCTYPE html><html><body><p>x</p><script>console.error('broken-report');"
        "throw new Error('uncaught-in-report');</script></body></html>"
    )
    _dom, messages = _open(page, tmp_path / "profile")
    assert any("broken-report" in m for m in messages)
    assert any("Uncaught" in m and "uncaught-in-report" in m for m in messages)


@pytest.mark.parametrize("which", ["four_bar", "slider_crank"])
def test_report_opens_without_console_errors(tmp_path, which, four_bar_analysis, slider_crank_analysis):
    analysis = {"four_bar": four_bar_analysis, "slider_crank": slider_crank_analysis}[which]
    rows = [(k, v["value"], v["unit"]) for k, v in analysis_scalars(analysis).items()]
    html = render_report(
        title=f"{which} <check> & co",
        problem_text="[mechanism]\ntype = \"four_bar\"  # <b>not bold</b>\n",
        summary_rows=rows,
        warnings=["a warning with <tags> & ampersands"],
        sections=[*analysis_sections(analysis, harmonics=torque_harmonics(linkage_scalars(analysis, harmonic_orders=6)[0])),  # noqa: E501
                  ("Extra", "<table><tr><td>extra cell</td></tr></table>")],
    )
    page = tmp_path / "report.html"
    page.write_text(html, encoding="utf-8")
    dom, messages = _open(page, tmp_path / "profile")
    assert messages == [], f"console messages: {messages}"
    assert dom.count("<svg") == 7, "every plot is an inline SVG in the loaded page"
    assert len(re.findall(r"<path\b", dom)) > 100, "the SVGs carry their drawing"
    assert "<script" not in dom
    assert f"<h1>{which} &lt;check&gt; &amp; co</h1>" in dom
    assert "extra cell" in dom and "driving_torque.max_abs" in dom
    assert "a warning with &lt;tags&gt; &amp; ampersands" in dom
