"""The designer's loop: ``machdyn run --open`` opens the report, ``machdyn watch`` re-runs a saved file.

``--open`` goes through Python's :mod:`webbrowser`, which honours the ``BROWSER`` variable: the tests point it at
a small script that records the address it is given. ``watch`` runs as a real process: the test edits the file
and waits for the new results, then stops it with Ctrl-C (SIGINT), which is a normal end (exit 0).
"""

from __future__ import annotations

import json
import os
import signal
import stat
import subprocess
import sys
import time
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
MACHDYN = [sys.executable, "-c", "from machdyn.cli import app; app()"]


def _browser_recorder(tmp_path: Path) -> tuple[dict[str, str], Path]:
    log = tmp_path / "opened.txt"
    script = tmp_path / "browser.sh"
    script.write_text(f'#!/bin/sh\necho "$1" >> "{log}"\n')
    script.chmod(script.stat().st_mode | stat.S_IEXEC)
    return {**os.environ, "BROWSER": str(script)}, log


def test_run_open_opens_the_written_report(tmp_path):
    env, log = _browser_recorder(tmp_path)
    out = tmp_path / "out"
    proc = subprocess.run([*MACHDYN, "run", str(EXAMPLES / "four_bar.toml"), "--out", str(out), "--open", "-q"],
                          env=env, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    deadline = time.monotonic() + 10
    while not log.exists() and time.monotonic() < deadline:
        time.sleep(0.05)
    assert log.read_text().strip() == (out / "report.html").resolve().as_uri()


def test_watch_reruns_the_saved_file_and_stamps_each_report(tmp_path):
    problem = tmp_path / "four_bar.toml"
    text = (EXAMPLES / "four_bar.toml").read_text()
    problem.write_text(text)
    out = tmp_path / "out"
    proc = subprocess.Popen([*MACHDYN, "watch", str(problem), "--out", str(out), "--interval", "0.1"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        stamp = out / "report.stamp.js"
        deadline = time.monotonic() + 60
        while not stamp.exists() and time.monotonic() < deadline:
            time.sleep(0.1)
        first = stamp.read_text()
        torque = json.loads((out / "results.json").read_text())["scalars"]["driving_torque.max_abs"]["value"]
        assert 'class="mdview"' in (out / "report.html").read_text()

        # a mistake: reported, the previous outputs stay, marked as the last valid ones with check's message
        problem.write_text(text.replace('length = "40 mm"', 'length = "-40 mm"', 1))
        deadline = time.monotonic() + 60
        while stamp.read_text() == first and time.monotonic() < deadline:
            time.sleep(0.1)
        marked = stamp.read_text()
        assert marked.splitlines()[0] == first.splitlines()[0]  # the same stamp: the open report does not re-load
        assert "must be > 0 m; got '-40 mm'" in marked and "mechanism.crank.length" in marked
        assert json.loads((out / "results.json").read_text())["scalars"]["driving_torque.max_abs"]["value"] == torque

        # fixed with a longer crank: a new run, a new stamp, a larger peak torque
        problem.write_text(text.replace('length = "40 mm"', 'length = "45 mm"', 1))
        deadline = time.monotonic() + 60
        while stamp.read_text() == marked and time.monotonic() < deadline:
            time.sleep(0.1)
        assert stamp.read_text() != marked and stamp.read_text().endswith("window.machdynInvalid = null;\n")
        again = json.loads((out / "results.json").read_text())["scalars"]["driving_torque.max_abs"]["value"]
        assert again != torque
    finally:
        proc.send_signal(signal.SIGINT)
        _out, err = proc.communicate(timeout=90)  # generous: a loaded CI machine may be mid-run
    assert proc.returncode == 0, err
    assert "report updated" in err and "not updated (exit 2)" in err and "stopped watching" in err
    # the terminal's banner follows the check's message
    assert "must be > 0 m; got '-40 mm'" in err
    assert "Last valid results shown. The saved file has mistakes (above)" in err
    assert "Traceback" not in err


def test_the_four_bar_report_fits_in_an_email(tmp_path):
    """The size budget of an interactive report: the four-bar example's at most 5 MB (docs/report.md)."""
    out = tmp_path / "out"
    proc = subprocess.run([*MACHDYN, "run", str(EXAMPLES / "four_bar.toml"), "--out", str(out), "-q"],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    size = (out / "report.html").stat().st_size
    assert size <= 5 * 2**20, f"report.html is {size / 2**20:.2f} MB"
