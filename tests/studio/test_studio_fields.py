"""The quantities of a problem file as the studio finds them, and the file with new values put in (tomlkit):
every quantity found under the path ``machdyn check`` gives it, words and [meta] left alone, and nothing but the
edited values changed."""

from __future__ import annotations

import pytest
import tomlkit

from machdyn.studio.fields import edited_text, fields_of

TEXT = '''# a comment at the top
[meta]
name = "kept"     # not a quantity
positions = 3

[mechanism]
type = "four_bar"          # a word, not a quantity
coupler_point = ["60 mm", "25 mm"]
[mechanism.crank]
length = "40 mm"   # the crank
flag = true

[drive]
speed = "120 rpm"
positions = 360
ratio = 1.5

[[loads.torques]]
torque = "-1.5 N*m"
'''


def test_every_quantity_is_found_under_the_path_check_names():
    found = {f.key: (f.number, f.unit, f.integer) for f in fields_of(tomlkit.parse(TEXT))}
    assert found == {
        "mechanism.coupler_point[0]": ("60", "mm", False), "mechanism.coupler_point[1]": ("25", "mm", False),
        "mechanism.crank.length": ("40", "mm", False), "drive.speed": ("120", "rpm", False),
        "drive.positions": ("360", "", True), "drive.ratio": ("1.5", "", False),
        "loads.torques[0].torque": ("-1.5", "N*m", False),
    }
    si = {f.key: f.si_per_unit for f in fields_of(tomlkit.parse(TEXT))}
    assert si["mechanism.crank.length"] == pytest.approx(1e-3)
    assert si["drive.speed"] == pytest.approx(2 * 3.141592653589793 / 60)


def test_an_edit_changes_its_value_alone_and_keeps_types_and_comments():
    new = edited_text(TEXT, {"mechanism.crank.length": "45.5", "drive.positions": "180", "drive.ratio": "2",
                             "mechanism.coupler_point[1]": "30", "loads.torques[0].torque": "-2e0"})
    old_lines, new_lines = TEXT.splitlines(), new.splitlines()
    assert len(old_lines) == len(new_lines)
    changed = {(a, b) for a, b in zip(old_lines, new_lines, strict=True) if a != b}
    assert changed == {
        ('length = "40 mm"   # the crank', 'length = "45.5 mm"   # the crank'),
        ("positions = 360", "positions = 180"),
        ("ratio = 1.5", "ratio = 2.0"),
        ('coupler_point = ["60 mm", "25 mm"]', 'coupler_point = ["60 mm", "30 mm"]'),
        ('torque = "-1.5 N*m"', 'torque = "-2e0 N*m"'),
    }


def test_what_is_not_a_number_goes_in_as_typed_for_the_loader_to_refuse():
    new = edited_text(TEXT, {"drive.positions": "many", "mechanism.crank.length": "abc"})
    assert 'positions = "many"' in new and 'length = "abc mm"' in new
    with pytest.raises(KeyError):
        edited_text(TEXT, {"meta.positions": "4"})
    with pytest.raises(ValueError, match="at most 40 characters"):
        edited_text(TEXT, {"drive.ratio": "1" * 41})
