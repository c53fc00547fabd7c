"""Vibration records judged without a machine, bands that leave out an order of the running speed, one
predicted value per quantity (or the difference said), and the user's labels on records."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.errors import ProblemFileError
from machdyn.kinds import kind
from machdyn.pipeline import no_step
from machdyn.reading import read_problem
from machdyn.report.vibration import predicted_note
from machdyn.runner import check_problem, run_problem
from machdyn.vibration.orders import band_order_warnings, orders_outside_band
from machdyn.vibration.stage import frame_outcome, signal_outcome
from machdyn.vibration.study import study_frame, study_signals

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "vibration_record.toml"
F1 = 5.0  # Hz: a machine at 300 rpm
A1, A3 = 8e-3, 1e-3  # m/s: amplitudes of the 1x and 3x velocity lines


def _record(path: Path, fs: float = 2560.0, seconds: float = 4.0) -> Path:
    t = np.arange(0.0, seconds, 1.0 / fs)
    v = A1 * np.sin(2 * np.pi * F1 * t) + A3 * np.sin(2 * np.pi * 3 * F1 * t + 0.3)
    lines = ["time [s],bearing [mm/s]"] + [f"{a:.9f},{b * 1e3:.12g}" for a, b in zip(t, v, strict=True)]
    path.write_text("\n".join(lines) + "\n")
    return path


def _file(tmp_path: Path, extra: str = "") -> Path:
    _record(tmp_path / "fan.csv")
    p = tmp_path / "fan.toml"
    p.write_text(f'[meta]\nname = "Fan bearing"\n\n[signals]\nrecord = "fan.csv"\nmachine_class = "II"\n{extra}')
    return p


def test_signals_file_without_a_machine_is_checked_and_runs(tmp_path):
    path = _file(tmp_path, 'label = "fan, as found"\n')
    runner = CliRunner()
    checked = runner.invoke(app, ["check", str(path)])
    assert checked.exit_code == 0, checked.output
    ran = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "out")])
    assert ran.exit_code == 0, ran.output
    results = json.loads((tmp_path / "out" / "results.json").read_text())
    assert results["kind"] == "signals"
    # Only the 3x line (15 Hz) is in the default 10-1000 Hz band: RMS = A3 / sqrt 2 (Parseval; the record holds
    # whole periods of both lines, so the ideal band-pass is exact up to the printed digits).
    assert results["scalars"]["signals.velocity_rms.before.bearing"]["value"] == pytest.approx(
        A3 / math.sqrt(2), rel=1e-6)  # m/s
    report = (tmp_path / "out" / "report.html").read_text()
    assert "Measured vibration" in report and "fan, as found" in report
    assert (tmp_path / "out" / "signals_psd.csv").is_file()


def test_signals_file_counts_the_first_order_in_a_wider_band(tmp_path):
    path = _file(tmp_path, 'band = ["2 Hz", "1000 Hz"]\nspeed = "300 rpm"\n')
    result = run_problem(read_problem(path))
    value = result.outcomes["signals"].scalars["signals.velocity_rms.before.bearing"]
    assert value == pytest.approx(math.sqrt((A1**2 + A3**2) / 2), rel=1e-6)
    assert not result.warnings  # 5 Hz lies in 2-1000 Hz


def test_band_leaving_out_the_running_speed_order_is_a_warning_naming_order_and_band(tmp_path):
    path = _file(tmp_path, 'speed = "300 rpm"\n')
    warnings = check_problem(read_problem(path))
    assert len(warnings) == 1
    assert "order 1 (5 Hz)" in warnings[0] and "10–1000 Hz" in warnings[0] and "300 rpm" in warnings[0]
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(tmp_path / "out")])
    assert result.exit_code == 0 and "order 1 (5 Hz)" in result.output


def test_orders_outside_band_are_counted_both_sides():
    omega = 2 * np.pi * 5.0
    assert orders_outside_band((10.0, 1000.0), omega, 6) == ([1], [])
    assert orders_outside_band((12.0, 22.0), omega, 6) == ([1, 2], [5, 6])
    assert orders_outside_band((10.0, 1000.0), omega) == ([1], [])  # a record: only the orders below
    assert orders_outside_band((5.0, 1000.0), omega, 6) == ([], [])  # the edge counts as inside
    text = band_order_warnings((12.0, 22.0), omega, 6, what="The [frame] band")
    assert "orders 1 to 2 (5–10 Hz)" in text[0] and "orders 5 to 6 (25–30 Hz)" in text[1]


def test_speed_in_a_machine_file_is_refused_by_check_and_run(tmp_path):
    text = EXAMPLE.read_text()
    assert text.rstrip().split("\n[")[-1].startswith("signals]")  # [signals] is the file's last table
    text += 'speed = "1200 rpm"\n'
    path = tmp_path / "with_speed.toml"
    path.write_text(text)
    with pytest.raises(ProblemFileError, match="signals.speed"):
        read_problem(path)


@pytest.fixture(scope="module")
def slow_machine(tmp_path_factory):
    """The tamper example at 300 rpm (a 5 Hz machine), the [frame] band left at 10-1000 Hz and the records
    judged in 4-1000 Hz, with the records labelled by the user."""
    text = EXAMPLE.read_text().replace('speed = "1200 rpm"', 'speed = "300 rpm"')
    text = text.replace('after_label = "after balancing"\nband = ["10 Hz", "1000 Hz"]',
                        'after_label = "after balancing"\nband = ["4 Hz", "1000 Hz"]')
    text = text.replace('label = "before balancing"           #', 'label = "site test 1"  #')
    text = text.replace('after_label = "after balancing"', 'after_label = "site test 2"')
    assert '["4 Hz", "1000 Hz"]' in text and "site test 1" in text
    path = tmp_path_factory.mktemp("slow") / "slow.toml"
    path.write_text(text)
    loaded = read_problem(path)
    outcome = kind(loaded.kind).analyse(loaded.spec, loaded.model, no_step)
    fs = study_frame(loaded.spec.frame, outcome.mechanism, outcome.analysis)
    ss = study_signals(loaded.spec.signals, source=str(path), crank_speed=loaded.spec.drive.speed, frame_study=fs)
    return loaded, fs, ss


def test_frame_band_leaving_out_the_first_order_is_a_warning(slow_machine):
    _, fs, _ = slow_machine
    warnings = frame_outcome(fs).warnings
    said = [w for w in warnings if "leaves out" in w]
    assert len(said) == 1 and said[0].startswith("The [frame] band 10–1000 Hz leaves out order 1 (5 Hz)")


def test_predicted_values_in_two_bands_are_explained(slow_machine):
    _, fs, ss = slow_machine
    point = fs.points["front"]
    frame_value = frame_outcome(fs).scalars["frame.rms_velocity.before.front"]
    out = signal_outcome(ss)
    predicted = out.scalars["signals.predicted_velocity_rms.before.front"]
    # The records' prediction counts the 1x order (5 Hz in 4-1000 Hz), the frame's does not (10-1000 Hz):
    # they differ by exactly that order, in quadrature.
    first = fs.before.rms(point, "velocity", fs.direction, (4.0, 6.0))
    assert predicted == pytest.approx(math.hypot(frame_value, first), rel=1e-9)
    assert predicted > frame_value
    assert "in the records' band 4–1000 Hz" in out.labels["signals.predicted_velocity_rms.before.front"].text
    note = predicted_note(ss)
    assert "[frame] band 10–1000 Hz" in note and "records' band 4–1000 Hz" in note


def test_one_band_gives_one_predicted_value_per_quantity():
    loaded = read_problem(EXAMPLE)
    outcome = kind(loaded.kind).analyse(loaded.spec, loaded.model, no_step)
    fs = study_frame(loaded.spec.frame, outcome.mechanism, outcome.analysis)
    ss = study_signals(loaded.spec.signals, source=str(EXAMPLE), crank_speed=loaded.spec.drive.speed, frame_study=fs)
    frame = frame_outcome(fs).scalars
    for name, value in ss.predicted_before.items():
        assert value == frame[f"frame.rms_velocity.before.{name}"]
    assert "[frame] band" not in predicted_note(ss)


def test_record_labels_are_the_users_not_the_frames(slow_machine, tmp_path):
    _, fs, ss = slow_machine
    assert ss.labels == ("site test 1", "site test 2")
    assert ss.predicted_labels == fs.labels == ("before balancing", "after balancing")
    out = signal_outcome(ss)
    assert out.labels["signals.velocity_rms.before.front"].text.endswith("site test 1")
    assert out.labels["signals.predicted_velocity_rms.after.front"].text.endswith("after balancing")
    # Without labels, the records are named by their files, never by the frame's variant.
    text = EXAMPLE.read_text().replace('label = "before balancing"           #', "#")
    text = text.replace('after_label = "after balancing"\n', "")
    path = tmp_path / "unlabelled.toml"
    path.write_text(text)
    loaded = read_problem(path)
    assert loaded.spec.signals.label is None
    study = study_signals(loaded.spec.signals, source=str(path), crank_speed=loaded.spec.drive.speed,
                          frame_study=fs)
    assert study.labels == ("tamper_before", "tamper_after")


def test_records_alone_are_judged_as_beside_the_machine():
    """The shipped records-alone example holds the records of vibration_record.toml: every measured value (RMS,
    zones, crest factors, reduction) is the same to the last bit; only the predictions are absent."""
    alone = run_problem(read_problem(ROOT / "examples" / "vibration_records_alone.toml"))
    beside = run_problem(read_problem(EXAMPLE))
    measured = {k: v for k, v in beside.outcomes["signals"].scalars.items() if not k.startswith("signals.predicted")}
    assert alone.outcomes["signals"].scalars == measured
    assert alone.kind == "signals" and not alone.failed_checks


def test_order_levels_of_a_record_are_its_lines_rms(tmp_path):
    """With the running speed known, the order table gives the RMS of each line: A1/sqrt 2 at 1x, A3/sqrt 2 at 3x
    (flat-top window, amplitude-correct within 0.1 %, Brandt 2011 §9.3.4), ~0 at 2x; the CSV holds the spectrum."""
    from machdyn.vibration.orders import order_levels

    path = _file(tmp_path, 'band = ["2 Hz", "1000 Hz"]\nspeed = "300 rpm"\n')
    result = run_problem(read_problem(path))
    c = result.outcomes["signals"].results.before.channel("bearing")
    first, second, third = order_levels(c.orders, c.order_rms, 3)
    assert first == pytest.approx(A1 / math.sqrt(2), rel=1e-3)
    assert third == pytest.approx(A3 / math.sqrt(2), rel=1e-3)
    assert second < 1e-3 * A3
    assert "signals_orders" in result.frames
    result.write(tmp_path / "out")
    html = (tmp_path / "out" / "report.html").read_text()
    assert "Orders of the running speed" in html


def test_machine_tables_without_their_main_table_name_it(tmp_path):
    """A machine's file whose [mechanism] is missing is not taken for records alone without a word: the
    message names the machine's tables and the main tables a machine needs."""
    text = EXAMPLE.read_text()
    start = text.index("[mechanism]\n")
    end = text.index("[drive]\n")  # [mechanism] and its sub-tables come first
    path = tmp_path / "no_mechanism.toml"
    path.write_text(text.replace(text[start:end], ""))
    for command in (["check", str(path)], ["run", str(path), "--out", str(tmp_path / "out")]):
        result = CliRunner().invoke(app, command)
        assert result.exit_code == 2
        assert "[drive], [frame], [loads] describe a machine" in result.output
        assert "[mechanism]" in result.output and "[rotary_screen]" in result.output


def test_records_alone_from_python_read_relative_records_against_the_file(tmp_path, monkeypatch):
    from machdyn.reading import load_problem

    path = _file(tmp_path, "")
    monkeypatch.chdir(ROOT)  # elsewhere than the problem file's folder
    problem = load_problem(path)
    assert problem.source == str(path)
    result = run_problem(problem)
    assert result.kind == "signals"
    assert result.outcomes["signals"].scalars["signals.velocity_rms.before.bearing"] == pytest.approx(
        A3 / math.sqrt(2), rel=1e-6)
