"""The cam checks judge each segment exactly, whatever the number of sampled positions: a rise that falls between
two samples fails, an undercut cam fails at 16 positions as at 720, and the exact extremes agree with a sampling
100 times denser."""

from __future__ import annotations

import numpy as np
import pytest
from typer.testing import CliRunner

from machdyn.cams.checks import check_cam
from machdyn.cams.exact import extremes
from machdyn.cams.followers import Follower
from machdyn.cams.profile import cam_angles, profile
from machdyn.cams.program import Segment, program
from machdyn.cli import app
from reproductions import feeder_with, steep_rise

D = np.radians


def test_a_rise_between_two_samples_fails_its_pressure_angle(tmp_path):
    """30 mm over 0.3 deg, sampled every 0.5 deg: the sampled profile never sees the rise (24 deg), the exact
    check does (cycloidal: v peaks at 2 h / beta, tan phi ~ 2 h / (beta d) ~ 90 deg)."""
    bad = tmp_path / "steep.toml"
    bad.write_text(steep_rise())
    result = CliRunner().invoke(app, ["run", str(bad), "--out", str(tmp_path / "o")])
    assert result.exit_code == 3, result.output
    assert "pressure angle 89." in result.output and "exceeds the limit 30 deg" in result.output
    assert "segment 1 (rise over 0.3 deg) is shorter than two steps" in result.output
    check = CliRunner().invoke(app, ["check", str(bad)])
    assert check.exit_code == 0, check.output  # the file is valid; the design fails its checks (exit 3 at run)


def _undercut_cam():
    prog = program([Segment("rise", D(40), 0.03, "cycloidal"), Segment("dwell", D(140)),
                    Segment("return", D(120), 0.03, "poly345"), Segment("dwell", D(60))])
    return prog, Follower("translating", "roller", 0.045, 0.03, 0.0)


def test_an_undercut_cam_fails_at_16_positions_as_at_720():
    prog, f = _undercut_cam()
    coarse = profile(prog, f, cam_angles(16))
    sampled = np.min(np.where(coarse.pitch_curvature_radius > 0, coarse.pitch_curvature_radius, np.inf))
    assert sampled > f.roller_radius  # the 16 samples alone miss the undercut
    results = [check_cam(profile(prog, f, cam_angles(n)), prog, pressure_limit=D(60)) for n in (16, 720)]
    for c in results:
        assert any(m.startswith("undercut") for m in c.failed), c.failed
        assert c.min_pitch_radius < f.roller_radius
    assert results[0].min_pitch_radius == results[1].min_pitch_radius
    assert results[0].max_pressure_angle == results[1].max_pressure_angle


def test_the_command_line_reports_the_undercut_at_16_positions(tmp_path):
    bad = tmp_path / "undercut.toml"
    bad.write_text(feeder_with("40 deg", "140 deg", 16, roller="30 mm").replace(
        'pressure_angle_limit = "30 deg"', 'pressure_angle_limit = "60 deg"'))
    result = CliRunner().invoke(app, ["run", str(bad), "--out", str(tmp_path / "o"), "-q"])
    assert result.exit_code == 3, result.output
    assert "undercut: the roller radius 30 mm" in result.output


