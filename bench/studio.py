"""Time per edit of `machdyn studio`: the server's answer to one edited value (judged as `check` judges the file,
computed as `run` computes it, the view's scene and the summary built), on shipped examples.

Each edit changes the crank length (alternating between two values, so no answer is cached) and is sent through
the studio's own JSON endpoint (Starlette's test client, in process: no network). The table gives, over
`--repeats` edits after one warm-up, min / median / max of the compute time the server reports (`compute_ms`) and
of the whole request (JSON in and out included). Run it with `.venv/bin/python bench/studio.py [--repeats N]`.
"""

from __future__ import annotations

import argparse
import json
import shutil
import statistics
import tempfile
import time
from pathlib import Path

from starlette.testclient import TestClient

from machdyn.studio.app import create_app
from machdyn.studio.session import Studio

ROOT = Path(__file__).resolve().parents[1]
TOKEN = "bench"
#: example -> (the field edited, two values in its unit)
CASES = {
    "four_bar.toml": ("mechanism.crank.length", ("40", "41")),
    "slider_crank.toml": ("mechanism.crank.length", ("50", "51")),
    "compactor_flywheel.toml": ("mechanism.crank.length", None),
    "crank_press.toml": ("mechanism.crank.length", ("40", "41")),
}


def times(example: str, field: str, pair: tuple[str, str] | None, repeats: int) -> dict[str, list[float]]:
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / example
        shutil.copy(ROOT / "examples" / example, path)
        studio = Studio(path)
        if pair is None:  # the file's own value and 2 % more
            number = next(f.number for f in studio.fields if f.key == field)
            pair = (number, f"{float(number) * 1.02:g}")
        with TestClient(create_app(studio, TOKEN)) as client:
            client.get("/api/state", headers={"X-Studio-Token": TOKEN})
            server, request = [], []
            for i in range(repeats + 1):
                started = time.perf_counter()
                answer = client.post("/api/evaluate", json={"values": {field: pair[i % 2]}},
                                     headers={"X-Studio-Token": TOKEN}).json()
                elapsed = 1e3 * (time.perf_counter() - started)
                if not answer["ok"]:
                    raise SystemExit(f"{example}: {answer['message']}")
                if i:  # the first edit is the warm-up
                    server.append(answer["compute_ms"])
                    request.append(elapsed)
    return {"server_ms": server, "request_ms": request}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=20)
    args = parser.parse_args()
    rows = {name: times(name, field, pair, args.repeats) for name, (field, pair) in CASES.items()}
    width = max(len(k) for k in rows)
    print(f"{'example (one edit)':<{width}}  {'server ms min / median / max':>30}  {'request ms median':>17}")
    for name, found in rows.items():
        s = found["server_ms"]
        print(f"{name:<{width}}  {min(s):8.1f} / {statistics.median(s):7.1f} / {max(s):7.1f}  "
              f"{statistics.median(found['request_ms']):17.1f}")
    print(json.dumps({k: {m: {"min": min(v), "median": statistics.median(v), "max": max(v)} for m, v in r.items()}
                      for k, r in rows.items()}))


if __name__ == "__main__":
    main()
