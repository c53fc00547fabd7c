"""The exploration store and the output folder as transactions: runs killed at random moments resume to exactly
the uninterrupted result, a changed problem never destroys the previous store, partitions are verified before
they are reused, one run at a time, and a swap cut half-way is completed."""

from __future__ import annotations

import json
import os
import random
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pandas as pd
import pytest

from machdyn.errors import OperationalError
from machdyn.outputs import LOCK, OutputSet, acquire_lock, release_lock
from machdyn.studies.exploration import explore
from machdyn.studies.exploration.store import PartitionStore

from .conftest import ROOT, machdyn, sweep_text

TEXT = sweep_text(samples=256, partition=16)
CHANGED = TEXT.replace('mass = "0.5 kg"', 'mass = "0.7 kg"')
#: 64 partitions that take a few seconds in all, so that a kill can land in the middle of the exploration.
BIG = sweep_text(samples=16384, partition=256).replace("positions = 36", "positions = 180")
BIG_CHANGED = BIG.replace('mass = "0.5 kg"', 'mass = "0.7 kg"')


def _reference(text: str, folder: Path) -> pd.DataFrame:
    """The exploration of ``text`` run without interruption, in this process."""
    return explore(text, store=folder).frame()


def _store(out: Path) -> pd.DataFrame:
    return pd.read_parquet(out / "sweep.parquet").sort_values("design", ignore_index=True)


def _start(problem: Path, out: Path, stderr=subprocess.DEVNULL) -> subprocess.Popen:
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    return subprocess.Popen([sys.executable, "-m", "machdyn.cli", "run", str(problem), "--out", str(out), "-q"],
                            env=env, stdout=subprocess.DEVNULL, stderr=stderr, text=True)


def _kill_when(process: subprocess.Popen, ready, seconds: float) -> None:
    """SIGKILL ``process`` ``seconds`` after ``ready()`` first holds (or when it ends by itself)."""
    deadline = time.monotonic() + 120
    while not ready() and process.poll() is None and time.monotonic() < deadline:
        time.sleep(0.05)
    time.sleep(seconds)
    if process.poll() is None:
        process.send_signal(signal.SIGKILL)
    process.wait(timeout=60)


def _parts(folder: Path) -> int:
    return len(list(folder.glob("part-*.parquet"))) if folder.is_dir() else 0


def _leftovers(out: Path) -> list[str]:
    names = [p.name for p in out.rglob("*")]
    return [n for n in names if n.endswith((".tmp", ".part")) or n.startswith(".machdyn-partial-")
            or ".pending-" in n or n.endswith(".old")]


def test_runs_killed_at_random_moments_resume_to_the_uninterrupted_result(tmp_path):
    expected = _reference(BIG, tmp_path / "reference.parquet")
    problem = tmp_path / "p.toml"
    problem.write_text(BIG)
    out = tmp_path / "out"
    chance = random.Random(20261124)
    cut = []
    # random moments in the run's progress, not in seconds (a fast machine finishes 64 partitions in a second or
    # two): each run is killed once its store holds a random, growing number of the 64 partitions
    for held in sorted(chance.sample(range(1, 60), 3)):
        run = _start(problem, out)
        _kill_when(run, lambda held=held: _parts(out / "sweep.parquet") >= held, chance.uniform(0.0, 0.05))
        cut.append(not (out / "results.json").exists())
    assert any(cut)  # at least one kill came before the run could finish
    code, _, err, _ = machdyn("run", str(problem), "--out", str(out), "-q")
    assert code == 0, err
    pd.testing.assert_frame_equal(_store(out), expected)
    assert json.loads((out / "results.json").read_text())["scalars"]["sweep.designs"]["value"] == 16384
    assert _leftovers(out) == []


