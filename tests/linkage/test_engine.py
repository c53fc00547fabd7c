"""Engine checks that complement the property tests: moving guides (Coriolis terms), the PRP group, closed-form
diagnostics, harmonics, design broadcasting and sweeps."""

import re
from dataclasses import replace

import numpy as np
import pytest

from machdyn.errors import InputError, SingularPositionError
from machdyn.linkage import (
    PRP,
    RRP,
    Body,
    BodyTorque,
    Guide,
    Mechanism,
    PointForce,
    PointMass,
    analyse,
    crank_angles,
    diagnose,
    double_slider_crank,
    four_bar,
    grashof_type,
    harmonics,
    joints,
    kinematics,
    kinetostatics,
    slider_crank,
    sweep,
)

# Central differences with h = 1e-6 rad have truncation error ~h^2 * f''' ~ 1e-12 and rounding error
# ~eps * |f| / h ~ 1e-10 for the O(1) quantities here: 1e-7 absolute leaves a wide margin.
FD_STEP = 1e-6
FD_TOL = 1e-7


def _with_moving_guides() -> Mechanism:
    """A crank-rocker four-bar carrying (1) a link from a ground pivot whose slider runs along the rocker
    (RRP with a moving guide) and (2) a PRP pair between a ground line and the coupler's axis."""
    base = four_bar(0.04, 0.12, 0.08, 0.10, masses=(0.2, 0.5, 0.4), gravity=(0.0, 0.0))
    bodies = base.bodies + (
        Body("arm", {"E": (0.0, 0.0), "K": (0.12, 0.0)}, 0.3, 2e-4, (0.06, 0.0)),
        Body("runner", {"K": (0.0, 0.0)}, 0.1, 1e-5),
        Body("cross", {"Q": (0.0, 0.0)}, 0.15, 1e-5),
        Body("shoe", {"Q": (0.0, 0.0)}, 0.05, 1e-6),
    )
    # E sits 0.15 m above the rocker pivot: its distance to the rocker's line (swinging 55-129 deg) stays
    # below the arm's 0.12 m; the coupler's axis (18-65 deg) never runs parallel to the ground line through F.
    ground = dict(base.ground, E=(0.10, 0.15), F=(0.0, 0.30))
    dyads = base.dyads + (
        RRP("arm", "runner", "ground.E", "K", Guide("rocker.D", 0.0), branch=1),
        PRP("cross", "shoe", "Q", Guide("ground.F", 0.0), Guide("coupler.A", 0.0)),
    )
    return Mechanism("guides", ground, bodies, base.crank, dyads, gravity=(0.0, -9.81))


def _finite_difference_errors(mech, phi, speed=1.0):
    k0 = kinematics(mech, phi, speed)
    kp = kinematics(mech, phi + FD_STEP, speed)
    km = kinematics(mech, phi - FD_STEP, speed)
    errors = []
    for name in mech.moving_bodies:
        b0, bp, bm = k0.body(name), kp.body(name), km.body(name)
        dangle = np.angle(np.exp(1j * (bp.angle - bm.angle)))
        errors += [
            np.max(np.abs(dangle / (2 * FD_STEP) - b0.omega)),
            np.max(np.abs((bp.omega - bm.omega) / (2 * FD_STEP) - b0.alpha)),
            np.max(np.abs((bp.x - bm.x) / (2 * FD_STEP) - b0.vx)),
            np.max(np.abs((bp.vy - bm.vy) / (2 * FD_STEP) - b0.ay)),
        ]
    for name, slide in k0.slides.items():
        errors += [
            np.max(np.abs((kp.slide(name).s - km.slide(name).s) / (2 * FD_STEP) - slide.v)),
            np.max(np.abs((kp.slide(name).v - km.slide(name).v) / (2 * FD_STEP) - slide.a)),
        ]
    return max(errors)


def test_moving_guides_match_finite_differences():
    mech = _with_moving_guides()
    phi = crank_angles(180)
    assert _finite_difference_errors(mech, phi) < FD_TOL


def test_moving_guides_balance_work_and_energy():
    mech = _with_moving_guides()
    result = analyse(mech, crank_angles(360), 12.0)
    assert result.work_balance.relative < 1e-9
    assert result.power_balance_relative < 1e-9
    np.testing.assert_allclose(
        result.energy.input_torque_from_energy, result.forces.driving_torque, rtol=1e-9, atol=1e-9
    )


def test_frame_force_is_minus_sum_of_mass_times_acceleration():
    mech = _with_moving_guides()
    mech = Mechanism(mech.name, mech.ground, mech.bodies, mech.crank, mech.dyads, gravity=(0.0, 0.0))
    forces = kinetostatics(mech, crank_angles(90), 7.0)
    kin = forces.kinematics
    sx = sum(mech.body(b).mass * kin.com(b).ax for b in mech.moving_bodies)
    sy = sum(mech.body(b).mass * kin.com(b).ay for b in mech.moving_bodies)
    scale = np.max(np.hypot(sx, sy))
    np.testing.assert_allclose(forces.frame_fx, -sx, atol=1e-12 * scale)
    np.testing.assert_allclose(forces.frame_fy, -sy, atol=1e-12 * scale)


