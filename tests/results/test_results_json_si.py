"""results.json holds every value in SI with its SI unit; a value the summary shows in another unit carries that
value beside it ("shown"), and the summary keeps its display units."""

from __future__ import annotations

import math

import pytest

from machdyn.results import Label, Results, summarise


def _results() -> Results:
    return Results(
        {"stroke": 0.1, "angle": math.pi / 4, "speed": [10.0, 20.0], "torque": 12.5, "fraction": 0.43},
        {"stroke": Label("Stroke", "m", "mm"), "angle": Label("Angle", "rad"), "speed": Label("Speed", "rad/s", "rpm"),
         "torque": Label("Torque", "N*m"), "fraction": Label("Reduction", "", "%")},
    )


def test_every_value_is_si_and_the_shown_one_beside_it():
    got = _results().as_json()
    assert got["stroke"] == {"value": 0.1, "unit": "m", "shown": {"value": pytest.approx(100.0), "unit": "mm"}}
    assert got["angle"] == {"value": math.pi / 4, "unit": "rad", "shown": {"value": pytest.approx(45.0), "unit": "deg"}}
    assert got["speed"]["value"] == [10.0, 20.0] and got["speed"]["unit"] == "rad/s"
    assert got["speed"]["shown"] == {"value": pytest.approx([10 * 30 / math.pi, 20 * 30 / math.pi]), "unit": "rpm"}
    assert got["torque"] == {"value": 12.5, "unit": "N*m"}  # shown in SI: nothing beside it
    assert got["fraction"] == {"value": 0.43, "unit": "", "shown": {"value": pytest.approx(43.0), "unit": "%"}}


def test_the_summary_keeps_its_display_units():
    rows = {r.key: (r.value, r.unit) for r in summarise("t", _results(), ["stroke", "angle", "torque"]).rows}
    assert rows["stroke"] == (pytest.approx(100.0), "mm") and rows["angle"] == (pytest.approx(45.0), "deg")
    assert rows["torque"] == (12.5, "N*m")
