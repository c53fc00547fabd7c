"""Exceptions and warnings of machdyn: one base class each.

Every message names the field, the rule and the value received, e.g.
``The length of body 'crank' must be > 0 m; got -0.15 m.``

The tree::

    MachdynError
    ├── InputError (also a ValueError): the input breaks a rule
    │   ├── ProblemFileError: a problem file's mistakes, all of them, each with its path
    │   ├── AssemblyError: the linkage cannot close at some requested crank angle
    │   └── SingularPositionError: the crank range passes a dead (toggle) position
    ├── AnalysisError: the analysis of a valid input failed (a simulation that does not settle, an optimiser
    │   that does not converge)
    └── OperationalError: the machine or the network stopped the work (a scheduler that does not answer, a full
        disk, a folder that may not be written, another run writing the same folder)
"""

from __future__ import annotations

import numpy as np


class MachdynError(Exception):
    """Base class of every error machdyn raises on purpose."""


class InputError(MachdynError, ValueError):
    """An input value breaks a rule (non-positive length, NaN, unknown name, ...)."""


class AssemblyError(InputError):
    """A linkage cannot be assembled (closed) at some or all of the requested crank angles."""


class SingularPositionError(InputError):
    """A linkage passes through a dead (toggle) position where velocities or forces are undefined."""


class ProblemFileError(InputError):
    """A problem file has one or more mistakes; ``problems`` lists each as (path, message)."""

    def __init__(self, problems: list[tuple[str, str]], source: str | None = None):
        # bounded: a key of half a megabyte in a file must not make a message of a megabyte
        self.problems = [(_cut(str(path), 200), _cut(str(message), 1000)) for path, message in problems]
        self.source = source
        where = f" in {source}" if source else ""
        lines = [f"{len(self.problems)} problem(s){where}:"]
        lines += [f"  {path}: {message}" if path else f"  {message}" for path, message in self.problems]
        super().__init__("\n".join(lines))


def input_problems(exc: InputError) -> list[tuple[str, str]]:
    """The (path, message) lines ``machdyn check`` prints for a bad input: a problem file's own mistakes, or the
    one line of a linkage that cannot close, passes a dead position or breaks another input rule."""
    if isinstance(exc, ProblemFileError):
        return list(exc.problems)
    if isinstance(exc, AssemblyError):
        return [("mechanism", f"cannot be assembled: {exc}")]
    if isinstance(exc, SingularPositionError):
        return [("mechanism", f"passes a dead position: {exc}")]
    return [("", str(exc))]


def _cut(text: str, limit: int) -> str:
    return text if len(text) <= limit else f"{text[: limit - 40]}... ({len(text):,} characters)"


class AnalysisError(MachdynError):
    """The analysis of a valid input failed: a simulation that does not settle, an optimiser that does not
    converge, a motor that cannot drive the machine. The message says what was tried and what would help."""


class OperationalError(MachdynError):
    """The work could not be done for a reason outside the input and outside machdyn: a Dask scheduler that does
    not answer, a lost worker, a full disk, a folder that may not be written or is a file, another run writing
    the same output folder. The message gives the cause in one line; the command line exits 1."""


class MachdynWarning(UserWarning):
    """Base class of every warning machdyn emits (a check near its limit, a paper's value differing, ...)."""


def check_finite(name: str, value, unit: str = "") -> None:
    """Raise :class:`InputError` if ``value`` (scalar or array) holds NaN or infinity."""
    arr = np.asarray(value, dtype=float)
    if not np.all(np.isfinite(arr)):
        bad = arr[~np.isfinite(arr)].ravel()[0] if arr.ndim else arr
        raise InputError(f"The {name} must be a finite number; got {bad}{' ' + unit if unit else ''}.")


def check_positive(name: str, value, unit: str = "", *, allow_zero: bool = False) -> None:
    """Raise :class:`InputError` unless every element of ``value`` is finite and > 0 (or >= 0)."""
    check_finite(name, value, unit)
    arr = np.asarray(value, dtype=float)
    bad = arr < 0 if allow_zero else arr <= 0
    if np.any(bad):
        got = arr[bad].ravel()[0] if arr.ndim else float(arr)
        rule = ">= 0" if allow_zero else "> 0"
        suffix = f" {unit}" if unit else ""
        raise InputError(f"The {name} must be {rule}{suffix}; got {got:g}{suffix}.")
