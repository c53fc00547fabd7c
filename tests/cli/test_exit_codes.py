"""Each documented exit code of the command line, from a real cause."""

from __future__ import annotations

from pathlib import Path

import pytest
from typer.testing import CliRunner

from machdyn import cli
from machdyn.cli import EXIT_BAD_INPUT, EXIT_CHECKS_FAILED, EXIT_FAILED, EXIT_INTERNAL, EXIT_OK, app

ROOT = Path(__file__).resolve().parents[2]
FOUR_BAR = ROOT / "examples" / "four_bar.toml"


@pytest.fixture
def runner():
    return CliRunner()


def test_codes_are_documented_in_help_and_readme(runner):
    text = runner.invoke(app, ["run", "--help"]).output
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    for code, meaning in ((0, "success"), (1, "the analysis failed"), (2, "bad input"), (3, "the design fails a check"),
                          (4, "internal error")):
        assert f"{code} {meaning}" in " ".join(text.split()), (code, text)
        assert f"| {code} |" in readme, code


def test_0_success(runner, tmp_path):
    assert runner.invoke(app, ["run", str(FOUR_BAR), "--out", str(tmp_path), "-q"]).exit_code == EXIT_OK


def test_1_outputs_cannot_be_written(runner, tmp_path):
    blocker = tmp_path / "a-file"
    blocker.write_text("x")
    result = runner.invoke(app, ["run", str(FOUR_BAR), "--out", str(blocker / "out"), "-q"])
    assert result.exit_code == EXIT_FAILED and "cannot write the outputs" in result.stderr


def test_2_bad_input(runner, tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text(FOUR_BAR.read_text().replace('speed = "120 rpm"', 'speed = "120 kg"'), encoding="utf-8")
    for command in ("check", "run"):
        result = runner.invoke(app, [command, str(bad)])
        assert result.exit_code == EXIT_BAD_INPUT and "drive.speed" in result.stderr


def test_3_a_design_that_fails_its_checks(runner, tmp_path):
    """The iodized-salt conveyor's coupling with bushes allowed only 0.5 MPa (their bearing stress is 0.94 MPa)
    fails that check: the outputs are written, the check is said once, and the exit code is 3."""
    text = (ROOT / "examples" / "iodized_salt_conveyor.toml").read_text(encoding="utf-8")
    src = tmp_path / "weak_bushes.toml"
    src.write_text(text.replace('allowable_bushing_stress = "2 MPa"', 'allowable_bushing_stress = "0.5 MPa"'),
                   encoding="utf-8")
    result = runner.invoke(app, ["run", str(src), "--out", str(tmp_path / "failed")])
    assert result.exit_code == EXIT_CHECKS_FAILED, result.output
    assert result.stderr.lower().count("bush") == 1, "the failed check is said once, in one wording"
    assert (tmp_path / "failed" / "report.html").exists()
    import json

    saved = json.loads((tmp_path / "failed" / "results.json").read_text())
    assert len(saved["failed_checks"]) == 1 and "0.5" in saved["failed_checks"][0]


def test_4_internal_error_without_a_traceback(runner, tmp_path, monkeypatch):
    from machdyn import runner as runner_module

    def broken(*args, **kwargs):
        raise RuntimeError("an unexpected defect")

    monkeypatch.setattr(runner_module, "run_problem", broken)
    result = runner.invoke(app, ["run", str(FOUR_BAR), "--out", str(tmp_path / "o")])
    assert result.exit_code == EXIT_INTERNAL
    assert "Traceback" not in result.output and "an unexpected defect" in result.stderr
    log = result.stderr.split("the traceback is in ")[1].split(" ")[0].rstrip(";")
    assert "RuntimeError: an unexpected defect" in Path(log).read_text()
    Path(log).unlink()
    shown = runner.invoke(app, ["run", str(FOUR_BAR), "--out", str(tmp_path / "o"), "--debug"])
    assert shown.exit_code == EXIT_INTERNAL and "Traceback" in shown.stderr
    assert not (tmp_path / "o").exists()


def test_check_reads_standard_input(runner):
    result = runner.invoke(app, ["check", "-"], input=FOUR_BAR.read_text())
    assert result.exit_code == EXIT_OK, result.output


@pytest.mark.parametrize("target", ["/dev/zero", "/dev/urandom"])
def test_devices_are_refused_at_once(runner, target):
    result = runner.invoke(app, ["check", target])
    assert result.exit_code == EXIT_BAD_INPUT and "not a regular file" in result.stderr


def test_a_pipe_is_refused_without_blocking(runner, tmp_path):
    import os

    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    result = runner.invoke(app, ["check", str(fifo)])
    assert result.exit_code == EXIT_BAD_INPUT and "not a regular file" in result.stderr


def test_an_oversized_file_is_refused(runner, tmp_path):
    big = tmp_path / "big.toml"
    big.write_text(FOUR_BAR.read_text() + "#" + "x" * (1 << 20) + "\n", encoding="utf-8")
    result = runner.invoke(app, ["check", str(big)])
    assert result.exit_code == EXIT_BAD_INPUT and "larger than 1024 KiB" in result.stderr


def test_exit_code_constants_are_distinct():
    codes = [cli.EXIT_OK, cli.EXIT_FAILED, cli.EXIT_BAD_INPUT, cli.EXIT_CHECKS_FAILED, cli.EXIT_INTERNAL]
    assert codes == [0, 1, 2, 3, 4]