def test_grashof_types():
    assert grashof_type(four_bar(0.04, 0.12, 0.08, 0.10)) == "crank-rocker"
    assert grashof_type(four_bar(0.10, 0.12, 0.11, 0.04)) == "double-crank"
    assert grashof_type(four_bar(0.10, 0.04, 0.12, 0.11)) == "Grashof double-rocker"
    assert grashof_type(four_bar(0.10, 0.11, 0.04, 0.12)) == "rocker-crank"
    assert grashof_type(four_bar(0.10, 0.10, 0.10, 0.10)) == "change-point"
    assert grashof_type(four_bar(0.10, 0.11, 0.12, 0.16)) == "non-Grashof triple-rocker"
    assert grashof_type(slider_crank(0.05, 0.2)) is None


def test_crank_rocker_limit_positions_and_time_ratio_match_closed_form():
    """Limit positions of a crank-rocker: crank and coupler in line, extended (coupler + crank) and folded
    (coupler - crank); time ratio (180 + a)/(180 - a) with a the angle between them (Norton, §3.3)."""
    r, c, k, g = 0.04, 0.12, 0.08, 0.10
    diag = diagnose(four_bar(r, c, k, g), samples=7200)

    def crank_angle_at(reach):  # angle of O->B when |OB| = reach, B above the ground line
        return np.arccos((reach**2 + g**2 - k**2) / (2 * reach * g))

    extended, folded = crank_angle_at(c + r), crank_angle_at(c - r) + np.pi
    found = sorted(p.crank_angle for p in diag.limit_positions)
    np.testing.assert_allclose(found, sorted([extended, folded]), atol=1e-6)
    alpha = abs(folded - extended - np.pi)
    assert diag.time_ratio == pytest.approx((np.pi + alpha) / (np.pi - alpha), rel=1e-5)
    assert diag.non_assembly_ranges == []


def test_offset_slider_crank_stroke_matches_closed_form():
    """Stroke of an offset slider-crank: sqrt((l + r)^2 - e^2) - sqrt((l - r)^2 - e^2)."""
    r, l, e = 0.05, 0.2, 0.03
    diag = diagnose(slider_crank(r, l, offset=e), samples=7200)
    expected = np.sqrt((l + r) ** 2 - e**2) - np.sqrt((l - r) ** 2 - e**2)
    # The stroke is read at sampled extremes: its error is ~ s'' * (dphi/2)^2 ~ r * 2e-7.
    assert diag.strokes["slider"] == pytest.approx(expected, abs=r * 1e-6)


def test_non_grashof_four_bar_reports_where_it_cannot_assemble():
    diag = diagnose(four_bar(0.10, 0.11, 0.12, 0.16))
    assert diag.grashof == "non-Grashof triple-rocker"
    assert diag.non_assembly_ranges
    assert any("cannot assemble" in w for w in diag.warnings)


def test_harmonics_recover_a_trigonometric_polynomial():
    phi = crank_angles(64, start=0.3)
    values = 2.0 + 3.0 * np.cos(phi + 0.4) + 0.5 * np.cos(3 * phi - 1.0)
    h = harmonics(values, phi, orders=4)
    np.testing.assert_allclose(h.mean, 2.0, atol=1e-12)
    np.testing.assert_allclose(h.amplitude, [3.0, 0.0, 0.5, 0.0], atol=1e-12)
    np.testing.assert_allclose(h.phase[[0, 2]], [0.4, -1.0], atol=1e-12)


def test_slider_acceleration_harmonics_follow_the_series():
    """Centric slider-crank: a = -r w^2 (cos phi + lam cos 2 phi + O(lam^3)) (seed 000 eq 7 with e = 0)."""
    r, l, w = 0.05, 1.0, 10.0
    kin = kinematics(slider_crank(r, l), crank_angles(256), w)
    h = harmonics(kin.slide("slider").a, kin.crank_angle, orders=3)
    lam = r / l
    assert h.amplitude[0] == pytest.approx(r * w**2, rel=lam**2)
    assert h.amplitude[1] == pytest.approx(lam * r * w**2, rel=lam**2)


def test_harmonics_reject_uneven_angles():
    with pytest.raises(InputError, match="evenly spaced over one full revolution"):
        harmonics(np.ones(10), np.linspace(0, np.pi, 10))


