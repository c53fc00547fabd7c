"""One studio session: the problem file it was started with, its edits judged by the loader, its machine computed.

Nothing here knows the web: :class:`Studio` takes the edited values (field key -> number as typed) and answers
plain dictionaries, JSON-ready. An edited file is judged exactly as ``machdyn check`` judges a file (the same
reader, validation and assembly check, the same (path, message) lines), then run as ``machdyn run`` runs it,
without its studies (``[sweep]``, ``[optimise]``: they would start a whole study on each keystroke). A valid
machine becomes the *last valid* one; an invalid edit answers its messages and leaves it in place.
"""

from __future__ import annotations

import math
import os
import re
import threading
import time
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import InputError, MachdynError, ProblemFileError, input_problems
from ..outputs import atomic_write_text
from ..problem.loader import parse_toml, read_text
from ..reading import LoadedProblem, kind_of, read_problem
from ..report.animation import scene
from ..runner import check_problem, run_problem
from .cam_view import cam_scene
from .dragging import drag_rules
from .fields import EditableText
from .live import DEFERRED, STUDIES, deferred_tables, live_flywheel, without_simulation
from .variants import MAX_VARIANTS, Variant, VariantRefused, changed_fields, check_name, compared

EDITABLE_KINDS = ("mechanism", "cam", "shaft_line")
MAX_POSITIONS = 3600  # the studio answers within a fraction of a second up to here
NEW_NAME = re.compile(r"^[A-Za-z0-9][A-Za-z0-9 ._-]{0,120}\.toml$")


class SaveRefused(ValueError):
    """A save the studio will not do: a name outside the file's folder, or a machine with mistakes."""


def _number(value: Any) -> Any:
    if isinstance(value, float | int | np.floating | np.integer) and not isinstance(value, bool):
        v = float(value)
        return v if math.isfinite(v) else None
    if isinstance(value, list | tuple):
        return [_number(v) for v in value]
    return str(value)


