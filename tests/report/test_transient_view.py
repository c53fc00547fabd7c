"""The machine in time in the report's animated view: the frame's trajectory is the run's, times the stated scale.

The view draws each frame corner and mount point at its rest position plus ``factor`` times its displacement; here
the drawn positions are checked against the run's own point displacement (the transient's
``point_displacement``, the frame's point matrix), for a mechanism on a planar frame and for a shaft line's frame
in space (projected on the plane across the shaft), and the caption must state the factor the scene uses."""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest

from machdyn.report.transient import sections
from machdyn.report.transient_view import EXCURSION, transient_scene
from machdyn.runner import run_problem
from machdyn.transient import Exciter, Scenario, coupled_model, run_scenario
from machdyn.transient.passage import amplitude_curve
from machdyn.transient.stage import TransientRun

ROOT = Path(__file__).resolve().parents[2]
COMPRESSOR = ROOT / "examples" / "shaft_compressor_run_up.toml"


@pytest.fixture(scope="module")
def shaft_outcome():
    text = COMPRESSOR.read_text(encoding="utf-8")
    for key, value in {"duration": '"0.8 s"', "switch_off": '"0.8 s"', "brake_time": '"0.8 s"'}.items():
        text = re.sub(rf"(?m)^{key} = .*$", f"{key} = {value}", text)
    return run_problem(text).outcomes["transient"]


@pytest.fixture(scope="module")
def planar_result():
    import sys

    sys.path.insert(0, str(ROOT / "tests"))
    from transient.machines import plate, small_press

    model = coupled_model([Exciter(small_press(), None)], plate())
    run = run_scenario(model, Scenario(duration=0.6, prescribed=(25.0, 0.0), method="DOP853"))
    return TransientRun(None, run, None, amplitude_curve(run, (0.6, -0.2)), (), (0.6, -0.2), "corner", None, False,
                        25.0, float("nan"))


def _scene_in(html: str) -> dict:
    found = re.search(r'<script type="application/json" class="mdview-data">(.*?)</script>', html, re.S)
    assert found, "the section holds an animated view"
    return next(iter(json.loads(found.group(1).replace("<\\/", "</"))["scenes"].values()))


def test_the_shaft_lines_frame_moves_in_the_view_by_the_runs_displacement_times_the_stated_scale(shaft_outcome):
    (heading, html), = sections(shaft_outcome)
    data = _scene_in(html)
    factor = data["scale"]
    assert f"scale factor {factor:.3g}" in html  # the scale is stated
    result = shaft_outcome.results
    run = result.run
    t = np.asarray(data["angles"], dtype=float)
    assert data["axis"]["unit"] == "s" and t[0] == 0.0 and t[-1] == pytest.approx(run.t[-1], rel=1e-5)
    idx = np.abs(run.t[None, :] - t[:, None]).argmin(axis=1)  # the run's samples shown (times to 6 digits)
    depth = float(run.model.frame.com[2])
    span = 0.0
    for i in range(1, 5):
        drawn = np.asarray(data["points"][f"frame.c{i}"], dtype=float).T  # frames x 2
        rest = drawn[0]  # at t = 0 the frame is at rest
        u = run.point_displacement((rest[0], rest[1], depth))[:2, idx].T  # the run's own point matrix
        # every instant: the drawn corner is its rest position plus factor times the run's displacement
        assert np.max(np.abs(drawn - rest - factor * u)) <= 2e-5 * np.ptp(drawn)
        span = max(span, float(np.ptp(drawn[:, 0])))
    # the exaggeration makes the frame's largest excursion a visible share of the drawing
    assert factor > 1.0
    mounts = [k for k in data["points"] if k.startswith("mount ") and k.endswith(".at")]
    assert len(mounts) == 6  # the axial mount has no line across the shaft
    assert {"crank c1.pin", "rod c1.piston"} <= set(data["points"])  # the machine on the frame is drawn


def test_a_mechanism_on_a_planar_frame_moves_in_the_view_with_its_frame(planar_result):
    data, factor = transient_scene(planar_result)
    run = planar_result.run
    t = np.asarray(data["angles"], dtype=float)
    idx = np.abs(run.t[None, :] - t[:, None]).argmin(axis=1)  # the run's samples shown (times to 6 digits)
    extent = data["extent"]
    size = max(extent[1] - extent[0], extent[3] - extent[2])
    largest = 0.0
    for i in range(1, 5):
        drawn = np.asarray(data["points"][f"frame.c{i}"], dtype=float).T
        rest = drawn[0]
        u = run.point_displacement(rest)[:, idx].T
        assert np.max(np.abs(drawn - rest - factor * u)) <= 2e-5 * size
        largest = max(largest, float(np.max(np.hypot(*(factor * u).T))))
    assert largest == pytest.approx(EXCURSION * size, rel=0.5)  # the stated share of the drawing, about
    # the crank pin turns with the run's crank angle, carried by the frame
    pin = np.asarray(data["points"]["crank.A"], dtype=float).T
    assert np.ptp(pin[:, 0]) > 0.09  # it goes round: 2 x the 50 mm crank


def test_the_view_plays_the_run_in_time_in_a_browser(shaft_outcome, tmp_path):
    """The page's script draws the transient's scene: its readout and the curves' axis are the run's time, and the
    frame's corner moves as the scene says (headless Chromium; skipped without one, as the other browser tests)."""
    import shutil

    from machdyn.report.animation import assets

    chromium = next((shutil.which(n) for n in ("chromium", "chromium-browser", "google-chrome") if shutil.which(n)),
                    None)
    if chromium is None:
        pytest.skip("no Chromium on PATH: apt-get install -y chromium")
    from playwright import sync_api as playwright

    (_heading, html), = sections(shaft_outcome)
    page_file = tmp_path / "view.html"
    page_file.write_text(f"<!doctype html><html><head><meta charset='utf-8'>{assets()}</head><body>{html}</body>"
                         "</html>", encoding="utf-8")
    data = _scene_in(html)
    with playwright.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=chromium, args=["--no-sandbox", "--disable-gpu"])
        page = browser.new_page()
        errors: list[str] = []
        page.on("pageerror", lambda e: errors.append(str(e)))
        page.goto(page_file.as_uri())
        page.wait_for_selector("div.mdview[data-ready]")
        last = len(data["angles"]) - 1
        page.eval_on_selector("div.mdview input.mdview-slider",
                              "(s, i) => { s.value = i; s.dispatchEvent(new Event('input')); }", last)
        readout = page.inner_text("div.mdview .mdview-angle")
        ticks = page.eval_on_selector_all("svg.mdview-curve text.mdview-tick", "ts => ts.map(t => t.textContent)")
        browser.close()
    assert readout.startswith("t = ") and readout.endswith(" s")
    assert any(t.endswith("s time") for t in ticks)
    assert not errors
