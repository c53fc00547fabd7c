"""The vibration capability's stages: a frame study from ``[frame]`` and a signal study from ``[signals]``.

``study_frame`` builds the frame, its modes and the steady-state response to the analysed mechanism's
shaking loads (and to a variant with counterweights added), the RMS levels at the named points, the transmitted
force per mount and the predicted severity. ``study_signals`` reads the records, judges them and, with a frame
study, sets the predicted RMS velocity next to the measured one. ``run_frame`` / ``run_signals`` wrap them as
capability stages (:mod:`machdyn.vibration.stage`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np

from ..constants import DOWNWARD_GRAVITY
from ..errors import InputError
from ..linkage import analyse
from ..linkage.model import PointMass, Spring
from ..notebook import ShownInNotebook
from .frame import Frame, Mount, rope, rubber_mount, tyre
from .modes import Modes, modes
from .orders import band_order_warnings
from .response import Comparison, FrameResponse, compare, shaking_loads, steady_state
from .severity import Severity, classify
from .signals import RecordAnalysis, analyse_record, compare_records, read_record

__all__ = ["FrameStudy", "SignalStudy", "build_frame", "study_frame", "study_signals", "with_variant"]


def build_frame(table, crank_frequency: float) -> Frame:
    """The :class:`Frame` of a validated ``[frame]`` table; rubber loss factors become viscous damping at
    ``crank_frequency`` [Hz]."""
    mounts: list[Mount] = []
    for m in table.mounts:
        if m.type == "spring":
            mounts.append(Mount(m.name, m.position, m.direction, m.stiffness, m.damping, "spring"))
        elif m.type == "rubber":
            mounts.extend(rubber_mount(m.name, m.position, m.vertical_stiffness, m.horizontal_stiffness,
                                       loss_factor=m.loss_factor, frequency=crank_frequency,
                                       vertical_damping=m.vertical_damping, horizontal_damping=m.horizontal_damping))
        elif m.type == "tyre":
            mounts.extend(tyre(m.name, m.position, m.vertical_stiffness, m.horizontal_stiffness,
                               vertical_damping=m.vertical_damping, lateral_damping=m.horizontal_damping))
        else:
            mounts.extend(rope(m.name, m.position, m.length, m.supported_mass, m.axial_stiffness, angle=m.angle,
                               damping=m.damping))
    return Frame(table.mass, table.inertia, tuple(mounts), com=tuple(table.com), name="frame",
                 gravity=frame_gravity(getattr(table, "gravity", "off")))


def frame_gravity(value) -> tuple[float, float]:
    """The acceleration of gravity [m/s^2] in frame axes of a ``[frame] gravity`` value: "on" standard gravity
    along the frame's -y axis (its y axis up, as vertical mounts at 90 deg have it), "off" none, or the vector."""
    if value == "on":
        return DOWNWARD_GRAVITY
    if value == "off":
        return (0.0, 0.0)
    return (float(value[0]), float(value[1]))


def with_variant(mechanism, variant):
    """``mechanism`` with the point masses and springs of a ``[frame.after]`` table added."""
    bodies = {b.name for b in mechanism.bodies}
    added = []
    for i, c in enumerate(variant.counterweights):
        if c.body not in bodies:
            raise InputError(f"frame.after.counterweights[{i}].body: no body '{c.body}'; bodies: "
                             f"{', '.join(sorted(bodies))}.")
        position = (c.radius * math.cos(c.angle), c.radius * math.sin(c.angle))
        added.append(PointMass(c.name or f"after_counterweight_{i + 1}", c.body, c.mass, position, c.inertia))
    known = {f"{b.name}.{p}" for b in mechanism.bodies for p in b.points} | {f"ground.{g}" for g in mechanism.ground}
    springs = []
    for i, sp in enumerate(variant.springs):
        for field in ("point_1", "point_2"):
            if getattr(sp, field) not in known:
                raise InputError(f"frame.after.springs[{i}].{field}: no point '{getattr(sp, field)}'; points: "
                                 f"{', '.join(sorted(known))}.")
        springs.append(Spring(sp.name or f"after_spring_{i + 1}", sp.point_1, sp.point_2, sp.stiffness,
                              sp.free_length))
    return replace(mechanism, point_masses=(*mechanism.point_masses, *added),
                   springs=(*mechanism.springs, *springs))


