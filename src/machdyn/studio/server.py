"""Serve a studio: a random token, 127.0.0.1 by default, the URL printed first, a clean stop on Ctrl-C."""

from __future__ import annotations

import os
import secrets
import socket
from collections.abc import Callable
from pathlib import Path

from .session import Studio


def free_port(host: str = "127.0.0.1") -> int:
    """A port the system has free now (for tests and ``--port 0``)."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as sock:
        sock.bind((host, 0))
        return int(sock.getsockname()[1])


def serve(path: str | os.PathLike, *, host: str = "127.0.0.1", port: int = 8765, open_browser: bool = True,
          say: Callable[[str], None] = print) -> None:
    """Run the studio of ``path`` until Ctrl-C. The first line said is the page's URL (with its token)."""
    import uvicorn

    from .app import create_app

    studio = Studio(Path(path))
    token = secrets.token_urlsafe(24)
    if port == 0:
        port = free_port(host)
    url = f"http://{'127.0.0.1' if host in ('127.0.0.1', 'localhost') else host}:{port}/?token={token}"
    say(url)
    if not studio.editable:
        say(f"note: a [{studio.kind}] file opens read-only: its summary and the report of its run")
    config = uvicorn.Config(create_app(studio, token), host=host, port=port, log_level="warning",
                            lifespan="on", timeout_graceful_shutdown=2)
    server = uvicorn.Server(config)
    if open_browser:
        import threading
        import webbrowser

        threading.Timer(0.5, lambda: webbrowser.open(url)).start()
    server.run()  # uvicorn stops on SIGINT/SIGTERM: connections closed, the worker shut down
