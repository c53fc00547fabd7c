"""The report's interactive views in a real browser (headless Chromium driven by Playwright).

The animated mechanism is checked against the run's own ``motion.csv``: at several slider positions every drawn
body point sits where the CSV puts it, to a third of a pixel (the screen position of each drawn circle against
the CSV's coordinates mapped through the drawing's own screen transform). Play advances the crank, a click on a
curve moves the slider, hovering a design of a design space shows its numbers, and the page works with the
network cut off and without a console message. Skipped only where no Chromium executable can be found (CI
installs one; set ``MACHDYN_CHROMIUM`` to choose it).
"""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from playwright import sync_api as playwright

from machdyn.report import render_report
from machdyn.report.animation import design_space_html
from machdyn.runner import run_problem

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
CHROMIUM = next((shutil.which(n) for n in ("chromium", "chromium-browser", "google-chrome") if shutil.which(n)), None)
pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="no Chromium on PATH: apt-get install -y chromium")


@pytest.fixture(scope="module")
def browser():
    with playwright.sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=["--no-sandbox", "--disable-gpu"])
        yield b
        b.close()


@pytest.fixture(scope="module")
def four_bar_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("four_bar")
    run_problem(EXAMPLES / "four_bar.toml").write(out)
    return out


def _open(browser, path: Path):
    """A page with the report loaded offline; console messages and any non-file request are recorded."""
    context = browser.new_context(offline=True, viewport={"width": 1200, "height": 1600})
    page = context.new_page()
    seen: dict[str, list[str]] = {"console": [], "requests": []}
    page.on("console", lambda m: seen["console"].append(f"{m.type}: {m.text}"))
    page.on("pageerror", lambda e: seen["console"].append(f"pageerror: {e}"))
    page.on("request", lambda r: None if r.url.startswith("file:") else seen["requests"].append(r.url))
    page.goto(path.as_uri())
    page.wait_for_selector("div.mdview[data-ready]")
    return page, seen


def _set_slider(page, index: int) -> None:
    page.eval_on_selector("div.mdview[data-view=mechanism] input.mdview-slider",
                          "(s, i) => { s.value = i; s.dispatchEvent(new Event('input')); }", index)


DRAWN = """
(view) => {
  const out = {};
  for (const c of view.querySelectorAll('circle.mdview-point')) {
    if (c.getAttribute('visibility') === 'hidden') continue;
    const box = c.getBoundingClientRect();
    out[c.dataset.point] = {sx: box.x + box.width / 2, sy: box.y + box.height / 2,
                            ctm: (({a, b, c: cc, d, e, f}) => ({a, b, c: cc, d, e, f}))(c.getScreenCTM())};
  }
  return out;
}
"""


def test_the_slider_puts_every_drawn_point_where_motion_csv_says(browser, four_bar_run):
    motion = pd.read_csv(four_bar_run / "motion.csv")
    page, seen = _open(browser, four_bar_run / "report.html")
    view = page.query_selector("div.mdview[data-view=mechanism]")
    checked = 0
    for index in (0, 37, 90, 181, 359):
        _set_slider(page, index)
        assert int(view.get_attribute("data-index")) == index
        assert float(view.get_attribute("data-angle")) == pytest.approx(motion["crank_angle [deg]"][index], abs=1e-3)
        drawn = view.evaluate(DRAWN)
        assert {"crank.A", "coupler.B", "coupler.P", "rocker.B"} <= set(drawn)
        for key, where in drawn.items():
            # motion.csv lists a joint once, under the first body that carries it (crank.A, not coupler.A)
            point = key.split(".")[1]
            name = key if f"{key}.x [m]" in motion else next(
                c[: -len(".x [m]")] for c in motion.columns if c.endswith(f".{point}.x [m]"))
            x, y = motion[f"{name}.x [m]"][index], motion[f"{name}.y [m]"][index]
            m = where["ctm"]  # the circle's own user space (metres, y up) -> screen pixels
            sx, sy = m["a"] * x + m["c"] * y + m["e"], m["b"] * x + m["d"] * y + m["f"]
            # a third of a pixel: the circle's centre from its bounding box, coordinates rounded to 1e-5 of the
            # drawing's extent (far below a pixel at this size)
            assert abs(where["sx"] - sx) < 0.34 and abs(where["sy"] - sy) < 0.34, (index, key, where, sx, sy)
            checked += 1
    assert checked >= 25
    assert seen["console"] == [] and seen["requests"] == []


