"""The command line end to end: every shipped example runs; outputs, formats, examples and atomic writes."""

from __future__ import annotations

import csv
import io
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from machdyn import __version__
from machdyn.cli import app

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))
PACKAGE_EXAMPLES = ROOT / "src" / "machdyn" / "data" / "examples"


def _command() -> list[str]:
    script = Path(sys.executable).with_name("machdyn")
    return [str(script)] if script.exists() else [sys.executable, "-m", "machdyn.cli"]


def _machdyn(*args: str, cwd: Path = ROOT) -> subprocess.CompletedProcess:
    return subprocess.run([*_command(), *args], cwd=cwd, capture_output=True, text=True, timeout=120)


@pytest.fixture
def runner():
    return CliRunner()


@pytest.mark.parametrize("example", EXAMPLES, ids=lambda p: p.stem)
def test_every_example_runs_from_the_command_line(example, tmp_path):
    out = tmp_path / "out"
    proc = _machdyn("run", str(example.relative_to(ROOT)), "--out", str(out))
    assert proc.returncode == 0, proc.stderr
    assert "Traceback" not in proc.stderr
    assert "quantity" in proc.stdout and "unit" in proc.stdout
    results = json.loads((out / "results.json").read_text())
    assert results["scalars"], "results.json holds the scalar results"
    assert results["units"] == "SI"
    for entry in results["scalars"].values():  # SI, and as shown where the summary shows another unit
        assert set(entry) in ({"value", "unit"}, {"value", "unit", "shown"})
    html = (out / "report.html").read_text()
    assert html.lstrip().lower().startswith("<!doctype html")
    assert "<script src" not in html and "<link" not in html  # self-contained
    leftovers = [p.name for p in out.iterdir() if p.name.startswith(".") and p.name != ".machdyn-outputs.json"]
    assert leftovers == [], "no temporary files remain"
    if results["kind"] in ("mechanism", "rotary_screen"):  # a machine with a crank cycle
        for name in ("motion", "joint_forces", "torque_power", "shaking", "energy"):
            rows = list(csv.reader((out / f"{name}.csv").read_text().splitlines()))
            header = rows[0]
            assert header[0] == "crank_angle [deg]"
            assert all(h.endswith("]") and " [" in h for h in header), header
            assert len(rows) - 1 == 360  # one row per crank angle


def test_rotary_screen_prints_the_seed_002_energy_figures(tmp_path):
    """What `make run` prints: T1max, T2, T3 and the range of W within the reference's tolerances."""
    out = tmp_path / "out"
    proc = _machdyn("run", "examples/rotary_screen.toml", "--out", str(out), "--format", "json")
    assert proc.returncode == 0, proc.stderr
    rows = {r["key"]: r for r in json.loads(proc.stdout)["summary"]}
    t1, t2, t3 = (rows[f"rotary_screen.{k}.formula"] for k in ("T1max", "T2", "T3"))
    w_min, w_max = (rows[f"rotary_screen.W_{k}.formula"] for k in ("min", "max"))
    t1_exact = rows["rotary_screen.T1max.engine"]
    assert "T1max" in t1["quantity"] and "eq 15" in t1["quantity"]
    assert t1["value"] == pytest.approx(284.5773, rel=1e-6)
    assert t2["value"] == pytest.approx(253.4206, rel=1e-6)
    assert t3["value"] == pytest.approx(1233.3032, rel=1e-6)
    assert w_min["value"] == pytest.approx(1486.7239, abs=1e-3) and w_max["value"] == pytest.approx(1771.3012, abs=1e-3)
    assert t1_exact["value"] == pytest.approx(284.6218, abs=1e-3)
    assert all(r["unit"] == "J" for r in (t1, t2, t3, w_min, w_max, t1_exact))
    scalars = json.loads((out / "results.json").read_text())["scalars"]
    assert scalars["rotary_screen.T1max.formula"] == {"value": pytest.approx(284.5773, rel=1e-6), "unit": "J"}
    assert scalars["rotary_screen.W_max.formula"]["value"] == pytest.approx(1771.3012, abs=1e-3)
    assert (out / "report.html").exists()


def test_start_up_does_not_import_heavy_libraries():
    heavy = "('matplotlib', 'pandas', 'dask', 'scipy', 'numba', 'pyarrow', 'pymoo', 'distributed')"
    code = f"import sys, machdyn.cli; heavy = [m for m in {heavy} if m in sys.modules]; print(','.join(heavy))"
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert proc.stdout.strip() == ""


@pytest.mark.parametrize("fmt", ["table", "csv", "json", "markdown"])
def test_table_formats(runner, tmp_path, fmt):
    result = runner.invoke(app, ["run", str(ROOT / "examples" / "four_bar.toml"), "--out", str(tmp_path),
                                 "--format", fmt])
    assert result.exit_code == 0, result.output
    text = result.stdout
    if fmt == "csv":
        rows = list(csv.reader(io.StringIO(text)))
        assert rows[0] == ["quantity", "value", "unit"] and len(rows) > 5
    elif fmt == "json":
        data = json.loads(text)
        assert data["problem"] == "Crank-rocker four-bar"
        assert {"quantity", "value", "unit"} <= set(data["summary"][0])
    elif fmt == "markdown":
        assert "| quantity | value | unit |" in text
    else:
        assert "Driving torque" in text


