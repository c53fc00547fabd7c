"""Variants of a studio session: kept under a name (a valid machine only), compared two at a time with the
fields that differ and each common result's difference."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from starlette.testclient import TestClient

from machdyn.studio.app import create_app
from machdyn.studio.session import Studio

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
TOKEN = "variants-token"
H = {"X-Studio-Token": TOKEN}


@pytest.fixture
def client(tmp_path):
    path = tmp_path / "four_bar.toml"
    shutil.copy(EXAMPLES / "four_bar.toml", path)
    return TestClient(create_app(Studio(path), TOKEN))


def test_two_variants_side_by_side_with_their_differences(client):
    assert client.post("/api/variant", json={"name": "base", "values": {}}, headers=H).json()["variants"] == ["base"]
    kept = client.post("/api/variant", json={"name": "long crank", "values": {"mechanism.crank.length": "45"}},
                       headers=H).json()
    assert kept["variants"] == ["base", "long crank"]
    both = client.post("/api/compare", json={"a": "base", "b": "long crank"}, headers=H).json()
    assert both["fields"] == [{"key": "mechanism.crank.length", "a": "40", "b": "45"}]
    rows = {r["label"]: r for r in both["rows"]}
    peak = rows["Driving torque, max |T|"]
    # each column is the variant's own answer; the difference is theirs
    assert peak["a"] == pytest.approx(both["a"]["answer"]["peak_torque"], rel=1e-9)
    assert peak["b"] == pytest.approx(both["b"]["answer"]["peak_torque"], rel=1e-9)
    assert peak["difference"] == pytest.approx(peak["b"] - peak["a"]) and peak["difference"] > 0
    assert peak["relative"] == pytest.approx(peak["difference"] / peak["a"])
    # the scenes of both machines travel with the comparison (the page draws them at one scale)
    assert both["a"]["answer"]["scene"]["extent"] != both["b"]["answer"]["scene"]["extent"]


@pytest.mark.parametrize(("body", "said"), [
    ({"name": "bad", "values": {"mechanism.crank.length": "-5"}}, "must be > 0 m; got '-5 mm'"),
    ({"name": "../up", "values": {}}, "a variant's name is 1 to 40 letters"),
    ({"name": "x", "values": {"nope": "1"}}, "'nope' is not an editable quantity"),
])
def test_a_variant_with_mistakes_or_a_bad_name_is_not_kept(client, body, said):
    answer = client.post("/api/variant", json=body, headers=H)
    assert answer.status_code == 400 and said in answer.json()["message"]
    missing = client.post("/api/compare", json={"a": "bad", "b": "x"}, headers=H).json()
    assert not missing["ok"] and "no variant named 'bad'; kept: none" in missing["message"]
