"""The studio in a real browser (headless Chromium driven by Playwright), against the real server (uvicorn on a
free port in a thread): a typed length changes the peak driving torque on the page, a bad value shows the check's
message beside its field with the last valid machine kept and marked, dragging the rocker pivot changes the
ground's fields, and save writes the file with its comments. Skipped only where no Chromium executable can be
found (set ``MACHDYN_CHROMIUM`` to choose one)."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from studio_browser import CHROMIUM, INVALID, NO_CHROMIUM, VALID

pytestmark = pytest.mark.skipif(CHROMIUM is None, reason=NO_CHROMIUM)


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
