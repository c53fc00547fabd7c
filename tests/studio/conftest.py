"""The studio's browser fixtures: its real server on a free port for a copy of an example, and a page in headless
Chromium driven by Playwright (skipped where no Chromium executable is found; from tests/studio_browser.py)."""

from __future__ import annotations

import shutil
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from studio_browser import EXAMPLES, TOKEN, page  # noqa: F401 - the page fixture, shared with tests/cli


@pytest.fixture
def serve(tmp_path) -> Iterator[Callable[[str], tuple[str, Path]]]:
    """``serve(example)``: a copy of the example served by the studio; its URL (with the token) and path."""
    import uvicorn

    from machdyn.studio.app import create_app
    from machdyn.studio.server import free_port
    from machdyn.studio.session import Studio

    running = []

    def start(example: str) -> tuple[str, Path]:
        path = tmp_path / example
        shutil.copy(EXAMPLES / example, path)
        port = free_port()
        server = uvicorn.Server(uvicorn.Config(create_app(Studio(path), TOKEN), host="127.0.0.1", port=port,
                                               log_level="warning"))
        thread = threading.Thread(target=server.run, daemon=True)
        thread.start()
        running.append((server, thread))
        deadline = time.monotonic() + 20
        while not server.started and time.monotonic() < deadline:
            time.sleep(0.02)
        assert server.started, "the studio's server did not start"
        return f"http://127.0.0.1:{port}/?token={TOKEN}", path

    yield start
    for server, thread in running:
        server.should_exit = True
        thread.join(timeout=10)
        assert not thread.is_alive(), "the server did not stop"


@pytest.fixture
def served(serve) -> tuple[str, Path]:
    return serve("four_bar.toml")
