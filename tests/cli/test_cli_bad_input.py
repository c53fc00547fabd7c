"""Bad problem files: each gives its message (path, rule, value) on stderr and exit code 2, never a traceback."""

from __future__ import annotations

import pytest
from typer.testing import CliRunner

from machdyn.cli import app

GOOD_FOUR_BAR = """
[mechanism]
type = "four_bar"
[mechanism.crank]
length = "40 mm"
mass = "0.25 kg"
[mechanism.coupler]
length = "120 mm"
[mechanism.rocker]
length = "100 mm"
[mechanism.ground]
length = "130 mm"
[drive]
speed = "120 rpm"
positions = 36
"""

SCREEN = """
[rotary_screen]
R = "0.045 m"
m1 = "2 kg"
L = "3.6 m"
m2 = "1200 kg"
m3 = "4 kg"
l_AS1 = "0.02 m"
l_BS2 = "1.9 m"
l_CS2 = "1.7 m"
m_e = "116.62 kg"
r_e = "0.219 m"
[drive]
speed = "21 rad/s"
"""

# (id, file text, expected fragments of stderr, exit code)
CASES = [
    ("malformed_toml", '[mechanism\ntype = "four_bar"\n', ["malformed TOML", "line 1"], 2),
    ("empty_file", "", ["needs one main table", "[mechanism]", "[rotary_screen]", "[screw_conveyor]"], 2),
    ("two_machines", GOOD_FOUR_BAR + SCREEN.replace("[drive]", "[drive_]"),
     ["describes one machine", "[mechanism]", "[rotary_screen]"], 2),
    ("misspelled_main_table", GOOD_FOUR_BAR.replace("[mechanism]", "[mechansim]")
     .replace("[mechanism.", "[mechansim."), ["mechansim: unknown table 'mechansim'; did you mean 'mechanism'?"], 2),
    ("missing_field", GOOD_FOUR_BAR.replace('length = "120 mm"', 'mass = "0.3 kg"'),
     ["mechanism.coupler.length: required, but missing"], 2),
    ("missing_drive", GOOD_FOUR_BAR.split("[drive]")[0], ["drive: required, but missing"], 2),
    ("wrong_dimension", GOOD_FOUR_BAR.replace('mass = "0.25 kg"', 'mass = "3 mm"'),
     ["mechanism.crank.mass: must be in units of [mass] (like kg); got '3 mm', which is [length]"], 2),
    ("speed_in_metres", GOOD_FOUR_BAR.replace('"120 rpm"', '"120 m"'),
     ["drive.speed: must be in units of 1 / [time] (like rad/s); got '120 m', which is [length]"], 2),
    ("bare_number", GOOD_FOUR_BAR.replace('length = "40 mm"', "length = 40"),
     ['mechanism.crank.length: needs a unit, like "40 mm"; got the bare number 40'], 2),
    ("not_a_quantity", GOOD_FOUR_BAR.replace('"40 mm"', '"forty mm"'),
     ["mechanism.crank.length: is not a quantity with a unit; got 'forty mm'"], 2),
    ("unknown_unit", GOOD_FOUR_BAR.replace('"40 mm"', '"40 furlongs_per_fortnight"'),
     ["mechanism.crank.length: is not a quantity", "40 furlongs_per_fortnight"], 2),
    ("negative_length", GOOD_FOUR_BAR.replace('"40 mm"', '"-40 mm"'),
     ["mechanism.crank.length: must be > 0 m; got '-40 mm'"], 2),
    ("infinite_length", GOOD_FOUR_BAR.replace('"40 mm"', '"inf mm"'),
     ["mechanism.crank.length: must be a finite number; got 'inf mm'"], 2),
    ("unknown_key", GOOD_FOUR_BAR.replace('[mechanism.coupler]\nlength', '[mechanism.coupler]\nlenght'),
     ["mechanism.coupler.lenght: unknown key 'lenght'; did you mean 'length'?"], 2),
    ("unknown_sub_table", GOOD_FOUR_BAR.replace("[mechanism.coupler]", "[mechanism.couplr]"),
     ["mechanism.couplr: unknown key 'couplr'; did you mean 'coupler'?"], 2),
    ("misspelled_type", GOOD_FOUR_BAR.replace('"four_bar"', '"four_barr"'),
     ["mechanism.type: unknown type 'four_barr'; did you mean 'four_bar'?", "slider_crank"], 2),
    ("missing_type", GOOD_FOUR_BAR.replace('type = "four_bar"', ""), ["mechanism.type: needs a 'type'"], 2),
    ("bad_branch", GOOD_FOUR_BAR.replace('type = "four_bar"', 'type = "four_bar"\nbranch = "upper"'),
     ['mechanism.branch: must be "open" (+1) or "crossed" (-1); got \'upper\''], 2),
    ("bad_gravity", GOOD_FOUR_BAR + '[loads]\ngravity = "sideways"\n',
     ['loads.gravity: must be "on", "off" or a vector', "got 'sideways'"], 2),
    ("too_few_positions", GOOD_FOUR_BAR.replace("positions = 36", "positions = 1"),
     ["drive.positions: must be >= 8; got 1"], 2),
    ("fractional_positions", GOOD_FOUR_BAR.replace("positions = 36", "positions = 36.5"),
     ["drive.positions: must be a whole number; got 36.5"], 2),
    ("stop_before_start", GOOD_FOUR_BAR + 'start = "90 deg"\nstop = "10 deg"\n',
     ["drive.stop: must be greater than start"], 2),
    ("point_pair_too_short", GOOD_FOUR_BAR.replace('mass = "0.25 kg"', 'mass = "0.25 kg"\ncom = ["20 mm"]'),
     ["mechanism.crank.com: must be a list of 2 values; got a list of 1"], 2),
    ("unknown_load_point", GOOD_FOUR_BAR + '[[loads.forces]]\npoint = "rockr.B"\nfx = "10 N"\n',
     ["loads.forces[0].point: unknown point 'rockr.B'; did you mean 'rocker.B'?"], 2),
    ("malformed_point_reference", GOOD_FOUR_BAR + '[[loads.forces]]\npoint = "rocker"\nfx = "10 N"\n',
     ["loads.forces[0].point: must name a point as 'body.point'", "got 'rocker'"], 2),
    ("unknown_counterweight_body", GOOD_FOUR_BAR
     + '[[counterweights]]\nbody = "crnk"\nmass = "1 kg"\nradius = "20 mm"\nangle = "180 deg"\n',
     ["counterweights[0].body: unknown body 'crnk'; did you mean 'crank'?"], 2),
    ("unassemblable_geometry", GOOD_FOUR_BAR.replace('length = "130 mm"', 'length = "400 mm"'),
     ["mechanism: cannot be assembled", "Grashof"], 2),
    ("partly_unassemblable", GOOD_FOUR_BAR.replace('length = "40 mm"', 'length = "110 mm"'),
     ["mechanism: cannot be assembled", "crank angles"], 2),
    ("custom_dyad_type", """
[mechanism]
type = "custom"
ground = {O = ["0 mm", "0 mm"]}
crank = {body = "crank", pivot = "ground.O"}
[[mechanism.bodies]]
name = "crank"
points = {O = ["0 mm", "0 mm"], A = ["10 mm", "0 mm"]}
[[mechanism.dyads]]
type = "RPP"
[drive]
speed = "1 rad/s"
""", ["mechanism.dyads[0].type: unknown type 'RPP'; did you mean 'RRP'?"], 2),
    ("custom_engine_rule", """
[mechanism]
type = "custom"
ground = {O = ["0 mm", "0 mm"]}
crank = {body = "crank", pivot = "ground.O"}
[[mechanism.bodies]]
name = "crank"
points = {P = ["0 mm", "0 mm"], A = ["10 mm", "0 mm"]}
[drive]
speed = "1 rad/s"
""", ["mechanism:", "needs a point 'O'"], 2),
    ("rotary_screen_inconsistent", SCREEN.replace('l_CS2 = "1.7 m"', 'l_CS2 = "1.5 m"'),
     ["rotary_screen:", "must add up to L"], 2),
    ("rotary_screen_missing_input", SCREEN.replace('m_e = "116.62 kg"\n', ""),
     ["rotary_screen.m_e: required, but missing"], 2),
    ("conveyor_missing_throughput", '[screw_conveyor]\nlength = "21 m"\n[screw_conveyor.material]\n'
     'bulk_density = "1.2 t/m^3"\n', ["screw_conveyor.throughput"], 2),
]


