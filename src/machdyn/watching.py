"""``machdyn watch``: run a problem file again each time it is saved.

The loop looks at the file's modification time, size and content (a SHA-256 digest, so that a save that keeps
the size within the same clock tick is seen too) every ``interval`` seconds; a change starts a new run,
whose outputs carry a new stamp in ``report.stamp.js``. An open report polls that file and re-loads itself when
the stamp changes, keeping its crank angle (see ``report/templates/report.html.j2``). A run that fails (a mistake
in the file) leaves the previous outputs in place; the next save tries again.
"""

from __future__ import annotations

import hashlib
import time
from collections.abc import Callable
from pathlib import Path

import typer

#: A problem file is at most 1 MiB (docs/problem-files.md): a larger one is not hashed, its run refuses it.
_MAX_HASHED = 1 << 20

#: What the line after a run that wrote nothing says, by exit code: only bad input (2) is the file's to fix.
NOT_UPDATED = {
    1: "the run failed (the message above says why); the previous outputs stay, save the file to run it again",
    2: "fix the file and save it again",
    4: "an internal error (the message above says where its traceback is); save the file to run it again",
}


def _signature(file: Path) -> tuple[int, int, str] | None:
    """The file's modification time [ns], size [bytes] and content digest, or None if it cannot be read."""
    try:
        info = file.stat()
        if info.st_size > _MAX_HASHED:
            return info.st_mtime_ns, info.st_size, ""
        digest = hashlib.sha256(file.read_bytes()).hexdigest()
    except OSError:
        return None
    return info.st_mtime_ns, info.st_size, digest


def unwatchable(file: Path) -> str | None:
    """Why ``file`` cannot be watched (standard input, a path that is no file), or None."""
    if str(file) == "-":
        return "standard input cannot be watched; give the problem file's path"
    if not file.is_file():
        return f"the problem file '{file}' {'is not a file' if file.exists() else 'does not exist'}; nothing to watch"
    return None


def watch_file(file: Path, out: Path, *, interval: float, run: Callable[[str], int],
               opened: Callable[[], None] | None = None, max_runs: int | None = None) -> int:
    """Run ``run(stamp)`` now and after every change of ``file``; returns the number of runs made.

    Parameters
    ----------
    file : the problem file watched.
    out : the output folder (named in the messages).
    interval : seconds between looks at the file [s].
    run : one run; returns its exit code (0 success, 3 a failed design check: both write the outputs).
    opened : called once, after the first run that wrote a report (``--open``).
    max_runs : stop after this many runs (for tests; None: until interrupted).
    """
    seen: tuple[int, int, str] | None = None
    runs = 0
    while max_runs is None or runs < max_runs:
        now = _signature(file)
        if now is not None and now != seen:
            seen = now
            runs += 1
            started = time.perf_counter()
            code = run(f"{time.time_ns()}-{runs}")
            took = time.perf_counter() - started
            if code in (0, 3):
                typer.echo(f"[{time.strftime('%H:%M:%S')}] {file.name}: report updated in {out}/ ({took:.2f} s)"
                           + (", a design check failed" if code == 3 else ""), err=True)
                if opened is not None:
                    opened()
                    opened = None
            else:
                typer.echo(f"[{time.strftime('%H:%M:%S')}] {file.name}: not updated (exit {code}); "
                           f"{NOT_UPDATED.get(code, 'save the file to run it again')}", err=True)
        elif now is None and seen is not None:
            typer.echo(f"{file} is gone; waiting for it", err=True)
            seen = None
        time.sleep(interval)
    return runs
