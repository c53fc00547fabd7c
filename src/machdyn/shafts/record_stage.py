"""The ``[field_records]`` capability of a shaft line: influence-coefficient field balancing from measured
records with a once-per-revolution reference channel (:mod:`machdyn.shafts.records`), one record per run."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from pathlib import Path  # noqa: TC003
from typing import Any

from pydantic import Field

from ..errors import InputError, ProblemFileError
from ..notebook import ShownInNotebook
from ..pipeline import Capability, Outcome, StageContext
from ..problem.fields import Angle, PositiveMass
from ..problem.schema import Name, Spec
from ..results.labels import Label
from ..vibration.study import resolve_record
from .field import FieldBalance, TrialRun, split_onto_holes
from .field import single_plane as field_single
from .field import two_plane as field_two
from .records import RunRecord, read_run


class RecordPlaneSpec(Spec):
    name: Name
    holes: int = Field(0, ge=0, le=360, strict=True)
    first_hole: Angle = 0.0


class RecordTrialSpec(Spec):
    plane: int = Field(ge=1, le=2, strict=True)
    mass: PositiveMass
    angle: Angle
    record: str = Field(min_length=1)
    removed: bool = True


class FieldRecordsSpec(Spec):
    """Records of the original run and of one trial run per plane (CSV files, relative to the problem file),
    the name of the once-per-revolution ``reference`` channel and the ``sensors`` read, one per plane."""

    reference: str = Field(min_length=1)
    sensors: list[str] = Field(min_length=1, max_length=2)
    planes: list[RecordPlaneSpec] = Field(min_length=1, max_length=2)
    original: str = Field(min_length=1)
    trials: list[RecordTrialSpec] = Field(min_length=1, max_length=2)


@dataclass(frozen=True)
class RecordBalance(ShownInNotebook):
    """The runs read from the records and the balance computed from them."""

    original: RunRecord
    trials: tuple[RunRecord, ...]
    balance: FieldBalance
    names: tuple[str, ...]
    splits: tuple[dict[int, float], ...]
    mass_unit: str = "kg"  # the unit the problem file writes masses in (the summary and report show it)


def _path(name: str, source: str | None) -> Path:
    """``machdyn:PATH`` inside machdyn's data folder (the shipped records), an absolute path as it is, a relative
    one against the problem file's folder."""
    return resolve_record(name, source)


def _solve(table: FieldRecordsSpec, source: str | None) -> tuple[RecordBalance | None, list[tuple[str, str]]]:
    problems: list[tuple[str, str]] = []
    n = len(table.planes)
    if len(table.sensors) != n:
        problems.append(("field_records.sensors", f"{n} plane(s) need {n} sensor(s); got {len(table.sensors)}"))
    if sorted(t.plane for t in table.trials) != list(range(1, n + 1)):
        problems.append(("field_records.trials", f"each of the {n} plane(s) needs exactly one trial run; got the "
                         f"planes {[t.plane for t in table.trials]}"))
    if problems:
        return None, problems
    sensors = tuple(table.sensors)
    try:
        original = read_run(_path(table.original, source), table.reference, sensors)
    except InputError as exc:
        return None, [("field_records.original", str(exc))]
    runs = []
    for i, t in enumerate(table.trials):
        try:
            runs.append(read_run(_path(t.record, source), table.reference, sensors))
        except InputError as exc:
            problems.append((f"field_records.trials[{i}].record", str(exc)))
    if problems:
        return None, problems
    speeds = [original.speed, *(r.speed for r in runs)]
    if (max(speeds) - min(speeds)) > 0.02 * max(speeds):
        rpm = ", ".join(f"{s * 30 / math.pi:.4g}" for s in speeds)
        return None, [("field_records", f"the runs must be at one speed (influence coefficients hold for one "
                       f"speed); the records run at {rpm} rpm")]
    trials = [TrialRun(t.plane - 1, t.mass, t.angle, r.readings, t.removed) for t, r in zip(table.trials, runs,
                                                                                          strict=True)]
    try:
        if n == 1:
            fb = field_single(original.readings[0], trials[0].mass, trials[0].angle, trials[0].readings[0],
                              trials[0].removed)
        else:
            fb = field_two(original.readings, trials)
    except InputError as exc:
        return None, [("field_records", str(exc))]
    holes = [tuple(p.first_hole + 2 * math.pi * k / p.holes for k in range(p.holes)) for p in table.planes]
    splits = tuple(split_onto_holes(m, a, h) if h else {} for m, a, h in
                   zip(fb.correction_mass, fb.correction_angle, holes, strict=True))
    return RecordBalance(original, tuple(runs), fb, tuple(p.name for p in table.planes), splits), []


def check(problem: Any, table: FieldRecordsSpec, source: str | None = None) -> list[tuple[str, str]]:
    return _solve(table, source)[1]


def run(ctx: StageContext) -> Outcome:
    result, problems = _solve(ctx.table, ctx.source)
    if result is None:  # check() has refused these already; a run without check meets the same message
        raise ProblemFileError(problems, ctx.source)
    mu = getattr(ctx.problem, "mass_unit", "kg")
    result = replace(result, mass_unit=mu)
    fb = result.balance
    sc: dict[str, Any] = {"shaft.records.speed": result.original.speed}
    labels: dict[str, Label] = {}
    summary = ["shaft.records.speed"]
    for k, name in enumerate(result.names):
        mk, ak = f"shaft.records.{name}.mass", f"shaft.records.{name}.angle"
        sc[mk], sc[ak] = fb.correction_mass[k], fb.correction_angle[k]
        labels[mk] = Label(f"Field balancing from records, plane {name}: correction mass", "kg", mu)
        labels[ak] = Label(f"Field balancing from records, plane {name}: correction angle (against rotation)",
                           "rad")
        summary += [mk, ak]
        for hole, m in result.splits[k].items():
            hk = f"shaft.records.{name}.hole{hole + 1}.mass"
            sc[hk] = m
            labels[hk] = Label(f"Field balancing from records, plane {name}: mass in hole {hole + 1}", "kg", mu)
            summary.append(hk)
    for j, reading in enumerate(result.original.readings, start=1):
        amp, ph = f"shaft.records.original.sensor{j}.amplitude", f"shaft.records.original.sensor{j}.phase"
        sc[amp], sc[ph] = reading.amplitude, reading.phase
        labels[amp] = Label(f"Original run, sensor {j}: 1x amplitude (in the record's unit)", "")
        labels[ph] = Label(f"Original run, sensor {j}: 1x phase lag from the reference pulse", "rad")
    warnings = tuple(f"the trial mass in plane {name} changed the readings by only {eff:.0%}; a trial mass that "
                     "changes them by 30 % or more gives a more reliable correction"
                     for name, eff in zip(result.names, fb.trial_effect, strict=True) if eff < 0.3)
    return Outcome(results=result, scalars=sc, labels=labels, summary=tuple(summary), warnings=warnings)


CAPABILITY = Capability(
    table="field_records",
    schema=FieldRecordsSpec,
    run=run,
    step="field balancing from records",
    kinds=("shaft_line",),
    labels={"shaft.records.speed": Label("Field balancing from records: shaft speed of the original run", "rad/s",
                                         "rpm", over="scalar", better="none")},
    report="machdyn.report.shafts:record_sections",
    check=check,
    result_type=RecordBalance,
)
