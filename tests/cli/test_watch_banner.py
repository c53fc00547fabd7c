"""``machdyn watch`` over a save that fails: the terminal prints the banner *Last valid results shown* after the
check's messages, and the open report keeps its results and shows the same banner in place, in a real browser
(headless Chromium), until a valid save re-loads it."""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from machdyn import watching
from machdyn.runner import run_problem
from studio_browser import CHROMIUM, NO_CHROMIUM

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
MESSAGE = "problem file p.toml has 1 problem:\n  mechanism.crank.length: must be > 0 m; got '-40 mm'"


def _written(out: Path, stamp: str) -> None:
    """A watched run's outputs (a shaft line: its report is written in a second)."""
    run_problem(EXAMPLES / "shaft_locomotive.toml").write(out, watch_stamp=stamp)


def test_a_failed_save_marks_the_last_valid_report_and_says_so(tmp_path, capsys):
    out = tmp_path / "out"
    problem = tmp_path / "p.toml"
    problem.write_text("x = 1\n")
    # no watched report yet: nothing to mark, the terminal says so
    watching.watch_file(problem, out, interval=0.1, run=lambda _s: (2, MESSAGE), max_runs=1)
    err = capsys.readouterr().err
    assert f"Last valid results shown. The saved file has mistakes (above); no valid run in {out}/ yet." in err

    out.mkdir()  # a watched run's outputs, as RunResult.write leaves them
    (out / "report.html").write_text(report := "<html>the last valid report</html>")
    (out / watching.STAMP_FILE).write_text(watching.stamp_script("first"))
    watching.watch_file(problem, out, interval=0.1, run=lambda _s: (2, MESSAGE), max_runs=1)
    err = capsys.readouterr().err
    assert f"{out}/ keeps the last valid run, marked so in its open report." in err
    text = (out / "report.stamp.js").read_text()
    assert text.startswith('window.machdynStamp = "first";') and "must be > 0 m; got '-40 mm'" in text
    assert (out / "report.html").read_text() == report  # the results stay as they were


@pytest.mark.skipif(CHROMIUM is None, reason=NO_CHROMIUM)
def test_the_open_report_shows_the_banner_in_place_and_drops_it_on_a_valid_save(tmp_path, page):
    out = tmp_path / "out"
    _written(out, "first")
    page.goto((out / "report.html").resolve().as_uri())
    page.wait_for_selector("#summary")
    assert page.locator("#watch-stale").count() == 0
    assert watching.mark_invalid(out, MESSAGE, "10:42:07")
    page.wait_for_selector("#watch-stale:not([hidden])", timeout=10_000)
    banner = page.inner_text("#watch-stale")
    assert "Last valid results shown." in banner and "10:42:07" in banner and "got '-40 mm'" in banner
    assert page.is_visible("#summary")  # the last valid results stay under it
    started = time.monotonic()
    _written(out, "second")  # a valid save: a new stamp, the page re-loads without the banner
    deadline = time.monotonic() + 10
    while page.locator("#watch-stale:not([hidden])").count() and time.monotonic() < deadline:
        page.wait_for_timeout(100)
    assert page.locator("#watch-stale:not([hidden])").count() == 0 and time.monotonic() - started < 10
