"""What the studio's browser tests share (their fixtures are in tests/studio/conftest.py): the Chromium executable,
the token and the selectors the page sets when it is ready, and the ``page`` fixture (a tab of headless Chromium
driven by Playwright), imported by the conftest of each folder whose tests use it."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
CANDIDATES = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")
CHROMIUM = os.environ.get("MACHDYN_CHROMIUM") or next((shutil.which(n) for n in CANDIDATES if shutil.which(n)), None)
NO_CHROMIUM = (f"no Chromium on PATH (looked for {', '.join(CANDIDATES)}): apt-get install -y chromium, or set "
               "MACHDYN_CHROMIUM")
TOKEN = "browser-test-token"
# the page says on its body whether a request is under way and whether the last answer was valid (the page's
# own Content-Security-Policy forbids evaluating test code in it, so the waits are selectors)
VALID = "body[data-busy='0'][data-state=valid]"
INVALID = "body[data-busy='0'][data-state=invalid]"


@pytest.fixture
def page():
    if CHROMIUM is None:
        pytest.skip(NO_CHROMIUM)
    from playwright import sync_api as playwright

    with playwright.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=["--no-sandbox", "--disable-gpu"])
        context = browser.new_context(viewport={"width": 1280, "height": 900})
        tab = context.new_page()
        tab.messages = []
        tab.on("console", lambda m: tab.messages.append(f"{m.type}: {m.text}"))
        tab.on("pageerror", lambda e: tab.messages.append(f"pageerror: {e}"))
        yield tab
        browser.close()
