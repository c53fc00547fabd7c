"""The conveyor's problem kind plugged into the registry (``machdyn.conveyor.kind:KIND``), end to end."""

import json
import math
from pathlib import Path

import pytest
from typer.testing import CliRunner

from machdyn import kinds
from machdyn.cli import app

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture
def conveyor_kind(monkeypatch):
    monkeypatch.setitem(kinds.KINDS, "screw_conveyor", "machdyn.conveyor.kind:KIND")
    kinds.kind.cache_clear()
    yield
    kinds.kind.cache_clear()


def test_registered_kind_writes_si_with_the_display_units_beside_and_exits_0(conveyor_kind, tmp_path):
    result = CliRunner().invoke(app, ["run", str(ROOT / "examples" / "iodized_salt_conveyor.toml"), "--out",
                                      str(tmp_path)])
    assert result.exit_code == 0, result.output
    scalars = json.loads((tmp_path / "results.json").read_text())["scalars"]
    assert scalars["shaft_power"]["unit"] == "W" and scalars["shaft_power"]["shown"]["unit"] == "kW"
    assert scalars["shaft_power"]["value"] == pytest.approx(1122.9322346201107, rel=1e-12)
    assert scalars["shaft_power"]["shown"]["value"] == pytest.approx(1.1229322346201107, rel=1e-12)
    assert scalars["diameter"] == {"value": pytest.approx(0.2), "unit": "m",
                                   "shown": {"value": pytest.approx(200.0), "unit": "mm"}}
    assert scalars["speed"]["unit"] == "rad/s"
    assert scalars["speed"]["value"] == pytest.approx(100.62305898749054 * math.pi / 30, rel=1e-12)
    assert scalars["speed"]["shown"] == {"value": pytest.approx(100.62305898749054, rel=1e-12), "unit": "rpm"}


def test_registered_kind_check_agrees_with_run(conveyor_kind, tmp_path):
    text = (ROOT / "examples" / "iodized_salt_conveyor.toml").read_text().replace('length = "21 m"',
                                                                                   'length = "1e300 m"')
    bad = tmp_path / "bad.toml"
    bad.write_text(text)
    for command in ("check", "run"):
        args = [command, str(bad)] + (["--out", str(tmp_path / "o")] if command == "run" else [])
        result = CliRunner().invoke(app, args)
        assert result.exit_code == 2, (command, result.output)
        assert "screw_conveyor.length" in result.output
