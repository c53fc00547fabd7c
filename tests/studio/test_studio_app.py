"""The studio's web application through Starlette's test client: the token, the body bound, an edit recomputed,
a bad value answered with the very lines ``machdyn check`` prints and the last valid machine kept, and saving
(comments kept, only the edited value changed, never outside the file's folder)."""

from __future__ import annotations

import difflib
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request
from pathlib import Path

import pytest
from starlette.testclient import TestClient
from typer.testing import CliRunner

from machdyn.cli import app as cli_app
from machdyn.studio.app import MAX_BODY, create_app
from machdyn.studio.fields import edited_text
from machdyn.studio.session import Studio

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
TOKEN = "test-token-0123456789"
H = {"X-Studio-Token": TOKEN}


@pytest.fixture
def four_bar(tmp_path) -> Path:
    path = tmp_path / "four_bar.toml"
    shutil.copy(EXAMPLES / "four_bar.toml", path)
    return path


@pytest.fixture
def client(four_bar):
    with TestClient(create_app(Studio(four_bar), TOKEN)) as c:
        yield c


def _check_output(path: Path, text: str) -> str:
    """What ``machdyn check`` prints (stdout and stderr) for this text written at ``path`` (the studio's file:
    the message names it; the studio keeps the text it read)."""
    path.write_text(text, encoding="utf-8")
    done = CliRunner().invoke(cli_app, ["check", str(path)])
    assert done.exit_code == 2
    return done.output


def test_the_token_is_required_on_every_request(client):
    assert client.get("/").status_code == 403
    assert client.get("/?token=wrong").status_code == 403
    assert client.get("/api/state").status_code == 403
    assert client.post("/api/evaluate", json={"values": {}}, headers={"X-Studio-Token": "x"}).status_code == 403
    page = client.get(f"/?token={TOKEN}")
    assert page.status_code == 200 and "machdyn studio" in page.text
    # no network resource: no tag or style loads one, and the page's calls go to its own server (paths only)
    assert not re.search(r"""(src|href)\s*=\s*["']?(https?:)?//|url\(\s*["']?https?:|@import""", page.text)
    called = re.findall(r"""(?:api|fetch)\(\s*(?:full \? "/api/full" : )?["']([^"']*)""", page.text)
    assert sorted(called) == ["/api/compare", "/api/evaluate", "/api/save", "/api/state", "/api/variant"]
    assert "default-src 'none'" in page.headers["content-security-policy"]
    assert client.get("/api/state", headers=H).json()["editable"] is True


def test_a_request_body_over_the_bound_is_refused(client):
    big = {"values": {"mechanism.crank.length": "4" * (MAX_BODY + 10)}}
    response = client.post("/api/evaluate", json=big, headers=H)
    assert response.status_code == 413 and "64 KiB" in response.json()["message"]


def test_an_edit_recomputes_the_peak_driving_torque(client):
    state = client.get("/api/state", headers=H).json()
    before = state["result"]
    keys = {f["key"]: f for f in state["fields"]}
    assert keys["mechanism.crank.length"]["unit"] == "mm" and keys["mechanism.crank.length"]["number"] == "40"
    after = client.post("/api/evaluate", json={"values": {"mechanism.crank.length": "50"}}, headers=H).json()
    assert after["ok"] and after["compute_ms"] > 0
    # a longer crank at the same speed drives the same loads through larger motions: more torque
    assert after["peak_torque"] > before["peak_torque"] * 1.05
    # the peak the page shows is the summary's own max |T| (two routes to one number)
    row = next(r for r in after["summary"] if r["label"] == "Driving torque, max |T|")
    assert row["value"] == pytest.approx(after["peak_torque"], rel=1e-12)
    crank_pin = after["scene"]["points"]["crank.A"]
    assert max(abs(x) for x in crank_pin[0]) == pytest.approx(0.050, rel=1e-4)  # the view moved with the edit


@pytest.mark.parametrize(("value", "path"), [("-5", "mechanism.crank.length"), ("95", "mechanism")])
def test_a_bad_value_answers_the_check_message_and_keeps_the_last_valid_machine(client, four_bar, value, path):
    good = client.post("/api/evaluate", json={"values": {"mechanism.crank.length": "42"}}, headers=H).json()
    bad = client.post("/api/evaluate", json={"values": {"mechanism.crank.length": value}}, headers=H).json()
    assert not bad["ok"] and bad["problems"][0]["path"] == path
    edited = edited_text(four_bar.read_text(), {"mechanism.crank.length": value})
    shown = _check_output(four_bar, edited).strip()
    assert bad["message"] == shown  # the very text `machdyn check` prints for the same file
    state = client.get("/api/state", headers=H).json()["result"]
    assert state["ok"] and state["peak_torque"] == good["peak_torque"]


def test_save_keeps_the_comments_and_changes_only_the_edited_value(client, four_bar):
    before = four_bar.read_text()
    saved = client.post("/api/save", json={"values": {"mechanism.ground.angle": "5"}}, headers=H).json()
    assert saved == {"ok": True, "saved": "four_bar.toml", "fields": saved["fields"]}
    after = four_bar.read_text()
    changed = [d for d in difflib.ndiff(before.splitlines(), after.splitlines()) if d[:2] in ("- ", "+ ")]
    assert changed == [
        '- angle = "0 deg"                    # direction from the crank pivot O to the rocker pivot D',
        '+ angle = "5 deg"                    # direction from the crank pivot O to the rocker pivot D',
    ]
    assert next(f for f in saved["fields"] if f["key"] == "mechanism.ground.angle")["number"] == "5"


