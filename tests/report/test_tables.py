"""DataFrames and scalars of linkage results: one row per crank angle, units in every header and entry."""

from __future__ import annotations

import json
import re

import numpy as np
import pytest

from machdyn.linkage import energy_fluctuation
from machdyn.report.tables import ANGLE_COLUMN, DESIGN_COLUMN, analysis_frames, scalars_frame, write_csv
from machdyn.results.linkage import analysis_scalars

HEADER = re.compile(r"^\S+ \[[^\[\]]*\]$")
GROUPS = {"motion", "joint_forces", "torque_power", "shaking", "energy"}


def test_one_row_per_crank_angle_and_units_in_headers(any_analysis):
    frames = analysis_frames(any_analysis)
    assert set(frames) == GROUPS
    phi = any_analysis.kinematics.crank_angle
    for name, frame in frames.items():
        assert len(frame) == phi.size, name
        assert frame.columns[0] == ANGLE_COLUMN
        np.testing.assert_allclose(frame[ANGLE_COLUMN], np.degrees(phi))
        for column in frame.columns:
            assert HEADER.match(column), f"{name}: column {column!r} has no unit"
        assert frame.columns.is_unique


def test_frame_values_are_the_results(four_bar_analysis):
    a = four_bar_analysis
    frames = analysis_frames(a)
    np.testing.assert_allclose(frames["torque_power"]["driving_torque [N*m]"], a.forces.driving_torque)
    np.testing.assert_allclose(frames["torque_power"]["input_power [W]"], a.forces.input_power)
    np.testing.assert_allclose(frames["motion"]["rocker.omega [rad/s]"], a.kinematics.body("rocker").omega)
    np.testing.assert_allclose(frames["motion"]["coupler.P.x [m]"], a.kinematics.point("coupler.P").x)
    np.testing.assert_allclose(frames["joint_forces"]["B.fy [N]"], a.forces.joint("B").fy)
    fx, fy = a.forces.frame_force
    np.testing.assert_allclose(frames["shaking"]["shaking_force.magnitude [N]"], np.hypot(fx, fy))
    np.testing.assert_allclose(frames["energy"]["kinetic_total [J]"], a.energy.kinetic_total)
    # every joint of the mechanism is in the joint frame, a shared joint point appears once in motion
    for j in a.forces.joints:
        assert f"{j.name}.magnitude [N]" in frames["joint_forces"].columns
    assert "crank.A.x [m]" in frames["motion"].columns
    assert "coupler.A.x [m]" not in frames["motion"].columns


def test_slider_columns(slider_crank_analysis):
    frames = analysis_frames(slider_crank_analysis)
    s = slider_crank_analysis.kinematics.slide("slider")
    np.testing.assert_allclose(frames["motion"]["slider.slide [m]"], s.s)
    np.testing.assert_allclose(frames["motion"]["slider.slide_acceleration [m/s^2]"], s.a)
    prismatic = [j.name for j in slider_crank_analysis.forces.joints if j.kind == "P"]
    assert prismatic
    assert f"{prismatic[0]}.normal [N]" in frames["joint_forces"].columns
    assert f"{prismatic[0]}.couple [N*m]" in frames["joint_forces"].columns


def test_design_variants_in_long_form(sweep_analysis):
    frames = analysis_frames(sweep_analysis)
    n, m = np.shape(sweep_analysis.forces.driving_torque)
    for frame in frames.values():
        assert frame.columns[0] == DESIGN_COLUMN
        assert len(frame) == n * m
        assert frame.groupby(DESIGN_COLUMN).size().tolist() == [m] * n
        per_design = frame[frame[DESIGN_COLUMN] == 2]
        assert per_design[ANGLE_COLUMN].is_unique
    torque = frames["torque_power"]
    np.testing.assert_allclose(
        torque[torque[DESIGN_COLUMN] == 1]["driving_torque [N*m]"], sweep_analysis.forces.driving_torque[1]
    )