def test_play_advances_the_crank_and_pause_stops_it(browser, four_bar_run):
    page, _seen = _open(browser, four_bar_run / "report.html")
    view = page.query_selector("div.mdview[data-view=mechanism]")
    _set_slider(page, 10)
    view.query_selector("button.mdview-play").click()
    page.wait_for_function("(v) => +v.dataset.index > 20", arg=view, timeout=5000)
    view.query_selector("button.mdview-play").click()
    stopped = int(view.get_attribute("data-index"))
    page.wait_for_timeout(300)
    assert int(view.get_attribute("data-index")) == stopped


def test_a_click_on_a_curve_moves_the_slider_there_and_the_cursor_follows(browser, four_bar_run):
    page, _seen = _open(browser, four_bar_run / "report.html")
    view = page.query_selector("div.mdview[data-view=mechanism]")
    curve = view.query_selector("svg.mdview-curve")
    box = curve.bounding_box()
    # the plotting area runs from 46 to 292 of the 300 user units: its middle is the middle of the crank range
    curve.click(position={"x": box["width"] * (46 + 0.5 * 246) / 300, "y": box["height"] / 2})
    index = int(view.get_attribute("data-index"))
    assert abs(index - 180) <= 2
    cursors = view.query_selector_all("line.mdview-cursor")
    assert cursors and all(int(c.get_attribute("data-index")) == index for c in cursors)


def test_the_report_needs_no_network_and_logs_nothing(browser, four_bar_run):
    page, seen = _open(browser, four_bar_run / "report.html")
    assert page.evaluate("window.machdynViews.length") >= 1
    assert seen["requests"] == [], "the report asked the network for something"
    assert seen["console"] == []


def test_hovering_a_design_shows_its_numbers_and_a_click_opens_it(browser, tmp_path):
    rng = np.random.default_rng(1)
    table = {"crank.length": rng.uniform(0.03, 0.05, 40), "driving_torque.max_abs": rng.uniform(1, 9, 40)}
    table["driving_torque.max_abs"][7] = 1e9  # a degenerate design: drawn, but not allowed to set the scale
    status = ["regular"] * 40
    status[7] = "transmission angle below 20°"
    html = render_report(title="space", problem_text="", summary_rows=[], warnings=[], sections=[
        ("Design space", str(design_space_html(table, {"crank.length": "m", "driving_torque.max_abs": "N·m"},
                                               x="crank.length", y="driving_torque.max_abs", status=status,
                                               highlight={"best": 3})))])
    page_path = tmp_path / "space.html"
    page_path.write_text(html, encoding="utf-8")
    page, seen = _open(browser, page_path)
    view = page.query_selector("div.mdview[data-view=space]")
    view.query_selector('circle[data-design="12"]').hover()
    tip = view.query_selector("div.mdview-tip")
    assert tip.is_visible() and tip.get_attribute("data-design") == "12"
    text = tip.inner_text()
    assert f"{table['crank.length'][12]:.4g}" in text and f"{table['driving_torque.max_abs'][12]:.4g}" in text
    # the regular designs set the scale: the degenerate one is pinned to the frame's edge, not stretching it
    ys = [float(c.get_attribute("cy")) for c in view.query_selector_all("circle.mdview-dot:not(.mdview-irregular)")]
    assert max(ys) - min(ys) > 250
    view.query_selector('circle[data-design="20"]').click()
    assert view.query_selector("div.mdview-detail").get_attribute("data-design") == "20"
    assert seen["console"] == []