@pytest.fixture
def runner():
    return CliRunner()


@pytest.mark.parametrize("command", ["check", "run"])
@pytest.mark.parametrize(("name", "text", "expected", "code"), CASES, ids=[c[0] for c in CASES])
def test_bad_problem_file(runner, tmp_path, command, name, text, expected, code):
    path = tmp_path / f"{name}.toml"
    path.write_text(text, encoding="utf-8")
    args = [command, str(path)] + (["--out", str(tmp_path / "out")] if command == "run" else [])
    result = runner.invoke(app, args)
    assert result.exit_code == code, result.output
    assert "Traceback" not in result.output
    assert result.exception is None or isinstance(result.exception, SystemExit)
    for fragment in expected:
        assert fragment in result.stderr, f"{fragment!r} not in:\n{result.stderr}"
    assert result.stdout == ""
    # a failed run writes nothing
    assert not (tmp_path / "out").exists()


def test_every_mistake_is_reported_at_once(runner, tmp_path):
    text = (GOOD_FOUR_BAR.replace('"40 mm"', '"-40 mm"').replace('mass = "0.25 kg"', 'mass = "3 mm"')
            .replace("[mechanism.coupler]\nlength", "[mechanism.coupler]\nlenght").replace('"120 rpm"', '"fast"'))
    path = tmp_path / "many.toml"
    path.write_text(text)
    result = runner.invoke(app, ["check", str(path)])
    assert result.exit_code == 2
    assert f"4 problem(s) in {path}" in result.stderr
    for fragment in ("mechanism.crank.length", "mechanism.crank.mass", "mechanism.coupler.lenght", "drive.speed"):
        assert fragment in result.stderr


