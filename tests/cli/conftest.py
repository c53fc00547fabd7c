"""The browser page of the report tests (headless Chromium; see tests/studio_browser.py)."""

from studio_browser import page  # noqa: F401 - a fixture
