"""Motor duty through the command line: an induction motor overloaded for its S3/S6 duty, or one whose rotor does
not stand the starts per hour asked for, is a failed design check (exit 3) with the figure that failed; ``check``
and ``run`` agree on what is valid."""

from __future__ import annotations

import json

import pytest

from .helpers import EXAMPLES, check_and_run

COMPACTOR = (EXAMPLES / "compactor_flywheel.toml").read_text(encoding="utf-8")
PRESS = (EXAMPLES / "crank_press.toml").read_text(encoding="utf-8")
SELECT = 'kind = "select"              # an induction motor from the IEC 60072-1 ratings'


def _compactor(extra: str) -> str:
    text = COMPACTOR.replace(SELECT, f'kind = "induction"\nrated_power = "0.25 kW"\nrated_speed = "1440 rpm"\n'
                                     f"{extra}")
    return text.replace('shape = "disc"', 'start_up = false\nshape = "disc"', 1)


def _scalars(tmp_path) -> dict:
    return {k: v["value"] for k, v in json.loads((tmp_path / "out" / "results.json").read_text())["scalars"].items()}


def test_a_motor_overloaded_in_s1_passes_in_s3_at_40_percent(tmp_path):
    """The 0.25 kW motor runs the compactor at 129 % of its S1 rating; switched off 60 % of the time (S3 40 %) its
    equivalent torque is sqrt(0.4) times the RMS torque while loaded."""
    check, run = check_and_run(tmp_path, _compactor('duty = "S3"\ncyclic_duration_factor = 0.4'))
    assert (check.code, run.code) == (0, 0), (check, run)
    s = _scalars(tmp_path)
    assert s["flywheel.motor_rms_load"] > 1.0
    assert s["flywheel.motor_duty_load"] == pytest.approx(0.4**0.5 * s["flywheel.motor_rms_load"], rel=1e-9)


def test_a_motor_overloaded_in_s6_is_a_failed_check_with_its_figure(tmp_path):
    check, run = check_and_run(tmp_path, _compactor('duty = "S6"\ncyclic_duration_factor = 0.9\n'
                                                    'no_load_torque = "5 N*m"'))
    assert check.code == 0 and run.code == 3, (check, run)
    s = _scalars(tmp_path)
    rated = 250.0 * 0.95 / 10.0  # P_r eta / omega_crank at the crank
    equivalent = (0.9 * s["flywheel.rms_drive_torque"] ** 2 + 0.1 * 5.0**2) ** 0.5
    assert s["flywheel.motor_duty_load"] == pytest.approx(equivalent / rated, rel=1e-9)
    said = " ".join(run.stderr.split())
    assert "overloaded for continuous periodic duty S6 at 90 % load" in said
    assert f"{100 * equivalent / rated:.4g} %" in said


def _press(starts: int, motor: str = 'kind = "select"') -> str:
    text = PRESS.replace("starts_per_hour = 10 ", f"starts_per_hour = {starts} ", 1)
    return text.replace('kind = "select"\nsynchronous_speed', f'{motor}\nsynchronous_speed', 1)


def test_too_many_starts_per_hour_is_a_failed_check_with_its_figure(tmp_path):
    """The crank press's 0.37 kW motor runs up its flywheel in about 4 s; its rotor heat allows some 16 starts an
    hour: 30 fail, naming both figures."""
    text = _press(30, 'kind = "induction"\nrated_power = "0.37 kW"\nrated_speed = "1440 rpm"')
    check, run = check_and_run(tmp_path, text)
    assert check.code == 0 and run.code == 3, (check, run)
    s = _scalars(tmp_path)
    allowed = s["flywheel.motor_starts_per_hour"]
    assert 0 < allowed < 30
    said = " ".join(run.stderr.split())
    assert f"stands {allowed:.4g} starts per hour" in said and "fewer than the 30 asked for" in said
    assert s["flywheel.motor_start_rotor_loss"] > 0
    report = (tmp_path / "out" / "report.html").read_text(encoding="utf-8")
    assert "starts per hour it stands" in report and "rotor loss of one start" in report


def test_the_selected_motor_stands_the_starts_asked_for(tmp_path):
    """Asked for 30 starts an hour, the selection goes past the 0.37 kW motor the press needs for its load."""
    check, run = check_and_run(tmp_path, _press(30))
    assert (check.code, run.code) == (0, 0), (check, run)
    s = _scalars(tmp_path)
    assert s["flywheel.motor_rated_power"] > 0.37  # kW, as results.json shows it
    assert s["flywheel.motor_starts_per_hour"] >= 30.0


def test_the_crank_press_example_stands_its_starts(tmp_path):
    check, run = check_and_run(tmp_path, PRESS)
    assert (check.code, run.code) == (0, 0), (check, run)
    assert _scalars(tmp_path)["flywheel.motor_starts_per_hour"] >= 10.0


@pytest.mark.parametrize("extra, field, rule", [
    ('duty = "S3"', "flywheel.motor", "needs cyclic_duration_factor"),
    ('duty = "S3"\ncyclic_duration_factor = 1.5', "cyclic_duration_factor", "must be <= 1.0; got 1.5"),
    ('duty = "S4"', "duty", "S1"),
    ('starts_per_hour = -1', "starts_per_hour", "must be >= 0.0; got -1"),
    ('rest_cooling = 0', "rest_cooling", "must be > 0.0; got 0"),
    ('kind = "constant_torque"\nduty = "S3"\ncyclic_duration_factor = 0.4', "flywheel.motor",
     "apply to an induction motor"),
])
def test_bad_duty_fields_exit_2_naming_the_field(tmp_path, extra, field, rule):
    text = _compactor(extra)
    if "constant_torque" in extra:
        text = text.replace('kind = "induction"\n', "", 1)
    check, run = check_and_run(tmp_path, text)
    assert check.code == 2 and run.code == 2, (check, run)
    said = " ".join(check.stderr.split())
    assert field in said and rule in said, said


def test_starts_asked_for_without_a_start_up_are_said_to_be_unchecked(tmp_path):
    check, run = check_and_run(tmp_path, _compactor('rated_power = "0.55 kW"\nstarts_per_hour = 5').replace(
        'rated_power = "0.25 kW"\n', "", 1))
    assert (check.code, run.code) == (0, 0), (check, run)
    said = json.loads((tmp_path / "out" / "results.json").read_text())["warnings"]
    assert any("starts_per_hour is not checked" in w for w in said), said
    assert "flywheel.motor_starts_per_hour" not in _scalars(tmp_path)
