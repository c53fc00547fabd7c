"""The ``machdyn`` command: run and check problem files, copy out the shipped examples.

Exit codes: 0 success; 1 the analysis failed on a valid problem, or an operational failure (a scheduler that does
not answer, a full disk, a folder that may not be written, another run on the same folder, an exploration store
of another problem file without ``--replace``, --max-time reached);
2 bad input (the problem file, the command line); 3 the design fails one of its checks (the outputs are
written and the failed checks listed); 4 an internal error (a short message; the traceback goes to a log file,
or to the terminal with ``--debug``). Messages go to stderr, without a traceback. Heavy libraries (pandas,
matplotlib) are imported only when a command needs them.
"""

from __future__ import annotations

import contextlib
import sys
import threading
import time
from enum import StrEnum
from pathlib import Path
from typing import Annotated, Any

import typer

from . import __version__

EXIT_OK, EXIT_FAILED, EXIT_BAD_INPUT, EXIT_CHECKS_FAILED, EXIT_INTERNAL = 0, 1, 2, 3, 4

EXIT_CODES_HELP = (
    "Exit codes: 0 success; 1 the analysis failed or the outputs could not be written (a locked folder, another "
    "file's store without --replace, --max-time); 2 bad input; 3 the design fails a check (an infeasible "
    "optimisation included); 4 internal error."
)

app = typer.Typer(
    name="machdyn",
    help="Analyse machine mechanisms and bulk-material machinery from problem files (TOML with units). "
    + EXIT_CODES_HELP,
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    rich_markup_mode=None,
)


FileArg = Annotated[Path, typer.Argument(help="The problem file (TOML).", show_default=False, metavar="FILE")]


class TableFormat(StrEnum):
    table = "table"
    csv = "csv"
    json = "json"
    markdown = "markdown"


def _console(stderr: bool = False):
    from rich.console import Console

    return Console(stderr=stderr, highlight=False, soft_wrap=False)


def _fail(message: str, code: int) -> typer.Exit:
    typer.echo(message, err=True)
    done = typer.Exit(code)
    done.message = message  # type: ignore[attr-defined]  # for watch's banner over the last valid results
    return done


def _version(value: bool) -> None:
    if value:
        typer.echo(f"machdyn {__version__}")
        raise typer.Exit(EXIT_OK)


@app.callback()
def main(
    version: Annotated[
        bool, typer.Option("--version", callback=_version, is_eager=True, help="Print the version and exit.")
    ] = False,
) -> None:
    """machdyn: exact planar linkage kinematics, kinetostatics and energy; screw conveyors."""


# ----------------------------------------------------------------------------------------- progress


class Progress:
    """A progress bar on stderr that appears only once a run has taken more than ``delay`` seconds."""

    def __init__(self, steps: list[str], enabled: bool, delay: float = 1.0):
        self.steps = steps
        self.enabled = enabled
        self.delay = delay
        self._bar: Any = None
        self._task: Any = None
        self._done = 0
        self._label = "starting"
        self._lock = threading.Lock()
        self._timer: threading.Timer | None = None

    def __enter__(self) -> Progress:
        if self.enabled:
            self._timer = threading.Timer(self.delay, self._show)
            self._timer.daemon = True
            self._timer.start()
        return self

    def _show(self) -> None:
        from rich.progress import BarColumn, TextColumn, TimeElapsedColumn
        from rich.progress import Progress as RichProgress

        with self._lock:
            if self._bar is not None or self._timer is None:
                return
            self._bar = RichProgress(
                TextColumn("{task.description:<16}"), BarColumn(), TextColumn("{task.completed}/{task.total}"),
                TimeElapsedColumn(), console=_console(stderr=True), transient=True,
            )
            self._task = self._bar.add_task(self._label, total=len(self.steps), completed=self._done)
            self._bar.start()

    def step(self, label: str) -> None:
        with self._lock:
            if label in self.steps:
                self._done = self.steps.index(label)
            self._label = label
            if self._bar is not None:
                self._bar.update(self._task, description=label, completed=self._done)

    def __exit__(self, *exc: Any) -> None:
        with self._lock:
            if self._timer is not None:
                self._timer.cancel()
                self._timer = None
            if self._bar is not None:
                self._bar.update(self._task, completed=len(self.steps))
                self._bar.stop()
                self._bar = None


# --------------------------------------------------------------------------------------------- tables


# ------------------------------------------------------------------------------------------- commands


def _load(file: Path):
    """The loaded problem of a file, or exit 2 with every problem listed."""
    from .errors import ProblemFileError
    from .reading import read_problem

    try:
        return read_problem(file)
    except ProblemFileError as exc:
        raise _fail(str(exc), EXIT_BAD_INPUT) from None


