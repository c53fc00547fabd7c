"""The studio in a real browser (headless Chromium, Playwright) on a cam and on variants: dragging the end of the
cam's rise to an earlier angle makes the rise steeper and the peak pressure angle on the page larger, a broken
program shows check's message with the last valid cam kept, and two kept variants are drawn side by side with
their differences. With ``MACHDYN_SCREENSHOTS=<folder>`` the pages are saved there (docs/images/ is made so)."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from studio_browser import CHROMIUM, INVALID, NO_CHROMIUM, VALID

pytestmark = pytest.mark.skipif(CHROMIUM is None, reason=NO_CHROMIUM)


def _shot(page, name: str, part: str | None = None) -> None:
    if os.environ.get("MACHDYN_SCREENSHOTS"):
        where = str(Path(os.environ["MACHDYN_SCREENSHOTS"]) / name)
        page.locator(part).screenshot(path=where) if part else page.screenshot(path=where, full_page=True)


def _number(page, key: str):
    return page.locator(f'#fields tr[data-key="{key}"] input[type=number]')


def _peak(page) -> float:
    return float(page.inner_text("#peak").split()[0])


def test_drag_a_cam_point_and_see_the_pressure_angle_change(serve, page):
    url, path = serve("feeder_cam.toml")
    page.goto(url)
    page.wait_for_selector("body[data-ready]")
    assert page.inner_text("#peaklabel") == "Peak pressure angle"
    before = _peak(page)
    assert page.locator("#view polygon[data-part=cam]").count() == 1
    titles = [page.locator("#plots svg").nth(i).get_attribute("data-title") for i in range(3)]
    assert titles == ["Follower displacement s", "Pressure angle", "Contact force along the follower's path"]
    page.fill("#varname", "rise 110 deg")
    page.click("#keep")
    page.wait_for_selector("#variants[data-count='1']", state="attached")

    # the end of the rise (110 deg, 30 mm) dragged 80 px to the left: a shorter rise, the dwell longer; the
    # cycloidal rise's peak velocity 2 h / beta grows and with it tan(phi) = (v - e) / (d + s) (Norton eq 8.31):
    # from about 20 deg to over 30 deg, above the return's 24.4 deg
    handle = page.locator('#diagram circle.handle[data-point="0"]')
    box = handle.bounding_box()
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    page.mouse.move(x - 80, y, steps=4)
    page.mouse.up()
    page.wait_for_selector(VALID, state="attached")
    rise, dwell = float(_number(page, "cam.segments[0].angle").input_value()), \
        float(_number(page, "cam.segments[1].angle").input_value())
    assert rise < 80 and rise + dwell == pytest.approx(180, abs=1e-9)  # the boundary moved, the turn is kept
    assert _number(page, "cam.segments[0].lift").input_value() == "30"  # a sideways drag keeps the stroke
    assert _peak(page) > before + 5
    _shot(page, "studio-cam.png")

    # the two cams side by side at one scale, the larger pressure angle in the table
    page.fill("#varname", "shorter rise")
    page.click("#keep")
    page.wait_for_selector("#variants[data-count='2']", state="attached")
    page.click("#compare")
    page.wait_for_selector("#comparison:not([hidden])")
    assert page.locator("#viewa polygon[data-part=cam]").count() == 1
    assert page.locator("#viewb polygon[data-part=cam]").count() == 1
    row = page.locator("#cmptable tr", has_text="Pressure angle: largest |phi|").inner_text().split("\t")
    assert float(row[2]) == pytest.approx(_peak(page), abs=0.01) and float(row[2]) > float(row[1])
    page.click("#closecompare")

    # a rise that no longer fits the turn: check's message, the last valid cam kept and marked
    steeper = _peak(page)
    _number(page, "cam.segments[3].angle").fill("40")
    _number(page, "cam.segments[3].angle").dispatch_event("change")
    page.wait_for_selector(INVALID, state="attached")
    assert "must fill one turn of the cam, 360 deg" in page.inner_text("#stale")
    assert page.is_visible("#stale") and _peak(page) == steeper
    assert page.messages == []


def test_two_variants_side_by_side(serve, page):
    url, _ = serve("four_bar.toml")
    page.goto(url)
    page.wait_for_selector("body[data-ready]")
    page.fill("#varname", "as drawn")
    page.click("#keep")
    page.wait_for_selector("#variants[data-count='1']", state="attached")
    _number(page, "mechanism.crank.length").fill("48")
    _number(page, "mechanism.crank.length").dispatch_event("change")
    page.wait_for_selector("body[data-edits='1'][data-busy='0'][data-state=valid]", state="attached")
    page.fill("#varname", "longer crank")
    page.click("#keep")
    page.wait_for_selector("#variants[data-count='2']", state="attached")
    page.select_option("#vara", "as drawn")
    page.select_option("#varb", "longer crank")
    page.click("#compare")
    page.wait_for_selector("#comparison:not([hidden])")
    assert page.inner_text("#cmpa") == "as drawn" and page.inner_text("#cmpb") == "longer crank"
    assert "mechanism.crank.length 40 → 48" in page.inner_text("#cmpfields")
    for view in ("#viewa", "#viewb"):  # both machines drawn
        assert page.locator(f"{view} polygon").count() >= 1
    row = page.locator("#cmptable tr", has_text="Driving torque, max |T|").inner_text().split("\t")
    a, b, difference = (float(v) for v in row[1:4])
    assert b > a and difference == pytest.approx(b - a, rel=2e-3) and row[4].startswith("+")
    _shot(page, "studio-compare.png", "#comparison")
    assert page.messages == []