@dataclass(frozen=True)
class FrameStudy(ShownInNotebook):
    """Frame, modes, responses before (the analysed mechanism) and after (the variant, or None), the named
    ``points``, the measuring ``direction`` [rad] (None: vector), the ``band`` [Hz], RMS ``comparison``s of
    acceleration and velocity, and the predicted ``severity`` per point (before, after)."""

    frame: Frame
    modes: Modes
    points: dict
    labels: tuple[str, str]
    direction: float | None
    band: tuple[float, float]
    before: FrameResponse
    after: FrameResponse | None
    acceleration: Comparison | None
    velocity: Comparison | None
    severity_before: tuple[Severity, ...]
    severity_after: tuple[Severity, ...] | None
    #: the mechanism and its analysis the loads came from, placed at ``origin`` [m] and turned by ``angle``
    #: [rad] in frame coordinates (for drawing the machine on its frame)
    mechanism: Any = None
    analysis: Any = None
    origin: tuple[float, float] = (0.0, 0.0)
    angle: float = 0.0
    #: the variant compared ("after") and its analysis, when there is one
    after_mechanism: Any = None
    after_analysis: Any = None

    def rms(self, which: str, quantity: str) -> np.ndarray:
        resp = self.before if which == "before" else self.after
        if resp is None:
            raise InputError("This frame study has no 'after' variant.")
        return np.array([resp.rms(p, quantity, self.direction, self.band) for p in self.points.values()])


def study_frame(table, mechanism, analysis, *, balanced=None) -> FrameStudy:
    """Run the frame study of a validated ``[frame]`` table for ``mechanism`` and its constant-speed ``analysis``.

    The variant compared is the table's ``[frame.after]``; without one, a ``balanced`` model (the mechanism as
    the file's ``[balance]`` left it) is compared, labelled "balanced"."""
    kin = analysis.kinematics
    crank_frequency = float(np.ravel(kin.speed)[0]) / (2 * np.pi)
    frame = build_frame(table, crank_frequency)
    md = modes(frame)
    opts = {"orders": table.orders, "origin": tuple(table.mechanism_origin), "angle": table.mechanism_angle}
    before = steady_state(frame, shaking_loads(analysis, **opts))
    after = acc = vel = an_after = None
    label_after = ""
    variant, label = None, ""
    if table.after is not None:
        variant, label = with_variant(mechanism, table.after), table.after.label
    elif balanced is not None:
        variant, label = balanced, "balanced"
    if variant is not None:
        an_after = analyse(variant, kin.crank_angle, float(np.ravel(kin.speed)[0]), diagnostics=False)
        after = steady_state(frame, shaking_loads(an_after, **opts))
        label_after = label
    points = dict(table.points)
    if after is not None:
        acc = _banded_compare(before, after, points, "acceleration", table.direction, table.band)
        vel = _banded_compare(before, after, points, "velocity", table.direction, table.band)

    def judge(resp):
        return tuple(classify(resp.rms(p, "velocity", table.direction, table.band), table.machine_class,
                              table.standard) for p in points.values())

    return FrameStudy(frame, md, points, (table.label, label_after), table.direction, tuple(table.band), before,
                      after, acc, vel, judge(before), judge(after) if after is not None else None, mechanism,
                      analysis, opts["origin"], float(opts["angle"]), variant, an_after)


def _banded_compare(before, after, points, quantity, direction, band) -> Comparison:
    cmp = compare(before, after, points, quantity, direction)
    b = np.array([before.rms(p, quantity, direction, band) for p in points.values()])
    a = np.array([after.rms(p, quantity, direction, band) for p in points.values()])
    return replace(cmp, before=b, after=a)


@dataclass(frozen=True)
class SignalStudy(ShownInNotebook):
    """Measured records analysed and judged: ``before`` (and ``after``) analyses, the severity of each channel,
    the reduction per channel [%] and the predicted RMS velocity [m/s] at channels named like frame points.

    ``labels`` name the records (the user's, or their file names); ``predicted_labels`` name the frame study's
    analysed mechanism and its variant, whose predictions stand next to the first and the second record.
    The predictions are RMS values in the records' ``band`` [Hz]; ``frame_band`` [Hz] is the band of the frame
    study's own RMS values (None without a frame study). ``running_speed`` [rad/s] is the machine's speed (None
    if unknown); ``warnings`` say which of its orders the band leaves out."""

    before: RecordAnalysis
    after: RecordAnalysis | None
    severity_before: tuple[Severity, ...]
    severity_after: tuple[Severity, ...] | None
    reduction: dict | None
    predicted_before: dict
    predicted_after: dict
    labels: tuple[str, str] = ("before", "after")
    predicted_labels: tuple[str, str] = ("before", "after")
    band: tuple[float, float] = (10.0, 1000.0)
    frame_band: tuple[float, float] | None = None
    running_speed: float | None = None
    warnings: tuple[str, ...] = ()


