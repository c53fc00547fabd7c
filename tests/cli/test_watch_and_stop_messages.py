"""What ``watch`` and a stopped run say: a missing file or standard input is refused at once, a locked output
folder is named as such, a save that keeps the size and the modification time is seen, a stopped run says
whether a rerun resumes, options that do nothing say so, and an analysis failure is not headed as bad input."""

from __future__ import annotations

import fcntl
import os
from pathlib import Path

import pytest
import typer
from typer.testing import CliRunner

from machdyn import watching
from machdyn.cli import _run_guard, _Terminated, _TimedOut, app
from machdyn.errors import AnalysisError
from machdyn.outputs import LOCK
from machdyn.studies.exploration.execution import RESTARTS
from machdyn.studies.exploration.run import ExplorationInterrupted
from problem_texts import four_bar

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.mark.parametrize(("name", "said"), [("typo.toml", "'typo.toml' does not exist; nothing to watch"),
                                            ("-", "standard input cannot be watched")])
def test_watch_refuses_a_missing_file_and_standard_input_at_once(tmp_path, name, said):
    result = CliRunner().invoke(app, ["watch", name, "--out", str(tmp_path / "out")])
    assert result.exit_code == 2 and said in result.output


def test_watch_on_a_folder_another_run_holds_says_so_not_fix_the_file(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    holder = os.open(out / LOCK, os.O_RDWR | os.O_CREAT)  # another run's hold on the folder
    fcntl.flock(holder, fcntl.LOCK_EX | fcntl.LOCK_NB)
    os.pwrite(holder, b"4242\n", 0)
    try:
        result = CliRunner().invoke(app, ["watch", str(EXAMPLES / "four_bar.toml"), "--out", str(out)])
    finally:
        os.close(holder)
    assert result.exit_code == 1
    assert "another machdyn run (process 4242) is writing the output folder" in result.output
    assert "fix the file" not in result.output


class _Looked(Exception):
    pass


def _looks(monkeypatch, limit: int) -> None:
    """Let the watch loop look ``limit`` times, then end it (instead of sleeping between looks)."""
    count = [0]

    def sleep(_seconds: float) -> None:
        count[0] += 1
        if count[0] >= limit:
            raise _Looked

    monkeypatch.setattr(watching.time, "sleep", sleep)


def test_a_save_that_keeps_size_and_modification_time_is_run_again(tmp_path, monkeypatch):
    problem = tmp_path / "p.toml"
    problem.write_text('speed = "10 rad/s"\n')
    stamp = problem.stat().st_mtime_ns
    seen: list[str] = []

    def run(_stamp: str) -> int:
        seen.append(problem.read_text())
        if len(seen) == 1:  # an editor's save within the same clock tick: same size, same time, new content
            problem.write_text('speed = "20 rad/s"\n')
            os.utime(problem, ns=(stamp, stamp))
        return 0

    _looks(monkeypatch, 5)
    with pytest.raises(_Looked):
        watching.watch_file(problem, tmp_path / "out", interval=0.1, run=run)
    assert seen == ['speed = "10 rad/s"\n', 'speed = "20 rad/s"\n']


@pytest.mark.parametrize(("code", "said", "not_said"), [
    (1, "the run failed (the message above says why)", "fix the file"),
    (2, "fix the file and save it again", "the run failed"),
])
def test_the_line_after_a_failed_watched_run_fits_its_exit_code(tmp_path, monkeypatch, capsys, code, said, not_said):
    problem = tmp_path / "p.toml"
    problem.write_text("x = 1\n")
    watching.watch_file(problem, tmp_path / "out", interval=0.1, run=lambda _s: code, max_runs=1)
    err = capsys.readouterr().err
    assert f"not updated (exit {code}); {said}" in err and not_said not in err


def _stopped(capsys, stop: BaseException) -> str:
    with pytest.raises(typer.Exit):
        with _run_guard(Path(os.getcwd()) / "out", 100.0):
            raise stop
    return capsys.readouterr().err


def test_a_stopped_run_that_is_no_exploration_says_it_restarts(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    timed = _stopped(capsys, _TimedOut())
    assert "stopped: the run took longer than --max-time 100 s" in timed and RESTARTS in timed
    assert "run again to resume" not in timed
    terminated = _stopped(capsys, _Terminated())
    assert "stopped: the run was terminated" in terminated and "starts from the beginning" in terminated


def test_a_stopped_exploration_says_what_a_rerun_reuses(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    stop = ExplorationInterrupted(tmp_path / "out" / "sweep.parquet", 3, 8)
    stop.__cause__ = _TimedOut()
    err = _stopped(capsys, stop)
    assert "3 of 8 partition(s) of the design-space exploration are on disk" in err and RESTARTS not in err


def test_workers_outside_an_exploration_are_said_to_be_ignored(tmp_path):
    problem = tmp_path / "p.toml"
    problem.write_text(four_bar(positions=12))
    result = CliRunner().invoke(app, ["run", str(problem), "--out", str(tmp_path / "o"), "--workers", "2"])
    assert result.exit_code == 0, result.output
    assert result.output.count("--workers was ignored: only a design-space exploration") == 1


def test_an_analysis_failure_is_headed_as_one_not_as_problems_in_the_file(tmp_path, monkeypatch):
    import machdyn.runner

    def fails(*_args, **_kwargs):
        raise AnalysisError("the solver did not converge")

    monkeypatch.setattr(machdyn.runner, "run_problem", fails)
    result = CliRunner().invoke(app, ["run", str(EXAMPLES / "four_bar.toml"), "--out", str(tmp_path / "o")])
    assert result.exit_code == 1
    assert result.output.startswith("error: the analysis of") and "problem(s)" not in result.output