def test_a_killed_run_of_a_changed_problem_keeps_the_previous_store_and_results(tmp_path):
    problem = tmp_path / "p.toml"
    problem.write_text(BIG)
    out = tmp_path / "out"
    code, _, err, _ = machdyn("run", str(problem), "--out", str(out), "-q")
    assert code == 0, err
    before, results = _store(out), (out / "results.json").read_bytes()
    problem.write_text(BIG_CHANGED)
    run = _start(problem, out)
    _kill_when(run, lambda: any(_parts(p) >= 2 for p in out.glob(".sweep.parquet.pending-*")), 0.0)
    pd.testing.assert_frame_equal(_store(out), before)  # the previous store is whole ...
    assert (out / "results.json").read_bytes() == results  # ... and still what results.json describes
    code, _, err, _ = machdyn("run", str(problem), "--out", str(out), "-q")
    assert code == 0, err
    pd.testing.assert_frame_equal(_store(out), _reference(BIG_CHANGED, tmp_path / "changed.parquet"))
    assert _leftovers(out) == []


def test_resume_recomputes_duplicated_foreign_truncated_and_corrupted_partitions(tmp_path):
    store = tmp_path / "s.parquet"
    expected = explore(TEXT, store=store).frame()
    other = tmp_path / "other.parquet"
    explore(TEXT.replace("seed = 3", "seed = 4"), store=other)
    shutil.copy(store / "part-000000.parquet", store / "part-000001.parquet")  # a duplicate under another number
    shutil.copy(other / "part-000002.parquet", store / "part-000002.parquet")  # from another exploration
    (store / "part-000003.parquet").write_bytes((store / "part-000003.parquet").read_bytes()[:500])  # truncated
    flipped = bytearray((store / "part-000004.parquet").read_bytes())
    flipped[len(flipped) // 3] ^= 0xFF
    (store / "part-000004.parquet").write_bytes(bytes(flipped))
    again = explore(TEXT, store=store)
    assert again.computed == 4 and again.reused == 12
    notes = " ".join(again.notes)
    for index, reason in ((1, "under another number"), (2, "another exploration"), (3, "cannot be read"),
                          (4, "")):
        assert f"Partition {index} " in notes and reason in notes
    pd.testing.assert_frame_equal(again.frame(), expected)


def test_a_second_run_on_the_same_output_folder_is_refused_at_once(tmp_path):
    problem = tmp_path / "p.toml"
    problem.write_text(TEXT)
    out = tmp_path / "out"
    out.mkdir()
    acquire_lock(out / LOCK, "the test's folder")
    try:
        code, _, err, seconds = machdyn("run", str(problem), "--out", str(out))
    finally:
        release_lock(out / LOCK)
    assert code == 1
    assert f"another machdyn run (process {os.getpid()}) is writing the output folder" in err
    assert len(err.strip().splitlines()) == 1 and seconds < 60


def test_a_second_exploration_of_the_same_store_is_refused(tmp_path):
    first = PartitionStore(tmp_path / "s.parquet", "f" * 64, {})
    try:
        code = ("from machdyn.studies.exploration.store import PartitionStore as P; "
                f"P({str(tmp_path / 's.parquet')!r}, 'f' * 64, {{}})")
        done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                              env={**os.environ, "PYTHONPATH": str(ROOT / "src")}, timeout=60)
    finally:
        first.close()
    assert done.returncode != 0
    assert "OperationalError: another machdyn run" in done.stderr and "is writing the exploration store" in done.stderr
    with pytest.raises(OperationalError, match="exists and is not a folder"):
        (tmp_path / "file.parquet").write_text("x")
        PartitionStore(tmp_path / "file.parquet", "f" * 64, {})


def test_leftovers_of_killed_runs_are_removed_on_resume(tmp_path):
    problem = tmp_path / "p.toml"
    problem.write_text(TEXT)
    out = tmp_path / "out"
    code, _, err, _ = machdyn("run", str(problem), "--out", str(out), "-q")
    assert code == 0, err
    (out / "sweep.parquet" / ".part-000002.parquet.12345.tmp").write_bytes(b"half a partition")
    (out / ".results.json.abc123.part").write_text("{")
    (out / ".machdyn-partial-zz").mkdir()
    (out / ".machdyn-partial-zz" / "results.json").write_text("{}")
    code, _, err, _ = machdyn("run", str(problem), "--out", str(out), "-q")
    assert code == 0, err
    assert _leftovers(out) == []