def _engine_error(exc: Exception, file: Path) -> typer.Exit:
    from .errors import InputError, ProblemFileError, input_problems

    if isinstance(exc, InputError):  # the same lines the studio shows beside a field
        return _fail(str(ProblemFileError(input_problems(exc), exc.source if isinstance(exc, ProblemFileError)
                                          else str(file))), EXIT_BAD_INPUT)
    return _fail(f"error: the analysis of {file} failed: {type(exc).__name__}: {exc}", EXIT_FAILED)


def _internal_error(exc: BaseException, debug: bool) -> typer.Exit:
    """A short message for an unexpected exception; the traceback goes to a log file (or the terminal)."""
    import tempfile
    import traceback

    text = "".join(traceback.format_exception(exc))
    if debug:
        typer.echo(text, err=True)
        return _fail(f"internal error: {type(exc).__name__}: {exc}", EXIT_INTERNAL)
    try:
        with tempfile.NamedTemporaryFile("w", prefix="machdyn-error-", suffix=".log", delete=False) as log:
            log.write(text)
        where = f"; the traceback is in {log.name}"
    except OSError:
        where = ""
    return _fail(f"internal error: {type(exc).__name__}: {exc}{where} (run with --debug to show it). "
                 "Please report it with the problem file.", EXIT_INTERNAL)


DebugOpt = Annotated[bool, typer.Option("--debug", help="Show the traceback of an internal error.")]


@app.command(epilog=EXIT_CODES_HELP)
def run(
    file: FileArg,
    out: Annotated[
        Path, typer.Option("--out", "-o", help="Directory for results.json, the CSV files and report.html.")
    ] = Path("out"),
    format: Annotated[
        TableFormat, typer.Option("--format", "-f", help="How the summary table is printed.")
    ] = TableFormat.table,
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="Print nothing but errors.")] = False,
    workers: Annotated[
        int | None, typer.Option("--workers", min=1, max=512, show_default=False,
                                 help="Run a design-space exploration on a local Dask cluster of N worker processes.")
    ] = None,
    scheduler: Annotated[
        str | None, typer.Option("--scheduler", metavar="ADDRESS", show_default=False,
                                 help="Run a design-space exploration on the Dask scheduler at ADDRESS "
                                      "(tcp://host:8786).")
    ] = None,
    open_report: Annotated[bool, typer.Option("--open", help="Open report.html in the web browser.")] = False,
    max_time: Annotated[
        float | None, typer.Option("--max-time", min=1.0, metavar="SECONDS", show_default=False,
                                   help="Stop the run after SECONDS (exit 1; the partitions of an exploration "
                                        "finished by then are kept, and a rerun resumes from them).")
    ] = None,
    replace: Annotated[bool, typer.Option("--replace", help="Replace an exploration store that is not this "
                                          "file's (another file's, or partitions without a manifest).")] = False,
    debug: DebugOpt = False,
) -> None:
    """Analyse a problem file, print a summary table and write the outputs."""
    if workers is not None and scheduler is not None:
        raise _fail("error: give --workers or --scheduler, not both", EXIT_BAD_INPUT)
    _check_where(workers, scheduler)
    try:
        from .studies.exploration.execution import execution

        with execution(workers=workers, scheduler=scheduler, store=out / "sweep.parquet", replace=replace), \
                _run_guard(out, max_time):
            _run(file, out, format, quiet)
    except typer.Exit as done:
        if open_report and done.exit_code == EXIT_CHECKS_FAILED:  # the outputs are written: show them
            _open_in_browser(out / "report.html")
        raise
    except KeyboardInterrupt as stop:
        raise _interrupted(stop, out) from None
    except Exception as exc:  # noqa: BLE001 - anything unexpected becomes exit 4 without a traceback
        raise _internal_error(exc, debug) from None


    if open_report:
        _open_in_browser(out / "report.html")


def _interrupted(stop: KeyboardInterrupt, out: Path) -> typer.Exit:
    """Ctrl-C during ``run``: say what is on disk and how to go on; exit 130 (128 + SIGINT), as shells do."""
    said = getattr(stop, "message", None)
    kept = f"the outputs in {out}/ were not replaced (a run writes them as one set at its end)"
    return _fail(f"interrupted: {said}; {kept}" if said else f"interrupted: {kept}", 130)


