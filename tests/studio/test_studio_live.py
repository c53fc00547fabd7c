"""The studio's live edit of a file with a flywheel: the tables that integrate the motion in time are left to
*Full run*, the flywheel shown live is the run's own energy-mass sizing computed another way, and in the browser
an edit is redrawn well within a second by the page's own clock."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

from machdyn.dynamics.equivalent import equivalent_machine
from machdyn.dynamics.flywheel import size_flywheel
from machdyn.dynamics.stage import speed_loads
from machdyn.reading import read_problem
from machdyn.studio.session import Studio
from studio_browser import CHROMIUM, NO_CHROMIUM, VALID

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
EXACT = "Flywheel sized by the energy-mass (Wittenbauer) method, constant-torque drive"


@pytest.fixture
def compactor(tmp_path) -> Path:
    path = tmp_path / "compactor_flywheel.toml"
    shutil.copy(EXAMPLES / "compactor_flywheel.toml", path)
    return path


def test_the_live_flywheel_is_the_stages_sizing_by_another_method(compactor):
    # two independent computations of Wittenbauer's least flywheel: the studio's, from the constant-speed run's own
    # 360 samples of M(phi) and J(phi) (machdyn.dynamics.population_flywheel: trapezoidal work, extremes on the
    # samples), and the [flywheel] stage's size_flywheel (the equivalent machine's cubic pieces on a fine grid).
    # They differ by the sampling: O(h^2) for smooth loads, O(h) where the 3 kN compaction force switches on and off
    # (h = 1 deg); 1 % covers both.
    studio = Studio(compactor)
    live = studio.evaluate({"mechanism.crank.length": "32"})
    assert live["ok"] and live["deferred"] == ["[flywheel]"] and not live["full"]
    assert "motor" not in " | ".join(r["label"] for r in live["summary"]).lower()
    rows = {r["label"]: r["value"] for r in live["summary"] if r.get("live")}
    loaded = read_problem(studio.source.edited({"mechanism.crank.length": "32"}))
    table = loaded.spec.flywheel
    machine = equivalent_machine(loaded.model, table.positions, speed_loads=speed_loads(table))
    sizing = size_flywheel(machine, float(loaded.spec.drive.speed), table.delta)
    assert rows[EXACT] == pytest.approx(float(sizing.exact[0]), rel=0.01)
    # no drive line: the flywheel is the sizing; a solid disc J = pi rho b R^4 / 2 with b = 0.2 D, so
    # D = (2 J / (pi rho 0.2 / 16))^(1/5) for steel (7850 kg/m^3)
    assert rows["Flywheel: moment of inertia, referred to the crank"] == rows[EXACT]
    diameter = (2 * rows[EXACT] / (np.pi * 7850 * 0.2 / 16)) ** 0.2
    assert rows["Flywheel: outer diameter"] == pytest.approx(1e3 * diameter, rel=1e-9)


@pytest.mark.skipif(CHROMIUM is None, reason=NO_CHROMIUM)
def test_a_flywheel_file_is_redrawn_within_a_second_of_an_edit(serve, page):
    url, _ = serve("compactor_flywheel.toml")
    page.goto(url)
    page.wait_for_selector("body[data-ready]")
    assert page.is_visible("#deferred") and "[flywheel]" in page.inner_text("#deferred")
    before = page.inner_text("#summary")
    field = page.locator('#fields tr[data-key="mechanism.crank.length"] input[type=number]')
    for count, value in enumerate(("33", "36"), start=1):
        field.fill(value)
        field.dispatch_event("change")
        page.wait_for_selector(f"body[data-edits='{count}'][data-busy='0'][data-state=valid]", state="attached")
        # the page's own clock, from the input event to the frame after the redraw (bench/studio.py: ~60-90 ms)
        assert 0 < float(page.get_attribute("#latency", "data-ms")) < 1000
    after = page.inner_text("#summary")
    assert "live estimate" in after and after != before
    # Full run: the motor, its steady state and start-up computed as machdyn run does; no live estimate left
    page.click("#fullrun")
    page.wait_for_selector("#fullmark:not([hidden])", state="attached")
    page.wait_for_selector(VALID, state="attached")
    full = page.inner_text("#summary")
    assert "motor" in full.lower() and "live estimate" not in full and page.is_hidden("#deferred")
    assert page.messages == []
