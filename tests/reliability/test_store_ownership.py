"""An exploration writes only into its own store: a folder that merely looks like one (partitions without a
manifest), or the store of another problem file, is refused unless the run is asked to replace it (``--replace``);
this problem file's own earlier store is replaced, and the run says so."""

from __future__ import annotations

from pathlib import Path

import pandas as pd
import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.errors import OperationalError
from machdyn.studies import explore

from .conftest import sweep_text

TEXT = sweep_text(samples=16, partition=8)
OTHER = TEXT.replace('mass = "0.5 kg"', 'mass = "0.7 kg"')


def _files(tmp_path: Path) -> tuple[Path, Path]:
    a, b = tmp_path / "a.toml", tmp_path / "b.toml"
    a.write_text(TEXT)
    b.write_text(OTHER)
    return a, b


def test_a_folder_that_only_looks_like_a_store_is_refused_unless_replace_is_asked(tmp_path):
    store = tmp_path / "s.parquet"
    store.mkdir()
    (store / "part-000000.parquet").write_bytes(b"someone's data, not an exploration's")
    a, _ = _files(tmp_path)
    with pytest.raises(OperationalError, match="no readable _exploration.json.*--replace"):
        explore(a, store=store)
    assert (store / "part-000000.parquet").read_bytes() == b"someone's data, not an exploration's"
    done = explore(a, store=store, replace=True)
    assert done.computed == 2 and any("--replace" in n for n in done.notes)
    assert len(pd.read_parquet(store)) == 16


def test_the_store_of_another_problem_file_is_refused_and_kept_unless_replace_is_asked(tmp_path):
    a, b = _files(tmp_path)
    store = tmp_path / "s.parquet"
    first = explore(a, store=store).frame()
    with pytest.raises(OperationalError, match="holds the exploration of the problem file .*a.toml"):
        explore(b, store=store)
    pd.testing.assert_frame_equal(pd.read_parquet(store).sort_values("design", ignore_index=True), first)
    replaced = explore(b, store=store, replace=True)
    assert replaced.computed == 2 and not replaced.frame().equals(first)


def test_this_problem_files_changed_exploration_replaces_its_store_and_says_so(tmp_path):
    a, _ = _files(tmp_path)
    store = tmp_path / "s.parquet"
    explore(a, store=store)
    a.write_text(OTHER)
    again = explore(a, store=store)
    assert again.computed == 2
    assert any("held this problem's exploration of another problem or design space" in n for n in again.notes)


def test_run_refuses_another_files_store_in_its_output_folder_and_replace_replaces_it(tmp_path):
    a, b = _files(tmp_path)
    out = tmp_path / "out"
    runner = CliRunner()
    assert runner.invoke(app, ["run", str(a), "--out", str(out), "-q"]).exit_code == 0
    before = (out / "results.json").read_text()
    refused = runner.invoke(app, ["run", str(b), "--out", str(out), "-q"])
    assert refused.exit_code == 1, refused.output
    assert "a.toml" in refused.output and "--replace" in refused.output and "Traceback" not in refused.output
    assert (out / "results.json").read_text() == before
    replaced = runner.invoke(app, ["run", str(b), "--out", str(out), "--replace"])
    assert replaced.exit_code == 0, replaced.output
    assert "of another problem is replaced by this one (--replace)" in replaced.output
