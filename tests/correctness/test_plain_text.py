"""Text of a problem file (names, labels, file names) is plain: a control character or a bidirectional override
is refused by ``check`` and ``run`` alike, naming the field, instead of reaching the report's plots and tables."""

from __future__ import annotations

import pytest

from .helpers import EXAMPLES, check_and_run

TAMPER = (EXAMPLES / "tamper_on_tyres.toml").read_text(encoding="utf-8")


@pytest.mark.parametrize(("character", "code"), [("\\u0000", "U+0000"), ("\\u001b", "U+001B"),
                                                 ("\\u202e", "U+202E")])
def test_control_characters_in_labels_are_refused(tmp_path, character, code):
    text = TAMPER.replace('label = "before balancing"', f'label = "before{character} balancing"', 1)
    check, run = check_and_run(tmp_path, text)
    assert (check.code, run.code) == (2, 2), (check, run)
    for said in (check, run):
        assert f"frame.label: must be plain text; it contains the control character {code}" in said.stderr


def test_line_breaks_and_accents_stay_allowed(tmp_path):
    text = TAMPER.replace('label = "before balancing"', 'label = "avant équilibrage\\tà 20 Hz"', 1)
    check, _run = check_and_run(tmp_path, text)
    assert check.code == 0, check
