"""The vibration capability through the command line and the report: outputs, sections and bad input."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from matplotlib.figure import Figure
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.report import vibration as rv
from machdyn.runner import run_problem

ROOT = Path(__file__).resolve().parents[2]
RECORD_EXAMPLE = ROOT / "examples" / "vibration_record.toml"


@pytest.fixture(scope="module")
def run():
    return run_problem(RECORD_EXAMPLE)


def test_cli_run_writes_vibration_results_and_report(tmp_path):
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["run", str(RECORD_EXAMPLE), "--out", str(out)])
    assert result.exit_code == 0, result.output
    scalars = json.loads((out / "results.json").read_text())["scalars"]
    assert scalars["frame.rms_velocity.before.front"]["unit"] == "m/s"
    assert scalars["frame.rms_velocity.before.front"]["shown"]["unit"] == "mm/s"
    assert scalars["signals.mean_reduction"]["unit"] == "" and scalars["signals.mean_reduction"]["shown"]["unit"] == "%"
    assert scalars["signals.mean_reduction"]["shown"]["value"] == pytest.approx(
        100 * scalars["signals.mean_reduction"]["value"], rel=1e-12)  # a fraction, shown in %
    # The same prediction twice: through the frame table and next to the measured channel (rel 1e-12).
    assert scalars["signals.predicted_velocity_rms.before.front"]["value"] == pytest.approx(
        scalars["frame.rms_velocity.before.front"]["value"], rel=1e-12)
    for name in ("frame_spectrum", "frame_time", "signals_psd"):
        header = (out / f"{name}.csv").read_text().splitlines()[0]
        assert "[" in header
    html = (out / "report.html").read_text()
    for heading in ("Frame modes", "Predicted severity", "Forces to the foundation", "Measured vibration",
                    "Predicted against measured"):
        assert heading in html
    assert "zone D" in result.output  # the warning for the front point before balancing


def test_sections_and_plots_read_results_only(run):
    frame, signals = run.outcomes["frame"], run.outcomes["signals"]
    assert [t for t, _ in rv.frame_sections(frame)][0] == "Frame modes"
    assert "mode" in rv.mode_table(frame.results)
    fig = Figure()
    axes = fig.subplots(2, 3).ravel()
    assert rv.plot_response_spectrum(frame.results, axes[0]) is axes[0]
    assert rv.plot_rms_comparison(frame.results, axes[1], "velocity") is axes[1]
    assert rv.plot_severity_zones([("before", list(frame.results.severity_before))], axes[2]) is axes[2]
    assert rv.plot_predicted_vs_measured(signals.results, axes[3]) is axes[3]
    assert rv.plot_velocity_psd(signals.results.before, axes[4], (10, 1000)) is axes[4]
    # bars: 3 points x (before, after)
    assert len(axes[1].patches) == 6


def _variant(tmp_path, old: str, new: str) -> Path:
    text = RECORD_EXAMPLE.read_text()
    assert old in text
    path = tmp_path / "variant.toml"
    path.write_text(text.replace(old, new, 1))
    return path


def test_negative_mount_stiffness_in_a_file_is_bad_input(tmp_path):
    path = _variant(tmp_path, 'vertical_stiffness = "800 kN/m"', 'vertical_stiffness = "-800 kN/m"')
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 2
    assert "frame.mounts" in result.output and "must be >= 0 N/m" in result.output


def test_unsupported_frame_in_a_file_is_bad_input(tmp_path):
    # Tyres without horizontal stiffness: the frame can slide fore and aft freely.
    text = RECORD_EXAMPLE.read_text().replace('horizontal_stiffness = "500 kN/m"', 'horizontal_stiffness = "0 N/m"')
    path = tmp_path / "sliding.toml"
    path.write_text(text)
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 2
    assert "mechanism, not a structure" in result.output


def test_missing_record_is_bad_input(tmp_path):
    # A relative path is read when the file runs (a check does not know the file's folder) ...
    path = _variant(tmp_path, 'after = "machdyn:examples/signals/tamper_after.csv"', 'after = "missing.csv"')
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(tmp_path / "o")])
    assert result.exit_code == 2
    assert "signals.after: The record file" in result.output
    assert "missing.csv does not exist" in result.output.replace("\n", "")
    # ... a shipped ("machdyn:") or absolute one already by check.
    path = _variant(tmp_path, 'after = "machdyn:examples/signals/tamper_after.csv"',
                    'after = "machdyn:examples/signals/nothing.csv"')
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 2
    assert "signals.after" in result.output and "does not exist" in result.output


def test_copied_example_runs_anywhere(tmp_path):
    # `machdyn examples vibration_record --to DIR` copies the file alone; its records are named "machdyn:...",
    # so the copy runs from any folder.
    runner = CliRunner()
    copied = runner.invoke(app, ["examples", "vibration_record", "--to", str(tmp_path)])
    assert copied.exit_code == 0, copied.output
    ran = runner.invoke(app, ["run", str(tmp_path / "vibration_record.toml"), "--out", str(tmp_path / "out")])
    assert ran.exit_code == 0, ran.output
    assert (tmp_path / "out" / "signals_psd.csv").exists()


def test_record_too_short_for_the_band_is_refused_by_check(tmp_path):
    # 2 s at 2560 Hz cannot resolve a band starting at 1 Hz (5 periods = 5 s).
    text = RECORD_EXAMPLE.read_text()
    i = text.index("[signals]")
    path = tmp_path / "short.toml"
    path.write_text(text[:i] + text[i:].replace('band = ["10 Hz", "1000 Hz"]', 'band = ["1 Hz", "1000 Hz"]'))
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 2
    assert "too few samples for the band 1-1000 Hz" in result.output.replace("\n", " ")


def test_variant_spring_on_an_unknown_point_is_refused_by_check(tmp_path):
    path = _variant(tmp_path, '[frame.after]\nlabel = "after balancing"\n',
                    '[frame.after]\nlabel = "after balancing"\nsprings = [{point_1 = "rod_1.Q", point_2 = "ground.O", '
                    'stiffness = "1 kN/m"}]\n')
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 2
    assert "frame.after.springs[0].point_1" in result.output and "no point 'rod_1.Q'" in result.output


def test_variant_on_a_rotary_screen_is_checked_too(tmp_path):
    text = (ROOT / "examples" / "rotary_screen.toml").read_text() + (
        '\n[frame]\nmass = "1000 kg"\ninertia = "600 kg*m^2"\n'
        '[[frame.mounts]]\ntype = "tyre"\nname = "a"\nposition = ["1 m", "0 m"]\n'
        'vertical_stiffness = "1 MN/m"\nhorizontal_stiffness = "1 MN/m"\n'
        '[[frame.mounts]]\ntype = "tyre"\nname = "b"\nposition = ["-1 m", "0 m"]\n'
        'vertical_stiffness = "1 MN/m"\nhorizontal_stiffness = "1 MN/m"\n'
        '[frame.after]\ncounterweights = [{body = "flywheel", mass = "1 kg", radius = "1 m", angle = "0 deg"}]\n')
    path = tmp_path / "screen.toml"
    path.write_text(text)
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 2
    assert "frame.after.counterweights[0].body" in result.output and "no body 'flywheel'" in result.output


def test_records_with_different_channels_before_and_after_run_and_report(tmp_path):
    # A before record with only one of the after record's channels: the zone chart places each level by its
    # channel name instead of assuming the same channels in the same order.
    src = ROOT / "examples" / "signals" / "tamper_before.csv"
    lines = [ln for ln in src.read_text().splitlines() if not ln.startswith("#")]
    (tmp_path / "centre_only.csv").write_text("\n".join(",".join(ln.split(",")[:2]) for ln in lines) + "\n")
    path = _variant(tmp_path, 'record = "machdyn:examples/signals/tamper_before.csv"',
                    f'record = "{(tmp_path / "centre_only.csv").as_posix()}"')
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(tmp_path / "o")])
    assert result.exit_code == 0, result.output
    scalars = json.loads((tmp_path / "o" / "results.json").read_text())["scalars"]
    assert "signals.mean_reduction" in scalars
    assert "Measured vibration" in (tmp_path / "o" / "report.html").read_text()