def test_an_output_set_cut_after_its_journal_is_completed_by_the_next_run(tmp_path, monkeypatch):
    out = tmp_path / "out"
    first = OutputSet(out)
    first.text("results.json", "old\n")
    first.text("old.csv", "old\n")
    first.commit()
    second = OutputSet(out)
    second.text("results.json", "new\n")
    second.text("report.html", "new\n")
    real = os.replace
    moved = []

    def cut(a, b):  # the process dies after moving the first file of the set
        if str(a).startswith(str(second.stage)) and Path(a).name != ".commit.json":
            if moved:
                raise KeyboardInterrupt
            moved.append(a)
        return real(a, b)

    monkeypatch.setattr(os, "replace", cut)
    with pytest.raises(KeyboardInterrupt):
        second.commit()
    monkeypatch.setattr(os, "replace", real)
    release_lock(out / LOCK)
    OutputSet(out).abort()  # the next run opening the folder completes the committed set first
    assert (out / "results.json").read_text() == "new\n" and (out / "report.html").read_text() == "new\n"
    assert not (out / "old.csv").exists()
    assert list(json.loads((out / ".machdyn-outputs.json").read_text())["files"]) == ["results.json", "report.html"]


def test_a_store_swap_cut_between_its_two_renames_is_completed(tmp_path):
    final = tmp_path / "s.parquet"
    old = explore(TEXT, store=final).frame()
    changed = tmp_path / "c.parquet"
    new = explore(CHANGED, store=changed).frame()
    fingerprint = json.loads((changed / "_exploration.json").read_text())["fingerprint"]
    pending = tmp_path / f".s.parquet.pending-{fingerprint[:16]}"
    changed.rename(pending)
    (pending / ".complete").write_text(fingerprint)
    final.rename(tmp_path / ".s.parquet.old")  # killed here: no store at all
    assert explore(CHANGED, store=final).computed == 0
    pd.testing.assert_frame_equal(pd.read_parquet(final).sort_values("design", ignore_index=True), new)
    assert not old.equals(new) and not (tmp_path / ".s.parquet.old").exists()


def test_sigterm_stops_a_run_and_leaves_no_staging_folder(tmp_path):
    problem = tmp_path / "p.toml"
    problem.write_text(BIG)
    out = tmp_path / "out"
    run = _start(problem, out, stderr=subprocess.PIPE)
    deadline = time.monotonic() + 120
    while _parts(out / "sweep.parquet") < 1 and run.poll() is None and time.monotonic() < deadline:
        time.sleep(0.05)
    run.send_signal(signal.SIGTERM)
    _, err = run.communicate(timeout=60)
    assert run.returncode == 143, err
    assert "stopped: the run was terminated" in err
    assert "Traceback" not in err
    assert _leftovers(out) == []


def test_a_worker_killed_during_a_run_has_its_partitions_retried(tmp_path):
    from distributed import LocalCluster

    text = sweep_text(samples=4096, partition=128).replace("positions = 36", "positions = 180")
    expected = _reference(text, tmp_path / "reference.parquet")
    killed = []
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address="127.0.0.1:0", silence_logs=50) as cluster:
        pids = [nanny.process.pid for nanny in cluster.workers.values()]

        def kill_one(index: int) -> None:  # after the first partition comes back, one worker dies (SIGKILL)
            if not killed:
                os.kill(pids[0], signal.SIGKILL)
                killed.append(index)

        done = explore(text, store=tmp_path / "dask", scheduler=cluster.scheduler_address, on_partition=kill_one)
    assert killed and done.computed == 32
    pd.testing.assert_frame_equal(done.frame(), expected)
