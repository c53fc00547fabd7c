"""The capability stages on the shipped example: tables, frame study, records, predicted against measured."""

from __future__ import annotations

import importlib.util
import tomllib
from pathlib import Path

import numpy as np
import pytest
from pydantic import ValidationError

from machdyn.errors import InputError
from machdyn.linkage import analyse
from machdyn.problem.build import build_mechanism, crank_angles
from machdyn.problem.loader import validate_linkage
from machdyn.vibration.study import (
    LABELS,
    frame_scalars,
    frame_series,
    signal_scalars,
    signal_series,
    study_frame,
    study_signals,
)
from machdyn.vibration.tables import FrameTable, SignalsTable

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "tamper_on_tyres.toml"


@pytest.fixture(scope="module")
def example():
    data = tomllib.loads(EXAMPLE.read_text())
    frame, signals = data.pop("frame"), data.pop("signals")
    problem = validate_linkage(data)
    mech = build_mechanism(problem)
    analysis = analyse(mech, crank_angles(problem), problem.drive.speed)
    fs = study_frame(FrameTable.model_validate(frame), mech, analysis)
    ss = study_signals(SignalsTable.model_validate(signals), source=EXAMPLE, crank_speed=problem.drive.speed,
                       frame_study=fs)
    return problem, frame, fs, ss


def test_frame_study_of_the_tamper_example(example):
    _, _, fs, _ = example
    scalars = frame_scalars(fs)
    assert set(scalars) <= set(LABELS)
    assert len(scalars["frame.natural_frequencies"]) == 3
    assert len(scalars["frame.transmitted_force.before"]) == 4  # two tyres, two lines each
    # Balancing lowers the RMS acceleration at every point and the mean level (about 43 % for this setting).
    assert all(r > 0 for r in scalars["frame.acceleration_reduction"])
    assert 30 < scalars["frame.mean_acceleration_reduction"] < 60
    assert scalars["frame.worst_zone.after"] <= scalars["frame.worst_zone.before"]
    series = frame_series(fs)
    t, centre = series["frame_time"]["time"][0], series["frame_time"]["centre_before"][0]
    # RMS of the vertical time series equals the predicted RMS (one whole revolution, rel 1e-9).
    assert np.sqrt(np.mean(centre**2)) == pytest.approx(fs.rms("before", "acceleration")[0], rel=1e-9)
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
    scalars = signal_scalars(ss)
    assert set(scalars) <= set(LABELS)
    assert scalars["signals.mean_reduction"] == pytest.approx(ss.reduction["mean"])
    assert signal_series(ss)["signals_psd"]["front"][0].size == signal_series(ss)["signals_psd"]["frequency"][0].size


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
    problem, frame, _, _ = example
    mech = build_mechanism(problem)
    analysis = analyse(mech, crank_angles(problem), problem.drive.speed)
    bad = dict(frame, after={"counterweights": [{"body": "shaft", "mass": "1 kg", "radius": "1 mm",
                                                 "angle": "0 deg"}]})
    with pytest.raises(InputError, match="no body 'shaft'"):
        study_frame(FrameTable.model_validate(bad), mech, analysis)
    with pytest.raises(InputError, match="does not exist"):
        study_signals(SignalsTable.model_validate({"record": "missing.csv"}), source=tmp_path / "p.toml")
