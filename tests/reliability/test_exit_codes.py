"""Operational failures exit 1 with their cause in one line, never 4 ("internal error ... please report it")."""

from __future__ import annotations

import errno

import pytest
from typer.testing import CliRunner

from machdyn.cli import app

from .conftest import machdyn, sweep_text


def _one_line_exit_1(code: int, err: str) -> None:
    assert code == 1, err
    assert "internal error" not in err and "Traceback" not in err
    assert len(err.strip().splitlines()) == 1, err


def test_an_exploration_store_that_is_a_file_exits_1_in_one_line(write):
    path = write(sweep_text(samples=64))
    out = path.parent / "out"
    out.mkdir()
    (out / "sweep.parquet").write_text("not a folder")
    code, _, err, _ = machdyn("run", str(path), "--out", str(out), "-q")
    _one_line_exit_1(code, err)
    assert "exists and is not a folder" in err
    assert (out / "sweep.parquet").read_text() == "not a folder"


def test_an_output_folder_that_is_a_file_exits_1_in_one_line(write):
    path = write(sweep_text(samples=64))
    (path.parent / "out").write_text("a file")
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(path.parent / "out")])
    _one_line_exit_1(result.exit_code, result.stderr)


def test_a_full_disk_while_writing_partitions_exits_1_in_one_line(write, monkeypatch):
    import pyarrow.parquet as pq

    def full(*args, **kwargs):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(pq, "write_table", full)
    path = write(sweep_text(samples=64))
    out = path.parent / "out"
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(out)])
    _one_line_exit_1(result.exit_code, result.stderr)
    assert "cannot write partition 0" in result.stderr and "No space left on device" in result.stderr
    assert not list((out / "sweep.parquet").glob(".part-*"))


def test_a_scheduler_without_workers_exits_1_in_one_line(write):
    pytest.importorskip("distributed")
    from distributed import LocalCluster

    path = write(sweep_text(samples=64))
    with LocalCluster(n_workers=0, processes=False, protocol="tcp://", host="127.0.0.1",
                      dashboard_address="127.0.0.1:0") as cluster:
        code, _, err, seconds = machdyn("run", str(path), "--out", str(path.parent / "out"), "--scheduler",
                                        cluster.scheduler_address, timeout=180)
    _one_line_exit_1(code, err)
    assert "has no worker" in err and seconds < 90
