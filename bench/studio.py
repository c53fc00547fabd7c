"""Time per edit of `machdyn studio`, on shipped examples: in the browser, from the input event to the redrawn
view and plots, and on the server, the answer to one edited value.

* **browser** (the figure a designer feels): headless Chromium (Playwright) on the studio's real server (uvicorn
  on a free port). Each edit types a new value into a field (the crank length; a cam's base radius); the page
  measures with its own clock (``performance.now()``) from the input event's time stamp to the animation frame
  after the view, the summary and the plots are redrawn, and shows it in ``#latency``. The file's own value and
  1 % more alternate, so no answer is cached.
* **server**: the same edits sent to the studio's JSON endpoint in process (Starlette's test client, no network):
  the compute time the server reports (``compute_ms``: judged as ``check`` judges the file, computed live) and the
  whole request.

Each row is min / median / max over ``--repeats`` edits after one warm-up edit. Run it with
``PYTHONPATH=src .venv/bin/python bench/studio.py [--repeats N] [--no-browser]``; the browser part needs Chromium
(``MACHDYN_CHROMIUM`` or ``chromium`` on the PATH).
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import statistics
import tempfile
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from starlette.testclient import TestClient

from machdyn.studio.app import create_app
from machdyn.studio.server import free_port
from machdyn.studio.session import Studio

ROOT = Path(__file__).resolve().parents[1]
TOKEN = "bench"
#: the examples timed and the field each edit changes: a plain four-bar with forces; a four-bar with forces, a
#: flywheel and a motor (360 positions); a slider-crank press with a flywheel on a belt shaft and a motor; a plate
#: cam with a roller follower, its spring and contact force (720 positions)
CASES = {"four_bar.toml": "mechanism.crank.length", "compactor_flywheel.toml": "mechanism.crank.length",
         "crank_press.toml": "mechanism.crank.length", "feeder_cam.toml": "cam.base_radius"}


def _pair(studio: Studio, field: str) -> tuple[str, str]:
    number = next(f.number for f in studio.fields if f.key == field)
    return number, f"{float(number) * 1.01:.6g}"


@contextmanager
def _copy(example: str) -> Iterator[Path]:
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / example
        shutil.copy(ROOT / "examples" / example, path)
        yield path


def server_times(example: str, field: str, repeats: int) -> dict[str, list[float]]:
    with _copy(example) as path:
        studio = Studio(path)
        pair = _pair(studio, field)
        with TestClient(create_app(studio, TOKEN)) as client:
            client.get("/api/state", headers={"X-Studio-Token": TOKEN})
            server, request = [], []
            for i in range(repeats + 1):
                started = time.perf_counter()
                answer = client.post("/api/evaluate", json={"values": {field: pair[(i + 1) % 2]}},
                                     headers={"X-Studio-Token": TOKEN}).json()
                elapsed = 1e3 * (time.perf_counter() - started)
                if not answer["ok"]:
                    raise SystemExit(f"{example}: {answer['message']}")
                if i:  # the first edit is the warm-up
                    server.append(answer["compute_ms"])
                    request.append(elapsed)
    return {"server_ms": server, "request_ms": request}


@contextmanager
def served(path: Path) -> Iterator[str]:
    """The studio of ``path`` on a free port in a thread; its URL."""
    import uvicorn

    port = free_port()
    server = uvicorn.Server(uvicorn.Config(create_app(Studio(path), TOKEN), host="127.0.0.1", port=port,
                                           log_level="warning"))
    thread = threading.Thread(target=server.run, daemon=True)
    thread.start()
    deadline = time.monotonic() + 30
    while not server.started and time.monotonic() < deadline:
        time.sleep(0.02)
    try:
        yield f"http://127.0.0.1:{port}/?token={TOKEN}"
    finally:
        server.should_exit = True
        thread.join(timeout=10)


def browser_edits(page, url: str, key: str, pair: tuple[str, str], count: int) -> list[float]:
    """Open ``url`` and make ``count`` edits of the field ``key``; the page's latency of each [ms]."""
    page.goto(url)
    page.wait_for_selector("body[data-ready]")
    field = page.locator(f'#fields tr[data-key="{key}"] input[type=number]')
    found = []
    for i in range(count):
        field.fill(pair[(i + 1) % 2])
        field.dispatch_event("change")
        page.wait_for_selector(f"body[data-edits='{i + 1}'][data-busy='0']", state="attached")
        found.append(float(page.get_attribute("#latency", "data-ms") or "nan"))
    return found


def browser_times(examples: dict[str, str], repeats: int, chromium: str) -> dict[str, list[float]]:
    from playwright import sync_api

    out = {}
    with sync_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=chromium, args=["--no-sandbox", "--disable-gpu"])
        page = browser.new_context(viewport={"width": 1280, "height": 900}).new_page()
        for example, key in examples.items():
            with _copy(example) as path, served(path) as url:
                pair = _pair(Studio(path), key)
                out[example] = browser_edits(page, url, key, pair, repeats + 1)[1:]  # less the warm-up
        browser.close()
    return out


def _stats(values: list[float]) -> dict[str, float]:
    return {"min": min(values), "median": statistics.median(values), "max": max(values)}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=20)
    parser.add_argument("--no-browser", action="store_true")
    args = parser.parse_args()
    chromium = os.environ.get("MACHDYN_CHROMIUM") or shutil.which("chromium") or shutil.which("chromium-browser")
    browser = {} if args.no_browser or chromium is None else browser_times(CASES, args.repeats, chromium)
    server = {name: server_times(name, key, args.repeats) for name, key in CASES.items()}
    width = max(len(k) for k in CASES)
    print(f"{'example (one edit, ms)':<{width}}  {'browser min / median / max':>27}  {'server min / median / max':>27}")
    for name in CASES:
        b = _stats(browser[name]) if name in browser else None
        s = _stats(server[name]["server_ms"])
        shown = f"{b['min']:7.1f} / {b['median']:6.1f} / {b['max']:6.1f}" if b else f"{'-':>27}"
        print(f"{name:<{width}}  {shown:>27}  {s['min']:7.1f} / {s['median']:6.1f} / {s['max']:6.1f}")
    print(json.dumps({"repeats": args.repeats,
                      "browser_ms": {k: _stats(v) for k, v in browser.items()},
                      "server_ms": {k: _stats(v["server_ms"]) for k, v in server.items()},
                      "request_ms": {k: _stats(v["request_ms"]) for k, v in server.items()}}))


if __name__ == "__main__":
    main()
