"""Report section of ``[drivetrain]``: the train drawn as stages, the torque of every shaft over the cycle, the
clutch engagement and the brake's stops."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from matplotlib.patches import FancyBboxPatch

from .html import _render, figures_html, format_value, rows_html
from .plotkit import PALETTE, _finish

RPM = 30.0 / np.pi


def plot_train(ax: Any, train: Any, clutch_shaft: int | None = None) -> Any:
    """The train as a row of shafts joined by their stages (ratio and efficiency written on each)."""
    n = len(train.stages)
    for k in range(n + 1):
        name = "motor" if k == 0 else ("crank" if k == n else f"shaft {k}")
        ax.add_patch(FancyBboxPatch((k * 2.0, 0.0), 1.2, 1.0, boxstyle="round,pad=0.05",
                                    facecolor="#e8eef7", edgecolor="#0b5cad"))
        ax.text(k * 2.0 + 0.6, 0.62, name, ha="center", va="center", fontsize="small")
        ax.text(k * 2.0 + 0.6, 0.3, f"{format_value(train.shaft_inertia[k])} kg·m²", ha="center", va="center",
                fontsize="x-small", color="#555555")
    for k, s in enumerate(train.stages):
        x = k * 2.0 + 1.25
        ax.annotate("", (x + 0.7, 0.5), (x, 0.5), arrowprops={"arrowstyle": "->", "color": "#333333"})
        ax.text(x + 0.35, 0.75, f"{s.kind} {format_value(s.ratio)}:1", ha="center", fontsize="x-small")
        ax.text(x + 0.35, 0.2, f"η {format_value(s.efficiency)}", ha="center", fontsize="x-small")
        if clutch_shaft == k:
            ax.plot([x + 0.35, x + 0.35], [0.35, 0.65], color=PALETTE[1], linewidth=3)
    ax.set_xlim(-0.3, 2.0 * n + 1.5)
    ax.set_ylim(-0.1, 1.1)
    ax.axis("off")
    return _finish(ax, "Drive train (orange bar: clutch)", legend=False)


def plot_shaft_torques(ax: Any, run: Any) -> Any:
    """The torque each shaft transmits over the crank angle."""
    phi = np.degrees(run.crank_angle)
    n = len(run.train.stages)
    for k, t in enumerate(run.shaft_torques):
        name = "motor" if k == 0 else ("crank" if k == n else f"shaft {k}")
        ax.plot(phi, t, color=PALETTE[k % len(PALETTE)], label=name)
    ax.set_xlabel("crank angle [deg]")
    ax.set_ylabel("torque [N·m]")
    ax.set_yscale("symlog", linthresh=max(1e-3, float(np.max(np.abs(run.shaft_torques[0]))) / 10))
    return _finish(ax, "Shaft torques")


def plot_stops(ax: Any, run: Any) -> Any:
    """Crank speed against the angle turned after the brake is applied, for every application angle."""
    for k, s in enumerate(run.stops):
        worst = s is run.worst_stop
        ax.plot(np.degrees(s.phi - s.phi[0]), s.omega * RPM, color=PALETTE[0] if worst else "#bbbbbb",
                linewidth=1.6 if worst else 0.8, label="worst" if worst else ("others" if k == 0 else None))
    ax.set_xlabel("crank angle after the brake is applied [deg]")
    ax.set_ylabel("crank speed [rpm]")
    return _finish(ax, "Brake stops")


_PHASES = (("slip", "#ffd8a8"), ("locked", "#d8f0d8"), ("braking", "#f8c8c8"), ("recovery", "#e4e4f4"))


def plot_single_stroke(axes: Any, stroke: Any) -> Any:
    """The single stroke against time: crank and flywheel-side speeds (crank units) with the phases shaded, and
    the torque the clutch passes (at the crank)."""
    speed_ax, torque_ax = axes
    for ax in axes:
        for name, colour in _PHASES:
            inside = stroke.phase == name
            if inside.any():
                times = stroke.t[inside]
                ax.axvspan(float(times.min()), float(times.max()), color=colour, alpha=0.6, linewidth=0,
                           label=name if ax is speed_ax else None)
    speed_ax.plot(stroke.t, stroke.omega * RPM, color=PALETTE[0], label="crank")
    speed_ax.plot(stroke.t, stroke.omega_drive * RPM, color=PALETTE[1], linestyle="--", label="flywheel side")
    speed_ax.set_xlabel("time [s]")
    speed_ax.set_ylabel("speed, crank units [rpm]")
    _finish(speed_ax, "Single stroke: speeds")
    torque_ax.plot(stroke.t, stroke.clutch_torque, color=PALETTE[2])
    torque_ax.set_xlabel("time [s]")
    torque_ax.set_ylabel("clutch torque at the crank [N·m]")
    return _finish(torque_ax, "Single stroke: clutch torque")


def plot_brake_heating(ax: Any, heating: Any) -> Any:
    """The drum's temperature rise over repeated stops: a jump of ΔT per stop, Newton cooling between them, and
    the steady peak the series tends to."""
    stops = 1 if not math.isfinite(heating.interval) else max(3, min(400, int(math.ceil(
        4.0 / max(heating.decay_rate * heating.interval, 1e-9)))))
    t, rise = heating.history(stops, points=max(4, 4000 // stops))
    ax.plot(np.asarray(t) / 60.0, rise, color=PALETTE[3 % len(PALETTE)], linewidth=0.9, label="drum")
    ax.axhline(heating.steady_peak_rise, color="#888888", linestyle="--", label="steady peak")
    ax.set_xlabel("time [min]")
    ax.set_ylabel("temperature rise [K]")
    return _finish(ax, "Brake drum heating over repeated stops")


def _geometry_rows(run: Any) -> list[list[str]]:
    """Rows for a clutch and a brake computed from their geometry."""
    rows = []
    rating = getattr(run, "clutch_rating", None)
    if rating is not None and run.engagement is not None:
        rows.append(["clutch: slip torque on its shaft", f"{format_value(rating.torque)} N·m"])
        if rating.force > 0:
            rows.append(["clutch: axial force, largest face pressure",
                         f"{format_value(rating.force)} N, {format_value(rating.max_pressure / 1e6)} MPa"])
        if rating.engagement_speed > 0:
            rows.append(["clutch: shoes touch the drum at", f"{format_value(rating.engagement_speed * 30 / np.pi)}"
                                                            " rpm of the clutch shaft"])
        rows.append(["clutch: driven side's acceleration while slipping",
                     f"{format_value(run.engagement.driven_acceleration)} rad/s² (driving side slows at "
                     f"{format_value(run.engagement.driving_deceleration)} rad/s²)"])
    braking = getattr(run, "brake_rating", None)
    if braking is not None and braking.lever_force > 0:
        rows.append(["brake: braking torque on its shaft",
                     f"{format_value(braking.torque)} N·m for {format_value(braking.lever_force)} N at the lever "
                     f"({'self-energising' if braking.self_energising else 'not self-energising'}; "
                     f"{format_value(braking.torque_reverse)} N·m turning the other way)"])
        if braking.max_pressure > 0:
            rows.append(["brake: largest lining pressure", f"{format_value(braking.max_pressure / 1e6)} MPa"])
    for g in getattr(run, "gear_checks", ()):
        allowed = (f" (allowed {format_value(g.allowable_bending / 1e6)} MPa)" if g.allowable_bending else "")
        rows.append([f"gear stage {g.stage}: tooth root stress (Lewis, K_v {format_value(g.velocity_factor)})",
                     f"pinion {format_value(g.pinion_bending / 1e6)} MPa, gear {format_value(g.gear_bending / 1e6)} "
                     f"MPa{allowed}; tangential load {format_value(g.tangential_load)} N at "
                     f"{format_value(g.pitch_speed)} m/s"])
        allowed = (f" (allowed {format_value(g.allowable_contact / 1e6)} MPa)" if g.allowable_contact else "")
        rows.append([f"gear stage {g.stage}: contact stress (Hertz)", f"{format_value(g.contact / 1e6)} MPa{allowed}"])
        r = g.strength
        if r is not None:
            wear = ("" if r.wear_strength is None or r.safety_wear is None else
                    f", wear strength {format_value(r.wear_strength)} N (safety {format_value(r.safety_wear)})")
            rows.append([f"gear stage {g.stage}: effective load ({r.method}) against the teeth's strengths",
                         f"{format_value(r.effective_load)} N; beam strength {format_value(r.beam_strength)} N "
                         f"(safety {format_value(r.safety_bending)}){wear}; required {format_value(r.safety_factor)}"])
    for c in getattr(run, "shaft_checks", ()):
        rows.append([f"shaft {c.shaft}: at the wheel",
                     f"M = {format_value(c.moment)} N·m, T = {format_value(c.torque_mean)} ± "
                     f"{format_value(c.torque_amplitude)} N·m; fatigue safety {format_value(c.fatigue_safety)}"
                     f"{'' if not math.isfinite(c.yield_safety) else f', yield {format_value(c.yield_safety)}'}"
                     f" (at least {format_value(c.min_safety)}); deflection {format_value(c.deflection * 1e3)} mm"])
        rows.append([f"shaft {c.shaft}: first critical speed",
                     f"{format_value(c.critical_dunkerley * 30 / math.pi)} rpm (Dunkerley) to "
                     f"{format_value(c.critical_rayleigh * 30 / math.pi)} rpm (Rayleigh); runs at "
                     f"{format_value(c.running_speed * 30 / math.pi)} rpm"])
    heating = getattr(run, "heating", None)
    if heating is not None:
        rows.append(["brake: drum temperature rise", f"{format_value(heating.rise_per_stop)} K per stop, "
                                                     f"{format_value(heating.steady_peak_rise)} K after many stops"])
    return rows


def _stroke_html(stroke: Any) -> str:
    figure = _render("single-stroke", "Single stroke", "Clutch in from rest, the stroke, clutch out and brake, "
                     "then the motor bringing the flywheel back to speed.", (10.0, 3.6),
                     lambda fig: plot_single_stroke(fig.subplots(1, 2), stroke), margins=(0.75, 0.3, 0.6, 0.45),
                     wspace=0.3)
    rows = [["clutch slips for", f"{format_value(stroke.slip_time)} s, dissipating "
                                  f"{format_value(stroke.clutch_energy)} J"],
            ["brake closes at", f"{format_value(np.degrees(stroke.brake_angle) % 360)}° of the crank"],
            ["crank at rest after", f"{format_value(stroke.stop_time)} s and "
                                    f"{format_value(np.degrees(stroke.stop_angle))}° of braking, "
                                    f"{format_value(np.degrees(stroke.overrun))}° past the start angle"],
            ["stroke (clutch in to rest)", f"{format_value(stroke.stroke_time)} s"],
            ["flywheel back to speed", f"{format_value(stroke.recovery_time)} s after the crank stops"],
            ["most strokes a minute", format_value(stroke.strokes_per_minute)]]
    return "<h3>Single stroke</h3>" + figures_html([figure]) + rows_html(rows, ("item", "value"))


def sections(outcome: Any) -> list[tuple[str, str]]:
    """The ``[drivetrain]`` section."""
    run = outcome.results
    heating = getattr(run, "heating", None)
    panels = 2 + (run.worst_stop is not None) + (heating is not None)

    def draw(fig):
        axes = fig.subplots(1, panels)
        plot_train(axes[0], run.train, run.clutch_shaft)
        plot_shaft_torques(axes[1], run)
        if run.worst_stop is not None:
            plot_stops(axes[2], run)
        if heating is not None:
            plot_brake_heating(axes[-1], heating)

    figure = _render("drivetrain", "Drive train, shaft torques and brake", "", (4.6 * panels, 3.4), draw,
                     margins=(0.7, 0.3, 0.65, 0.45), wspace=0.35)
    rows = []
    if run.engagement is not None:
        e = run.engagement
        ratio = run.train.speed_ratios[run.clutch_shaft]
        rows += [["clutch: slip time", f"{format_value(e.slip_time)} s"],
                 ["clutch: energy dissipated per engagement", f"{format_value(e.dissipated)} J"],
                 ["clutch: crank speed when the slip ends",
                  f"{format_value(e.common_speed / ratio * RPM)} rpm (running {format_value(run.crank_speed * RPM)})"]]
    rows += _geometry_rows(run)
    if run.worst_stop is not None:
        s = run.worst_stop
        rows += [["brake: worst stop", f"{format_value(s.time)} s over {format_value(np.degrees(s.angle))}° of the "
                                      f"crank, applied at {format_value(np.degrees(s.phi[0]) % 360)}°"]]
    intro = (f"<p>{len(run.train.stages)} stage(s), motor speed / crank speed {format_value(run.train.total_ratio)},"
             f" efficiency {format_value(run.train.efficiency)}; the shafts' inertia reflected to the crank is "
             f"{format_value(run.train.reflected_inertia())} kg·m². Stopping time and overrun are the figures "
             "ISO 16092-1 requires a press to know and monitor.</p>")
    stroke = _stroke_html(run.single_stroke) if getattr(run, "single_stroke", None) is not None else ""
    return [("Drive train", intro + figures_html([figure]) + (rows_html(rows, ("item", "value")) if rows else "")
             + stroke)]
