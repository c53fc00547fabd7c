"""What the studio's browser tests share (their fixtures are in tests/studio/conftest.py): the Chromium executable,
the token and the selectors the page sets when it is ready."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

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