#: Prefix of a record shipped with machdyn: ``"machdyn:examples/signals/tamper_before.csv"``.
PACKAGE_PREFIX = "machdyn:"


def resolve_record(name: str, source=None) -> Path:
    """The file a ``[signals]`` entry names: ``machdyn:PATH`` inside machdyn's data folder (the shipped example
    records), any other path against the problem file's folder (``source``; the working folder for text given
    directly). The file must lie inside that folder (symbolic links followed): a problem file from someone else
    cannot make machdyn read other files of the machine. Raises :class:`InputError` saying why not."""
    if name.startswith(PACKAGE_PREFIX):
        base = Path(str(resources.files("machdyn") / "data"))
        relative = name[len(PACKAGE_PREFIX):]
        if Path(relative).is_absolute() or ".." in Path(relative.replace("\\", "/")).parts:
            raise InputError(f"The record '{_cut(name)}' must name a file shipped with machdyn, without '..' or an "
                             f"absolute path (e.g. \"machdyn:examples/signals/tamper_before.csv\").")
        where = "machdyn's data folder"
        candidate = base / relative
    else:
        base = Path(source).parent if source is not None else Path.cwd()
        where = f"the problem file's folder {base.resolve()}"
        candidate = Path(name) if Path(name).is_absolute() else base / name
    try:
        resolved = candidate.resolve()
        inside = base.resolve()
    except (OSError, RuntimeError):  # Python 3.11 raises RuntimeError on a loop of symbolic links
        raise InputError(f"The record file {_cut(str(candidate))} is a loop of symbolic links.") from None
    if not resolved.is_relative_to(inside):
        raise InputError(f"The record file {_cut(name)} lies outside {where}; records are read from that folder "
                         f"only: copy the record next to the problem file.")
    return candidate


def _cut(text: str, limit: int = 80) -> str:
    return text if len(text) <= limit else text[: limit - 3] + "..."


def record_label(name: str) -> str:
    """The default label of a record: its file name without folder and extension."""
    return Path(name[len(PACKAGE_PREFIX):] if name.startswith(PACKAGE_PREFIX) else name).stem or name


def study_signals(table, *, source=None, crank_speed: float | None = None,
                  frame_study: FrameStudy | None = None) -> SignalStudy:
    """Read and judge the records of a validated ``[signals]`` table (file names relative to ``source``'s
    folder); with a ``frame_study``, predicted RMS velocities in the records' band at the channels named like
    its points. ``crank_speed`` [rad/s] is the machine's running speed (the table's ``speed`` when None)."""
    band = (float(table.band[0]), float(table.band[1]))
    speed = crank_speed if crank_speed is not None else table.speed

    def analyse_file(name, field):
        try:
            return analyse_record(read_record(resolve_record(name, source)), band, crank_speed=speed)
        except InputError as exc:
            raise InputError(f"signals.{field}: {exc}") from None

    def judge(analysis):
        return tuple(classify(c.velocity_rms, table.machine_class, table.standard, boundaries=table.boundaries)
                     for c in analysis.channels)

    before = analyse_file(table.record, "record")
    after = analyse_file(table.after, "after") if table.after else None
    labels = (table.label or record_label(table.record),
              table.after_label or (record_label(table.after) if table.after else "after"))
    pred_b: dict = {}
    pred_a: dict = {}
    predicted_labels = ("before", "after")
    frame_band: tuple[float, float] | None = None
    if frame_study is not None:
        predicted_labels = (frame_study.labels[0], frame_study.labels[1] or "after")
        frame_band = (float(frame_study.band[0]), float(frame_study.band[1]))
        for c in before.channels:
            if c.name in frame_study.points:
                p = frame_study.points[c.name]
                pred_b[c.name] = frame_study.before.rms(p, "velocity", frame_study.direction, band)
                if frame_study.after is not None:
                    pred_a[c.name] = frame_study.after.rms(p, "velocity", frame_study.direction, band)
    warnings = band_order_warnings(band, abs(speed), what="The records' band") if speed is not None else ()
    return SignalStudy(before, after, judge(before), judge(after) if after else None,
                       compare_records(before, after) if after else None, pred_b, pred_a, labels,
                       predicted_labels, band, frame_band, speed, warnings)
