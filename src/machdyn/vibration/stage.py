"""The ``[frame]`` and ``[signals]`` capabilities: stage functions, flat SI results with labels, CSV series.

Keys are made per point, mount and channel (``frame.rms_acceleration.before.centre``); their labels travel
with the outcome. Registered in :mod:`machdyn.kinds` by one line each.
"""

from __future__ import annotations

import math

import numpy as np

from ..balancing.frame import BalanceRun
from ..errors import InputError
from ..pipeline import Capability, Outcome, StageContext
from ..results.labels import Label
from .modes import check_supported
from .orders import band_order_warnings, resonance_warnings
from .response import check_resonance
from .signals import analyse_record, read_record
from .study import FrameStudy, SignalStudy, build_frame, resolve_record, study_frame, study_signals, with_variant
from .tables import FrameTable, SignalsTable

__all__ = ["FRAME", "SIGNALS", "frame_outcome", "run_frame", "run_signals", "signal_outcome"]

_ZONE = "0 = A/good ... 3 = D/unacceptable"


def _frame_values(study: FrameStudy) -> tuple[dict, dict, list[str]]:
    values: dict = {}
    labels: dict = {}
    summary: list[str] = []

    def put(key, value, text, unit="", display=None, show=False):
        values[key] = float(value)
        labels[key] = Label(text, unit, display)
        if show:
            summary.append(key)

    for j, (f, z) in enumerate(zip(study.modes.frequencies, study.modes.damping_ratios, strict=True), start=1):
        put(f"frame.mode_{j}.frequency", f, f"Frame mode {j}: natural frequency", "Hz", show=True)
        put(f"frame.mode_{j}.damping_ratio", z, f"Frame mode {j}: damping ratio")
    tags = [("before", study.before, study.severity_before, study.labels[0])]
    if study.after is not None and study.severity_after is not None:
        tags.append(("after", study.after, study.severity_after, study.labels[1]))
    for tag, resp, severity, label in tags:
        for (name, p), sev in zip(study.points.items(), severity, strict=True):
            acc = resp.rms(p, "acceleration", study.direction, study.band)
            put(f"frame.rms_acceleration.{tag}.{name}", acc, f"RMS acceleration at {name}, {label}", "m/s^2",
                show=True)
            put(f"frame.rms_velocity.{tag}.{name}", sev.velocity_rms, f"RMS velocity at {name}, {label}", "m/s",
                "mm/s")
            put(f"frame.zone.{tag}.{name}", sev.index, f"Predicted {sev.standard} zone at {name}, {label} ({_ZONE})")
        for m in study.frame.mounts:
            put(f"frame.transmitted_force.{tag}.{m.name}", resp.transmitted_force_rms(m.name),
                f"RMS force through {m.name} to the foundation, {label}", "N")
    if study.acceleration is not None:
        for name, r in zip(study.points, study.acceleration.reduction, strict=True):
            # a fraction, as every result is kept (SI: dimensionless), shown in %
            put(f"frame.acceleration_reduction.{name}", r / 100.0, f"Reduction of RMS acceleration at {name}", "",
                "%")
        put("frame.mean_acceleration_reduction", study.acceleration.mean_reduction / 100.0,
            "Reduction of the mean RMS acceleration over the points", "", "%", show=True)
    return values, labels, summary


def _frame_series(study: FrameStudy, samples: int = 360) -> dict:
    """``frame_spectrum``: velocity amplitude per order at each point; ``frame_time``: acceleration over one
    revolution (along the measuring direction, or x and y)."""
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


def _band(band) -> str:
    return f"{band[0]:g}–{band[1]:g} Hz"


def _zone_warnings(severities, what: str) -> tuple[str, ...]:
    return tuple(f"{what}: {s.velocity_rms * 1e3:.3g} mm/s RMS is in zone {s.zone} of {s.standard}, class "
                 f"{s.machine_class} ({s.meaning})." for s in severities if s.index == 3)


