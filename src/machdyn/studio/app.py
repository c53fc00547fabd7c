"""The studio's web application (Starlette): the page, its JSON endpoints, and the guards on every request.

Every request carries the session's token (``?token=`` in the page's URL, the ``X-Studio-Token`` header on
its calls), compared in constant time; a request body is at most :data:`MAX_BODY` bytes; a computation is
given :data:`COMPUTE_SECONDS` before the answer says it took too long (the one worker thread finishes it, and
later edits wait for it). The page and its script are files of this package: nothing is fetched from the
network.

Endpoints: ``GET /`` the page; ``GET /api/state`` the fields and the machine as on disk; ``POST /api/evaluate``
``{"values": {key: number}}`` the machine with those values, live (:mod:`machdyn.studio.live`); ``POST
/api/full`` the same with every table (*Full run*); ``POST /api/variant`` ``{"name": ..., "values": ...}`` keeps
that machine as a named variant; ``POST /api/compare`` ``{"a": name, "b": name}`` two variants side by side;
``POST /api/save`` ``{"values": ..., "name": optional new file name}``; ``GET /report`` the ordinary run's report
(files the studio shows read-only).
"""

from __future__ import annotations

import asyncio
import contextlib
import json
import secrets
from collections.abc import AsyncIterator
from concurrent.futures import ThreadPoolExecutor
from importlib import resources
from typing import Any

from starlette.applications import Starlette
from starlette.requests import Request
from starlette.responses import HTMLResponse, JSONResponse, Response
from starlette.routing import Route
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from .session import SaveRefused, Studio

MAX_BODY = 64 * 1024
COMPUTE_SECONDS = 20.0
TOKEN_HEADER = "x-studio-token"


class Guard:
    """ASGI middleware: refuse a request without the session's token (403) or with a body over ``limit`` (413),
    before the application reads it."""

    def __init__(self, app: ASGIApp, token: str, limit: int = MAX_BODY) -> None:
        self.app, self.token, self.limit = app, token, limit

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        request = Request(scope)
        given = request.headers.get(TOKEN_HEADER) or request.query_params.get("token") or ""
        if not secrets.compare_digest(given.encode(), self.token.encode()):
            await JSONResponse({"ok": False, "message": "the studio's token is missing or wrong: open the URL "
                                "it printed"}, status_code=403)(scope, receive, send)
            return
        declared = request.headers.get("content-length")
        if declared is not None and (not declared.isdigit() or int(declared) > self.limit):
            await _too_large(self.limit)(scope, receive, send)
            return
        seen = 0

        async def bounded() -> Message:  # a chunked body without a length is counted as it comes
            nonlocal seen
            message = await receive()
            if message["type"] == "http.request":
                seen += len(message.get("body", b""))
                if seen > self.limit:
                    raise _BodyTooLarge
            return message

        try:
            await self.app(scope, bounded, send)
        except _BodyTooLarge:
            await _too_large(self.limit)(scope, receive, send)


class _BodyTooLarge(Exception):
    pass


def _too_large(limit: int) -> JSONResponse:
    return JSONResponse({"ok": False, "message": f"the request is larger than {limit // 1024} KiB"},
                        status_code=413)


def _said(exc: Exception) -> str:
    """The message of a refusal (a KeyError's without the quotes its str adds)."""
    return str(exc.args[0]) if isinstance(exc, KeyError) and exc.args else str(exc)


def _asset(name: str) -> str:
    return resources.files("machdyn.studio").joinpath("static", name).read_text(encoding="utf-8")


def page() -> str:
    """The studio's page with its style and script inline (one document, no other request)."""
    html = _asset("studio.html")
    return html.replace("/*STYLE*/", _asset("studio.css")).replace("/*SCRIPT*/", _asset("studio.js"))


async def _values(request: Request) -> tuple[dict[str, str], Any]:
    try:
        body = await request.json()
    except (json.JSONDecodeError, UnicodeDecodeError):
        raise SaveRefused("the request body is not JSON") from None
    values = body.get("values", {}) if isinstance(body, dict) else None
    if not isinstance(values, dict) or not all(isinstance(k, str) and isinstance(v, str | int | float)
                                               for k, v in values.items()):
        raise SaveRefused('the request body is {"values": {field: number, ...}}')
    return {k: str(v) for k, v in values.items()}, body