def test_scalars_carry_units_and_match(any_analysis):
    a = any_analysis
    scalars = analysis_scalars(a)
    for key, entry in scalars.items():
        assert set(entry) in ({"value", "unit"}, {"value", "unit", "shown"}), key  # SI, and as shown
        assert isinstance(entry["value"], float), key
        assert isinstance(entry["unit"], str), key
    json.dumps(scalars)  # serialisable as it is
    torque = a.forces.driving_torque
    assert scalars["driving_torque.max_abs"] == {"value": pytest.approx(np.max(np.abs(torque))), "unit": "N*m"}
    assert scalars["driving_torque.rms"]["value"] == pytest.approx(np.sqrt(np.mean(torque**2)))
    assert scalars["input_power.mean"]["unit"] == "W"
    for j in a.forces.joints:
        entry = scalars[f"joint.{j.name}.max_force"]
        assert entry["unit"] == "N"
        assert entry["value"] == pytest.approx(np.max(a.forces.joint(j.name).magnitude))
    assert scalars["frame_force.max"]["unit"] == "N"
    assert scalars["shaking_moment.max_abs"]["unit"] == "N*m"
    assert scalars["reduced_inertia.min"]["unit"] == "kg*m^2"
    assert scalars["reduced_inertia.min"]["value"] <= scalars["reduced_inertia.max"]["value"]
    assert abs(scalars["work_balance.relative_residual"]["value"]) < 1e-9
    assert scalars["transmission_angle.min"]["unit"] == "rad"
    assert scalars["transmission_angle.min"]["shown"]["unit"] == "deg"
    assert 0 < scalars["transmission_angle.min"]["value"] <= scalars["transmission_angle.max"]["value"] <= np.pi
    assert "time_ratio" in scalars
    assert any(k.startswith("stroke.") for k in scalars)


def test_stroke_units(slider_crank_analysis, four_bar_analysis):
    s = analysis_scalars(slider_crank_analysis)
    assert s["stroke.slider"]["unit"] == "m"
    # an offset slider-crank has a stroke a little over twice the crank
    assert 0.1 <= s["stroke.slider"]["value"] < 0.101
    f = analysis_scalars(four_bar_analysis)
    assert f["stroke.rocker"]["unit"] == "rad" and f["stroke.rocker"]["shown"]["unit"] == "deg"


def test_scalars_of_design_variants_are_lists(sweep_analysis):
    scalars = analysis_scalars(sweep_analysis)
    n = np.shape(sweep_analysis.forces.driving_torque)[0]
    entry = scalars["driving_torque.max_abs"]
    assert isinstance(entry["value"], list) and len(entry["value"]) == n
    np.testing.assert_allclose(entry["value"], np.max(np.abs(sweep_analysis.forces.driving_torque), axis=1))
    frame = scalars_frame(scalars)
    assert set(frame.columns) >= {"quantity", "design", "value", "unit"}


def test_flywheel_energy_fluctuation_of_a_sine():
    """T = T0 sin(phi) has the work integral T0 (1 - cos phi): max - min = 2 T0."""
    phi = np.arange(3600) * 2 * np.pi / 3600
    assert energy_fluctuation(5.0 * np.sin(phi), phi) == pytest.approx(10.0, rel=1e-6)


def test_write_csv(tmp_path, slider_crank_analysis):
    frames = analysis_frames(slider_crank_analysis)
    paths = write_csv(frames, tmp_path)
    assert sorted(p.name for p in paths) == sorted(f"{g}.csv" for g in GROUPS)
    import pandas as pd

    back = pd.read_csv(tmp_path / "torque_power.csv")
    assert list(back.columns) == list(frames["torque_power"].columns)
    assert len(back) == slider_crank_analysis.kinematics.crank_angle.size


def test_summary_rows_have_labels_and_clean_round_off(four_bar_analysis):
    from machdyn.results import collect, summarise
    from machdyn.results.linkage import LINKAGE_LABELS, linkage_scalars

    values, units = linkage_scalars(four_bar_analysis)
    results = collect(values, LINKAGE_LABELS, units)
    rows = summarise("four-bar", results, list(values)).as_tuples()
    assert len(rows) == len(values)
    labels = {label: (value, unit) for label, value, unit in rows}
    assert labels["Driving torque, max |T|"][1] == "N*m"
    # without loads the mean torque over a cycle is zero: round-off is shown as 0
    assert abs(values["driving_torque.mean"]) < 1e-9 and labels["Driving torque, mean"][0] == 0.0
    assert "Joint B, max force" in labels
    assert labels["Work balance: residual"][0] == values["work_balance.residual"]
    assert labels["Transmission angle, min"][1] == "deg", "angles are kept in rad and shown in degrees"
    assert labels["Transmission angle, min"][0] == pytest.approx(np.degrees(values["transmission_angle.min"]))
