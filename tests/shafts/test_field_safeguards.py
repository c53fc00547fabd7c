"""Field balancing refuses what would give a quietly wrong correction: a vibration channel taken as the phase
reference, a trial mass that hardly changed the readings, and two trial runs that act alike."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from machdyn.cli import app
from machdyn.errors import InputError
from machdyn.shafts.field import MAX_CONDITION, Reading, TrialRun, single_plane, two_plane
from machdyn.shafts.records import read_run
from reproductions import tiny_trial, vibration_reference


def _both(path: Path, tmp_path: Path) -> tuple[int, int, str]:
    runner = CliRunner()
    check = runner.invoke(app, ["check", str(path)])
    run = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "out"), "-q"])
    return check.exit_code, run.exit_code, check.output + run.output


def test_a_vibration_channel_as_the_phase_reference_is_refused_by_check_and_run(tmp_path):
    """With reference = "drive_end" the records example balanced to 333 g at 158 deg instead of 24 g at 70 deg:
    the channel is a vibration sensor (mm/s), not a keyphasor."""
    bad = tmp_path / "vibration_reference.toml"
    bad.write_text(vibration_reference())
    check, run, output = _both(bad, tmp_path)
    assert check == run == 2, output
    assert "field_records.original" in output and "keyphasor or tachometer" in output
    assert "also read as a vibration sensor" in output


def _write(path: Path, t, reference, unit: str, vibration) -> Path:
    rows = ["time [s],ref [" + unit + "],x [mm/s]"] + [f"{a:.9g},{b:.9g},{c:.9g}" for a, b, c in
                                                      zip(t, reference, vibration, strict=True)]
    path.write_text("\n".join(rows) + "\n")
    return path


def test_a_reference_in_a_vibration_unit_or_shaped_like_a_vibration_is_refused(tmp_path):
    t = np.arange(4000) / 4000.0
    angle = 2 * np.pi * 25.0 * t
    vibration = 3.0 * np.cos(angle - 1.1)
    other = 2.0 * np.cos(angle + 0.4)  # a second vibration channel, not among the sensors read
    with pytest.raises(InputError, match="vibration unit"):
        read_run(_write(tmp_path / "a.csv", t, other, "um", vibration), "ref", ("x",))
    with pytest.raises(InputError, match="not a pulse train"):  # the same signal relabelled in volts
        read_run(_write(tmp_path / "b.csv", t, other, "V", vibration), "ref", ("x",))
    key = np.where(np.mod(angle, 2 * np.pi) < 0.2, 5.0, 0.0)  # a keyphasor is accepted
    r = read_run(_write(tmp_path / "c.csv", t, key, "V", vibration), "ref", ("x",))
    assert r.readings[0].amplitude == pytest.approx(3.0, rel=2e-3)
    assert r.readings[0].phase == pytest.approx(1.1, abs=2 * np.pi * 25.0 / 4000.0)


def test_a_trial_mass_that_hardly_changes_the_readings_is_refused(tmp_path):
    """A trial that changed one reading by 0.0001 mm/s gave a 1.74 t correction with exit 0."""
    bad = tmp_path / "tiny_trial.toml"
    bad.write_text(tiny_trial())
    check, run, output = _both(bad, tmp_path)
    assert check == run == 2, output
    assert "field_balancing" in output and "30% in amplitude or 30 deg in phase" in output
    with pytest.raises(InputError, match="changed the readings too little"):
        single_plane(Reading(8.6, math.radians(62)), 0.02, 0.0, Reading(8.6001, math.radians(62)))
    # at the rule's edge: 29 deg of phase is refused, 31 deg (or 31 % of amplitude) is accepted
    with pytest.raises(InputError, match="too little"):
        single_plane(Reading(8.6, 0.0), 0.02, 0.0, Reading(8.6, math.radians(29)))
    single_plane(Reading(8.6, 0.0), 0.02, 0.0, Reading(8.6, math.radians(31)))
    fb = single_plane(Reading(8.6, 0.0), 0.02, 0.0, Reading(8.6 * 1.31, 0.0))
    assert fb.correction_mass[0] == pytest.approx(0.02 / 0.31)  # W = -V0 / a exactly


def test_two_trial_runs_that_act_almost_alike_are_refused_by_the_condition_number():
    """Influence columns 4 deg apart (each trial changes the readings by far more than 30 %): the scaled matrix's
    condition number cot(1 deg) ~ 57 exceeds the limit; 60 deg apart (kappa = cot(15 deg) = 3.7) passes."""
    original = [Reading(1.0, 0.0), Reading(1.0, 0.0)]

    def trials(gap_deg: float) -> list[TrialRun]:
        a1 = np.array([1.0, 1.0])
        a2 = np.array([1.0, np.exp(1j * math.radians(gap_deg))])  # columns at gap_deg (complex angle)
        v1 = np.array([1.0, 1.0]) + 0.01 * a1 * 100.0
        v2 = np.array([1.0, 1.0]) + 0.01 * a2 * 100.0
        return [TrialRun(0, 0.01, 0.0, tuple(Reading(abs(v), math.atan2(v.imag, v.real)) for v in v1)),
                TrialRun(1, 0.01, 0.0, tuple(Reading(abs(v), math.atan2(v.imag, v.real)) for v in v2))]

    with pytest.raises(InputError, match="nearly singular"):
        two_plane(original, trials(4.0))
    fb = two_plane(original, trials(60.0))
    cols = fb.coefficients / np.linalg.norm(fb.coefficients, axis=0)
    assert np.linalg.cond(cols) < MAX_CONDITION
    assert np.allclose(fb.coefficients @ fb.correction(), -np.array([1.0, 1.0]))  # the corrections cancel V0
