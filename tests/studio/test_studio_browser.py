"""The studio in a real browser (headless Chromium driven by Playwright), against the real server (uvicorn on a
free port in a thread): a typed length changes the peak driving torque on the page, a bad value shows the check's
message beside its field with the last valid machine kept and marked, dragging the rocker pivot changes the
ground's fields, and save writes the file with its comments. Skipped only where no Chromium executable can be
found (set ``MACHDYN_CHROMIUM`` to choose one)."""

from __future__ import annotations

import os
import shutil
import threading
import time
from pathlib import Path

import pytest
import uvicorn
from playwright import sync_api as playwright

from machdyn.studio.app import create_app
from machdyn.studio.server import free_port
from machdyn.studio.session import Studio

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
CANDIDATES = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")
CHROMIUM = os.environ.get("MACHDYN_CHROMIUM") or next((shutil.which(n) for n in CANDIDATES if shutil.which(n)), None)
pytestmark = pytest.mark.skipif(CHROMIUM is None, reason=f"no Chromium on PATH (looked for {', '.join(CANDIDATES)}): "
                                "apt-get install -y chromium, or set MACHDYN_CHROMIUM")
TOKEN = "browser-test-token"
# the page says on its body whether a request is under way and whether the last answer was valid (the page's
# own Content-Security-Policy forbids evaluating test code in it, so the waits are selectors)
VALID = "body[data-busy='0'][data-state=valid]"
INVALID = "body[data-busy='0'][data-state=invalid]"


@pytest.fixture
def served(tmp_path):
    path = tmp_path / "four_bar.toml"
    shutil.copy(EXAMPLES / "four_bar.toml", path)
    port = free_port()
    server = uvicorn.Server(uvicorn.Config(create_app(Studio(path), TOKEN), host="127.0.0.1", port=port,
                                           log_level="warning"))
    thread = threading.Thread(target=server.run, daemon=True)
    thread.start()
    deadline = time.monotonic() + 20
    while not server.started and time.monotonic() < deadline:
        time.sleep(0.02)
    assert server.started, "the studio's server did not start"
    yield f"http://127.0.0.1:{port}/?token={TOKEN}", path
    server.should_exit = True
    thread.join(timeout=10)
    assert not thread.is_alive(), "the server did not stop"


@pytest.fixture
def page():
    with playwright.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=["--no-sandbox", "--disable-gpu"])
        context = browser.new_context(viewport={"width": 1280, "height": 900})
        tab = context.new_page()
        tab.messages = []
        tab.on("console", lambda m: tab.messages.append(f"{m.type}: {m.text}"))
        tab.on("pageerror", lambda e: tab.messages.append(f"pageerror: {e}"))
        yield tab
        browser.close()


def _peak(page) -> float:
    return float(page.inner_text("#peak").split()[0])


def _field(page, key: str):
    return page.locator(f'#fields tr[data-key="{key}"]')


def _number(page, key: str):
    return _field(page, key).locator("input[type=number]")


def test_edit_drag_error_and_save_in_the_browser(served, page):
    url, path = served
    page.goto(url)
    page.wait_for_selector("body[data-ready]")
    before = _peak(page)
    assert page.locator("#view circle.handle").count() >= 3  # D, A and B can be dragged

    # a longer crank: the peak torque on the page changes
    _number(page, "mechanism.crank.length").fill("50")
    _number(page, "mechanism.crank.length").dispatch_event("change")
    page.wait_for_selector(VALID, state="attached")
    longer = _peak(page)
    assert longer > before * 1.05
    assert "computed in" in page.inner_text("#status")

    # a negative length: the check's message beside the field, the last valid machine kept and marked
    _number(page, "mechanism.crank.length").fill("-5")
    _number(page, "mechanism.crank.length").dispatch_event("change")
    page.wait_for_selector(INVALID, state="attached")
    assert "must be > 0 m; got '-5 mm'" in _field(page, "mechanism.crank.length").inner_text()
    assert page.is_visible("#stale") and "Last valid machine shown" in page.inner_text("#stale")
    assert _peak(page) == longer

    # undo brings back 50 mm and a valid machine
    page.click("#undo")
    page.wait_for_selector(VALID, state="attached")
    assert _number(page, "mechanism.crank.length").input_value() == "50"
    assert not page.is_visible("#stale")

    # drag the rocker pivot D up and right: the ground's length and angle follow the pointer
    handle = page.locator('#view circle[data-point="ground:D"]')
    box = handle.bounding_box()
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    page.mouse.move(x + 10, y - 12, steps=4)
    page.mouse.up()
    page.wait_for_selector(VALID, state="attached")
    angle = float(_number(page, "mechanism.ground.angle").input_value())
    length = float(_number(page, "mechanism.ground.length").input_value())
    assert 0.5 < angle < 20 and length > 130
    # the round trip pointer -> fields -> server -> drawing puts the pivot where it was dropped
    moved = page.locator('#view circle[data-point="ground:D"]').bounding_box()
    assert moved["x"] + moved["width"] / 2 == pytest.approx(x + 10, abs=1.0)
    assert moved["y"] + moved["height"] / 2 == pytest.approx(y - 12, abs=1.0)

    if os.environ.get("MACHDYN_SCREENSHOTS"):  # docs/images/studio.png is made this way
        page.screenshot(path=str(Path(os.environ["MACHDYN_SCREENSHOTS"]) / "studio.png"))

    page.click("#save")
    page.wait_for_selector("#saved.ok")
    text = path.read_text()
    assert 'length = "50 mm"' in text and "# direction from the crank pivot O to the rocker pivot D" in text
    assert f'angle = "{angle:g} deg"' in text

    # the rocker's slider (50 to 200 mm in steps of 0.5 %): one step right is 0.5 mm more, recomputed
    peak = _peak(page)
    _field(page, "mechanism.rocker.length").locator("input[type=range]").focus()
    page.keyboard.press("ArrowRight")
    page.wait_for_selector(VALID, state="attached")
    assert _number(page, "mechanism.rocker.length").input_value() == "100.5"
    assert _peak(page) != peak
    assert page.messages == []