class Studio:
    """The session of ``machdyn studio FILE``: ``evaluate(edits)`` on each edit, ``save(edits, name)`` on request."""

    def __init__(self, path: str | os.PathLike) -> None:
        self.path = Path(path)
        self.folder = self.path.resolve().parent
        self.text, _ = read_text(self.path)  # bounded: at most the loader's file size
        self.kind = kind_of(parse_toml(self.text, str(self.path)), str(self.path))  # malformed TOML refused here
        self.source = EditableText(self.text)
        self.fields = self.source.fields
        self.editable = self.kind in EDITABLE_KINDS
        self.last_valid: dict[str, Any] | None = None
        self.report_html: str | None = None
        self.variants: dict[str, Variant] = {}
        self._lock = threading.Lock()

    # ------------------------------------------------------------------ the page's first view

    def state(self) -> dict[str, Any]:
        """The file's fields and its machine as it is on disk (computed once)."""
        with self._lock:
            first = self.last_valid if self.last_valid is not None else self._evaluate({})
        return {"file": self.path.name, "kind": self.kind, "editable": self.editable,
                "fields": [f.as_json() for f in self.fields], "result": first}

    # ------------------------------------------------------------------ an edit

    def evaluate(self, edits: dict[str, str], *, full: bool = False) -> dict[str, Any]:
        """The machine with ``edits`` applied: its view, summary and curves, or the check's messages. Live
        (``full`` False) the tables that simulate the motion in time are left out (:mod:`machdyn.studio.live`);
        ``full`` runs them too."""
        if not self.editable:
            raise SaveRefused(f"a [{self.kind}] file opens read-only in the studio")
        with self._lock:
            return self._evaluate(edits, full=full)

    def _evaluate(self, edits: dict[str, str], *, full: bool = False) -> dict[str, Any]:
        started = time.perf_counter()
        text = self.source.edited(edits)
        try:
            answer = self._compute(text, full)
        except InputError as exc:
            answer = self._refused(input_problems(exc))
        except (MachdynError, ArithmeticError, ValueError) as exc:
            answer = self._refused([("", f"error: the analysis of {self.path} failed: {type(exc).__name__}: "
                                         f"{exc}")])
        answer["compute_ms"] = round(1e3 * (time.perf_counter() - started), 2)
        if answer["ok"]:
            self.last_valid = answer
        return answer

    def _refused(self, problems: list[tuple[str, str]]) -> dict[str, Any]:
        return {"ok": False, "problems": [{"path": p, "message": m} for p, m in problems],
                "message": str(ProblemFileError(problems, str(self.path)))}

    def _compute(self, text: str, full: bool = False) -> dict[str, Any]:
        loaded = read_problem(text)
        drive = getattr(loaded.spec, "drive", None)
        positions = getattr(drive, "positions", 0) or 0
        if positions > MAX_POSITIONS:
            return self._refused([("drive.positions", f"the studio computes at most {MAX_POSITIONS} positions; "
                                   f"got {positions} (machdyn run takes more)")])
        warnings = check_problem(loaded) if self.editable else []  # every table judged, deferred ones too
        spec = loaded.spec  # with its deferred tables
        deferred = deferred_tables(loaded.spec) if self.editable else []
        left_out = {t: None for t in (*STUDIES, *(() if full or not self.editable else DEFERRED))
                    if getattr(loaded.spec, t, None) is not None}
        live = loaded.spec.model_copy(update=left_out) if left_out else loaded.spec
        if not full and self.editable:
            live = without_simulation(live)
        if live is not loaded.spec:
            loaded = LoadedProblem(loaded.kind, live, loaded.text, loaded.source, loaded.model)
        result = run_problem(loaded)
        answer = self._answer(result, warnings)
        if result.kind == "cam":
            answer["cam"] = cam_scene(spec, result.outcomes["cam"], self.fields)
            answer["headline"] = {"label": "Peak pressure angle", "value": answer["cam"]["max_pressure_angle"],
                                  "unit": "deg"}
        answer["full"], answer["deferred"] = full or not deferred, deferred  # deferred: run only when full
        if not full and "[flywheel]" in deferred and result.analysis is not None:
            answer["summary"] += live_flywheel(spec, result.analysis)
        return answer

    def _answer(self, result: Any, warnings: list[str]) -> dict[str, Any]:
        rows = [{"label": label, "value": _number(value), "unit": unit}
                for label, value, unit in result.summary_rows]
        answer: dict[str, Any] = {"ok": True, "title": result.title, "summary": rows,
                                  "warnings": list(dict.fromkeys([*warnings, *result.warnings])),
                                  "failed_checks": list(result.failed_checks), "scene": None, "peak_torque": None,
                                  "drags": []}
        analysis = result.analysis
        if analysis is not None and getattr(analysis, "kinematics", None) is not None:
            outcome = result.outcomes[result.kind]
            about = (float(outcome.scalars.get("shaking_moment.about_x", 0.0)),
                     float(outcome.scalars.get("shaking_moment.about_y", 0.0)))
            answer["scene"] = scene(analysis, result.mechanism, about=about)
            forces = getattr(analysis, "forces", None)
            if forces is not None:  # the run's exact peak (refined between the samples), as the summary shows it
                exact = outcome.scalars.get("driving_torque.max_abs")
                answer["peak_torque"] = float(exact) if exact is not None else \
                    float(np.nanmax(np.abs(np.asarray(forces.driving_torque, dtype=float))))
                answer["headline"] = {"label": "Peak driving torque", "value": answer["peak_torque"], "unit": "N·m"}
            answer["drags"] = drag_rules(result.problem, self.fields, answer["scene"])
        return answer

    # ------------------------------------------------------------------ variants

    def keep_variant(self, name: str, edits: dict[str, str]) -> dict[str, Any]:
        """Keep the machine of ``edits`` under ``name`` (a valid machine only; a name kept again is replaced)."""
        if not self.editable:
            raise SaveRefused(f"a [{self.kind}] file opens read-only in the studio")
        name = check_name(name)
        if name not in self.variants and len(self.variants) >= MAX_VARIANTS:
            raise VariantRefused(f"the studio keeps at most {MAX_VARIANTS} variants")
        with self._lock:
            answer = self._evaluate(edits)
        if not answer["ok"]:
            raise VariantRefused(f"variant {name!r} not kept: the machine has mistakes\n{answer['message']}")
        self.variants[name] = Variant(name, dict(edits), answer)
        return {"ok": True, "variants": list(self.variants)}

    def compare(self, a: str, b: str) -> dict[str, Any]:
        """Variants ``a`` and ``b`` side by side: both machines (views, summaries), the fields that differ and
        the table of their common results with the differences."""
        missing = [n for n in (a, b) if n not in self.variants]
        if missing:
            raise VariantRefused(f"no variant named {missing[0]!r}; kept: {', '.join(self.variants) or 'none'}")
        first, second = self.variants[a], self.variants[b]
        return {"ok": True, "a": {"name": a, "answer": first.answer}, "b": {"name": b, "answer": second.answer},
                "fields": changed_fields(first, second, {f.key: f.number for f in self.fields}),
                "rows": compared(first, second)}

    # ------------------------------------------------------------------ saving

    def target(self, name: str | None) -> Path:
        """Where a save goes: the file itself, or a new name in its folder (no path, ends in .toml)."""
        if not name or name == self.path.name:
            return self.path
        if "/" in name or "\\" in name or os.sep in name or name in (".", "..") or not NEW_NAME.fullmatch(name):
            raise SaveRefused(f"a new file name is a plain name ending in .toml, in the folder of {self.path.name} "
                              f"(letters, digits, space, '.', '_', '-'); got {name!r}")
        return self.folder / name

    def save(self, edits: dict[str, str], name: str | None = None) -> dict[str, Any]:
        """Write the edited file (comments and layout kept) to the file itself or a new name in its folder; a
        machine with mistakes is not written."""
        if not self.editable:
            raise SaveRefused(f"a [{self.kind}] file opens read-only in the studio")
        where = self.target(name)
        with self._lock:
            text = self.source.edited(edits)
            answer = self._evaluate(edits)
            if not answer["ok"]:
                raise SaveRefused(answer["message"])
            atomic_write_text(where, text)
            if where == self.path:  # later edits are relative to what is now on disk
                self.text = text
                self.source = EditableText(text)
                self.fields = self.source.fields
        return {"ok": True, "saved": where.name, "fields": [f.as_json() for f in self.fields]}

    # ------------------------------------------------------------------ other kinds

    def report(self) -> str:
        """The report of the ordinary run of the file (``machdyn run``), made once."""
        with self._lock:
            if self.report_html is None:
                self.report_html = run_problem(self.path).report_html()
            return self.report_html
