"""The capability stages on the shipped example: tables, frame study, records, predicted against measured."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np
import pytest
from pydantic import ValidationError

from machdyn.errors import InputError
from machdyn.kinds import kind
from machdyn.pipeline import no_step
from machdyn.reading import read_problem
from machdyn.vibration.stage import frame_outcome, signal_outcome
from machdyn.vibration.study import study_frame, study_signals
from machdyn.vibration.tables import FrameTable, SignalsTable

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "vibration_record.toml"


@pytest.fixture(scope="module")
def example():
    loaded = read_problem(EXAMPLE)
    outcome = kind(loaded.kind).analyse(loaded.spec, loaded.model, no_step)
    problem = loaded.spec
    fs = study_frame(problem.frame, outcome.mechanism, outcome.analysis)
    ss = study_signals(problem.signals, source=EXAMPLE, crank_speed=problem.drive.speed, frame_study=fs)
    frame = tomllib_table(EXAMPLE, "frame")
    return (outcome.mechanism, outcome.analysis), frame, fs, ss


def tomllib_table(path, name):
    import tomllib

    return tomllib.loads(Path(path).read_text())[name]


def test_frame_study_of_the_tamper_example(example):
    _, _, fs, _ = example
    out = frame_outcome(fs)
    values = out.scalars
    assert set(values) == set(out.labels)
    assert [k for k in values if k.endswith(".frequency")] == [f"frame.mode_{j}.frequency" for j in (1, 2, 3)]
    assert len([k for k in values if k.startswith("frame.transmitted_force.before.")]) == 4  # 2 tyres x 2 lines
    # Balancing lowers the RMS acceleration at every point and the mean level (about 43 % for this setting).
    assert all(values[f"frame.acceleration_reduction.{p}"] > 0 for p in fs.points)
    assert 0.30 < values["frame.mean_acceleration_reduction"] < 0.60  # a fraction (SI), shown in %
    assert max(values[f"frame.zone.after.{p}"] for p in fs.points) <= max(values[f"frame.zone.before.{p}"]
                                                                          for p in fs.points)
    assert any("zone D" in w for w in out.warnings)
    t, centre = out.series["frame_time"]["time"][0], out.series["frame_time"]["centre_before"][0]
    # RMS of the vertical time series equals the predicted RMS (one whole revolution, rel 1e-9).
    assert np.sqrt(np.mean(centre**2)) == pytest.approx(values["frame.rms_acceleration.before.centre"], rel=1e-9)
    assert t.size == 360


def test_measured_records_match_the_prediction(example):
    # The records are the prediction plus a 1.5 Hz sway and an offset (both removed by the 10-1000 Hz band) and
    # white noise of 0.03 m/s^2 RMS over 0-1280 Hz, which integrates to about 4e-5 m/s in the band and adds in
    # quadrature to levels of 1e-3 m/s and more (< 0.2 %). The 3 % tolerance leaves room for the 2 s record.
    _, _, _, ss = example
    for c in ss.before.channels:
        assert c.velocity_rms == pytest.approx(ss.predicted_before[c.name], rel=0.03)
    for c in ss.after.channels:
        assert c.velocity_rms == pytest.approx(ss.predicted_after[c.name], rel=0.03)
    out = signal_outcome(ss)
    assert set(out.scalars) == set(out.labels)
    assert out.scalars["signals.mean_reduction"] == pytest.approx(ss.reduction["mean"] / 100)  # % -> fraction
    assert out.series["signals_psd"]["front"][0].size == out.series["signals_psd"]["frequency"][0].size


def test_committed_records_are_what_the_script_makes(example, tmp_path):
    spec = importlib.util.spec_from_file_location("make_record", ROOT / "examples" / "signals" / "make_record.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    _, _, fs, _ = example
    rng = np.random.default_rng(module.SEED)
    rows = module.record(fs.before, fs.points, fs.direction, rng)
    module.write(tmp_path / "before.csv", list(fs.points), rows,
                 "screed frame, vertical acceleration, before balancing (synthetic test record)")
    assert (tmp_path / "before.csv").read_text() == (ROOT / "examples" / "signals" / "tamper_before.csv").read_text()


def test_table_errors(example):
    _, frame, _, _ = example
    bad = dict(frame, mounts=[dict(frame["mounts"][0], vertical_stiffness="-1 MN/m")])
    with pytest.raises(ValidationError, match="must be >= 0 N/m"):
        FrameTable.model_validate(bad)
    twice = dict(frame, mounts=[frame["mounts"][0], frame["mounts"][0]])
    with pytest.raises(ValidationError, match="mount names must be unique; got front_tyre twice"):
        FrameTable.model_validate(twice)
    with pytest.raises(ValidationError, match="low < high"):
        SignalsTable.model_validate({"record": "x.csv", "band": ["1000 Hz", "10 Hz"]})
    with pytest.raises(ValidationError, match="machine_class"):
        SignalsTable.model_validate({"record": "x.csv", "machine_class": "V"})


def test_unknown_counterweight_body_and_missing_record(example, tmp_path):
    (mech, analysis), frame, _, _ = example
    bad = dict(frame, after={"counterweights": [{"body": "shaft", "mass": "1 kg", "radius": "1 mm",
                                                 "angle": "0 deg"}]})
    with pytest.raises(InputError, match="no body 'shaft'"):
        study_frame(FrameTable.model_validate(bad), mech, analysis)
    with pytest.raises(InputError, match="does not exist"):
        study_signals(SignalsTable.model_validate({"record": "missing.csv"}), source=tmp_path / "p.toml")


def test_rotary_screen_frame_hung_on_ropes():
    # Seed 002's screen stands on a frame hung on four steel ropes. With the ropes carrying the frame's whole
    # weight at the height of its centre of mass, the fore-aft mode is the pendulum sqrt(g/L) (rel 1e-9), and
    # the screen's 21 rad/s (3.34 Hz) shaking gives a finite response at every point.
    from machdyn.runner import run_problem

    ropes = "\n".join(
        f'[[frame.mounts]]\ntype = "rope"\nname = "rope_{i}"\nposition = ["{x} m", "0 m"]\nlength = "1.2 m"\n'
        f'supported_mass = "250 kg"\naxial_stiffness = "40 MN/m"\ndamping = "500 N*s/m"\n'
        for i, x in enumerate((-1.5, -0.5, 0.5, 1.5)))
    text = (ROOT / "examples" / "rotary_screen.toml").read_text() + (
        '\n[frame]\nmass = "1000 kg"\ninertia = "600 kg*m^2"\nmechanism_origin = ["-1.8 m", "0 m"]\n'
        'direction = "0 deg"\n[frame.points]\nrope_end = ["1.5 m", "0 m"]\n\n' + ropes)
    run = run_problem(text)
    study = run.outcomes["frame"].results
    assert study.modes.angular_frequencies[0] == pytest.approx(np.sqrt(9.80665 / 1.2), rel=1e-9)
    assert study.modes.dominant()[0] == "x"
    assert 0 < run.results["frame.rms_velocity.before.rope_end"] < 1.0


def test_spring_variant_leaves_the_frame_loads_unchanged():
    # At constant crank speed the frame's shaking force and moment are the rates of change of the moving parts'
    # linear and angular momentum (Wilson & Sadler, Kinematics and Dynamics of Machinery, 3rd ed., ch. 16:
    # shaking force = -sum m a_G, shaking moment = -sum (r_G x m a_G + I alpha)). A spring between a link and the
    # frame (seed 002's K = m_C w^2) is internal to machine + frame: it changes the driving torque, whose
    # reaction on the motor's stator is part of the moment, by exactly what it adds through the joints. So the
    # harmonics must agree to rounding (1e-9 of the largest amplitude), while the driving torque does change.
    from machdyn.linkage import analyse as run_analysis
    from machdyn.linkage import crank_angles as angles
    from machdyn.linkage import slider_crank
    from machdyn.vibration import shaking_loads
    from machdyn.vibration.study import with_variant
    from machdyn.vibration.tables import VariantSpec

    w, r, rod, m_c = 21.0, 0.045, 3.6, 637.33
    mech = slider_crank(r, rod, offset=0.05, masses=(2.0, 120.0, m_c), gravity=(0.0, 0.0))
    free = float(np.sqrt(rod**2 - r**2))
    variant = VariantSpec.model_validate({"label": "with spring", "springs": [
        {"point_1": "slider.B", "point_2": "ground.O", "stiffness": f"{m_c * w**2} N/m", "free_length": f"{free} m"}]})
    phi = angles(360)
    an_before, an_after = run_analysis(mech, phi, w), run_analysis(with_variant(mech, variant), phi, w)
    before, after = shaking_loads(an_before, orders=4), shaking_loads(an_after, orders=4)
    for name in ("force_x", "force_y", "moment"):
        b, a = getattr(before, name), getattr(after, name)
        np.testing.assert_allclose(a, b, atol=1e-9 * np.max(np.abs(b)))
    torque_b, torque_a = an_before.forces.driving_torque, an_after.forces.driving_torque
    assert np.ptp(torque_a) < 0.5 * np.ptp(torque_b)
    with pytest.raises(ValidationError, match="at least one counterweight or spring"):
        VariantSpec.model_validate({"label": "nothing"})
    bad = VariantSpec.model_validate({"springs": [{"point_1": "slider.X", "point_2": "ground.O",
                                                   "stiffness": "1 N/m"}]})
    with pytest.raises(InputError, match=r"frame.after.springs\[0\].point_1: no point 'slider.X'"):
        with_variant(mech, bad)


def test_frame_compares_with_the_balanced_model_of_the_file():
    # A file with [balance] (crank counterweight: all the rotating and half the reciprocating mass) and a
    # [frame] without [frame.after]: the frame study compares the analysed mechanism with the balanced one.
    # The first-order vertical shaking force (across the stroke of this horizontal engine) grows with half
    # the reciprocating mass moved there, the horizontal one falls: the mount along the stroke carries less.
    from machdyn.runner import run_problem

    text = (ROOT / "examples" / "slider_crank_balance.toml").read_text() + (
        '\n[frame]\nmass = "200 kg"\ninertia = "20 kg*m^2"\n'
        '[[frame.mounts]]\ntype = "rubber"\nname = "front"\nposition = ["0.3 m", "-0.2 m"]\n'
        'vertical_stiffness = "400 kN/m"\nhorizontal_stiffness = "300 kN/m"\nloss_factor = 0.1\n'
        '[[frame.mounts]]\ntype = "rubber"\nname = "rear"\nposition = ["-0.3 m", "-0.2 m"]\n'
        'vertical_stiffness = "400 kN/m"\nhorizontal_stiffness = "300 kN/m"\nloss_factor = 0.1\n'
        '[frame.points]\ntop = ["0 m", "0.2 m"]\n')
    run = run_problem(text)
    study = run.outcomes["frame"].results
    assert study.labels[1] == "balanced" and study.after is not None
    force = {tag: [resp.transmitted_force_rms(m) for m in ("front.h", "rear.h")]
             for tag, resp in (("before", study.before), ("after", study.after))}
    assert all(a < b for a, b in zip(force["after"], force["before"], strict=True))
    assert "frame.mean_acceleration_reduction" in run.results
