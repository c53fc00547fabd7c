"""An induction motor whose RMS torque over the cycle exceeds its rating for continuous duty S1 (IEC 60034-1) is
a failed design check with the figure, also when the start-up is not simulated; one within its rating passes."""

from __future__ import annotations

import json

import numpy as np
import pytest

from .helpers import EXAMPLES, check_and_run

COMPACTOR = (EXAMPLES / "compactor_flywheel.toml").read_text(encoding="utf-8")
SELECT = 'kind = "select"              # an induction motor from the IEC 60072-1 ratings'


def _induction(power: str) -> str:
    text = COMPACTOR.replace(SELECT, f'kind = "induction"\nrated_power = "{power}"\nrated_speed = "1440 rpm"')
    return text.replace('shape = "disc"', 'start_up = false\nshape = "disc"', 1)


def test_overloaded_motor_is_a_failed_check_with_its_rms_figure(tmp_path):
    check, run = check_and_run(tmp_path, _induction("0.25 kW"))
    assert check.code == 0 and run.code == 3, (check, run)
    assert "overloaded for continuous duty S1 (IEC 60034-1)" in run.stderr
    scalars = json.loads((tmp_path / "out" / "results.json").read_text())["scalars"]
    # rated torque at the crank = P_r / omega_r * i * eta, with i = omega_r / omega_crank: P_r eta / omega_crank
    rated = 250.0 * 0.95 / 10.0
    rms = scalars["flywheel.rms_drive_torque"]["value"]
    assert scalars["flywheel.motor_rms_load"]["value"] == pytest.approx(rms / rated, rel=1e-9)
    assert rms / rated > 1.0
    assert f"{100 * rms / rated:.4g} %" in run.stderr


def test_motor_within_its_rating_passes(tmp_path):
    check, run = check_and_run(tmp_path, _induction("0.55 kW"))
    assert (check.code, run.code) == (0, 0), (check, run)
    scalars = json.loads((tmp_path / "out" / "results.json").read_text())["scalars"]
    assert 0.0 < scalars["flywheel.motor_rms_load"]["value"] < 1.0


def test_selected_motor_is_never_overloaded(tmp_path):
    check, run = check_and_run(tmp_path, COMPACTOR)
    assert run.code == 0, run
    scalars = json.loads((tmp_path / "out" / "results.json").read_text())["scalars"]
    assert scalars["flywheel.motor_rms_load"]["value"] <= 1.0
    assert np.isfinite(scalars["flywheel.motor_rated_power"]["value"])


@pytest.mark.parametrize(("duty_factor", "code"), [(0.4, 0), (0.9, 3)])
def test_intermittent_duty_s3_judges_the_equivalent_torque(tmp_path, duty_factor, code):
    # the 0.25 kW motor is overloaded in S1; running 40 % of the time its equivalent torque T_rms sqrt(0.4) is
    # within the rating, 90 % of the time it is not
    duty = f'\nduty = "S3"\ncyclic_duration_factor = {duty_factor}'
    text = _induction("0.25 kW").replace('rated_speed = "1440 rpm"', f'rated_speed = "1440 rpm"{duty}', 1)
    check, run = check_and_run(tmp_path, text)
    assert (check.code, run.code) == (0, code), (check, run)
    scalars = json.loads((tmp_path / "out" / "results.json").read_text())["scalars"]
    rms = scalars["flywheel.rms_drive_torque"]["value"]
    assert scalars["flywheel.motor_duty_load"]["value"] == pytest.approx(rms * duty_factor**0.5 / 23.75, rel=1e-9)
    if code == 3:
        assert "intermittent periodic duty S3 at 90 %" in run.stderr


def test_s3_without_its_cyclic_duration_factor_is_refused(tmp_path):
    text = _induction("0.25 kW").replace('rated_speed = "1440 rpm"', 'rated_speed = "1440 rpm"\nduty = "S3"', 1)
    check, run = check_and_run(tmp_path, text)
    assert (check.code, run.code) == (2, 2)
    assert "cyclic_duration_factor" in check.stderr
