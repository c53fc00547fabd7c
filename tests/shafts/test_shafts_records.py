"""Field balancing from records with a once-per-revolution reference: 1x readings, the example's recovered
unbalance, and records without a usable phase reference refused by name."""

from __future__ import annotations

import json
import math
import shutil
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.errors import InputError
from machdyn.shafts.records import one_x, pulses, read_run

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "shaft_field_records.toml"


def _write(path: Path, t, key, *channels) -> Path:
    lines = ["time [s],key [V]," + ",".join(f"c{i} [mm/s]" for i in range(len(channels)))]
    lines += [",".join(f"{v:.9g}" for v in row) for row in zip(t, key, *channels, strict=True)]
    path.write_text("\n".join(lines) + "\n")
    return path


def test_one_x_reads_amplitude_and_phase_lag_exactly_from_a_clean_signal():
    speed = 2 * np.pi * 25.0
    t = np.arange(4000) / 4000.0
    angle = speed * t - 0.4
    key = np.where(np.mod(angle, 2 * np.pi) < 0.2, 5.0, 0.0)
    x = 3.0 * np.cos(angle - 1.1) + 0.7 + 0.5 * np.cos(3 * angle)
    times = pulses(t, key)
    assert np.allclose(np.diff(times), 1 / 25.0, rtol=1e-3)
    r = one_x(t, x, times)
    assert r.amplitude == pytest.approx(3.0, rel=2e-3)
    # a square pulse is located to within half a sample: a phase uncertainty of w / (2 f_s)
    assert r.phase == pytest.approx(1.1, abs=speed / 4000.0 / 2)


def test_the_records_example_recovers_the_unbalance_it_was_made_with(tmp_path):
    """make_records.py puts 24 g at 250 deg and 15 g at 40 deg (against rotation, 160 mm) on the rotor: the
    corrections are 24 g at 70 deg and 15 g at 220 deg, up to the records' noise (0.05 mm/s RMS)."""
    result = CliRunner().invoke(app, ["run", str(EXAMPLE), "--out", str(tmp_path / "o"), "-q"])
    assert result.exit_code == 0, result.output
    s = json.loads((tmp_path / "o" / "results.json").read_text())["scalars"]
    assert s["shaft.records.plane1.mass"]["value"] == pytest.approx(24.0e-3, rel=0.01)  # kg
    assert s["shaft.records.plane1.angle"]["value"] == pytest.approx(np.radians(70.0), abs=np.radians(0.5))
    assert s["shaft.records.plane2.mass"]["value"] == pytest.approx(15.0e-3, rel=0.01)
    assert s["shaft.records.plane2.angle"]["value"] == pytest.approx(np.radians(220.0), abs=np.radians(0.5))
    assert s["shaft.records.speed"]["value"] == pytest.approx(1485.0 * np.pi / 30, rel=1e-3)  # rad/s
    assert "Field balancing from records" in (tmp_path / "o" / "report.html").read_text()


def test_a_record_without_pulses_is_refused_by_check_and_run(tmp_path):
    folder = tmp_path / "case"
    shutil.copytree(EXAMPLE.parent / "field_records", folder / "field_records")  # records beside the problem
    (folder / EXAMPLE.name).write_text(EXAMPLE.read_text().replace('"machdyn:examples/field_records/',
                                                                   '"field_records/'))
    rows = (folder / "field_records" / "original.csv").read_text().splitlines()
    flat = [rows[0], rows[1]] + [",".join([r.split(",")[0], "0.0", *r.split(",")[2:]]) for r in rows[2:]]
    (folder / "field_records" / "original.csv").write_text("\n".join(flat) + "\n")
    runner = CliRunner()
    check = runner.invoke(app, ["check", str(folder / EXAMPLE.name)])
    run = runner.invoke(app, ["run", str(folder / EXAMPLE.name), "--out", str(tmp_path / "o"), "-q"])
    assert check.exit_code == run.exit_code == 2, check.output + run.output
    assert "field_records.original" in check.output and "no once-per-revolution pulse" in check.output


def test_missing_channel_too_few_revolutions_and_unsteady_speed_are_refused(tmp_path):
    t = np.arange(3000) / 3000.0
    angle = 2 * np.pi * 20.0 * t
    key = np.where(np.mod(angle, 2 * np.pi) < 0.2, 5.0, 0.0)
    good = _write(tmp_path / "good.csv", t, key, np.cos(angle))
    with pytest.raises(InputError, match="no channel 'front'"):
        read_run(good, "key", ("front",))
    short = _write(tmp_path / "short.csv", t[:200], key[:200], np.cos(angle[:200]))
    with pytest.raises(InputError, match="at least 3"):
        read_run(short, "key", ("c0",))
    wobble = 2 * np.pi * (20.0 * t + 3.0 * t**2)  # 20 -> 26 Hz within the record
    key2 = np.where(np.mod(wobble, 2 * np.pi) < 0.2, 5.0, 0.0)
    unsteady = _write(tmp_path / "unsteady.csv", t, key2, np.cos(wobble))
    with pytest.raises(InputError, match="not steady"):
        read_run(unsteady, "key", ("c0",))
    r = read_run(good, "key", ("c0",))
    assert r.readings[0].amplitude == pytest.approx(1.0, rel=5e-3) and r.speed == pytest.approx(40 * math.pi, rel=1e-3)
