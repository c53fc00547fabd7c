"""The tutorial (docs/tutorial.md) runs as written, states what it computes, and covers every capability.

Every ``python`` block of the page is run in order in one namespace, as a notebook would, in a temporary working
directory (the page writes a report under ``out/``). The values the text states are the blocks' own ``assert``
statements, so a block that stops agreeing with its text fails here, naming its section.
"""

from __future__ import annotations

import re
import time
from pathlib import Path

import pytest

DOCS = Path(__file__).resolve().parents[2] / "docs"
TUTORIAL = DOCS / "tutorial.md"
BLOCK = re.compile(r"^```python\n(.*?)^```", re.DOTALL | re.MULTILINE)
HEADING = re.compile(r"^## (.*)$", re.MULTILINE)


def _blocks() -> list[tuple[str, str]]:
    """(section heading, code) of every python block, in page order."""
    text = TUTORIAL.read_text(encoding="utf-8")
    headings = [(m.start(), m.group(1)) for m in HEADING.finditer(text)]
    found = []
    for match in BLOCK.finditer(text):
        section = next((title for start, title in reversed(headings) if start < match.start()), "(top)")
        found.append((section, match.group(1)))
    return found


def test_every_block_checks_what_the_text_states() -> None:
    blocks = _blocks()
    assert len(blocks) >= 20
    silent = [section for section, code in blocks if "assert " not in code]
    assert not silent, f"blocks without an assert of the value their text states, in sections: {silent}"


def test_every_problem_kind_and_capability_table_has_a_section() -> None:
    from machdyn.kinds import CAPABILITIES, KINDS

    headings = " ".join(HEADING.findall(TUTORIAL.read_text(encoding="utf-8")))
    missing = [name for name in sorted(set(KINDS) | set(CAPABILITIES)) if f"`[{name}]`" not in headings]
    assert not missing, f"tables with no section of the tutorial: {missing}"


def test_links_to_other_pages_exist() -> None:
    links = set(re.findall(r"\]\(([\w.-]+\.md)\)", TUTORIAL.read_text(encoding="utf-8")))
    assert links, "the tutorial links to the capability pages"
    assert not [link for link in sorted(links) if not (DOCS / link).is_file()]


def test_the_tutorial_runs_in_order_and_agrees_with_its_text(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                              capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.chdir(tmp_path)
    namespace: dict[str, object] = {"__name__": "tutorial"}
    started = time.perf_counter()
    for number, (section, code) in enumerate(_blocks(), start=1):
        try:
            exec(compile(code, f"docs/tutorial.md block {number}", "exec"), namespace)
        except Exception as error:  # name the section whose text no longer holds
            raise AssertionError(f"block {number} in section '{section}' failed: {error!r}\n{code}") from error
    elapsed = time.perf_counter() - started
    capsys.readouterr()
    assert (tmp_path / "out" / "compressor" / "results.json").is_file()
    assert elapsed < 60.0, f"the tutorial took {elapsed:.1f} s; its examples must stay small"