@pytest.mark.parametrize("follower", [
    Follower("translating", "roller", 0.045, 0.012, 0.005),
    Follower("translating", "knife", 0.04, 0.0, -0.004),
    Follower("oscillating", "roller", 0.04, 0.01, pivot_distance=0.09, arm_length=0.07),
])
def test_the_exact_extremes_agree_with_a_sampling_100_times_denser(follower):
    """At 360 positions the checks and a profile sampled at 36 000 agree: the exact maximum is at least the dense
    samples' (it is the supremum) and exceeds it by no more than the pressure angle's change over half a dense
    step (its slope here is below 3 rad/rad, half a step 8.7e-5 rad: 3e-4 rad)."""
    lift = 0.03 if follower.motion == "translating" else D(20)
    prog = program([Segment("rise", D(110), lift, "cycloidal"), Segment("dwell", D(70)),
                    Segment("return", D(120), lift, "modified_sine"), Segment("dwell", D(60))])
    c = check_cam(profile(prog, follower, cam_angles(360)), prog, pressure_limit=D(89))
    dense = profile(prog, follower, cam_angles(36_000))
    sampled = float(np.max(np.abs(dense.pressure_angle)))
    assert sampled <= c.max_pressure_angle + 1e-12
    assert c.max_pressure_angle == pytest.approx(sampled, abs=3e-4)
    rho = dense.pitch_curvature_radius
    dense_rho = float(np.min(np.where(rho > 0, rho, np.inf)))
    assert c.min_pitch_radius <= dense_rho * (1 + 1e-12)
    assert c.min_pitch_radius == pytest.approx(dense_rho, rel=1e-4)


def test_a_flat_face_s_contact_range_and_cusp_are_exact():
    """Flat face: contact v = ds/dtheta runs over [v_min, v_max] = the law's closed-form peaks, 2 h / beta for
    the cycloidal rise and -1.875 h / beta for the 3-4-5 return (Norton table 8-2 peak factors); the smallest
    radius R_b + s + a agrees with dense sampling."""
    h, rise, ret = 0.02, D(90), D(100)
    prog = program([Segment("rise", rise, h, "cycloidal"), Segment("dwell", D(80)),
                    Segment("return", ret, h, "poly345"), Segment("dwell", D(90))])
    f = Follower("translating", "flat", 0.03)
    ext = extremes(prog, f)
    assert ext.contact_max == pytest.approx(2.0 * h / rise, rel=1e-10)
    assert ext.contact_min == pytest.approx(-1.875 * h / ret, rel=1e-10)
    dense = profile(prog, f, cam_angles(36_000))
    assert ext.min_flat_radius == pytest.approx(float(np.min(dense.surface_curvature_radius)), rel=1e-5)
    small = Follower("translating", "flat", 0.005)  # R_b + s + a < 0 somewhere: a cusp at every sampling
    for n in (16, 720):
        assert any("cusp" in m for m in check_cam(profile(prog, small, cam_angles(n)), prog).failed)


def test_the_jump_speed_sees_a_short_rise_at_any_number_of_positions():
    """A 30 mm cycloidal rise over 2 deg, a spring of 2 N/mm with 40 N preload, 4 kg: the jump speed found by
    brute force on 200 001 angles of the rise (the quadratic's root at each, no damping: w = sqrt((k s + F0) /
    (-m a))) is what the run reports at 16 and at 720 positions, to 0.1 % (65 samples on each piece of the
    segment: the acceleration's peak to (pi/64)^2/8)."""
    from machdyn.cams.dynamics import FollowerTrain, Spring, cam_forces

    rise, h = D(2), 0.03
    prog = program([Segment("rise", rise, h, "cycloidal"), Segment("dwell", D(178)),
                    Segment("return", D(120), h, "poly345"), Segment("dwell", D(60))])
    train, spring = FollowerTrain(4.0, 2000.0, 40.0), Spring(2000.0, 40.0)
    x = np.linspace(0.0, 1.0, 200_001)
    s = h * (x - np.sin(2 * np.pi * x) / (2 * np.pi))
    a = h * 2 * np.pi * np.sin(2 * np.pi * x) / rise**2
    neg = a < 0
    brute = float(np.min(np.sqrt((2000.0 * s[neg] + 40.0) / (-4.0 * a[neg]))))
    found = [cam_forces(prog, train, spring, 1.0, cam_angles(n)).jump_speed for n in (16, 720)]
    assert found[0] == found[1]
    assert found[0] == pytest.approx(brute, rel=1e-3)
    assert found[0] >= brute * (1 - 1e-12)  # samples can only miss the lowest speed, never undercut it
