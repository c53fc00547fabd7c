"""Serve a studio: a random token, 127.0.0.1 by default, the URL printed first, a clean stop on Ctrl-C."""

from __future__ import annotations

import os
import secrets
import socket
import threading
import webbrowser
from collections.abc import Callable
from pathlib import Path

import typer
import uvicorn

from ..errors import ProblemFileError
from .app import create_app
from .session import Studio


def free_port(host: str = "127.0.0.1") -> int:
    """A port the system has free now (for tests and ``--port 0``)."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as sock:
        sock.bind((host, 0))
        return int(sock.getsockname()[1])


def serve(path: str | os.PathLike, *, host: str = "127.0.0.1", port: int = 8765, open_browser: bool = True,
          say: Callable[..., None] = typer.echo) -> None:
    """Run the studio of ``path`` until Ctrl-C. The first line said is the page's URL (with its token)."""
    studio = Studio(Path(path))
    first = studio.state()["result"]  # judged and computed once before serving: a file with mistakes is refused
    if not first["ok"]:
        raise ProblemFileError([(p["path"], p["message"]) for p in first["problems"]], str(path))
    token = secrets.token_urlsafe(24)
    listening = socket.socket(socket.AF_INET, socket.SOCK_STREAM)  # bound here: a port in use is an OSError
    listening.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    try:
        listening.bind((host, port))
    except OSError as exc:
        listening.close()
        raise OSError(exc.errno, f"cannot listen on {host}:{port} ({exc.strerror}); choose another --port") from None
    port = int(listening.getsockname()[1])
    url = f"http://{'127.0.0.1' if host in ('127.0.0.1', 'localhost') else host}:{port}/?token={token}"
    say(url)
    if not studio.editable:
        say(f"note: a [{studio.kind}] file opens read-only: its summary and the report of its run", err=True)
    config = uvicorn.Config(create_app(studio, token), host=host, port=port, log_level="warning",
                            lifespan="on", timeout_graceful_shutdown=2)
    server = uvicorn.Server(config)
    if open_browser:
        threading.Timer(0.5, lambda: webbrowser.open(url)).start()
    with listening:
        server.run(sockets=[listening])  # uvicorn stops on SIGINT/SIGTERM: connections closed, worker shut down


def serve_command(path: str | os.PathLike, *, port: int, open_browser: bool, say: Callable[..., None]) -> int:
    """``machdyn studio``: serve until Ctrl-C; the exit code (0, 2 for a file with mistakes, 1 when the server
    cannot start). Messages other than the URL go to stderr."""
    try:
        serve(path, port=port, open_browser=open_browser, say=say)
    except ProblemFileError as exc:
        say(str(exc), err=True)
        return 2
    except OSError as exc:
        say(f"error: the studio cannot start: {exc.strerror or exc}", err=True)
        return 1
    except KeyboardInterrupt:
        say("studio stopped", err=True)
    return 0
