"""A cam of absurd size is refused as an input mistake, and a cam whose rim runs faster than a steel disc can
turn fails a design check (exit 3), instead of results like a 3.9e15 N contact force with exit 0."""

from __future__ import annotations

import numpy as np
import pytest
from typer.testing import CliRunner

from machdyn.cams.checks import BURST_RIM_SPEED, rim_speed_failure
from machdyn.cams.followers import MAX_CAM_SIZE, Follower
from machdyn.cli import app
from machdyn.errors import InputError
from reproductions import example, fast_cam, huge_base_radius, kinematic


def test_a_base_circle_of_1e9_m_is_refused_by_check_and_run(tmp_path):
    bad = tmp_path / "huge.toml"
    bad.write_text(huge_base_radius())
    runner = CliRunner()
    check = runner.invoke(app, ["check", str(bad)])
    run = runner.invoke(app, ["run", str(bad), "--out", str(tmp_path / "o"), "-q"])
    assert check.exit_code == run.exit_code == 2, check.output + run.output
    assert "cam.base_radius" in check.output and "more than 10 m" in check.output
    with pytest.raises(InputError, match="arm_length"):
        Follower("oscillating", "roller", 0.04, 0.01, pivot_distance=0.09, arm_length=2 * MAX_CAM_SIZE)


def test_a_cam_at_1e9_rpm_fails_its_rim_speed_check(tmp_path):
    bad = tmp_path / "fast.toml"
    bad.write_text(fast_cam())
    result = CliRunner().invoke(app, ["run", str(bad), "--out", str(tmp_path / "o"), "-q"])
    assert result.exit_code == 3, result.output
    assert "rim runs at" in result.output and "bursts above about 556 m/s" in result.output
    ok = tmp_path / "ok.toml"
    ok.write_text(kinematic(example("feeder_cam")))
    assert "rim runs" not in CliRunner().invoke(app, ["run", str(ok), "--out", str(tmp_path / "p"), "-q"]).output


def test_the_bursting_rim_speed_is_the_rotating_disc_s_bore_stress_at_2_gpa():
    """Shigley's MED, 8th ed., eq 3-55: sigma_t(r) = rho w^2 (3 + nu)/8 (ri^2 + ro^2 + ri^2 ro^2/r^2
    - (1 + 3 nu)/(3 + nu) r^2); at the bore of a disc with a small bore (ri = ro/1000) and rim speed w ro at the
    bound it is 2 GPa to 1e-6; just below the bound no failure, just above one."""
    rho, nu, ro = 7850.0, 0.3, 0.1
    ri = ro / 1000
    w = BURST_RIM_SPEED / ro
    sigma = rho * w**2 * (3 + nu) / 8 * (ri**2 + ro**2 + ro**2 - (1 + 3 * nu) / (3 + nu) * ri**2)
    assert sigma == pytest.approx(2.0e9, rel=1e-6)
    assert rim_speed_failure(ro, w * (1 - 1e-9)) is None
    assert rim_speed_failure(ro, w * (1 + 1e-9)) is not None
    assert np.isclose(BURST_RIM_SPEED, 555.7, atol=0.1)