def frame_outcome(study: FrameStudy) -> Outcome:
    """The outcome of a frame study: flat results, labels, summary keys, series and zone-D warnings."""
    values, labels, summary = _frame_values(study)
    loads = study.before.loads
    orders = int(np.max(loads.orders))
    warnings = resonance_warnings(study.modes.frequencies, abs(loads.crank_speed), orders)
    warnings += band_order_warnings(study.band, abs(loads.crank_speed), orders, what="The [frame] band")
    warnings += _zone_warnings(study.severity_before, f"Predicted vibration ({study.labels[0]})")
    if study.severity_after is not None:
        warnings += _zone_warnings(study.severity_after, f"Predicted vibration ({study.labels[1]})")
    return Outcome(results=study, scalars=values, labels=labels, series=_frame_series(study), summary=summary,
                   warnings=warnings)


def run_frame(ctx: StageContext) -> Outcome:
    """Stage of ``[frame]``: the frame on its mounts driven by the analysed mechanism's shaking loads; compared
    with ``[frame.after]`` or, without it, with the mechanism as ``[balance]`` left it (its single balanced
    model)."""
    balance = ctx.result_of("balance", BalanceRun)
    balanced = balance.model if balance is not None else None
    return frame_outcome(study_frame(ctx.table, ctx.mechanism, ctx.analysis, balanced=balanced))


def signal_outcome(study: SignalStudy) -> Outcome:
    """The outcome of a signal study: per-channel RMS, zones and reductions; the velocity spectra as CSV."""
    values: dict = {}
    labels: dict = {}
    summary: list[str] = []
    runs = [("before", study.before, study.severity_before, study.labels[0])]
    if study.after is not None and study.severity_after is not None:
        runs.append(("after", study.after, study.severity_after, study.labels[1]))
    for tag, analysis, severity, label in runs:
        for c, sev in zip(analysis.channels, severity, strict=True):
            key = f"signals.velocity_rms.{tag}.{c.name}"
            values[key] = c.velocity_rms
            labels[key] = Label(f"Measured RMS velocity, {c.name}, {label}", "m/s", "mm/s")
            summary.append(key)
            values[f"signals.zone.{tag}.{c.name}"] = float(sev.index)
            labels[f"signals.zone.{tag}.{c.name}"] = Label(
                f"Measured {sev.standard} zone, {c.name}, {label} ({_ZONE})")
            if c.crest_factor is not None:
                values[f"signals.crest_factor.{tag}.{c.name}"] = c.crest_factor
                labels[f"signals.crest_factor.{tag}.{c.name}"] = Label(f"Crest factor, {c.name}, {label}")
            if c.acceleration_rms is not None:
                values[f"signals.acceleration_rms.{tag}.{c.name}"] = c.acceleration_rms
                labels[f"signals.acceleration_rms.{tag}.{c.name}"] = Label(
                    f"Measured RMS acceleration, {c.name}, {label}", "m/s^2")
        values[f"signals.mean_velocity_rms.{tag}"] = analysis.mean_velocity_rms
        labels[f"signals.mean_velocity_rms.{tag}"] = Label(f"Mean measured RMS velocity, {label}", "m/s", "mm/s")
    # in the records' band; said in the label when the frame's own RMS values use another band
    band = "" if study.frame_band in (None, study.band) else f" in the records' band {_band(study.band)}"
    for tag, predicted, label in (("before", study.predicted_before, study.predicted_labels[0]),
                                  ("after", study.predicted_after, study.predicted_labels[1])):
        for name, value in predicted.items():
            values[f"signals.predicted_velocity_rms.{tag}.{name}"] = value
            labels[f"signals.predicted_velocity_rms.{tag}.{name}"] = Label(
                f"Predicted RMS velocity{band}, {name}, {label}", "m/s", "mm/s")
    if study.reduction is not None:
        for name, r in study.reduction.items():
            key = "signals.mean_reduction" if name == "mean" else f"signals.reduction.{name}"
            values[key] = r / 100.0  # a fraction, shown in %
            labels[key] = Label("Reduction of the mean measured RMS velocity" if name == "mean"
                                else f"Reduction of measured RMS velocity, {name}", "", "%")
        summary.append("signals.mean_reduction")
    first = study.before.channels[0]
    psd: dict = {"frequency": (first.frequencies, "Hz")}
    for c in study.before.channels:
        psd[c.name] = (np.asarray(c.velocity_psd), "m^2/s^2/Hz")
    series: dict = {"signals_psd": psd}
    for tag, record in (("", study.before), ("_after", study.after)):
        if record is not None and record.channels[0].orders is not None:
            columns: dict = {"order": (record.channels[0].orders, "")}
            for c in record.channels:
                columns[c.name] = (np.asarray(c.order_rms), "m/s")
            series[f"signals_orders{tag}"] = columns
    warnings = (*study.warnings, *_zone_warnings(study.severity_before, f"Measured vibration ({study.labels[0]})"))
    return Outcome(results=study, scalars=values, labels=labels, series=series, summary=summary,
                   warnings=warnings)


