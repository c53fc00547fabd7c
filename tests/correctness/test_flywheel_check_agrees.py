"""``check`` runs every validation of ``[flywheel]`` that ``run`` relies on, and a drive too weak for the
machine is a failed design check (exit 3 with its figures), not bad input after ``check`` said OK."""

from __future__ import annotations

import pytest

from .helpers import EXAMPLES, check_and_run

COMPACTOR = (EXAMPLES / "compactor_flywheel.toml").read_text(encoding="utf-8")
SELECT = 'kind = "select"              # an induction motor from the IEC 60072-1 ratings'


def _motor(lines: str) -> str:
    assert SELECT in COMPACTOR
    return COMPACTOR.replace(SELECT, lines)


REFUSED = [
    ("negative_drive_speed_with_flywheel", COMPACTOR.replace('speed = "10 rad/s"', 'speed = "-10 rad/s"'),
     "drive.speed: must be > 0 for [flywheel]"),
    ("synchronous_speed_zero", COMPACTOR.replace('synchronous_speed = "1500 rpm"', 'synchronous_speed = "0 rpm"'),
     "flywheel.motor.synchronous_speed: must be > 0"),
    ("synchronous_speed_negative",
     COMPACTOR.replace('synchronous_speed = "1500 rpm"', 'synchronous_speed = "-1500 rpm"'),
     "flywheel.motor.synchronous_speed: must be > 0"),
    ("rated_speed_above_synchronous",
     _motor('kind = "induction"\nrated_power = "0.75 kW"\nrated_speed = "1600 rpm"'),
     "flywheel.motor: the rated speed of the induction motor must be below its synchronous speed"),
]


@pytest.mark.parametrize(("text", "message"), [c[1:] for c in REFUSED], ids=[c[0] for c in REFUSED])
def test_flywheel_input_refused_by_check_as_by_run(tmp_path, text, message):
    check, run = check_and_run(tmp_path, text)
    assert (check.code, run.code) == (2, 2), (check, run)
    assert message in check.stderr and message in run.stderr


WEAK = [
    ("induction_motor_too_small", _motor('kind = "induction"\nrated_power = "0.09 kW"\nrated_speed = "1440 rpm"'),
     "breakdown torque 21.38 N*m"),
    ("tiny_gear_ratio", _motor('kind = "induction"\nrated_power = "3 kW"\nrated_speed = "1440 rpm"\nratio = 0.5'),
     "breakdown torque 23.62 N*m"),
    ("hydraulic_motor_too_small",
     _motor('kind = "hydraulic"\ndisplacement = "1 cm^3"\nflow = "1 l/min"\npressure_limit = "10 bar"'),
     "breakdown torque 0.1361 N*m"),  # 0.1432 N*m of the motor through the table's gear of efficiency 0.95
]


@pytest.mark.parametrize(("text", "figure"), [c[1:] for c in WEAK], ids=[c[0] for c in WEAK])
def test_drive_that_cannot_carry_the_load_is_a_failed_check(tmp_path, text, figure):
    check, run = check_and_run(tmp_path, text)
    assert check.code == 0 and run.code == 3, (check, run)
    assert "The drive cannot carry the load" in run.stderr and figure in run.stderr
    assert "peak load torque 91.18 N*m" in run.stderr
    assert (tmp_path / "out" / "report.html").is_file()