def test_quiet_prints_nothing(runner, tmp_path):
    result = runner.invoke(app, ["run", str(ROOT / "examples" / "slider_crank.toml"), "--out", str(tmp_path),
                                 "--quiet"])
    assert result.exit_code == 0
    assert result.output == ""
    assert (tmp_path / "report.html").exists()


def test_check_ok(runner):
    result = runner.invoke(app, ["check", str(ROOT / "examples" / "rotary_screen.toml")])
    assert result.exit_code == 0
    assert result.stdout.strip().endswith(": OK")


def test_version():
    proc = _machdyn("--version")
    assert proc.returncode == 0
    assert proc.stdout.strip() == f"machdyn {__version__}"


def test_examples_list_and_copy(runner, tmp_path):
    listed = runner.invoke(app, ["examples"])
    assert listed.exit_code == 0
    for name in ("slider_crank", "four_bar", "rotary_screen"):
        assert name in listed.stdout
    target = tmp_path / "mine.toml"
    copied = runner.invoke(app, ["examples", "rotary_screen", "--to", str(target)])
    assert copied.exit_code == 0, copied.output
    assert target.read_text() == (ROOT / "examples" / "rotary_screen.toml").read_text()
    again = runner.invoke(app, ["examples", "rotary_screen", "--to", str(target)])
    assert again.exit_code == 2 and "--force" in again.stderr
    into_dir = runner.invoke(app, ["examples", "four_bar", "--to", str(tmp_path)])
    assert into_dir.exit_code == 0 and (tmp_path / "four_bar.toml").exists()
    unknown = runner.invoke(app, ["examples", "rotary"])
    assert unknown.exit_code == 2 and "did you mean 'rotary_screen'?" in unknown.stderr
    # the copy runs
    ran = runner.invoke(app, ["check", str(target)])
    assert ran.exit_code == 0


def test_shipped_examples_are_the_repository_examples():
    """examples/ (what the repository shows) and the package data (what `machdyn examples` ships) are the
    same files; after editing one, copy it over the other."""
    repo = {p.name: p.read_bytes() for p in (ROOT / "examples").glob("*.toml")}
    shipped = {p.name: p.read_bytes() for p in PACKAGE_EXAMPLES.glob("*.toml")}
    assert sorted(repo) == sorted(shipped)
    for name in repo:
        assert repo[name] == shipped[name], f"examples/{name} differs from src/machdyn/data/examples/{name}"


def test_interrupted_write_leaves_no_half_file(tmp_path, monkeypatch):
    from machdyn import outputs

    target = tmp_path / "results.json"
    target.write_text("previous")

    def interrupted(handle):
        handle.write('{"half": ')
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        outputs.atomic_write(target, interrupted)
    assert target.read_text() == "previous"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["results.json"]

    def interrupted_csv(frame_to_csv_self, handle, **kwargs):
        handle.write("crank_angle [deg],x [m]\n0,")
        raise KeyboardInterrupt

    import pandas as pd

    monkeypatch.setattr(pd.DataFrame, "to_csv", interrupted_csv)
    with pytest.raises(KeyboardInterrupt):
        outputs.write_frame_csv(tmp_path / "motion.csv", pd.DataFrame({"a": [1.0]}))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["results.json"]


def test_interrupted_run_leaves_the_previous_set_whole(tmp_path, monkeypatch):
    """Ctrl-C while the report is rendered: an output folder of an earlier run keeps that run's whole set (no
    mix of old and new files), a new folder is not left behind, and no staging files remain."""
    from machdyn import runner as runner_module
    from machdyn.reading import load_problem

    old = runner_module.run_problem(load_problem(ROOT / "examples" / "slider_crank.toml"))
    kept = tmp_path / "kept"
    old.write(kept)
    before = {p.name: p.read_bytes() for p in kept.iterdir()}
    result = runner_module.run_problem(load_problem(ROOT / "examples" / "four_bar.toml"))

    def interrupt(self, *_args, **_kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(runner_module.RunResult, "report_html", interrupt)
    with pytest.raises(KeyboardInterrupt):
        result.write(kept)
    assert {p.name: p.read_bytes() for p in kept.iterdir()} == before
    fresh = tmp_path / "fresh"
    with pytest.raises(KeyboardInterrupt):
        result.write(fresh)
    assert not fresh.exists(), "a folder the run created is removed with its partial files"


def test_a_new_set_replaces_the_old_one_entirely(tmp_path):
    """A sweep's sweep.csv does not outlive the sweep: files the new run did not write are removed."""
    from machdyn import runner as runner_module

    runner_module.run_problem(ROOT / "examples" / "four_bar_sweep.toml").write(tmp_path)
    assert (tmp_path / "sweep.csv").exists()
    (tmp_path / "notes.txt").write_text("mine")
    runner_module.run_problem(ROOT / "examples" / "four_bar.toml").write(tmp_path)
    assert not (tmp_path / "sweep.csv").exists()
    assert (tmp_path / "notes.txt").read_text() == "mine", "files machdyn did not write are left alone"


def test_out_directory_is_created(tmp_path):
    out = tmp_path / "a" / "b"
    proc = _machdyn("run", "examples/four_bar.toml", "--out", str(out), "--quiet")
    assert proc.returncode == 0, proc.stderr
    assert (out / "results.json").exists()


def test_run_from_another_directory(tmp_path):
    shutil.copy(ROOT / "examples" / "slider_crank.toml", tmp_path / "p.toml")
    proc = _machdyn("run", "p.toml", "--quiet", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert (tmp_path / "out" / "report.html").exists()
    assert os.listdir(tmp_path / "out")