def _check_where(workers: int | None, scheduler: str | None) -> None:
    """Exit 2 for a scheduler address that is none, or more local workers than the machine allows."""
    if scheduler is not None:
        from .studies.table import scheduler_address_error

        problem = scheduler_address_error(scheduler)
        if problem is not None:
            raise _fail(f"error: --scheduler {problem}", EXIT_BAD_INPUT)
    if workers is not None:
        from .studies.exploration.execution import workers_error

        problem = workers_error(workers)
        if problem is not None:
            raise _fail(f"error: --workers {problem}", EXIT_BAD_INPUT)


class _Terminated(KeyboardInterrupt):
    """SIGTERM, turned into an interruption so that a terminated run cleans up as after Ctrl-C."""


class _TimedOut(KeyboardInterrupt):
    """--max-time elapsed, turned into an interruption so that the run cleans up as after Ctrl-C."""


@contextlib.contextmanager
def _run_guard(out: Path, max_time: float | None = None):
    """Hold the output folder's lock for the whole run (a second run on it exits 1 at once), turn SIGTERM and
    the end of ``max_time`` [s] into an interruption, so that staging folders are removed; an operational
    failure exits 1 in one line."""
    import signal

    from .errors import OperationalError
    from .outputs import lock_folder, unlock_folder

    try:
        created = lock_folder(out)
    except OperationalError as exc:
        raise _fail(f"error: {exc}", EXIT_FAILED) from None

    def terminated(signum, frame):
        raise _Terminated()

    def timed_out(signum, frame):
        raise _TimedOut()

    previous = alarm = None
    if threading.current_thread() is threading.main_thread():
        previous = signal.signal(signal.SIGTERM, terminated)
        if max_time is not None:
            alarm = signal.signal(signal.SIGALRM, timed_out)
            signal.setitimer(signal.ITIMER_REAL, max_time)
    try:
        yield
    except OperationalError as exc:
        raise _fail(f"error: {exc}", EXIT_FAILED) from None
    except KeyboardInterrupt as stop:
        said = getattr(stop, "message", None)  # an exploration's: what is on disk and that a rerun resumes
        from .studies.exploration.execution import RESTARTS

        kept = said or RESTARTS
        if isinstance(stop, _TimedOut) or isinstance(stop.__cause__, _TimedOut):
            raise _fail(f"stopped: the run took longer than --max-time {max_time:g} s; {kept}", EXIT_FAILED) from None
        if not isinstance(stop, _Terminated) and not isinstance(stop.__cause__, _Terminated):
            raise  # Ctrl-C: said by run's own handler
        raise _fail(f"stopped: the run was terminated; {kept}", 143) from None
    finally:
        if alarm is not None:
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, alarm)
        if previous is not None:
            signal.signal(signal.SIGTERM, previous)
        unlock_folder(out, created)  # the folder removed only if the run created it and left it empty


def _open_in_browser(report: Path) -> None:
    """Open the report in the user's web browser (a message, not a failure, where there is none)."""
    import webbrowser

    if not (report.is_file() and webbrowser.open(report.resolve().as_uri())):
        typer.echo(f"note: could not open a web browser; the report is {report}", err=True)


@app.command(epilog=EXIT_CODES_HELP)
def watch(
    file: FileArg,
    out: Annotated[
        Path, typer.Option("--out", "-o", help="Directory for results.json, the CSV files and report.html.")
    ] = Path("out"),
    open_report: Annotated[bool, typer.Option("--open", help="Open report.html in the web browser.")] = False,
    interval: Annotated[float, typer.Option("--interval", min=0.1, max=60.0,
                                            help="Seconds between looks at the file.")] = 0.5,
    debug: DebugOpt = False,
) -> None:
    """Run the problem file again each time it is saved; an open report re-loads itself. Stop with Ctrl-C.

    A file with mistakes is reported and the previous outputs stay until it is fixed. The output folder is
    locked while watching: another run on it is refused."""
    from .errors import OperationalError
    from .outputs import lock_folder, unlock_folder
    from .watching import unwatchable, watch_file

    if (why := unwatchable(file)) is not None:
        raise _fail(f"error: {why}", EXIT_BAD_INPUT)
    try:
        created = lock_folder(out)
    except OperationalError as exc:
        raise _fail(f"error: {exc}", EXIT_FAILED) from None
    try:
        watch_file(file, out, interval=interval, run=lambda stamp: _watched_run(file, out, stamp),
                   opened=(lambda: _open_in_browser(out / "report.html")) if open_report else None)
    except KeyboardInterrupt:
        typer.echo("stopped watching", err=True)
    except Exception as exc:  # noqa: BLE001 - anything unexpected becomes exit 4 without a traceback
        raise _internal_error(exc, debug) from None
    finally:
        unlock_folder(out, created)