def test_missing_file(runner, tmp_path):
    result = runner.invoke(app, ["run", str(tmp_path / "nope.toml")])
    assert result.exit_code == 2
    assert "does not exist" in result.stderr


def test_directory_instead_of_file(runner, tmp_path):
    result = runner.invoke(app, ["check", str(tmp_path)])
    assert result.exit_code == 2
    assert "is a directory" in result.stderr


@pytest.mark.parametrize("args", [["run"], ["run", "x.toml", "--format", "xml"], ["frobnicate"]])
def test_usage_errors_exit_2(runner, args):
    result = runner.invoke(app, args)
    assert result.exit_code == 2
    assert "Traceback" not in result.output


def test_unwritable_output_is_an_analysis_failure(runner, tmp_path):
    path = tmp_path / "ok.toml"
    path.write_text(GOOD_FOUR_BAR)
    blocker = tmp_path / "file"
    blocker.write_text("not a directory")
    result = runner.invoke(app, ["run", str(path), "--out", str(blocker)])
    assert result.exit_code == 1
    assert "cannot write the outputs" in result.stderr
    assert "Traceback" not in result.output



def _write(tmp_path, text, name="p.toml"):
    path = tmp_path / name
    path.write_text(text)
    return path


def test_a_shaft_speed_in_hz_is_refused(runner, tmp_path):
    result = runner.invoke(app, ["check", str(_write(tmp_path, GOOD_FOUR_BAR.replace('"120 rpm"', '"120 Hz"')))])
    assert result.exit_code == 2
    assert "drive.speed: must not be given in Hz, which is ambiguous for a shaft speed" in result.stderr


def test_a_zero_speed_is_refused_by_check(runner, tmp_path):
    result = runner.invoke(app, ["check", str(_write(tmp_path, GOOD_FOUR_BAR.replace('"120 rpm"', '"0 rpm"')))])
    assert result.exit_code == 2
    assert "drive.speed: must not be zero (the analysis divides by the crank speed); got 0 rad/s" in result.stderr


def test_a_byte_order_mark_is_accepted(runner, tmp_path):
    path = tmp_path / "bom.toml"
    path.write_bytes(b"\xef\xbb\xbf" + GOOD_FOUR_BAR.encode())
    result = runner.invoke(app, ["check", str(path)])
    assert result.exit_code == 0, result.output


def test_a_toggle_inside_the_crank_range_fails_naming_the_angles(runner, tmp_path):
    """Four-bar 30/22/28/40 mm: coupler and rocker fall in line at +-90 deg, both sampled."""
    path = _write(tmp_path,
                  '[mechanism]\ntype = "four_bar"\ncrank = {length = "30 mm"}\ncoupler = {length = "22 mm"}\n'
                  'rocker = {length = "28 mm"}\nground = {length = "40 mm"}\n'
                  '[drive]\nspeed = "60 rpm"\npositions = 181\nstart = "-90 deg"\nstop = "90 deg"\n')
    result = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "out"), "--quiet"])
    assert result.exit_code == 2, "a crank range through a dead position is bad input"
    assert "dead (toggle) or indeterminate position" in result.stderr and "-90.00°, 90.00°" in result.stderr
    assert "Traceback" not in result.output