def test_design_arrays_equal_single_designs():
    cranks = np.array([0.03, 0.04, 0.045])
    phi = crank_angles(72)
    many = kinetostatics(four_bar(cranks, 0.12, 0.08, 0.10), phi, 10.0)
    assert many.driving_torque.shape == (3, 72)
    for i, r in enumerate(cranks):
        one = kinetostatics(four_bar(float(r), 0.12, 0.08, 0.10), phi, 10.0)
        np.testing.assert_allclose(many.driving_torque[i], one.driving_torque, rtol=1e-13, atol=1e-15)
        np.testing.assert_allclose(many.joint("B").fx[i], one.joint("B").fx, rtol=1e-13, atol=1e-15)


def test_sweep_summaries_equal_direct_results_and_flag_unassemblable_designs():
    cranks = np.array([0.03, 0.04, 0.09])  # the last one cannot turn fully
    phi = crank_angles(90)
    mech = four_bar(cranks, 0.12, 0.08, 0.10)
    result = sweep(mech, phi, 10.0, chunk_positions=100)  # force several chunks
    assert result.assembled.tolist() == [True, True, False]
    assert np.isnan(result.max_driving_torque[2])
    for i in range(2):
        one = kinetostatics(mech.take_designs(i), phi, 10.0)
        assert result.max_driving_torque[i] == pytest.approx(np.max(np.abs(one.driving_torque)), rel=1e-13)
        assert result.max_joint_force["O"][i] == pytest.approx(np.max(one.joint("O").magnitude), rel=1e-13)
        assert result.max_shaking_force[i] == pytest.approx(np.max(one.shaking_force), rel=1e-13)


def test_shaking_moment_about_another_point_shifts_by_the_force_moment():
    forces = kinetostatics(four_bar(0.04, 0.12, 0.08, 0.10), crank_angles(36), 10.0)
    z = (0.05, -0.02)
    expected = forces.shaking_moment() - (z[0] * forces.frame_fy - z[1] * forces.frame_fx)
    np.testing.assert_allclose(forces.shaking_moment(z), expected, rtol=1e-14, atol=1e-14)


def test_a_load_window_of_a_full_turn_keeps_the_load_on():
    base = slider_crank(0.05, 0.2, gravity=(0.0, 0.0))
    phi = crank_angles(24)
    always = replace(base, forces=(PointForce("F", "slider.B", -100.0, 0.0),))
    full_turn = replace(base, forces=(PointForce("F", "slider.B", -100.0, 0.0, active=(0.0, 2 * np.pi)),))
    np.testing.assert_allclose(
        kinetostatics(full_turn, phi, 10.0).driving_torque, kinetostatics(always, phi, 10.0).driving_torque
    )


def test_a_toggle_within_rounding_is_a_singular_position():
    """Non-Grashof four-bar at the end of its assembly range: coupler and rocker in line."""
    a, b, c, g = 2.0, 2.2, 1.5, 3.0
    toggle = np.arccos((a**2 + g**2 - (b + c) ** 2) / (2 * a * g))
    with pytest.raises(SingularPositionError, match="dead \\(toggle\\) or indeterminate position"):
        kinematics(four_bar(a, b, c, g), np.array([toggle]))


def test_sweep_flags_a_design_that_passes_a_singular_position():
    """A kite four-bar (1, 2, 2, 1) puts its crank pin on the rocker pivot at phi = 0."""
    result = sweep(four_bar(np.array([1.0, 0.9]), 2.0, 2.0, 1.0), crank_angles(8), 1.0)
    assert result.assembled.tolist() == [True, True]
    assert result.regular.tolist() == [False, True]
    assert np.isnan(result.max_driving_torque[0]) and np.isfinite(result.max_driving_torque[1])


def test_parallelogram_dead_positions_and_no_false_limit_positions():
    diag = diagnose(four_bar(1.0, 2.0, 1.0, 2.0), samples=720)
    np.testing.assert_allclose(np.degrees(diag.dead_positions), [0.0, 180.0], atol=1e-9)
    assert diag.limit_positions == []


def test_mean_power_and_rms_torque_are_time_averages_at_variable_speed():
    """Mean input power = work per turn / period = integral(T dphi) / integral(dphi / omega)."""
    mech = four_bar(np.array([0.04, 0.035]), 0.12, 0.08, 0.10, masses=(0.2, 0.5, 0.4))
    mech = replace(mech, torques=(BodyTorque("load", "crank", -2.0),))  # a resisting torque on the shaft
    phi = crank_angles(720)
    speed = 7.0 + 3.0 * np.sin(phi)
    accel = 3.0 * np.cos(phi) * speed  # d(omega)/dt = d(omega)/dphi * omega
    result = sweep(mech, phi, speed, accel, chunk_positions=800)
    forces = kinetostatics(mech, phi, speed, accel)
    period = np.sum(1.0 / speed) * (2 * np.pi / phi.size)
    work = np.sum(forces.driving_torque, axis=-1) * (2 * np.pi / phi.size)
    np.testing.assert_allclose(result.mean_input_power, work / period, rtol=1e-12)
    rms = np.sqrt(np.sum(forces.driving_torque**2 / speed, axis=-1) * (2 * np.pi / phi.size) / period)
    np.testing.assert_allclose(result.rms_driving_torque, rms, rtol=1e-12)


