"""The command line says what happened: an interrupted exploration (what is on disk, how to resume), a resumed
one (partitions reused and computed), a mode near an order of the running speed, a linkage near a dead
position, and one angle unit (degrees) in every CSV file."""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from machdyn.cli import app

ROOT = Path(__file__).resolve().parents[2]

EXPLORATION = """
[mechanism]
type = "four_bar"
crank = {length = "40 mm", mass = "0.2 kg"}
coupler = {length = "120 mm", mass = "0.5 kg"}
rocker = {length = "80 mm", mass = "0.4 kg"}
ground = {length = "100 mm"}

[drive]
speed = "10 rad/s"
positions = 36

[sweep]
method = "lhs"
samples = 120
seed = 5
partition = 30

[[sweep.quantities]]
parameter = "mechanism.crank.length"
start = "30 mm"
stop = "45 mm"

[[sweep.quantities]]
parameter = "mechanism.coupler.mass"
start = "0.3 kg"
stop = "0.8 kg"
"""


def test_interrupted_exploration_says_what_is_on_disk_and_how_to_resume(tmp_path, monkeypatch):
    from machdyn.studies.exploration import run as explore_run

    path = tmp_path / "explore.toml"
    path.write_text(EXPLORATION)
    out = tmp_path / "out"
    real = explore_run.run_partitions

    def stopped_after_two(*args, **kwargs):
        seen: list[int] = []

        def on_partition(index: int) -> None:
            seen.append(index)
            if len(seen) == 2:
                raise KeyboardInterrupt

        return real(*args, **{**kwargs, "on_partition": on_partition})

    monkeypatch.setattr(explore_run, "run_partitions", stopped_after_two)
    runner = CliRunner()
    stopped = runner.invoke(app, ["run", str(path), "--out", str(out)])
    assert stopped.exit_code == 130
    assert "interrupted: 2 of 4 partition(s)" in stopped.output
    assert str(out / "sweep.parquet") in stopped.output and "run the same command again" in stopped.output
    assert len(list((out / "sweep.parquet").glob("part-*.parquet"))) == 2
    assert not (out / "results.json").exists()

    monkeypatch.setattr(explore_run, "run_partitions", real)
    resumed = runner.invoke(app, ["run", str(path), "--out", str(out)])
    assert resumed.exit_code == 0, resumed.output
    assert "resumed: 2 partition(s) reused" in resumed.output and "2 computed" in resumed.output
    assert "computed 2 partition(s) and reused 2" in (out / "report.html").read_text()


def test_interrupted_run_says_the_outputs_were_not_replaced(tmp_path, monkeypatch):
    from machdyn import runner as runner_module

    def interrupted(*_args, **_kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(runner_module.RunResult, "write", interrupted)
    result = CliRunner().invoke(app, ["run", str(ROOT / "examples" / "four_bar.toml"), "--out", str(tmp_path)])
    assert result.exit_code == 130
    assert "interrupted: the outputs in" in result.output and "were not replaced" in result.output


def test_mode_near_the_first_order_is_a_warning_on_the_command_line(tmp_path):
    # The tamper example's third frame mode is at 13.88 Hz (its weight's pendulum term included); at 800 rpm the 1x
    # order is 13.33 Hz, 4.1 % below.
    text = (ROOT / "examples" / "tamper_on_tyres.toml").read_text()
    assert text.count('speed = "1200 rpm"') == 1
    path = tmp_path / "tamper_800.toml"
    path.write_text(text.replace('speed = "1200 rpm"', 'speed = "800 rpm"'))
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    said = [line for line in result.output.splitlines() if "within 15 % of order 1" in line]
    assert len(said) == 1 and said[0].startswith("warning: Frame mode 3 (13.9 Hz)")
    assert "+4.1 %" in said[0]
    report = (tmp_path / "out" / "report.html").read_text()
    assert "Near resonance:</b> mode 3 (13.9 Hz) near order 1 (13.3 Hz, +4.1 %, within 15 %)" in report


def test_near_dead_position_names_the_crank_angle_and_the_margin(tmp_path):
    # Crank-rocker a = 55, coupler b = 100, rocker c = 70, ground d = 110 mm: at crank angle 180 deg the
    # diagonal is d + a and the transmission angle mu = acos((b^2 + c^2 - (d + a)^2) / (2 b c)) = 151.7 deg,
    # 28.3 deg from the 180 deg dead position (law of cosines; the extreme of a crank-rocker lies there).
    path = tmp_path / "toggle.toml"
    path.write_text('[mechanism]\ntype = "four_bar"\ncrank = {length = "55 mm", mass = "0.2 kg"}\n'
                    'coupler = {length = "100 mm", mass = "0.5 kg"}\nrocker = {length = "70 mm", mass = "0.4 kg"}\n'
                    'ground = {length = "110 mm"}\n\n[drive]\nspeed = "100 rpm"\npositions = 360\n')
    mu = math.degrees(math.acos((100**2 + 70**2 - 165**2) / (2 * 100 * 70)))
    runner = CliRunner()
    for command in (["check", str(path)], ["run", str(path), "--out", str(tmp_path / "out")]):
        result = runner.invoke(app, command)
        assert result.exit_code == 0, result.output
        assert f"nearest a dead position (0° or 180°) at crank angle 180.0°, {180 - mu:.1f}° away" in result.output


@pytest.mark.parametrize("example", ["slider_crank_balance.toml", "compactor_flywheel.toml"])
def test_every_csv_gives_angles_in_degrees(example, tmp_path):
    result = CliRunner().invoke(app, ["run", str(ROOT / "examples" / example), "--out", str(tmp_path)])
    assert result.exit_code in (0, 3), result.output
    files = sorted(tmp_path.glob("*.csv"))
    assert len(files) > 5
    for path in files:
        with path.open() as handle:
            header = next(csv.reader(handle))
        assert not [h for h in header if h.endswith("[rad]")], f"{path.name} gives an angle in rad"
    motion = np.loadtxt(tmp_path / "motion.csv", delimiter=",", skiprows=1, usecols=0)
    for name in ("balance_force.csv", "flywheel_cycle.csv"):
        if (tmp_path / name).exists():
            with (tmp_path / name).open() as handle:
                assert next(csv.reader(handle))[0] == "crank_angle [deg]"
            angles = np.loadtxt(tmp_path / name, delimiter=",", skiprows=1, usecols=0)
            # the same crank angles as motion.csv (degrees), up to the printed digits
            assert angles[0] == pytest.approx(motion[0], abs=1e-9) and angles.max() <= 360.0 + 1e-9
            assert angles.max() > 2 * math.pi  # not radians