def _watched_run(file: Path, out: Path, stamp: str) -> tuple[int, str | None]:
    """One run of ``machdyn watch``: the exit code ``run`` would give and the message it printed (printed as
    ``run`` prints it)."""
    try:
        _run(file, out, TableFormat.table, quiet=True, watch_stamp=stamp)
    except typer.Exit as done:
        return int(done.exit_code or 0), getattr(done, "message", None)
    return EXIT_OK, None


def _run(file: Path, out: Path, format: TableFormat, quiet: bool, watch_stamp: str | None = None) -> None:
    from .errors import InputError, MachdynError, OperationalError
    from .kinds import steps_of

    started = time.perf_counter()
    show_progress = not quiet and sys.stderr.isatty()
    with Progress(["reading"], enabled=show_progress) as progress:
        progress.step("reading")
        loaded = _load(file)
        from .runner import run_problem

        tables = tuple(name for name in type(loaded.spec).model_fields if getattr(loaded.spec, name, None)) \
            if hasattr(type(loaded.spec), "model_fields") else ()
        progress.steps = steps_of(loaded.kind, tables)
        try:
            from .studies.exploration.execution import execution, ignored_where

            def partitions(done: int, total: int) -> None:
                progress.step(f"design sweep {100 * done // max(total, 1)}%")

            deferred: list = []
            def estimate(text: str) -> None:
                if not quiet:
                    typer.echo(f"note: {text}", err=True)

            with execution(progress=partitions, deferred=deferred, estimate=estimate):
                result = run_problem(loaded, step=progress.step)
        except OperationalError as exc:
            raise _fail(f"error: {exc}", EXIT_FAILED) from None
        except InputError as exc:  # a file's mistakes, a linkage that cannot close or passes a dead position
            raise _engine_error(exc, file) from None
        except MachdynError as exc:
            raise _fail(f"error: the analysis of {file} failed: {exc}", EXIT_FAILED) from None
        except (ArithmeticError, ValueError, FloatingPointError, MemoryError) as exc:
            raise _engine_error(exc, file) from None
        except OSError as exc:  # a file or folder of the run that cannot be read or written: operational
            where = f" '{exc.filename}'" if exc.filename else ""
            raise _fail(f"error: the run of {file} failed on{where or ' a file'}: {exc.strerror or exc}",
                        EXIT_FAILED) from None
        try:
            paths = result.write(out, step=progress.step, watch_stamp=watch_stamp, folders=deferred)
        except OperationalError as exc:
            raise _fail(f"error: {exc}", EXIT_FAILED) from None
        except OSError as exc:
            raise _fail(f"error: cannot write the outputs to '{out}': {exc.strerror or exc}", EXIT_FAILED) from None
        except MachdynError as exc:
            raise _fail(f"error: the outputs of {file} could not be produced: {exc}", EXIT_FAILED) from None
    for note in result.folder_notes:  # the user's own files, kept: said even with --quiet
        typer.echo(f"note: {note}", err=True)
    if not quiet:
        from .runner import print_summary

        print_summary(result.summary, format, result.warnings + ignored_where(loaded.spec, result.warnings))
        for outcome in result.outcomes.values():  # a resumed exploration says what it took from disk
            explored: Any = getattr(outcome, "results", None)
            if getattr(explored, "reused", 0):
                typer.echo(f"resumed: {explored.reused} partition(s) reused from {explored.store}, "
                           f"{explored.computed} computed", err=True)
        if format is TableFormat.table:
            elapsed = time.perf_counter() - started
            typer.echo(f"wrote {len(paths)} file(s) to {out}/ ({', '.join(p.name for p in paths)}) in "
                       f"{elapsed:.2f} s", err=True)
    if result.failed_checks:
        for check in result.failed_checks:
            typer.echo(f"design check failed: {check}", err=True)
        raise typer.Exit(EXIT_CHECKS_FAILED)


@app.command(epilog=EXIT_CODES_HELP)
def studio(file: FileArg, debug: DebugOpt = False,
           port: Annotated[int, typer.Option(min=0, max=65535, help="The port (0: any free one).")] = 8765,
           no_open: Annotated[bool, typer.Option("--no-open", help="Do not open the web browser.")] = False) -> None:
    """Edit a linkage file in the web browser: its motion, forces and summary recomputed on each edit. The first
    line printed is the page's URL (with its access token); it listens on 127.0.0.1 only. Stop with Ctrl-C."""
    try:
        from .studio.server import serve_command  # the web framework loads only here

        code = serve_command(file, port=port, open_browser=not no_open, say=typer.echo)
    except Exception as exc:  # noqa: BLE001 - anything unexpected becomes exit 4 without a traceback
        raise _internal_error(exc, debug) from None
    raise typer.Exit(code)