def run_signals(ctx: StageContext) -> Outcome:
    """Stage of ``[signals]``: the records judged; next to the ``[frame]`` prediction when the file has one."""
    frame = ctx.result_of("frame", FrameStudy)
    # the running speed's magnitude: a crank turning clockwise (negative speed) has the same orders
    speed = abs(float(np.ravel(ctx.analysis.kinematics.speed)[0])) if ctx.analysis is not None else None
    study = study_signals(ctx.table, source=ctx.source, crank_speed=speed,
                          frame_study=frame)
    return signal_outcome(study)


def check_frame(problem, table, source: str | None = None) -> list[tuple[str, str]]:
    """What ``machdyn check`` can tell without analysing: the mounts support the frame (the variant's
    counterweights and springs are checked against the built mechanism by :func:`check_frame_model`)."""
    problems: list[tuple[str, str]] = []
    speed = float(problem.drive.speed)
    if not speed > 0:
        problems.append(("drive.speed", f"must be > 0 for [frame] (the shaking loads are harmonics of the crank "
                                        f"speed); got {speed:g} rad/s"))
    try:
        frame = build_frame(table, abs(speed) / (2 * math.pi))
        check_supported(frame)
        if speed > 0:
            orders = np.arange(1, table.orders + 1)
            check_resonance(frame, orders * speed, orders)
    except InputError as exc:
        problems.append(("frame.mounts", str(exc)))
    return problems


def check_frame_model(mechanism, table) -> list[tuple[str, str]]:
    """The variant's counterweights and springs sit on bodies and points of the file's built mechanism."""
    if table.after is None:
        return []
    try:
        with_variant(mechanism, table.after)
    except InputError as exc:
        where, _, message = str(exc).partition(": ")
        return [(where, message)]
    return []


def check_signals(problem, table, source: str | None = None) -> list[tuple[str, str]]:
    """Every record is read and checked against the band: ``machdyn:`` names a shipped record, an absolute path
    is read as it is, a relative one against the problem file's folder (``source``; for TOML text given directly,
    against the working folder). In a machine's file the running speed is the machine's: ``speed`` is refused."""
    problems: list[tuple[str, str]] = []
    if table.speed is not None and getattr(problem, "drive", None) is not None:
        problems.append(("signals.speed", f"the records' running speed is the machine's ([drive] speed) in a "
                                          f"file with a machine; got {table.speed:g} rad/s here too: leave "
                                          f"signals.speed out (it is for a file with [signals] alone)"))
    for field in ("record", "after"):
        name = getattr(table, field)
        if name is None:
            continue
        try:
            # the same reading and analysis as the run (band, integration, dead channels): check agrees with run
            analyse_record(read_record(resolve_record(name, source)), tuple(table.band))
        except InputError as exc:
            problems.append((f"signals.{field}", str(exc)))
    return problems


FRAME = Capability(
    table="frame", schema=FrameTable, run=run_frame, step="frame vibration", check=check_frame,
    check_model=check_frame_model,
    kinds=("mechanism", "rotary_screen"), report="machdyn.report.vibration:frame_sections", after=("balance",),
    result_type=FrameStudy, population="machdyn.vibration.population:frame_population",
)
SIGNALS = Capability(
    table="signals", schema=SignalsTable, run=run_signals, step="measured signals",
    kinds=("mechanism", "rotary_screen"), report="machdyn.report.vibration:signal_sections", after=("frame",),
    check=check_signals, result_type=SignalStudy,
)
