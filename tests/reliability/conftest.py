"""Problems and helpers shared by the reliability tests: each test names the failure it guards against."""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

from problem_texts import four_bar

ROOT = Path(__file__).resolve().parents[2]

FOUR_BAR = four_bar("reliability", positions=36)

SWEEP = """
[[sweep.quantities]]
parameter = "mechanism.crank.length"
start = "30 mm"
stop = "50 mm"

[[sweep.quantities]]
parameter = "drive.speed"
start = "5 rad/s"
stop = "15 rad/s"
"""


def sweep_text(samples: int = 256, partition: int = 32, extra: str = "", base: str = FOUR_BAR) -> str:
    """The four-bar with a two-quantity Sobol' exploration of ``samples`` designs."""
    head = f'\n[sweep]\nmethod = "sobol"\nsamples = {samples}\nseed = 3\npartition = {partition}\n{extra}'
    return base + head + SWEEP


def machdyn(*args: str, cwd: Path | None = None, timeout: float = 120.0, **popen) -> tuple[int, str, str, float]:
    """Run ``python -m machdyn.cli args`` in a fresh process: (exit code, stdout, stderr, seconds)."""
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "machdyn.cli", *args], capture_output=True, text=True, env=env,
                          cwd=cwd, timeout=timeout, **popen)
    return done.returncode, done.stdout, done.stderr, time.perf_counter() - start


@pytest.fixture
def write(tmp_path):
    """Write a problem file into the test's folder and return its path."""

    def _write(text: str, name: str = "problem.toml") -> Path:
        path = tmp_path / name
        path.write_text(text)
        return path

    return _write
