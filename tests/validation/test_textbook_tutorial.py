"""The textbook tutorial (docs/textbook-examples.md) runs as written and prints what it shows.

Each ``python`` block is run in order in one namespace; the ``text`` block right after it is the output it must
print. The published values the tutorial quotes are checked with their tolerances in
test_textbook_slider_crank.py and test_textbook_flywheel.py.
"""

import contextlib
import io
import re
from pathlib import Path

TUTORIAL = Path(__file__).resolve().parents[2] / "docs" / "textbook-examples.md"
BLOCK = re.compile(r"```(python|text)\n(.*?)```", re.DOTALL)


def test_tutorial_blocks_print_what_the_tutorial_shows():
    blocks = BLOCK.findall(TUTORIAL.read_text(encoding="utf-8"))
    assert sum(kind == "python" for kind, _ in blocks) >= 6
    namespace: dict = {}
    pending = None
    for kind, body in blocks:
        if kind == "python":
            assert pending is None, f"a python block shows no output:\n{pending}"
            out = io.StringIO()
            with contextlib.redirect_stdout(out):
                exec(compile(body, str(TUTORIAL), "exec"), namespace)  # noqa: S102 - the documentation's own code
            pending = (body, out.getvalue())
        else:
            assert pending is not None, f"an output block follows no code:\n{body}"
            code, printed = pending
            assert printed == body, f"the block\n{code}\nprints\n{printed}\nbut the tutorial shows\n{body}"
            pending = None
    assert pending is None
