"""``machdyn watch``: run a problem file again each time it is saved.

The loop looks at the file's modification time, size and content (a SHA-256 digest, so that a save that keeps
the size within the same clock tick is seen too) every ``interval`` seconds; a change starts a new run,
whose outputs carry a new stamp in ``report.stamp.js``. An open report polls that file and re-loads itself when
the stamp changes, keeping its crank angle (see ``report/templates/report.html.j2``). A run that fails (a mistake
in the file) leaves the previous outputs in place and says so as ``machdyn studio`` does: the terminal prints the
banner *Last valid results shown* under the check's messages, and ``report.stamp.js`` keeps the last valid run's
stamp and adds the messages, which the open report shows in place in the same banner (without re-loading: its
results are the last valid ones). The next save tries again; a valid run writes a stamp without messages.
"""

from __future__ import annotations

import hashlib
import json
import re
import time
from collections.abc import Callable
from pathlib import Path

import typer

from .outputs import STAMP_FILE, atomic_write_text, stamp_script

#: A problem file is at most 1 MiB (docs/problem-files.md): a larger one is not hashed, its run refuses it.
_MAX_HASHED = 1 << 20

#: What the line after a run that wrote nothing says, by exit code: only bad input (2) is the file's to fix.
NOT_UPDATED = {
    1: "the run failed (the message above says why); the previous outputs stay, save the file to run it again",
    2: "fix the file and save it again",
    4: "an internal error (the message above says where its traceback is); save the file to run it again",
}


#: What the terminal and the report say over the last valid results while the saved file cannot be run.
BANNER = "Last valid results shown."
#: what a run gives back: its exit code, or its exit code and the message it printed
RunAnswer = int | tuple[int, str | None]


def _stamp_of(out: Path) -> str | None:
    """The stamp of the report in ``out`` (None where there is none)."""
    try:
        found = re.match(r'window\.machdynStamp = ("(?:[^"\\]|\\.)*");', (out / STAMP_FILE).read_text())
    except OSError:
        return None
    return json.loads(found.group(1)) if found else None


def mark_invalid(out: Path, message: str, at: str) -> bool:
    """Keep the report in ``out`` and mark it as the last valid one, with the messages of the save that failed;
    False where ``out`` holds no watched report."""
    stamp = _stamp_of(out)
    if stamp is None or not (out / "report.html").is_file():
        return False
    atomic_write_text(out / STAMP_FILE, stamp_script(stamp, {"message": message, "at": at}))
    return True


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


def watch_file(file: Path, out: Path, *, interval: float, run: Callable[[str], RunAnswer],
               opened: Callable[[], None] | None = None, max_runs: int | None = None) -> int:
    """Run ``run(stamp)`` now and after every change of ``file``; returns the number of runs made.

    Parameters
    ----------
    file : the problem file watched.
    out : the output folder (named in the messages).
    interval : seconds between looks at the file [s].
    run : one run; returns its exit code (0 success, 3 a failed design check: both write the outputs), or its exit
        code and the message it printed (for the banner over the last valid results).
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
            answer = run(f"{time.time_ns()}-{runs}")
            code, message = answer if isinstance(answer, tuple) else (answer, None)
            took = time.perf_counter() - started
            if code in (0, 3):
                typer.echo(f"[{time.strftime('%H:%M:%S')}] {file.name}: report updated in {out}/ ({took:.2f} s)"
                           + (", a design check failed" if code == 3 else ""), err=True)
                if opened is not None:
                    opened()
                    opened = None
            else:
                at = time.strftime('%H:%M:%S')
                typer.echo(f"[{at}] {file.name}: not updated (exit {code}); "
                           f"{NOT_UPDATED.get(code, 'save the file to run it again')}", err=True)
                if code in (1, 2) and message:
                    why = "has mistakes" if code == 2 else "could not be run"
                    kept = (f"{out}/ keeps the last valid run, marked so in its open report"
                            if mark_invalid(out, message, at) else f"no valid run in {out}/ yet")
                    typer.echo(f"  {BANNER} The saved file {why} (above); {kept}.", err=True)
        elif now is None and seen is not None:
            typer.echo(f"{file} is gone; waiting for it", err=True)
            seen = None
        time.sleep(interval)
    return runs
