"""``check`` reads and analyses the vibration records and tests the frame for resonance exactly as ``run`` does;
a near-undamped resonance is refused with its margin, not only an exact one; absurd sample values are named."""

from __future__ import annotations

import math

import numpy as np
import pytest

from .helpers import EXAMPLES, check_and_run

TAMPER = (EXAMPLES / "tamper_on_tyres.toml").read_text(encoding="utf-8")
SLIDER = (EXAMPLES / "slider_crank.toml").read_text(encoding="utf-8")


def _record(path, values, fs=2560.0):
    t = np.arange(values.size) / fs
    lines = ["time [s],centre [m/s^2]"] + [f"{a:.9g},{float(b)!r}" for a, b in zip(t, values, strict=True)]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")


def _signals(tmp_path, values, extra=""):
    _record(tmp_path / "rec.csv", values)
    return TAMPER + f'\n[signals]\nrecord = "rec.csv"\n{extra}\n'


SINE = 2.0 * np.sin(2 * np.pi * 20 * np.arange(5120) / 2560.0)
CASES = [
    ("constant_record_channel", np.full(5120, 1.0), "", "is constant (1 in SI units)"),
    ("samples_of_1e308", SINE * 0.5e308, "", "beyond 1e+12 in SI units"),
    ("band_from_0_hz_for_acceleration", SINE, 'band = ["0 Hz", "1000 Hz"]',
     "Integration to velocity needs a band with a lower edge > 0 Hz"),
    ("decreasing_zone_boundaries", SINE, 'boundaries = ["4.5 mm/s", "2.8 mm/s", "7.1 mm/s"]',
     "signals.boundaries: must be three increasing velocities > 0"),
]


@pytest.mark.parametrize(("values", "extra", "message"), [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_record_problem_refused_by_check_as_by_run(tmp_path, values, extra, message):
    check, run = check_and_run(tmp_path, _signals(tmp_path, values, extra))
    assert (check.code, run.code) == (2, 2), (check, run)
    assert message in check.stderr and message in run.stderr
    assert "NaN" not in check.stderr


FRAME = """
[frame]
mass = "100 kg"
inertia = "10 kg*m^2"
orders = 3

[[frame.mounts]]
type = "spring"
name = "left"
position = ["-1 m", "0 m"]
direction = "90 deg"
stiffness = "{k} N/m"

[[frame.mounts]]
type = "spring"
name = "right"
position = ["1 m", "0 m"]
direction = "90 deg"
stiffness = "{k} N/m"

[[frame.mounts]]
type = "spring"
name = "side"
position = ["0 m", "0 m"]
direction = "0 deg"
stiffness = "3e5 N/m"
"""

# the bounce mode sqrt(2 k / m) on the 1x order of 1500 rpm: k = m (50 pi)^2 / 2 (Rao, Mechanical Vibrations, 5th
# ed., sec. 2.2), with two vertical springs 1 m either side of the centre of mass of a 100 kg frame
K_RESONANT = 100.0 * (50.0 * math.pi) ** 2 / 2.0


@pytest.mark.parametrize("relative_offset", [0.0, 1e-12, 1e-7])
def test_near_undamped_resonance_is_refused_with_its_margin(tmp_path, relative_offset):
    k = K_RESONANT * (1.0 + relative_offset)
    check, run = check_and_run(tmp_path, SLIDER + FRAME.format(k=repr(k)))
    assert (check.code, run.code) == (2, 2), (check, run)
    for said in (check, run):
        assert "Order 1 at 25 Hz is within" in said.stderr and "damping ratio 0" in said.stderr
        assert "dynamic magnification" in said.stderr


def test_undamped_frame_away_from_resonance_runs(tmp_path):
    # 2 % below: r = 1 / sqrt(0.98), magnification 1 / |1 - r^2| = 49, well within the limit
    check, run = check_and_run(tmp_path, SLIDER + FRAME.format(k=repr(K_RESONANT * 0.98)))
    assert (check.code, run.code) == (0, 0), (check, run)


def test_negative_speed_with_frame_refused_by_check_as_by_run(tmp_path):
    text = SLIDER.replace('speed = "1500 rpm"', 'speed = "-1500 rpm"') + FRAME.format(k="1e6")
    check, run = check_and_run(tmp_path, text)
    assert (check.code, run.code) == (2, 2), (check, run)
    assert "drive.speed: must be > 0 for [frame]" in check.stderr
