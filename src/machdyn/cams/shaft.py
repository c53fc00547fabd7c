"""The ``[shaft_cam]`` capability: a cam on the crank shaft of a linkage, turning with the crank (cam angle =
crank angle + phase) and driven by the same shaft.

The cam is analysed as in a ``[cam]`` file at the crank's speed (``[drive] speed``): profile, checks, spring
against jump, contact force and camshaft torque. Its torque adds to the linkage's driving torque at every crank
angle (one shaft, one driving torque: T = T_linkage(phi) + F_c v(phi + phase), virtual work), and a
``[flywheel]`` table in the same file sizes the shaft's flywheel and drive for the sum: the cam's reduced inertia
J_cam + m v^2, the spring's potential and the damping c v^2 are added to the linkage's equivalent machine, node by
node with their exact slopes (Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 4th ed., ch. 17:
reduced quantities of a one-degree-of-freedom machine add).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from ..dynamics.contributions import ShaftContribution
from ..dynamics.equivalent import EquivalentMachine
from ..dynamics.tables import PeriodicCurve
from ..errors import ProblemFileError
from ..notebook import ShownInNotebook
from ..pipeline import Capability, Outcome, StageContext, no_step
from ..results.labels import Label
from .dynamics import cam_forces, cam_machine
from .schema import CamBody, CamProblem, CamSpec, ShaftCamTable
from .stage import LABELS, CamResult, analyse, build
from .stage import check as check_kind

PREFIX = "shaft_cam."


def _rename(text: str) -> str:
    return re.sub(r"\bcam\.", PREFIX, text)


@dataclass(frozen=True)
class ShaftCamResult(CamResult, ShaftContribution, ShownInNotebook):
    """A cam's result on the crank shaft, at ``phase`` [rad] (cam angle = crank angle + phase): its reduced
    quantities add to the linkage's machine for ``[flywheel]``."""

    phase: float = 0.0

    def added_to(self, machine: Any, positions: int) -> Any:
        return with_shaft_cam(machine, self, self.phase, positions)


def _as_cam_problem(problem: Any, table: ShaftCamTable) -> CamProblem:
    fields = {k: getattr(table, k) for k in CamBody.model_fields}
    cam = CamSpec.model_construct(**fields, speed=float(problem.drive.speed))
    return CamProblem.model_construct(meta=problem.meta, cam=cam)


def _problems(problem: Any, table: ShaftCamTable) -> tuple[Any, Any, list[tuple[str, str]]]:
    if not problem.drive.speed > 0:
        return None, None, [("drive.speed", f"must be > 0 for a cam on the crank shaft; got "
                                            f"{problem.drive.speed:g} rad/s")]
    if table.dynamics is None:
        return None, None, [("shaft_cam.dynamics", "a cam on the crank shaft loads it: give its follower train "
                                                   "(mass ...)")]
    cp = _as_cam_problem(problem, table)
    model, found = build(cp)
    if not found:
        try:
            check_kind(cp, model)
        except ProblemFileError as exc:
            found = list(exc.problems)
    return cp, model, [(_rename(p), _rename(m)) for p, m in found]


def check(problem: Any, table: ShaftCamTable, source: str | None) -> list[tuple[str, str]]:
    """The table's validations beyond its schema (the same as a ``[cam]`` file's, with its field names)."""
    return _problems(problem, table)[2]


