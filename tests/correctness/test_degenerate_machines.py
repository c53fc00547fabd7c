"""Degenerate but valid machines run: results that do not exist for them are absent, never NaN, and a closed-form
balance that cannot be built is refused by ``check`` as by ``run``."""

from __future__ import annotations

import json
import math
import re

import pytest

from .helpers import EXAMPLES, ROOT, check_and_run

ROTOR = """
[mechanism]
type = "custom"
name = "exciter"
ground = { O = ["0 mm", "0 mm"] }
crank = { body = "rotor", pivot = "ground.O" }

[[mechanism.bodies]]
name = "rotor"
points = { O = ["0 mm", "0 mm"], E = ["20 mm", "0 mm"] }
mass = "3 kg"
inertia = "0.002 kg*m^2"
com = ["20 mm", "0 mm"]

[drive]
speed = "1500 rpm"
positions = 72

[loads]
gravity = "off"
"""

STATICS = """
[mechanism]
type = "slider_crank"
offset = "0 mm"
[mechanism.crank]
length = "50 mm"
mass = "0 kg"
[mechanism.rod]
length = "200 mm"
mass = "0 kg"
[mechanism.slider]
mass = "0 kg"
[drive]
speed = "100 rpm"
positions = 36
[[loads.forces]]
name = "press"
point = "slider.B"
fx = "-1 kN"
"""


def _scalars(tmp_path):
    return json.loads((tmp_path / "out" / "results.json").read_text())["scalars"]


def test_crank_with_only_a_rotating_unbalance_runs_without_transmission_angle(tmp_path):
    check, run = check_and_run(tmp_path, ROTOR)
    assert (check.code, run.code) == (0, 0), (check, run)
    scalars = _scalars(tmp_path)
    assert not [k for k in scalars if k.startswith("transmission_angle")]
    assert all(math.isfinite(v["value"]) for v in scalars.values() if isinstance(v["value"], float))
    # the rotating unbalance m r omega^2 is the whole inertial shaking force: 3 kg * 0.02 m * (50 pi rad/s)^2
    assert scalars["inertial_shaking_force.max"]["value"] == pytest.approx(3 * 0.02 * (50 * math.pi) ** 2, rel=1e-9)


def test_massless_statics_slider_crank_with_a_process_force_runs(tmp_path):
    check, run = check_and_run(tmp_path, STATICS)
    assert (check.code, run.code) == (0, 0), (check, run)
    scalars = _scalars(tmp_path)
    assert scalars["inertial_shaking_force.max"]["value"] == 0.0
    # inertia neglected, the two-force rod carries F / cos(beta), largest where sin(beta) = r / l = 0.25 (crank at
    # 90 deg, one of the 36 positions): 1000 N / sqrt(1 - 0.0625) (statics of the slider-crank; Norton, Design of
    # Machinery, 5th ed., sec. 11.8)
    assert scalars["joint.B.max_force"]["value"] == pytest.approx(1000.0 / math.sqrt(1 - 0.0625), rel=1e-9)


def test_single_dyad_and_zero_offset_run(tmp_path):
    for name in ("four_bar.toml", "slider_crank.toml"):
        check, run = check_and_run(tmp_path, (EXAMPLES / name).read_text(encoding="utf-8"), name=name)
        assert (check.code, run.code) == (0, 0), (name, check, run)
    doc = (ROOT / "docs" / "problem-files.md").read_text(encoding="utf-8")
    custom = re.search(r'```toml\n(\[mechanism\]\ntype = "custom".*?)```', doc, re.S)
    assert custom is not None
    check, run = check_and_run(tmp_path, custom.group(1) + '\n[drive]\nspeed = "60 rpm"\npositions = 36\n',
                               name="quick_return.toml")
    assert (check.code, run.code) == (0, 0), (check, run)


def test_counterweight_that_cannot_be_built_is_refused_by_check_and_run(tmp_path):
    text = (EXAMPLES / "slider_crank.toml").read_text(encoding="utf-8")
    text += '\n[balance]\nmethod = "counterweights"\n[[balance.counterweights]]\nbody = "rod"\n'
    check, run = check_and_run(tmp_path, text)
    assert (check.code, run.code) == (2, 2), (check, run)
    for said in (check, run):
        assert "balance: The force-optimal counterweight on floating body 'rod'" in said.stderr
        assert "[balance.objective]" in said.stderr


def test_counterweight_slot_on_a_slider_runs(tmp_path):
    text = (EXAMPLES / "slider_crank.toml").read_text(encoding="utf-8")
    text += '\n[balance]\nmethod = "counterweights"\n[[balance.counterweights]]\nbody = "slider"\n'
    check, run = check_and_run(tmp_path, text)
    assert (check.code, run.code) == (0, 0), (check, run)
