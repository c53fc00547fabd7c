"""Design-space exploration at scale: throughput in this process and on a local Dask cluster of 1 and 2 worker
processes, and the peak memory of a 10^7-design exploration.

    python bench/explore.py throughput [--designs 65536] [--positions 360] [--repeats 3]
    python bench/explore.py memory [--designs 10000000] [--positions 12] [--workers N]
    /usr/bin/time -v python bench/explore.py memory      # the kernel's own count of the peak resident set

The job: the four-bar press drive of ``examples/four_bar_press_explore.toml`` (four link lengths and the crank
speed over a scrambled Sobol' sample), full kinetostatics at every crank position, per-design summaries written
to a Parquet folder in a temporary directory (removed afterwards). Each configuration runs ``--repeats`` times
on a fresh folder and reports min/median/max of the wall time, in designs/s and positions/s; the Dask
configurations include starting the cluster. ``memory`` runs one exploration in this process and prints the
peak resident set size of the process (``resource.getrusage``) and of the largest child process; the last line
of each command is one JSON object.
"""

from __future__ import annotations

import argparse
import json
import re
import resource
import statistics
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

EXAMPLE = ROOT / "examples" / "four_bar_press_explore.toml"


def problem(designs: int, positions: int, partition: int | None = None):
    """The press exploration with ``designs`` Sobol' designs at ``positions`` crank angles."""
    from machdyn.reading import load_problem

    text = EXAMPLE.read_text()
    text = re.sub(r"(?m)^samples = \d+", f"samples = {designs}", text)
    text = re.sub(r"(?m)^positions = \d+", f"positions = {positions}", text)
    text = re.sub(r"(?m)^partition = \d+.*$", "" if partition is None else f"partition = {partition}", text)
    return load_problem(text)


def _run(spec, workers: int | None) -> tuple[float, int]:
    from machdyn.studies.exploration import explore

    with tempfile.TemporaryDirectory(prefix="machdyn-bench-") as folder:
        started = time.perf_counter()
        done = explore(spec, store=Path(folder) / "sweep.parquet", workers=workers)
        seconds = time.perf_counter() - started
        assert done.computed == done.plan.space.partitions and done.reused == 0
        return seconds, done.digest.regular


def throughput(args) -> dict:
    spec = problem(args.designs, args.positions, args.partition)
    positions = args.designs * args.positions
    out: dict = {"designs": args.designs, "positions_per_design": args.positions,
                 "partition": spec.sweep.partition or 16384, "repeats": args.repeats, "runs": {}}
    print(f"{args.designs:,} designs x {args.positions} positions, {args.repeats} repeats (wall time, s)")
    regular = None
    for name, workers in (("in process", None), ("1 worker", 1), ("2 workers", 2)):
        times = []
        for _ in range(args.repeats):
            seconds, count = _run(spec, workers)
            times.append(seconds)
            assert regular is None or count == regular, "every configuration finds the same regular designs"
            regular = count
        lo, med, hi = min(times), statistics.median(times), max(times)
        out["runs"][name] = {"seconds": [lo, med, hi], "designs_per_s": [args.designs / t for t in (hi, med, lo)],
                             "positions_per_s": [positions / t for t in (hi, med, lo)]}
        print(f"  {name:<11} time min/median/max {lo:7.2f} {med:7.2f} {hi:7.2f}   designs/s (median) "
              f"{args.designs / med:10,.0f}   positions/s (median) {positions / med / 1e6:6.2f} M")
    base = statistics.median(t for t in [out["runs"]["1 worker"]["seconds"][1]])
    two = out["runs"]["2 workers"]["seconds"]
    out["speedup_2_vs_1_worker"] = [base / t for t in (two[2], two[1], two[0])]
    print("  2 workers / 1 worker speed-up (from max/median/min time of 2 workers): "
          + " ".join(f"{v:.2f}" for v in out["speedup_2_vs_1_worker"]))
    return out


def memory(args) -> dict:
    spec = problem(args.designs, args.positions, args.partition)
    seconds, regular = _run(spec, args.workers)
    own = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024  # kB on Linux
    children = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    positions = args.designs * args.positions
    where = "in this process" if args.workers is None else f"on {args.workers} local Dask worker(s)"
    print(f"{args.designs:,} designs x {args.positions} positions {where} in {seconds:.1f} s "
          f"({args.designs / seconds:,.0f} designs/s, {positions / seconds / 1e6:.2f} M positions/s), "
          f"{regular:,} regular; peak resident set {own:.0f} MB (largest child {children:.0f} MB)")
    return {"designs": args.designs, "positions_per_design": args.positions, "workers": args.workers,
            "seconds": seconds,
            "regular": regular, "peak_rss_mb": own, "peak_child_rss_mb": children}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("what", choices=("throughput", "memory"))
    parser.add_argument("--designs", type=int, default=None)
    parser.add_argument("--positions", type=int, default=None)
    parser.add_argument("--partition", type=int, default=None)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--workers", type=int, default=None, help="memory: run on a local Dask cluster")
    args = parser.parse_args()
    if args.what == "throughput":
        args.designs = args.designs or 65536
        args.positions = args.positions or 360
        result = throughput(args)
    else:
        args.designs = args.designs or 10_000_000
        args.positions = args.positions or 12
        result = memory(args)
    print(json.dumps(result))


if __name__ == "__main__":
    main()