def run(ctx: StageContext) -> Outcome:
    table: ShaftCamTable = ctx.table
    cp, model, problems = _problems(ctx.problem, table)
    if problems:
        raise ProblemFileError(problems, ctx.source)
    out = analyse(cp, model, no_step)
    r = ShaftCamResult(**{f.name: getattr(out.results, f.name) for f in fields(out.results)},
                       phase=table.phase)
    scalars = {_rename(k): v for k, v in out.scalars.items()}
    labels = {_rename(k): Label(f"Shaft cam: {lab.text}", lab.unit, lab.display,
                                None if lab.zero_below is None else _rename(lab.zero_below))
              for k, lab in {**LABELS, **out.labels}.items()}
    series = {f"shaft_{name}": cols for name, cols in out.series.items()}
    warnings = [f"shaft cam: {w}" for w in out.warnings]
    failed = [f"shaft cam: {c}" for c in out.failed_checks]
    if ctx.analysis is not None:
        phi = np.asarray(ctx.analysis.kinematics.crank_angle, dtype=float)
        linkage = np.asarray(ctx.analysis.forces.driving_torque, dtype=float)
        train = r.model.train
        cam_t = cam_forces(r.model.program, train, r.spring, r.speed, np.ravel(phi) + table.phase).torque
        cam_t = cam_t.reshape(np.shape(phi))
        total = linkage + cam_t
        if total.ndim == 1:
            scalars |= {"shaft_cam.combined_peak_torque": float(np.max(np.abs(total))),
                        "shaft_cam.linkage_peak_torque": float(np.max(np.abs(linkage)))}
            series["shaft_torque"] = {"crank_angle": (phi, "rad"), "linkage_torque": (linkage, "N*m"),
                                      "cam_torque": (cam_t, "N*m"), "total_torque": (total, "N*m")}
        else:
            scalars |= {"shaft_cam.combined_peak_torque": [float(x) for x in np.max(np.abs(total), axis=-1)],
                        "shaft_cam.linkage_peak_torque": [float(x) for x in np.max(np.abs(linkage), axis=-1)]}
    summary = tuple(_rename(k) for k in out.summary if _rename(k) in scalars)
    summary += tuple(k for k in ("shaft_cam.linkage_peak_torque", "shaft_cam.combined_peak_torque") if k in scalars)
    files = {f"shaft_{name}": text for name, text in out.files.items()}
    return Outcome(results=r, scalars=scalars, labels=labels, series=series, files=files, summary=summary,
                   warnings=tuple(warnings), failed_checks=tuple(failed))


def with_shaft_cam(machine: Any, cam_result: CamResult, phase: float, positions: int) -> Any:
    """The linkage's equivalent machine with the shaft cam's reduced inertia, potential and damping added (module
    docstring); the linkage's external moment and speed-dependent forces kept."""
    r = cam_result
    cam = cam_machine(r.model.program, r.model.train, r.spring, positions, phase=phase)
    phi = np.arange(int(positions)) * (2.0 * np.pi / int(positions))
    period = 2.0 * np.pi

    def add(a, b):
        values = np.asarray(a(phi)) + np.asarray(b(phi))
        slopes = np.asarray(a.derivative(phi)) + np.asarray(b.derivative(phi))
        return PeriodicCurve.hermite(phi, values, slopes, period)

    return EquivalentMachine(add(machine.inertia, cam.inertia), add(machine.potential, cam.potential),
                             machine.moment, add(machine.damping, cam.damping), machine.forces, machine.mechanism,
                             machine.speed_loads, machine.single)


def _shaft_labels() -> dict[str, Label]:
    """The cam's own results under the ``shaft_cam.`` prefix, declared once for the catalogue."""

    return {_rename(k): Label(f"Shaft cam: {lab.text}", lab.unit, lab.display,
                              None if lab.zero_below is None else _rename(lab.zero_below), lab.over, lab.better)
            for k, lab in LABELS.items()}


CAPABILITY = Capability(
    table="shaft_cam",
    schema=ShaftCamTable,
    run=run,
    step="cam on the crank shaft",
    kinds=("mechanism",),
    labels={**_shaft_labels(),
            "shaft_cam.combined_peak_torque": Label("Shaft: peak driving torque, linkage + cam", "N*m",
                                                    over="max_abs", better="lower"),
            "shaft_cam.linkage_peak_torque": Label("Shaft: peak driving torque of the linkage alone", "N*m",
                                                   over="max_abs", better="lower")},
    report="machdyn.report.cams:shaft_sections",
    check=check,
    result_type=ShaftCamResult,
)