def _lifespan(worker: ThreadPoolExecutor) -> Any:
    @contextlib.asynccontextmanager
    async def lifespan(app: Starlette) -> AsyncIterator[None]:
        yield
        worker.shutdown(wait=False, cancel_futures=True)  # a computation under way is not waited for

    return lifespan


def create_app(studio: Studio, token: str, *, compute_seconds: float = COMPUTE_SECONDS,
               max_body: int = MAX_BODY) -> ASGIApp:
    """The studio's ASGI application for one session and its token."""
    worker = ThreadPoolExecutor(max_workers=1, thread_name_prefix="machdyn-studio")

    async def computed(fn: Any, *args: Any) -> Any:
        loop = asyncio.get_running_loop()
        return await asyncio.wait_for(loop.run_in_executor(worker, fn, *args), timeout=compute_seconds)

    def too_long() -> JSONResponse:
        return JSONResponse({"ok": False, "problems": [], "message": f"the computation took longer than "
                             f"{compute_seconds:g} s; fewer positions (drive.positions) answer faster"},
                            status_code=503)

    async def home(request: Request) -> Response:
        return HTMLResponse(page(), headers={"Content-Security-Policy": "default-src 'none'; img-src data:; "
                                             "style-src 'unsafe-inline'; script-src 'unsafe-inline'; "
                                             "connect-src 'self'", "Cache-Control": "no-store"})

    async def state(request: Request) -> Response:
        try:
            return JSONResponse(await computed(studio.state))
        except TimeoutError:
            return too_long()

    async def evaluate(request: Request, full: bool = False) -> Response:
        try:
            values, _ = await _values(request)
            return JSONResponse(await computed(lambda: studio.evaluate(values, full=full)))
        except (ValueError, KeyError) as exc:  # a refused save, an unknown field, a value too long
            return JSONResponse({"ok": False, "problems": [], "message": _said(exc)}, status_code=400)
        except TimeoutError:
            return too_long()

    async def full_run(request: Request) -> Response:
        return await evaluate(request, full=True)

    async def variant(request: Request) -> Response:
        try:
            values, body = await _values(request)
            return JSONResponse(await computed(studio.keep_variant, str(body.get("name", "")), values))
        except (ValueError, KeyError) as exc:  # a refused name or machine, an unknown field
            return JSONResponse({"ok": False, "message": _said(exc)}, status_code=400)
        except TimeoutError:
            return too_long()

    async def compare(request: Request) -> Response:
        try:
            body = await request.json()
            if not isinstance(body, dict):
                raise ValueError('the request body is {"a": name, "b": name}')
            return JSONResponse(studio.compare(str(body.get("a", "")), str(body.get("b", ""))))
        except (ValueError, UnicodeDecodeError) as exc:
            return JSONResponse({"ok": False, "message": _said(exc)}, status_code=400)

    async def save(request: Request) -> Response:
        try:
            values, body = await _values(request)
            name = body.get("name") if isinstance(body.get("name"), str) else None
            return JSONResponse(await computed(studio.save, values, name))
        except (ValueError, KeyError) as exc:  # a refused save, an unknown field, a value too long
            return JSONResponse({"ok": False, "message": _said(exc)}, status_code=400)
        except OSError as exc:
            return JSONResponse({"ok": False, "message": f"cannot write the file: {exc.strerror or exc}"},
                                status_code=500)
        except TimeoutError:
            return too_long()

    async def report(request: Request) -> Response:
        try:
            return HTMLResponse(await computed(studio.report))
        except TimeoutError:
            return too_long()

    app = Starlette(routes=[
        Route("/", home), Route("/api/state", state), Route("/api/evaluate", evaluate, methods=["POST"]),
        Route("/api/full", full_run, methods=["POST"]),
        Route("/api/variant", variant, methods=["POST"]), Route("/api/compare", compare, methods=["POST"]),
        Route("/api/save", save, methods=["POST"]), Route("/report", report),
    ], lifespan=_lifespan(worker))
    return Guard(app, token, max_body)
