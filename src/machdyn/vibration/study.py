"""The vibration capability's stages: a frame study from ``[frame]`` and a signal study from ``[signals]``.

``study_frame`` builds the frame, its modes and the steady-state response to the analysed mechanism's
shaking loads (and to a variant with counterweights added), the RMS levels at the named points, the transmitted
force per mount and the predicted severity. ``study_signals`` reads the records, judges them and, with a frame
study, sets the predicted RMS velocity next to the measured one. ``run_frame`` / ``run_signals`` wrap them as
capability stages; ``scalars``/``series`` give the flat SI values written to results.json and CSV.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from ..errors import InputError
from .frame import Frame, Mount, rope, rubber_mount, tyre
from .modes import Modes, modes
from .response import Comparison, FrameResponse, compare, shaking_loads, steady_state
from .severity import Severity, classify
from .signals import RecordAnalysis, analyse_record, compare_records, read_record

__all__ = ["FrameStudy", "SignalStudy", "build_frame", "study_frame", "study_signals", "frame_scalars",
           "frame_series", "signal_scalars", "signal_series", "run_frame", "run_signals", "LABELS"]


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
    return Frame(table.mass, table.inertia, tuple(mounts), com=tuple(table.com), name="frame")


def with_counterweights(mechanism, counterweights):
    """``mechanism`` with the point masses of ``counterweights`` (problem-file specs) added."""
    from ..linkage.model import PointMass

    bodies = {b.name for b in mechanism.bodies}
    added = []
    for i, c in enumerate(counterweights):
        if c.body not in bodies:
            raise InputError(f"frame.after.counterweights[{i}].body: no body '{c.body}'; bodies: "
                             f"{', '.join(sorted(bodies))}.")
        position = (c.radius * math.cos(c.angle), c.radius * math.sin(c.angle))
        added.append(PointMass(c.name or f"after_counterweight_{i + 1}", c.body, c.mass, position, c.inertia))
    return replace(mechanism, point_masses=(*mechanism.point_masses, *added))


@dataclass(frozen=True)
class FrameStudy:
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

    def rms(self, which: str, quantity: str) -> np.ndarray:
        resp = self.before if which == "before" else self.after
        if resp is None:
            raise InputError("This frame study has no 'after' variant.")
        return np.array([resp.rms(p, quantity, self.direction, self.band) for p in self.points.values()])


def study_frame(table, mechanism, analysis) -> FrameStudy:
    """Run the frame study of a validated ``[frame]`` table for ``mechanism`` and its constant-speed ``analysis``."""
    from ..linkage import analyse

    kin = analysis.kinematics
    crank_frequency = float(np.ravel(kin.speed)[0]) / (2 * np.pi)
    frame = build_frame(table, crank_frequency)
    md = modes(frame)
    opts = {"orders": table.orders, "origin": tuple(table.mechanism_origin), "angle": table.mechanism_angle}
    before = steady_state(frame, shaking_loads(analysis, **opts))
    after = acc = vel = None
    label_after = ""
    if table.after is not None:
        variant = with_counterweights(mechanism, table.after.counterweights)
        an_after = analyse(variant, kin.crank_angle, float(np.ravel(kin.speed)[0]), diagnostics=False)
        after = steady_state(frame, shaking_loads(an_after, **opts))
        label_after = table.after.label
    points = dict(table.points)
    if after is not None:
        acc = _banded_compare(before, after, points, "acceleration", table.direction, table.band)
        vel = _banded_compare(before, after, points, "velocity", table.direction, table.band)

    def judge(resp):
        return tuple(classify(resp.rms(p, "velocity", table.direction, table.band), table.machine_class,
                              table.standard) for p in points.values())

    return FrameStudy(frame, md, points, (table.label, label_after), table.direction, tuple(table.band), before,
                      after, acc, vel, judge(before), judge(after) if after is not None else None)


def _banded_compare(before, after, points, quantity, direction, band) -> Comparison:
    cmp = compare(before, after, points, quantity, direction)
    b = np.array([before.rms(p, quantity, direction, band) for p in points.values()])
    a = np.array([after.rms(p, quantity, direction, band) for p in points.values()])
    return replace(cmp, before=b, after=a)


@dataclass(frozen=True)
class SignalStudy:
    """Measured records analysed and judged: ``before`` (and ``after``) analyses, the severity of each channel,
    the reduction per channel [%] and the predicted RMS velocity [m/s] at channels named like frame points."""

    before: RecordAnalysis
    after: RecordAnalysis | None
    severity_before: tuple[Severity, ...]
    severity_after: tuple[Severity, ...] | None
    reduction: dict | None
    predicted_before: dict
    predicted_after: dict
    labels: tuple[str, str] = ("before", "after")


def _resolve(name: str, source) -> Path:
    p = Path(name)
    if not p.is_absolute() and source is not None:
        p = Path(source).parent / p
    return p


def study_signals(table, *, source=None, crank_speed: float | None = None,
                  frame_study: FrameStudy | None = None) -> SignalStudy:
    """Read and judge the records of a validated ``[signals]`` table (file names relative to ``source``'s
    folder); with a ``frame_study``, predicted RMS velocities at the channels named like its points."""
    band = tuple(table.band)

    def analyse_file(name):
        return analyse_record(read_record(_resolve(name, source)), band, crank_speed=crank_speed)

    def judge(analysis):
        return tuple(classify(c.velocity_rms, table.machine_class, table.standard, boundaries=table.boundaries)
                     for c in analysis.channels)

    before = analyse_file(table.record)
    after = analyse_file(table.after) if table.after else None
    pred_b: dict = {}
    pred_a: dict = {}
    labels = ("before", "after")
    if frame_study is not None:
        labels = (frame_study.labels[0], frame_study.labels[1] or "after")
        for c in before.channels:
            if c.name in frame_study.points:
                p = frame_study.points[c.name]
                pred_b[c.name] = frame_study.before.rms(p, "velocity", frame_study.direction, band)
                if frame_study.after is not None:
                    pred_a[c.name] = frame_study.after.rms(p, "velocity", frame_study.direction, band)
    return SignalStudy(before, after, judge(before), judge(after) if after else None,
                       compare_records(before, after) if after else None, pred_b, pred_a, labels)


# ------------------------------------------------------------------------------------------- flat results

#: result key -> (label, SI unit, display unit)
LABELS: dict[str, tuple[str, str, str]] = {
    "frame.natural_frequencies": ("Natural frequencies of the frame", "Hz", "Hz"),
    "frame.damping_ratios": ("Modal damping ratios", "", ""),
    "frame.rms_acceleration.before": ("RMS acceleration at the points, before", "m/s^2", "m/s^2"),
    "frame.rms_acceleration.after": ("RMS acceleration at the points, after", "m/s^2", "m/s^2"),
    "frame.rms_velocity.before": ("RMS velocity at the points, before", "m/s", "mm/s"),
    "frame.rms_velocity.after": ("RMS velocity at the points, after", "m/s", "mm/s"),
    "frame.acceleration_reduction": ("Reduction of RMS acceleration per point", "%", "%"),
    "frame.mean_acceleration_reduction": ("Reduction of the mean RMS acceleration", "%", "%"),
    "frame.transmitted_force.before": ("RMS force per mount to the foundation, before", "N", "N"),
    "frame.transmitted_force.after": ("RMS force per mount to the foundation, after", "N", "N"),
    "frame.worst_zone.before": ("Worst predicted severity zone, before (0 = A ... 3 = D)", "", ""),
    "frame.worst_zone.after": ("Worst predicted severity zone, after (0 = A ... 3 = D)", "", ""),
    "signals.velocity_rms.before": ("Measured RMS velocity per channel", "m/s", "mm/s"),
    "signals.velocity_rms.after": ("Measured RMS velocity per channel, after", "m/s", "mm/s"),
    "signals.mean_velocity_rms.before": ("Mean measured RMS velocity", "m/s", "mm/s"),
    "signals.mean_velocity_rms.after": ("Mean measured RMS velocity, after", "m/s", "mm/s"),
    "signals.mean_reduction": ("Reduction of the mean RMS velocity", "%", "%"),
    "signals.worst_zone.before": ("Worst measured severity zone (0 = A ... 3 = D)", "", ""),
    "signals.worst_zone.after": ("Worst measured severity zone, after (0 = A ... 3 = D)", "", ""),
    "signals.crest_factor": ("Crest factor per channel", "", ""),
}


def frame_scalars(study: FrameStudy) -> dict:
    out: dict = {
        "frame.natural_frequencies": [float(v) for v in study.modes.frequencies],
        "frame.damping_ratios": [float(v) for v in study.modes.damping_ratios],
        "frame.rms_acceleration.before": [float(v) for v in study.rms("before", "acceleration")],
        "frame.rms_velocity.before": [float(v) for v in study.rms("before", "velocity")],
        "frame.transmitted_force.before": [study.before.transmitted_force_rms(m.name) for m in study.frame.mounts],
        "frame.worst_zone.before": float(max(s.index for s in study.severity_before)),
    }
    if study.after is not None and study.acceleration is not None and study.severity_after is not None:
        out.update({
            "frame.rms_acceleration.after": [float(v) for v in study.acceleration.after],
            "frame.rms_velocity.after": [float(v) for v in study.rms("after", "velocity")],
            "frame.acceleration_reduction": [float(v) for v in study.acceleration.reduction],
            "frame.mean_acceleration_reduction": study.acceleration.mean_reduction,
            "frame.transmitted_force.after": [study.after.transmitted_force_rms(m.name) for m in study.frame.mounts],
            "frame.worst_zone.after": float(max(s.index for s in study.severity_after)),
        })
    return out


def frame_series(study: FrameStudy, samples: int = 360) -> dict:
    """``frame_spectrum``: velocity amplitude per order at each point; ``frame_time``: acceleration along the
    measuring direction over one revolution (before, after)."""
    spectrum: dict = {"frequency": (study.before.loads.frequencies, "Hz")}
    time: dict = {}
    for name, p in study.points.items():
        for tag, resp in (("before", study.before), ("after", study.after)):
            if resp is None:
                continue
            spectrum[f"{name}_{tag}"] = (resp.amplitudes(p, "velocity", study.direction), "m/s")
            t, ax, ay = resp.time_history(p, "acceleration", samples)
            time.setdefault("time", (t, "s"))
            if study.direction is None:
                time[f"{name}_{tag}_x"] = (ax, "m/s^2")
                time[f"{name}_{tag}_y"] = (ay, "m/s^2")
            else:
                time[f"{name}_{tag}"] = (ax * math.cos(study.direction) + ay * math.sin(study.direction), "m/s^2")
    return {"frame_spectrum": spectrum, "frame_time": time}


def signal_scalars(study: SignalStudy) -> dict:
    out: dict = {
        "signals.velocity_rms.before": [c.velocity_rms for c in study.before.channels],
        "signals.mean_velocity_rms.before": study.before.mean_velocity_rms,
        "signals.worst_zone.before": float(max(s.index for s in study.severity_before)),
        "signals.crest_factor": [c.crest_factor for c in study.before.channels],
    }
    if study.after is not None and study.severity_after is not None and study.reduction is not None:
        out["signals.velocity_rms.after"] = [c.velocity_rms for c in study.after.channels]
        out["signals.mean_velocity_rms.after"] = study.after.mean_velocity_rms
        out["signals.mean_reduction"] = study.reduction["mean"]
        out["signals.worst_zone.after"] = float(max(s.index for s in study.severity_after))
    return out


def signal_series(study: SignalStudy) -> dict:
    """``signals_psd``: the Welch velocity spectrum of each channel of the (before) record."""
    first = study.before.channels[0]
    psd: dict = {"frequency": (first.frequencies, "Hz")}
    for c in study.before.channels:
        psd[c.name] = (c.velocity_psd, "m^2/s^2/Hz")
    return {"signals_psd": psd}


def _warnings(severities, what: str) -> tuple[str, ...]:
    return tuple(f"{what}: {s.velocity_rms * 1e3:.3g} mm/s is in zone {s.zone} of {s.standard}, class "
                 f"{s.machine_class} ({s.meaning})." for s in severities if s.index == 3)


def run_frame(ctx):
    """Capability stage of ``[frame]``: (ctx) -> Outcome."""
    from ..results import Outcome  # type: ignore[import-not-found]

    study = study_frame(ctx.table, ctx.mechanism, ctx.analysis)
    warnings = _warnings(study.severity_before, f"Predicted vibration ({study.labels[0]})")
    if study.severity_after is not None:
        warnings += _warnings(study.severity_after, f"Predicted vibration ({study.labels[1]})")
    return Outcome(results=study, scalars=frame_scalars(study), series=frame_series(study), warnings=warnings)


def run_signals(ctx):
    """Capability stage of ``[signals]``: (ctx) -> Outcome; uses the ``[frame]`` outcome when there is one."""
    from ..results import Outcome  # type: ignore[import-not-found]

    frame_outcome = getattr(ctx, "outcomes", {}).get("frame")
    speed = float(np.ravel(ctx.analysis.kinematics.speed)[0]) if ctx.analysis is not None else None
    study = study_signals(ctx.table, source=ctx.source, crank_speed=speed,
                          frame_study=frame_outcome.results if frame_outcome is not None else None)
    warnings = _warnings(study.severity_before, "Measured vibration")
    return Outcome(results=study, scalars=signal_scalars(study), series=signal_series(study), warnings=warnings)