def test_save_under_a_new_name_stays_in_the_folder(client, four_bar):
    original = four_bar.read_text()
    for name in ("../escape.toml", "sub/x.toml", "/tmp/x.toml", "x.txt", "..", "a\\b.toml"):
        response = client.post("/api/save", json={"values": {}, "name": name}, headers=H)
        assert response.status_code == 400 and "folder" in response.json()["message"], name
    assert not (four_bar.parent.parent / "escape.toml").exists()
    ok = client.post("/api/save", json={"values": {"mechanism.rocker.length": "105"}, "name": "variant.toml"},
                     headers=H).json()
    assert ok["saved"] == "variant.toml"
    assert 'length = "105 mm"' in (four_bar.parent / "variant.toml").read_text()
    assert four_bar.read_text() == original


def test_a_machine_with_mistakes_is_not_saved(client, four_bar):
    original = four_bar.read_text()
    response = client.post("/api/save", json={"values": {"mechanism.crank.length": "-1"}}, headers=H)
    assert response.status_code == 400 and "must be > 0 m" in response.json()["message"]
    assert four_bar.read_text() == original


def test_unknown_fields_and_bodies_that_are_not_json_are_refused(client):
    assert client.post("/api/evaluate", json={"values": {"meta.name": "1"}}, headers=H).status_code == 400
    assert client.post("/api/evaluate", content=b"{not json", headers=H).status_code == 400
    assert client.post("/api/evaluate", json={"values": [1]}, headers=H).status_code == 400
    long = client.post("/api/evaluate", json={"values": {"mechanism.crank.length": "1" * 41}}, headers=H)
    assert long.status_code == 400 and "at most 40 characters" in long.json()["message"]


def test_a_computation_over_its_time_bound_is_answered(four_bar):
    with TestClient(create_app(Studio(four_bar), TOKEN, compute_seconds=1e-6)) as slow:
        response = slow.post("/api/evaluate", json={"values": {"mechanism.crank.length": "41"}}, headers=H)
    assert response.status_code == 503 and "longer than" in response.json()["message"]


def test_the_drag_rules_name_the_fields_that_define_the_dragged_points(client):
    drags = client.get("/api/state", headers=H).json()["result"]["drags"]
    rules = {tuple(r["points"]): [(s["key"], s["measure"], s["from"]) for s in r["set"]] for r in drags}
    assert rules[("ground:D",)] == [("mechanism.ground.length", "distance", "ground:O"),
                                    ("mechanism.ground.angle", "angle", "ground:O")]
    assert rules[("coupler.B", "rocker.B")] == [("mechanism.coupler.length", "distance", "coupler.A"),
                                                ("mechanism.rocker.length", "distance", "ground:D")]


def test_other_kinds_open_read_only_with_their_report(tmp_path):
    path = tmp_path / "conveyor.toml"
    shutil.copy(EXAMPLES / "conveyor_lift_torque.toml", path)
    with TestClient(create_app(Studio(path), TOKEN)) as c:
        state = c.get("/api/state", headers=H).json()
        assert state["editable"] is False and state["kind"] == "screw_conveyor"
        assert state["result"]["ok"] and state["result"]["summary"]
        assert c.post("/api/evaluate", json={"values": {}}, headers=H).status_code == 400
        assert c.post("/api/save", json={"values": {}}, headers=H).status_code == 400
        report = c.get("/report", headers=H)
        assert report.status_code == 200 and "<html" in report.text.lower()
    assert path.read_text() == (EXAMPLES / "conveyor_lift_torque.toml").read_text()


@pytest.mark.parametrize(("old", "new"), [('"0.25 kg"', '"-0.25 kg"'), ('length = "40 mm"', 'length = "40 mm'),
                                          ('length = "40 mm"', 'length = "95 mm"')])
def test_the_command_refuses_a_file_with_mistakes_as_check_does(tmp_path, old, new):
    path = tmp_path / "bad.toml"
    path.write_text((EXAMPLES / "four_bar.toml").read_text().replace(old, new, 1))
    done = CliRunner().invoke(cli_app, ["studio", str(path), "--no-open", "--port", "0"])
    checked = CliRunner().invoke(cli_app, ["check", str(path)])
    assert done.exit_code == checked.exit_code == 2
    assert done.output == checked.output  # the same lines, and no URL: nothing is served


def test_the_command_prints_its_url_first_serves_it_and_stops_cleanly_on_ctrl_c(four_bar):
    env = {**os.environ, "PYTHONPATH": str(Path(__file__).resolve().parents[2] / "src")}
    proc = subprocess.Popen([sys.executable, "-m", "machdyn.cli", "studio", str(four_bar), "--no-open", "--port",
                             "0"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    try:
        url = proc.stdout.readline().strip()  # the first line of output, before the server runs
        assert re.fullmatch(r"http://127\.0\.0\.1:\d+/\?token=[A-Za-z0-9_-]{32}", url), url
        deadline = time.monotonic() + 30
        while True:  # the server listens a moment after the URL is printed
            try:
                with urllib.request.urlopen(url, timeout=5) as page:
                    assert page.status == 200 and "machdyn studio" in page.read().decode()
                break
            except urllib.error.URLError:
                assert time.monotonic() < deadline, "the studio did not start listening"
                time.sleep(0.05)
        with pytest.raises(urllib.error.HTTPError) as refused:
            urllib.request.urlopen(url.split("?")[0], timeout=5)
        assert refused.value.code == 403
        refused.value.close()
        proc.send_signal(signal.SIGINT)
        assert proc.wait(timeout=15) == 0
    finally:
        if proc.poll() is None:
            proc.kill()
        proc.communicate()


def test_a_port_in_use_is_said_plainly(four_bar):
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        done = CliRunner().invoke(cli_app, ["studio", str(four_bar), "--no-open", "--port", str(port)])
    assert done.exit_code == 1
    assert f"cannot listen on 127.0.0.1:{port}" in done.output and "http://" not in done.output