def test_an_open_report_reloads_itself_when_watch_writes_a_new_stamp(browser, tmp_path):
    result = run_problem(EXAMPLES / "four_bar.toml")
    result.write(tmp_path, watch_stamp="first")
    page, _seen = _open(browser, tmp_path / "report.html")
    _set_slider(page, 42)
    with page.expect_event("load", timeout=60000):  # generous: writing the report takes seconds on a loaded machine
        result.write(tmp_path, watch_stamp="second")  # what the next run of `machdyn watch` does
    page.wait_for_selector("div.mdview[data-ready]")
    # the crank angle the reader had chosen survives the reload
    assert page.get_attribute("div.mdview[data-view=mechanism]", "data-index") == "42"


def _scene_data(page, selector: str) -> dict:
    return page.eval_on_selector(selector, "v => JSON.parse(v.querySelector('script.mdview-data').textContent)")


def test_an_optimisation_plays_the_optimum_beside_the_nominal_design(browser, tmp_path):
    result = run_problem(EXAMPLES / "compactor_optimise.toml")
    result.write(tmp_path)
    page, seen = _open(browser, tmp_path / "report.html")
    side = page.query_selector_all("div.mdview[data-view=mechanism]")
    pair = [v for v in side if "optimum" in _scene_data(page, f"#{v.get_attribute('id')}")["scenes"]]
    assert len(pair) == 1, "one view plays the optimum beside the nominal design"
    scenes = _scene_data(page, f"#{pair[0].get_attribute('id')}")["scenes"]
    assert set(scenes) == {"nominal", "optimum"}
    # each scene is its own design: the drawn crank is the nominal 30 mm and the optimum's own radius
    best_r = float(result.outcomes["optimise"].scalars["optimise.best.variable.r"])  # SI [m]
    for name, radius in (("nominal", 0.030), ("optimum", best_r)):
        points = scenes[name]["points"]
        pin = [points[k] for k in points if k.startswith("crank.")]
        pivot = scenes[name]["ground"][0]
        drawn = max(np.hypot(p[0][0] - pivot["x"], p[1][0] - pivot["y"]) for p in pin)
        # coordinates are rounded to 1e-5 of the drawing's extent (< 1 m here): 1e-5 m covers it
        assert drawn == pytest.approx(radius, abs=1e-5)
    assert abs(best_r - 0.030) > 1e-4, "the optimum differs from the nominal design"
    # one slider moves both
    pair[0].query_selector("button.mdview-play").click()
    page.wait_for_timeout(400)
    assert int(pair[0].get_attribute("data-index")) > 0
    assert seen["console"] == []


def test_an_exploration_scatter_opens_its_best_design_with_its_motion(browser, tmp_path):
    run_problem(EXAMPLES / "four_bar_press_explore.toml").write(tmp_path)
    page, seen = _open(browser, tmp_path / "report.html")
    space = page.query_selector("div.mdview[data-view=space]")
    data = _scene_data(page, f"#{space.get_attribute('id')}")
    best_row = data["highlight"]["best"]
    assert data["status"][best_row] == "regular"
    objective = data["y"]
    regular = [v for v, s in zip(data["columns"][objective], data["status"], strict=True) if s == "regular"]
    assert data["columns"][objective][best_row] == min(regular), "the ringed design is the best one"
    space.query_selector('g.mdview-highlight[data-highlight="best"]').click()
    detail = space.query_selector("div.mdview-detail")
    assert detail.get_attribute("data-design") == str(best_row)
    assert detail.query_selector("div.mdview svg") is not None, "the best design plays its motion"
    design = data["columns"]["design"][best_row]
    assert f"Design {design:g}" in detail.inner_text()
    assert seen["console"] == []