@app.command(epilog=EXIT_CODES_HELP)
def check(file: FileArg, debug: DebugOpt = False) -> None:
    """Validate a problem file without analysing it: units, ranges, names, and that the linkage assembles."""
    try:
        _check(file)
    except (typer.Exit, KeyboardInterrupt):
        raise
    except Exception as exc:  # noqa: BLE001 - anything unexpected becomes exit 4 without a traceback
        raise _internal_error(exc, debug) from None


def _check(file: Path) -> None:
    from .errors import InputError

    loaded = _load(file)
    from .runner import check_problem

    try:
        warnings = check_problem(loaded)
    except InputError as exc:  # a file's mistakes, a linkage that cannot close or passes a dead position
        raise _engine_error(exc, file) from None
    for w in warnings:
        typer.echo(f"warning: {w}", err=True)
    typer.echo(f"{file}: OK")


@app.command(name="results", epilog=EXIT_CODES_HELP)
def results_of(file: FileArg, debug: DebugOpt = False) -> None:
    """List every result key a run of FILE reports, with its unit, meaning, reduction over the crank positions and
    better direction (the names a [sweep], an exploration and [optimise] accept). The file is run; nothing is
    written."""
    from .errors import AssemblyError, InputError, ProblemFileError, SingularPositionError

    loaded = _load(file)
    try:
        from .listing import listed
        from .runner import run_problem

        rows = listed(run_problem(loaded).results.labels)
    except (ProblemFileError, AssemblyError, InputError, SingularPositionError) as exc:
        raise _engine_error(exc, file) from None
    except Exception as exc:  # noqa: BLE001 - anything unexpected becomes exit 4 without a traceback
        raise _internal_error(exc, debug) from None
    from rich.table import Table

    table = Table(title=f"Results of {file.name} ({len(rows)} keys)", title_justify="left")
    for column in ("key", "unit", "meaning", "reduction", "better"):
        table.add_column(column)
    for row in rows:
        table.add_row(row.key, row.unit, row.meaning, row.reduction or "–", row.better or "–")
    _console().print(table)


def _examples_dir() -> Path:
    from importlib import resources

    return Path(str(resources.files("machdyn") / "data" / "examples"))


def _examples() -> dict[str, Path]:
    return {p.stem: p for p in sorted(_examples_dir().glob("*.toml"))}


def _describe(path: Path) -> str:
    import tomllib

    try:
        meta = tomllib.loads(path.read_text(encoding="utf-8")).get("meta", {})
    except (OSError, tomllib.TOMLDecodeError):
        return ""
    return str(meta.get("name", ""))


@app.command()
def examples(
    name: Annotated[
        str | None, typer.Argument(help="The example to copy out.", show_default=False, metavar="NAME")
    ] = None,
    to: Annotated[
        Path | None, typer.Option("--to", help="Where to copy it (a file or a directory; default ./NAME.toml).")
    ] = None,
    force: Annotated[bool, typer.Option("--force", help="Overwrite an existing file.")] = False,
) -> None:
    """List the shipped example problems, or copy one out to start from."""
    found = _examples()
    if name is None:
        from rich.table import Table

        table = Table(title="Shipped examples (machdyn examples NAME --to FILE copies one out)", title_justify="left")
        table.add_column("name")
        table.add_column("description")
        for stem, path in found.items():
            table.add_row(stem, _describe(path))
        _console().print(table)
        return
    key = name.removesuffix(".toml")
    if key not in found:
        import difflib

        near = difflib.get_close_matches(key, list(found), n=1)
        hint = f"; did you mean '{near[0]}'?" if near else ""
        raise _fail(f"error: no example named '{name}'{hint} (examples: {', '.join(found)})", EXIT_BAD_INPUT)
    target = to if to is not None else Path(f"{key}.toml")
    if target.is_dir():
        target = target / f"{key}.toml"
    if target.exists() and not force:
        raise _fail(f"error: '{target}' exists; use --force to overwrite it", EXIT_BAD_INPUT)
    from .outputs import atomic_write_text

    try:
        atomic_write_text(target, found[key].read_text(encoding="utf-8"))
    except OSError as exc:
        raise _fail(f"error: cannot write '{target}': {exc.strerror or exc}", EXIT_FAILED) from None
    typer.echo(f"copied example '{key}' to {target}; run it with: machdyn run {target}")


def entry() -> None:  # pragma: no cover - the console script calls app() directly
    app()


if __name__ == "__main__":  # pragma: no cover
    app()
