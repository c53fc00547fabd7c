"""Report sections and plots of the vibration capability: mode table, response spectrum, RMS before/after per
point, severity zone chart, predicted against measured RMS velocity, and the measured spectra.

Plots take a result and an optional matplotlib ``ax`` and return the ``ax``; they read results only.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from markupsafe import escape

from ..vibration.orders import RESONANCE_MARGIN, near_resonances, order_levels
from .frame_view import frame_view
from .html import _render, format_value, rows_html

_COLOURS = {"before": "#c0392b", "after": "#2471a3"}
_ZONE_COLOURS = ("#d5f5e3", "#fcf3cf", "#fae5d3", "#f5b7b1")


def _axes(ax):
    if ax is None:
        from matplotlib.figure import Figure

        ax = Figure(figsize=(6, 3.5)).subplots()
    return ax


def _runs(study) -> list[tuple[str, Any, str]]:
    runs = [("before", study.before, study.labels[0])]
    if study.after is not None:
        runs.append(("after", study.after, study.labels[1]))
    return runs


def plot_response_spectrum(study, ax=None, point: str | None = None):
    """Velocity amplitude [mm/s] per harmonic order of the crank at one point (the first by default), before
    and after."""
    ax = _axes(ax)
    name = point or next(iter(study.points))
    p = study.points[name]
    f = study.before.loads.frequencies
    runs = _runs(study)
    width = 0.8 / len(runs)
    for i, (tag, resp, label) in enumerate(runs):
        amp = resp.amplitudes(p, "velocity", study.direction) * 1e3
        x = np.arange(f.size) + (i - (len(runs) - 1) / 2) * width
        ax.bar(x, amp, width, color=_COLOURS[tag], label=label)
    ax.set_xticks(np.arange(f.size), [f"{k}\n{v:.3g} Hz" for k, v in zip(study.before.loads.orders, f, strict=True)])
    ax.set_xlabel("harmonic order of the crank (frequency)")
    ax.set_ylabel("velocity amplitude [mm/s]")
    ax.set_title(f"Response spectrum at {name}")
    ax.legend()
    return ax


def plot_rms_comparison(study, ax=None, quantity: str = "acceleration"):
    """RMS ``quantity`` at every point, before and after (bars), with the reduction in % written above."""
    ax = _axes(ax)
    names = list(study.points)
    scale, unit = (1.0, "m/s²") if quantity == "acceleration" else (1e3, "mm/s")
    runs = _runs(study)
    width = 0.8 / len(runs)
    levels = {tag: study.rms(tag, quantity) * scale for tag, _, _ in runs}
    for i, (tag, _, label) in enumerate(runs):
        x = np.arange(len(names)) + (i - (len(runs) - 1) / 2) * width
        ax.bar(x, levels[tag], width, color=_COLOURS[tag], label=label)
    if "after" in levels:
        for j, (b, a) in enumerate(zip(levels["before"], levels["after"], strict=True)):
            ax.annotate(f"{(b - a) / b * 100:+.0f} %".replace("+", "−") if b > a else f"+{(a - b) / b * 100:.0f} %",
                        (j, max(a, b)), ha="center", va="bottom", fontsize=8)
    ax.set_xticks(np.arange(len(names)), names)
    ax.set_ylabel(f"RMS {quantity} [{unit}]")
    ax.set_title(f"RMS {quantity} per point")
    ax.legend()
    return ax


def plot_severity_zones(severities, ax=None, names=None, markers=None, series_names=None):
    """Zone chart: the zone bands of the standard (log velocity axis) and each judged level as a marker.

    ``severities`` : a list of (label, [Severity, ...]) series drawn side by side; ``names`` the tick labels.
    ``series_names`` : for each series, the tick name of each of its levels (records before and after may
    hold different channels); without it the levels of every series follow ``names`` in order.
    """
    ax = _axes(ax)
    first = severities[0][1][0]
    bounds = np.array(first.boundaries) * 1e3
    values = np.concatenate([[s.velocity_rms * 1e3 for s in sev] for _, sev in severities])
    top = max(bounds[-1] * 2.0, float(np.max(values)) * 1.5)
    low = min(bounds[0] / 4.0, max(float(np.min(values)) / 1.5, 1e-3))
    edges = [low, *bounds, top]
    labels = ("A", "B", "C", "D") if first.standard != "ISO 2372" else ("good", "satisf.", "unsatisf.", "unacc.")
    for k in range(4):
        ax.axhspan(edges[k], edges[k + 1], color=_ZONE_COLOURS[k], zorder=0)
        ax.text(1.0, np.sqrt(edges[k] * edges[k + 1]), f" {labels[k]}", transform=ax.get_yaxis_transform(),
                va="center", ha="left", fontsize=8)
    count = len(names) if names is not None else max(len(sev) for _, sev in severities)
    for i, (label, sev) in enumerate(severities):
        slots = (np.array([list(names).index(n) for n in series_names[i]]) if series_names is not None
                 and names is not None else np.arange(len(sev)))
        x = slots + (i - (len(severities) - 1) / 2) * 0.25
        colour = _COLOURS.get("after" if i else "before", None)
        ax.plot(x, [s.velocity_rms * 1e3 for s in sev], markers[i] if markers else "o", color=colour, label=label,
                linestyle="none")
    from matplotlib.ticker import FuncFormatter, LogLocator

    ax.set_yscale("log")
    ax.set_ylim(low, top)
    ax.yaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
    ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _pos: f"{v:g}"))
    ax.yaxis.set_minor_formatter(FuncFormatter(lambda v, _pos: ""))
    ax.set_xticks(np.arange(count), names if names is not None else [str(i + 1) for i in range(count)])
    ax.set_ylabel("RMS velocity [mm/s]")
    ax.set_title(f"{first.standard}, class {first.machine_class}")
    ax.legend(loc="upper left")
    return ax


def plot_predicted_vs_measured(study, ax=None):
    """Predicted and measured RMS velocity [mm/s] at each channel named like a frame point, before and after,
    on one plot (bars: measured; diamonds: predicted)."""
    ax = _axes(ax)
    names = [c.name for c in study.before.channels if c.name in study.predicted_before]
    runs = [("before", study.before, study.predicted_before, study.labels[0], study.predicted_labels[0])]
    if study.after is not None and study.predicted_after:
        runs.append(("after", study.after, study.predicted_after, study.labels[1], study.predicted_labels[1]))
    width = 0.8 / len(runs)
    for i, (tag, analysis, predicted, label, predicted_label) in enumerate(runs):
        x = np.arange(len(names)) + (i - (len(runs) - 1) / 2) * width
        ax.bar(x, [analysis.channel(n).velocity_rms * 1e3 for n in names], width, color=_COLOURS[tag], alpha=0.6,
               label=f"measured, {label}")
        ax.plot(x, [predicted[n] * 1e3 for n in names], "D", color=_COLOURS[tag], markeredgecolor="black",
                label=f"predicted, {predicted_label}")
    ax.set_xticks(np.arange(len(names)), names)
    ax.set_ylabel("RMS velocity [mm/s]")
    ax.set_title("Predicted against measured")
    ax.legend(fontsize=7)
    return ax


def plot_velocity_psd(analysis, ax=None, band=None):
    """Welch spectra of the band-limited velocity of every channel [(mm/s)²/Hz]."""
    ax = _axes(ax)
    top = 0.0
    for c in analysis.channels:
        keep = c.velocity_psd > 0
        ax.semilogy(c.frequencies[keep], c.velocity_psd[keep] * 1e6, label=c.name, linewidth=0.9)
        top = max(top, float(np.max(c.velocity_psd, initial=0.0)) * 1e6)
    if top > 0:
        ax.set_ylim(top * 1e-9, top * 3)  # nine decades: the band's filtered-out lines would reach 1e-20
    if band is not None:
        ax.set_xlim(0, min(band[1], float(analysis.channels[0].frequencies[-1])))
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel("velocity PSD [(mm/s)²/Hz]")
    ax.set_title("Measured velocity spectra (Welch)")
    ax.legend()
    return ax


# ------------------------------------------------------------------------------------------------ sections


def _figure(key, title, size, draw, ncols=1) -> str:
    fig = _render(key, title, "", size, draw, margins=(0.8, 0.45, 0.75, 0.4), wspace=0.35)
    return f'<figure class="plot">{fig.svg}</figure>'


def mode_table(study) -> str:
    """HTML table of the modes: frequency, damping ratio, dominant coordinate, mass-normalised shape."""
    rows = []
    for j, (f, z, dom) in enumerate(zip(study.modes.frequencies, study.modes.damping_ratios, study.modes.dominant(),
                                        strict=True), start=1):
        shape = study.modes.shapes[:, j - 1]
        # entries of rounding size (an uncoupled coordinate) are shown as 0
        x, y, th = np.where(np.abs(shape) < 1e-9 * np.max(np.abs(shape)), 0.0, shape)
        rows.append((str(j), format_value(float(f)), format_value(float(z)), {"theta": "rotation"}.get(dom, dom),
                     format_value(float(x)), format_value(float(y)), format_value(float(th))))
    table = rows_html(rows, ("mode", "frequency [Hz]", "damping ratio", "mostly", "x [m/√kg]", "y [m/√kg]",
                             "θ [rad/√kg]"))
    return table.replace('class="summary"', 'class="figures"', 1)


def frame_sections(outcome: Any) -> list[tuple[str, str]]:
    """Report sections of a ``[frame]`` outcome."""
    study = outcome.results
    crank_hz = study.before.loads.crank_speed / (2 * np.pi)
    orders = study.before.loads.orders
    near = [f"mode {j} ({f:.3g} Hz) near order {k} ({fk:.3g} Hz, {100 * d:+.1f} %, within "
            f"{100 * RESONANCE_MARGIN:.0f} %)" for j, f, k, fk, d in
            near_resonances(study.modes.frequencies, abs(study.before.loads.crank_speed), int(np.max(orders)))]
    direction = ("the vector of x and y" if study.direction is None
                 else f"the direction {np.degrees(study.direction):.4g}° from the x axis")
    intro = (f"<p>Rigid frame of {format_value(study.frame.mass)} kg on {len(study.frame.mounts)} mount lines, "
             f"driven by {orders.size} harmonics of the mechanism's shaking force and moment at "
             f"{crank_hz:.4g} Hz. RMS values along {escape(direction)}, in the band "
             f"{study.band[0]:g}–{study.band[1]:g} Hz.</p>")
    if near:
        intro += f"<p><b>Near resonance:</b> {escape('; '.join(near))}.</p>"
    moving = frame_view(study)
    sections = [("Frame modes", intro + (str(moving) if moving is not None else "") + mode_table(study))]
    names = list(study.points)
    rows = []
    for k, name in enumerate(names):
        row = [name]
        for tag, _, _ in _runs(study):
            acc, vel = study.rms(tag, "acceleration")[k], study.rms(tag, "velocity")[k]
            sev = (study.severity_before if tag == "before" else study.severity_after)[k]
            row += [format_value(float(acc)), format_value(float(vel * 1e3)), sev.zone]
        if study.acceleration is not None:
            row.append(format_value(float(study.acceleration.reduction[k])))
        rows.append(row)
    head = ["point"]
    for _, _, label in _runs(study):
        head += [f"RMS acc. {label} [m/s²]", f"RMS vel. {label} [mm/s]", f"zone {label}"]
    if study.acceleration is not None:
        head.append("reduction [%]")
    table = rows_html(rows, head).replace('class="summary"', 'class="figures"', 1)
    mount_rows = [[m.name, m.kind, format_value(m.stiffness), format_value(m.damping)]
                  + [format_value(resp.transmitted_force_rms(m.name)) for _, resp, _ in _runs(study)]
                  for m in study.frame.mounts]
    mount_head = ["mount line", "kind", "k [N/m]", "c [N·s/m]"] + [f"RMS force {lab} [N]" for _, _, lab in _runs(study)]
    mounts = rows_html(mount_rows, mount_head).replace('class="summary"', 'class="figures"', 1)

    def draw(fig):
        a1, a2 = fig.subplots(1, 2)
        plot_rms_comparison(study, a1, "acceleration")
        plot_response_spectrum(study, a2)

    def draw_zones(fig):
        ax = fig.subplots()
        series = [(study.labels[0], list(study.severity_before))]
        if study.severity_after is not None:
            series.append((study.labels[1], list(study.severity_after)))
        plot_severity_zones(series, ax, names)

    figures = _figure("frame-rms", "RMS and spectrum", (10.0, 3.8), draw)
    zones = _figure("frame-zones", "Severity zones", (6.5, 3.6), draw_zones)
    sections += [("Frame response: RMS per point", figures + table),
                 ("Predicted severity", zones), ("Forces to the foundation", mounts)]
    return sections


def predicted_note(study) -> str:
    """What the predicted column holds: which prediction stands next to which record, and in which band (with
    why it differs from the frame section's RMS velocities when the bands differ)."""
    pairs = f"'{study.labels[0]}' is set next to the prediction for '{study.predicted_labels[0]}'"
    if study.after is not None and study.predicted_after:
        pairs += f", '{study.labels[1]}' next to the one for '{study.predicted_labels[1]}'"
    text = (f"Predicted RMS velocity at the frame point named like each channel: {pairs}. The predictions are "
            f"taken in the records' band {study.band[0]:g}–{study.band[1]:g} Hz, to compare like with like.")
    if study.frame_band is not None and tuple(study.frame_band) != tuple(study.band):
        text += (f" The frame section's RMS velocities use the [frame] band {study.frame_band[0]:g}–"
                 f"{study.frame_band[1]:g} Hz, so they differ from these by the orders in one band and not in the "
                 f"other.")
    return text


def order_table(runs, count: int = 6) -> str:
    """HTML table of the RMS velocity [mm/s] of the first ``count`` orders of the running speed per record and
    channel (empty without a running speed); the orders below the band's lower edge read 0."""
    rows = []
    for _, analysis, _, label in runs:
        for c in analysis.channels:
            if c.orders is None:
                return ""
            levels = order_levels(c.orders, c.order_rms, count)
            rows.append([label, c.name] + ["–" if v is None else format_value(v * 1e3) for v in levels])
    head = ["record", "channel"] + [f"{k}× [mm/s]" for k in range(1, count + 1)]
    table = rows_html(rows, head).replace('class="summary"', 'class="figures"', 1)
    return ("<h3>Orders of the running speed</h3><p>RMS velocity of each order in the band (flat-top order "
            "spectrum); the whole order spectra are in <code>signals_orders.csv</code>.</p>" + table)


def signal_sections(outcome: Any) -> list[tuple[str, str]]:
    """Report sections of a ``[signals]`` outcome."""
    study = outcome.results
    runs = [("before", study.before, study.severity_before, study.labels[0])]
    if study.after is not None and study.severity_after is not None:
        runs.append(("after", study.after, study.severity_after, study.labels[1]))
    rows = []
    for tag, analysis, severity, label in runs:
        for c, s in zip(analysis.channels, severity, strict=True):
            pred = (study.predicted_before if tag == "before" else study.predicted_after).get(c.name)
            rows.append([label, c.name, c.quantity, format_value(c.velocity_rms * 1e3),
                         format_value(c.velocity_peak * 1e3),
                         "–" if c.acceleration_rms is None else format_value(c.acceleration_rms),
                         "–" if c.crest_factor is None else format_value(c.crest_factor), s.zone,
                         "–" if pred is None else format_value(pred * 1e3)])
    head = ["record", "channel", "measured", "RMS velocity [mm/s]", "peak velocity [mm/s]", "RMS acc. [m/s²]",
            "crest factor", "zone", "predicted RMS velocity [mm/s]"]
    if not study.predicted_before:
        head, rows = head[:-1], [r[:-1] for r in rows]
    table = rows_html(rows, head).replace('class="summary"', 'class="figures"', 1)
    first = study.severity_before[0]
    band = study.before.channels[0].band
    intro = (f"<p>Record <code>{escape(study.before.source)}</code> ({escape(study.labels[0])}): "
             f"{study.before.sampling_rate:.6g} Hz, {study.before.duration:.4g} s; band {band[0]:g}–{band[1]:g} Hz; "
             f"judged by {escape(first.standard)}, class {escape(first.machine_class)}.</p>")
    if study.running_speed is not None:
        f1 = abs(study.running_speed) / (2 * np.pi)
        intro += f"<p>Running speed of the machine: {f1 * 60:.4g} rpm ({f1:.4g} Hz, the 1× order).</p>"
    if study.reduction is not None:
        intro += (f"<p>Reduction of the mean RMS velocity from <code>{escape(study.before.source)}</code> "
                  f"({escape(study.labels[0])}) to <code>{escape(study.after.source if study.after else '')}</code> "
                  f"({escape(study.labels[1])}): <b>{study.reduction['mean']:.4g} %</b>.</p>")
    if study.predicted_before:
        intro += "<p>" + escape(predicted_note(study)) + "</p>"
    orders = order_table(runs)
    def draw_zones(fig):
        a1, a2 = fig.subplots(1, 2)
        names = [c.name for c in study.before.channels]
        names += [c.name for _, analysis, _, _ in runs for c in analysis.channels if c.name not in names]
        plot_severity_zones([(label, list(sev)) for _, _, sev, label in runs], a1, names,
                            series_names=[[c.name for c in analysis.channels] for _, analysis, _, _ in runs])
        plot_velocity_psd(study.before, a2, study.before.channels[0].band)

    sections = [("Measured vibration", intro + table + _figure("signals", "Zones and spectra", (10.0, 3.8),
                                                                draw_zones) + orders)]
    if study.predicted_before:
        def draw_pred(fig):
            plot_predicted_vs_measured(study, fig.subplots())

        sections.append(("Predicted against measured", _figure("pred-meas", "Predicted against measured",
                                                                (6.5, 3.6), draw_pred)))
    return sections
