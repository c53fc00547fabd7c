"""Wall time of the command line: `machdyn --version` (start-up) and `machdyn run` on every shipped example.

Each command runs as a whole process, `--repeats` times after one warm-up; the table gives min / median / max
in seconds. Run it with `make bench` or `.venv/bin/python bench/cli.py [--repeats N]`.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
MACHDYN = [sys.executable, "-m", "machdyn.cli"]


def wall_times(command: list[str], repeats: int) -> list[float]:
    """Seconds per run of ``command`` (after one warm-up run)."""
    subprocess.run(command, check=False, capture_output=True, cwd=ROOT)
    out = []
    for _ in range(repeats):
        started = time.perf_counter()
        subprocess.run(command, check=False, capture_output=True, cwd=ROOT)
        out.append(time.perf_counter() - started)
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    rows = {"machdyn --version": wall_times([*MACHDYN, "--version"], args.repeats)}
    with tempfile.TemporaryDirectory() as tmp:
        for example in sorted((ROOT / "examples").glob("*.toml")):
            command = [*MACHDYN, "run", str(example), "--out", str(Path(tmp) / example.stem), "--quiet"]
            rows[f"machdyn run {example.name}"] = wall_times(command, args.repeats)
    width = max(len(k) for k in rows)
    print(f"{'command':<{width}}  {'min s':>7}  {'median s':>8}  {'max s':>7}")
    for name, times in rows.items():
        print(f"{name:<{width}}  {min(times):7.3f}  {statistics.median(times):8.3f}  {max(times):7.3f}")
    print(json.dumps({k: {"min": min(v), "median": statistics.median(v), "max": max(v)} for k, v in rows.items()}))


if __name__ == "__main__":
    main()
