"""Paths named in a problem file stay where they belong: records and stores inside the problem file's folder,
``machdyn:`` inside the shipped data; an error never prints another file's content."""

from __future__ import annotations

import os
import time
from pathlib import Path

import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.errors import InputError
from machdyn.vibration.signals import read_record
from machdyn.vibration.study import resolve_record

from .conftest import ROOT, sweep_text

SECRET = "TOPSECRET-first-line-of-someone-elses-file"
RECORD_EXAMPLE = ROOT / "examples" / "vibration_record.toml"


def _vibration_problem(folder: Path, record: str) -> Path:
    text = RECORD_EXAMPLE.read_text().replace('record = "machdyn:examples/signals/tamper_before.csv"',
                                              f'record = "{record}"')
    path = folder / "screen.toml"
    path.write_text(text)
    return path


@pytest.fixture
def project(tmp_path):
    """A project folder inside tmp_path, and a file beside it (outside) that must stay private."""
    (tmp_path / "secret.csv").write_text(SECRET + "\n1,2\n")
    folder = tmp_path / "project"
    folder.mkdir()
    return folder


@pytest.mark.parametrize("command", ["check", "run"])
def test_sweep_store_outside_the_problem_folder_is_refused_and_nothing_outside_is_touched(project, command):
    victim = project.parent / "victim"
    victim.mkdir()
    (victim / "part-000000.parquet").write_text("precious")
    path = project / "p.toml"
    path.write_text(sweep_text(extra='store = "../victim"\n'))
    args = [command, str(path)] + (["--out", str(project / "out")] if command == "run" else [])
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 2, result.output
    assert "sweep.store" in result.output and "inside the problem file's folder" in result.output
    assert (victim / "part-000000.parquet").read_text() == "precious"


def test_sweep_store_naming_the_problem_folder_itself_is_refused(project):
    path = project / "p.toml"
    path.write_text(sweep_text(extra='store = "."\n'))
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 2 and "sweep.store" in result.output


@pytest.mark.parametrize("how", ["relative", "absolute", "symlink"])
def test_record_outside_the_problem_folder_is_refused_without_echoing_its_content(project, how):
    if how == "symlink":
        os.symlink(project.parent / "secret.csv", project / "link.csv")
        record = "link.csv"
    else:
        record = "../secret.csv" if how == "relative" else str(project.parent / "secret.csv")
    result = CliRunner().invoke(app, ["check", str(_vibration_problem(project, record))])
    assert result.exit_code == 2
    assert "signals.record" in result.output and "outside" in result.output
    assert SECRET not in result.output


@pytest.mark.parametrize("name", ["machdyn:../__init__.py", "machdyn:examples/../../cli.py", "machdyn:/etc/passwd"])
def test_machdyn_prefix_names_only_shipped_data(name):
    with pytest.raises(InputError, match="shipped with machdyn|outside machdyn's data folder"):
        resolve_record(name)


def test_record_that_is_a_folder_a_fifo_or_a_symlink_loop_gets_a_precise_message(tmp_path):
    (tmp_path / "folder.csv").mkdir()
    os.mkfifo(tmp_path / "pipe.csv")
    os.symlink(tmp_path / "loop_b.csv", tmp_path / "loop_a.csv")
    os.symlink(tmp_path / "loop_a.csv", tmp_path / "loop_b.csv")
    with pytest.raises(InputError, match="is a folder, not a CSV file"):
        read_record(tmp_path / "folder.csv")
    start = time.perf_counter()
    with pytest.raises(InputError, match="not a regular file"):
        read_record(tmp_path / "pipe.csv")  # never opened: reading a FIFO would wait for a writer
    assert time.perf_counter() - start < 1
    with pytest.raises(InputError, match="loop of symbolic links"):
        read_record(tmp_path / "loop_a.csv")
    with pytest.raises(InputError, match="loop of symbolic links"):
        resolve_record("loop_a.csv", source=tmp_path / "p.toml")


def test_record_with_millions_of_columns_is_refused_before_it_is_parsed(tmp_path):
    path = tmp_path / "wide.csv"
    path.write_text("time [s]," + ",".join(f"c{i} [m/s]" for i in range(1_000_000)) + "\n0,1\n")
    start = time.perf_counter()
    with pytest.raises(InputError, match="more than 65 columns"):
        read_record(path)
    assert time.perf_counter() - start < 2


def test_a_repeated_channel_name_is_reported_as_repeated(tmp_path):
    path = tmp_path / "twice.csv"
    path.write_text("time [s],front [m/s^2],front [m/s^2]\n0,1,2\n0.001,1,2\n")
    with pytest.raises(InputError, match="must be unique; column 3 repeats column 2"):
        read_record(path)


def test_a_long_header_is_not_echoed_in_full(tmp_path):
    path = tmp_path / "long.csv"
    path.write_text("x" * 500_000 + "\n0\n")
    with pytest.raises(InputError) as caught:
        read_record(path)
    assert len(str(caught.value)) < 400


def test_a_huge_unknown_key_gives_a_short_message(tmp_path):
    path = tmp_path / "p.toml"
    path.write_text(f'{ "k" * 500_000 } = 1\n' + (ROOT / "examples" / "four_bar.toml").read_text())
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 2 and "unknown key" in result.output
    assert len(result.output) < 3000
