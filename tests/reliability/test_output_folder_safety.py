"""An output folder holds the user's own files too (``--out .``): a run removes only earlier outputs that machdyn
wrote and that are unchanged since, never the problem file, a hidden file, a link or anything outside the folder,
whatever the folder's list of outputs (``.machdyn-outputs.json``) says."""

from __future__ import annotations

import hashlib
import json
import os
from pathlib import Path

from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.outputs import LOCK, MANIFEST, OutputSet, release_lock

from .conftest import FOUR_BAR


def _sha(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _project(tmp_path: Path) -> tuple[Path, dict[str, str]]:
    """A project folder with the problem file and files of the user's own; their contents by name."""
    folder = tmp_path / "rotor"
    folder.mkdir()
    own = {"README.md": "# my project\n", "setup.py": "print('setup')\n", ".env": "KEY=1\n",
           "rotor.toml": FOUR_BAR, "notes.csv": "a,b\n1,2\n", "design.json": "{}\n"}
    for name, text in own.items():
        (folder / name).write_text(text)
    (tmp_path / "outside.csv").write_text("x\n")
    return folder, own


def _run_here(folder: Path):
    cwd = os.getcwd()
    os.chdir(folder)
    try:
        return CliRunner().invoke(app, ["run", "rotor.toml", "--out", ".", "-q"])
    finally:
        os.chdir(cwd)


def test_a_planted_list_of_names_deletes_nothing_of_the_users(tmp_path):
    folder, own = _project(tmp_path)
    (folder / MANIFEST).write_text(json.dumps(list(own) + ["../outside.csv", "/etc/hostname", ""]))
    result = _run_here(folder)
    assert result.exit_code == 0, result.output
    assert {n: (folder / n).read_text() for n in own} == own
    assert (tmp_path / "outside.csv").exists()
    assert (folder / "results.json").is_file()
    note = [line for line in result.output.splitlines() if "no earlier output was removed" in line]
    assert len(note) == 1 and MANIFEST in note[0]


def test_a_planted_manifest_with_true_digests_deletes_neither_the_problem_file_nor_foreign_kinds(tmp_path):
    folder, own = _project(tmp_path)
    os.symlink(tmp_path / "outside.csv", folder / "linked.csv")
    os.link(folder / "notes.csv", folder / "hard.csv")
    listed = {n: _sha(folder / n) for n in [*own, "linked.csv", "hard.csv"]}
    listed["../outside.csv"] = _sha(tmp_path / "outside.csv")
    (folder / MANIFEST).write_text(json.dumps({"machdyn_outputs": 2, "files": listed}))
    result = _run_here(folder)
    assert result.exit_code == 0, result.output
    # the problem file, hidden files, kinds machdyn never writes and links are kept; design.json is of a kind
    # machdyn writes and is unchanged since the manifest named it, so it alone could go: it is no link, no
    # problem file, and its digest is the one listed (a forged manifest can do no more than that)
    assert {n: (folder / n).read_text() for n in own if n != "design.json"} == {
        n: t for n, t in own.items() if n != "design.json"}
    assert (folder / "linked.csv").is_symlink() and (folder / "hard.csv").exists()
    assert (tmp_path / "outside.csv").exists()
    note = [line for line in result.output.splitlines() if "not unchanged outputs of an earlier run" in line]
    assert len(note) == 1 and "README.md" in note[0] and "../outside.csv" in note[0]


def test_earlier_outputs_are_removed_only_while_unchanged(tmp_path):
    out = tmp_path / "out"
    first = OutputSet(out)
    for name in ("results.json", "old.csv", "edited.csv"):
        first.text(name, f"{name}\n")
    first.commit()
    manifest = json.loads((out / MANIFEST).read_text())
    assert manifest["files"]["old.csv"] == _sha(out / "old.csv")
    (out / "edited.csv").write_text("the user's own edit\n")
    second = OutputSet(out)
    second.text("results.json", "new\n")
    second.commit()
    assert not (out / "old.csv").exists()
    assert (out / "edited.csv").read_text() == "the user's own edit\n"
    assert second.notes == [f"left in {out}/ as they are not unchanged outputs of an earlier run: edited.csv"]
    assert list(json.loads((out / MANIFEST).read_text())["files"]) == ["results.json"]


def test_the_problem_file_is_kept_even_when_it_is_an_unchanged_earlier_output(tmp_path):
    out = tmp_path / "out"
    first = OutputSet(out)
    first.text("best_design.toml", FOUR_BAR)
    first.commit()
    second = OutputSet(out, protect=(out / "best_design.toml",))  # the user runs the best design in place
    second.text("results.json", "{}\n")
    second.commit()
    assert (out / "best_design.toml").read_text() == FOUR_BAR
    release_lock(out / LOCK)