def test_sweep_with_one_speed_per_design_across_chunks():
    mech = slider_crank(np.array([0.03, 0.04, 0.05, 0.06]), 0.2)
    speeds = np.array([1.0, 2.0, 3.0, 4.0])
    phi = crank_angles(24)
    result = sweep(mech, phi, speeds, chunk_positions=30)
    for i, w in enumerate(speeds):
        one = kinetostatics(mech.take_designs(i), phi, w)
        assert result.max_driving_torque[i] == pytest.approx(np.max(np.abs(one.driving_torque)), rel=1e-13)


def test_point_mass_names_must_not_clash_with_bodies():
    with pytest.raises(InputError, match=re.escape(
        "Point-mass names must differ from each other and from body names in mechanism 'slider_crank'; "
        "got crank more than once."
    )):
        replace(slider_crank(0.05, 0.2), point_masses=(PointMass("crank", "crank", 5.0, (0.05, 0.0)),))


def test_joint_names_are_unique_in_solution_order():
    """Two rods on one crank pin: the first keeps the name 'A', the second is 'A:rod_2'."""
    base = double_slider_crank(0.05, 0.2, 0.05, 0.25, phase=0.0)
    crank = replace(base.body("crank"), points={"O": (0.0, 0.0), "A": (0.05, 0.0)})
    rod_2 = replace(base.body("rod_2"), points={"A": (0.0, 0.0), "B2": (0.25, 0.0)})
    rod_1 = replace(base.body("rod_1"), points={"A": (0.0, 0.0), "B1": (0.2, 0.0)})
    bodies = tuple({"crank": crank, "rod_1": rod_1, "rod_2": rod_2}.get(b.name, b) for b in base.bodies)
    dyads = tuple(replace(d, pin_a="crank.A") for d in base.dyads)
    mech = replace(base, bodies=bodies, dyads=dyads)
    forces = kinetostatics(mech, crank_angles(12), 5.0)
    names = [j.name for j in forces.joints]
    assert names[:2] == ["O", "A"] and "A:rod_2" in names
    assert names == [j[0] for j in joints(mech)]


def test_diagnostics_sized_to_the_request_equal_a_resampling():
    # At constant crank speed the diagnostics of an analysed revolution of n positions are those of diagnose at n
    # samples: the same dead and limit positions, strokes and time ratio (to rounding: the rates are scaled by
    # the crank speed before the zero crossings are interpolated).
    for mech in (four_bar(0.04, 0.12, 0.08, 0.10), slider_crank(0.1, 0.4, 0.05), four_bar(1.0, 2.0, 1.0, 2.0)):
        phi = crank_angles(720)
        kin = kinematics(mech, phi, 7.5, on_fail="mask")
        sized = diagnose(mech, kinematics_result=kin)
        resampled = diagnose(mech, 720)
        assert sized.grashof == resampled.grashof
        assert sized.assembly_ranges == resampled.assembly_ranges
        np.testing.assert_allclose(sized.dead_positions, resampled.dead_positions, rtol=1e-12, atol=1e-12)
        assert [p.body for p in sized.limit_positions] == [p.body for p in resampled.limit_positions]
        for a, b in zip(sized.limit_positions, resampled.limit_positions, strict=True):
            assert abs(a.crank_angle - b.crank_angle) < 1e-12 and abs(a.value - b.value) < 1e-12
        assert sized.strokes.keys() == resampled.strokes.keys()
        for body, stroke in sized.strokes.items():
            assert stroke == pytest.approx(resampled.strokes[body], rel=1e-12)
        assert (sized.time_ratio is None) == (resampled.time_ratio is None)
        if sized.time_ratio is not None:
            assert sized.time_ratio == pytest.approx(resampled.time_ratio, rel=1e-12)
    with pytest.raises(InputError, match="full revolution"):
        diagnose(mech, kinematics_result=kinematics(mech, np.linspace(0.0, 1.0, 50), on_fail="mask"))


def test_analysis_diagnostics_are_computed_when_read_and_kept():
    mech = four_bar(0.04, 0.12, 0.08, 0.10)
    result = analyse(mech, crank_angles(360), 10.0)
    assert "diagnostics" not in vars(result)  # not computed by analyse itself
    first = result.diagnostics
    assert first == diagnose(mech) and diagnose(mech) is first  # kept with the (immutable) mechanism
    assert analyse(mech, crank_angles(360), 10.0, diagnostics=False).diagnostics is None
