"""Report section of a ``[cam]`` problem: the SVAJ diagrams, the cam profile drawn with its largest pressure
angle and its smallest radius of curvature marked, the pressure angle against its limit, and the contact force
and camshaft torque over the turn."""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.ticker import MultipleLocator

from .cam_view import cam_view
from .html import _render, figures_html, format_value, rows_html
from .plotkit import PALETTE, _finish


def _cam_axis(ax: Any) -> None:
    ax.set_xlim(0, 360)
    ax.xaxis.set_major_locator(MultipleLocator(60))
    ax.grid(True, alpha=0.35, linewidth=0.6)
    ax.axhline(0.0, color="#888888", linewidth=0.6, zorder=0)


def plot_svaj(axes: Any, r: Any) -> None:
    """s, v, a, j per second at the running speed over the cam angle, the jumps marked."""
    m = r.model.profile.svaj
    deg = np.degrees(m.theta)
    v, a, j = m.per_second(r.speed)
    osc = r.model.follower.motion == "oscillating"
    scale, unit = (np.degrees(1.0), "deg") if osc else (1e3, "mm")
    rows = ((m.s * scale, f"s [{unit}]"), (v * scale, f"v [{unit}/s]"), (a * scale, f"a [{unit}/s²]"),
            (j * scale, f"j [{unit}/s³]"))
    for k, (ax, (y, name)) in enumerate(zip(axes, rows, strict=True)):
        ax.plot(deg, y, color=PALETTE[k], linewidth=1.2)
        ax.set_ylabel(name)
        _cam_axis(ax)
        for jump in r.model.program.jumps:
            ax.axvline(np.degrees(jump.angle), color=PALETTE[1], linewidth=0.6, linestyle=":")
    axes[-1].set_xlabel("cam angle θ [deg]")
    _finish(axes[0], "SVAJ at the running speed (dotted: a jump of velocity or acceleration)", legend=False)


def plot_profile(ax: Any, r: Any) -> Any:
    """The cam drawn: surface, pitch curve, cutter path, base circle; the points of the largest pressure angle and
    of the smallest convex radius of curvature marked (the follower drawn at the first)."""
    p = r.model.profile
    f = r.model.follower
    c = r.checks
    ax.fill(p.surface[0] * 1e3, p.surface[1] * 1e3, color="#e8eef7", zorder=0)
    ax.plot(p.surface[0] * 1e3, p.surface[1] * 1e3, color=PALETTE[0], linewidth=1.4, label="cam surface")
    if f.contact == "roller":
        ax.plot(p.pitch[0] * 1e3, p.pitch[1] * 1e3, color="#777777", linewidth=0.8, linestyle="--",
                label="pitch curve")
    if p.cutter_radius != f.roller_radius or f.contact != "roller":
        if p.cutter_radius > 0:
            ax.plot(p.cutter[0] * 1e3, p.cutter[1] * 1e3, color=PALETTE[4], linewidth=0.8, linestyle="-.",
                    label=f"cutter path (R {format_value(p.cutter_radius * 1e3)} mm)")
    t = np.linspace(0, 2 * np.pi, 200)
    ax.plot(f.base_radius * 1e3 * np.cos(t), f.base_radius * 1e3 * np.sin(t), color="#bbbbbb", linewidth=0.6,
            label="base circle")
    th = p.svaj.theta
    i = int(np.argmin(np.abs(th - c.max_pressure_angle_at)))
    if f.contact != "flat":  # a flat face's pressure angle is 0 everywhere
        ax.plot(p.surface[0, i] * 1e3, p.surface[1, i] * 1e3, "o", color=PALETTE[1],
                label=f"largest pressure angle {format_value(np.degrees(c.max_pressure_angle))}° "
                      f"at θ = {format_value(np.degrees(th[i]))}°")
    k = int(np.argmin(np.abs(th - c.min_radius_at)))
    if np.isfinite(c.min_pitch_radius) or f.contact == "flat":
        rho = c.min_surface_radius if f.contact == "flat" else c.min_pitch_radius
        ax.plot(p.surface[0, k] * 1e3, p.surface[1, k] * 1e3, "s", color=PALETTE[2],
                label=f"smallest radius of curvature {format_value(rho * 1e3)} mm "
                      f"at θ = {format_value(np.degrees(th[k]))}°")
        n = p.normal[:, k]
        centre = (p.pitch[:, k] - n * rho) if f.contact == "roller" else (p.surface[:, k] - n * rho)
        if 0 < rho < 10 * f.base_radius:
            ax.plot([p.surface[0, k] * 1e3, centre[0] * 1e3], [p.surface[1, k] * 1e3, centre[1] * 1e3],
                    color=PALETTE[2], linewidth=0.6)
    ax.plot([0], [0], "+", color="#333333")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.grid(True, alpha=0.3, linewidth=0.5)
    ax.legend(fontsize="x-small", loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2, framealpha=0.85)
    return _finish(ax, f"Cam profile ({'clockwise' if r.clockwise else 'counter-clockwise'}, θ = 0 up)",
                   legend=False)


def plot_pressure_and_curvature(ax: Any, r: Any) -> Any:
    """The pressure angle against its limit; for a flat face (whose pressure angle is 0) the contact point's
    distance from the follower's axis against the face's half width."""
    p = r.model.profile
    deg = np.degrees(p.svaj.theta)
    if r.model.follower.contact == "flat":
        off = (p.contact_offset - r.model.follower.offset) * 1e3
        ax.plot(deg, off, color=PALETTE[0], label="contact point from the follower's axis")
        width = r.face_width_given
        if width is not None:
            ax.axhline(width * 500, color=PALETTE[1], linestyle="--", linewidth=0.8, label="edge of the face")
            ax.axhline(-width * 500, color=PALETTE[1], linestyle="--", linewidth=0.8)
        ax.set_ylabel("contact offset [mm]")
        _cam_axis(ax)
        ax.set_xlabel("cam angle θ [deg]")
        return _finish(ax, "Contact point on the flat face")
    ax.plot(deg, np.degrees(p.pressure_angle), color=PALETTE[0], label="pressure angle φ")
    lim = np.degrees(r.checks.pressure_angle_limit)
    ax.axhline(lim, color=PALETTE[1], linestyle="--", linewidth=0.8, label=f"limit ±{format_value(lim)}°")
    ax.axhline(-lim, color=PALETTE[1], linestyle="--", linewidth=0.8)
    ax.set_ylabel("φ [deg]")
    _cam_axis(ax)
    ax.set_xlabel("cam angle θ [deg]")
    return _finish(ax, "Pressure angle")


def plot_forces(ax: Any, r: Any) -> Any:
    f = r.forces
    deg = np.degrees(f.svaj.theta)
    arm = r.model.arm
    ax.plot(deg, f.contact / arm, color=PALETTE[0], label="contact force F_c")
    ax.plot(deg, f.spring / arm, color=PALETTE[2], linewidth=0.8, label="spring force")
    ax.plot(deg, -f.inertia / arm, color=PALETTE[3], linewidth=0.8, label="−m a (inertia)")
    ax.set_ylabel("force [N]")
    _cam_axis(ax)
    ax.set_xlabel("cam angle θ [deg]")
    sim = r.simulation
    if sim is not None:
        order = np.argsort(np.mod(sim.theta, 2 * np.pi))
        ax.plot(np.degrees(np.mod(sim.theta, 2 * np.pi))[order], sim.contact[order] / arm, color="#333333",
                linewidth=0.7, linestyle=":", label="contact force, forward simulation")
    tw = ax.twinx()
    tw.plot(deg, f.torque, color=PALETTE[1], linewidth=1.0, linestyle="--", label="camshaft torque")
    tw.set_ylabel("torque [N·m]", color=PALETTE[1])
    handles = ax.get_legend_handles_labels()
    more = tw.get_legend_handles_labels()
    ax.legend(handles[0] + more[0], handles[1] + more[1], fontsize="x-small", framealpha=0.85)
    return _finish(ax, "Contact force and camshaft torque at the running speed", legend=False)


def sections(outcome: Any) -> list[tuple[str, str]]:
    """The cam's sections: motion, profile and checks, forces."""
    r = outcome.results

    def draw_svaj(fig):
        plot_svaj(fig.subplots(4, 1, sharex=True), r)

    def draw_profile(fig):
        a, b = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1.1, 1.0]})
        plot_profile(a, r)
        plot_pressure_and_curvature(b, r)

    figs = [_render("cam-svaj", "Follower motion (SVAJ)", "Displacement, velocity, acceleration and jerk per "
                    "second at the running speed.", (8.0, 7.0), draw_svaj, margins=(0.9, 0.2, 0.5, 0.35),
                    hspace=0.15),
            _render("cam-profile", "Cam profile and pressure angle" if r.model.follower.contact != "flat" else
                    "Cam profile and contact point on the face", "The profile as written to cam_profile.dxf "
                    "and cam_profile.csv, with the largest pressure angle and the smallest radius of curvature "
                    "marked.", (10.0, 5.6), draw_profile, margins=(0.7, 0.3, 1.35, 0.35), wspace=0.3)]
    if r.forces is not None:
        figs.append(_render("cam-forces", "Contact force and camshaft torque", "Force the cam must supply along "
                            "the follower's path (it loses contact where it would turn negative), the same force "
                            "from the forward simulation of the follower on the cam (dotted), and the camshaft "
                            "torque by virtual work.", (8.0, 3.6), lambda fig: plot_forces(fig.subplots(),
                                                                                                        r),
                            margins=(0.8, 0.8, 0.5, 0.35)))
    lift_unit = "rad" if r.model.follower.motion == "oscillating" else "m"
    rows = [[j.describe(lift_unit), ""] for j in r.model.program.jumps]
    seg_rows = []
    for k, s in enumerate(r.model.program.segments):
        osc = r.model.follower.motion == "oscillating"
        lift = (f"{format_value(np.degrees(s.lift))}°" if osc else f"{format_value(s.lift * 1e3)} mm") \
            if s.motion != "dwell" else ""
        seg_rows.append([str(k + 1), s.motion, f"{format_value(np.degrees(r.model.program.starts[k]))}°",
                         f"{format_value(np.degrees(s.duration))}°", lift, s.law if s.motion != "dwell" else ""])
    intro = (f"<p>{r.model.follower.motion.capitalize()} {r.model.follower.contact} follower, base circle "
             f"{format_value(r.model.follower.base_radius * 1e3)} mm, cam speed {format_value(r.speed * 30 / np.pi)} "
             "rpm. Pressure-angle limits after Norton, <i>Design of Machinery</i>, §8.6 (30° translating) and "
             "Rothbart, <i>Cam Design Handbook</i> (35–45° oscillating).</p>")
    html = intro + rows_html(seg_rows, ("segment", "motion", "start", "angle", "lift", "law"))
    html += stroke_table(r)
    if rows:
        html += "<p>Jumps in the program (the fundamental law of cam design asks for none):</p>" + rows_html(
            [[row[0]] for row in rows], ("jump",))
    moving = cam_view(r)
    return [("Cam", html + (str(moving) if moving is not None else "") + figures_html(figs))]


#: The strokes' figures shown in the report's table: figure -> (column, translating (factor, unit), oscillating).
_STROKE_COLUMNS: dict[str, tuple[str, tuple[float, str], tuple[float, str]]] = {
    "max_velocity": ("peak |v|", (1.0, "m/s"), (1.0, "rad/s")),
    "max_acceleration": ("peak |a|", (1.0, "m/s²"), (1.0, "rad/s²")),
    "max_jerk": ("peak |j|", (1.0, "m/s³"), (1.0, "rad/s³")),
    "max_pressure_angle": ("largest |φ|", (180 / np.pi, "°"), (180 / np.pi, "°")),
    "min_pitch_curvature_radius": ("smallest convex ρ (pitch)", (1e3, "mm"), (1e3, "mm")),
    "min_surface_curvature_radius": ("smallest ρ (face)", (1e3, "mm"), (1e3, "mm")),
    "max_contact_force": ("largest contact force", (1.0, "N"), (1.0, "N")),
    "max_normal_force": ("largest normal force", (1.0, "N"), (1.0, "N")),
    "peak_torque": ("peak |T| camshaft", (1.0, "N·m"), (1.0, "N·m")),
}


def stroke_table(r: Any) -> str:
    """Each rise's and return's own exact extremes (``cam.segment<n>.<figure>``), one row a stroke, with the cam
    angle of each figure under its value."""
    each = getattr(r, "strokes", ())
    if not each:
        return ""
    osc = r.model.follower.motion == "oscillating"
    shown = [f for f in _STROKE_COLUMNS if any(f in s.figures for s in each)]
    rows = []
    for s in each:
        row = [str(s.number), s.motion, f"{format_value(np.degrees(s.start))}–{format_value(np.degrees(s.end))}°"]
        for f in shown:
            column = _STROKE_COLUMNS[f]
            factor, unit = column[2] if osc else column[1]
            at = format_value(round(float(np.degrees(s.where[f])), 4) + 0.0)  # 1e-10° just inside an end: 0°
            shown_unit = unit if unit == "°" else f" {unit}"
            row.append(f"{format_value(s.figures[f] * factor)}{shown_unit} at {at}°" if f in s.figures else "—")
        rows.append(row)
    head = ("segment", "stroke", "cam angles", *(_STROKE_COLUMNS[f][0] for f in shown))
    return ("<p>Each stroke's own extremes, exact on its law (results <code>cam.segment&lt;n&gt;.&lt;figure&gt;"
            "</code>; the largest of them is the turn's exact peak, which the turn's results sampled at the profile's "
            "angles approach from below):</p>" + rows_html(rows, head))


def shaft_sections(outcome: Any) -> list[tuple[str, str]]:
    """The ``[shaft_cam]`` section of a linkage file: the cam's section under its own heading."""
    return [("Cam on the crank shaft", html) for _, html in sections(outcome)]


def plot_follower_linkage_torque(ax: Any, r: Any) -> Any:
    """The camshaft torque of the cam alone and with the linkage its follower drives, over the cam angle."""
    deg = np.degrees(r.cam_angle)
    ax.plot(deg, r.cam_torque, color=PALETTE[0], linewidth=1.0, linestyle="--", label="cam alone")
    ax.plot(deg, r.total_torque, color=PALETTE[1], linewidth=1.4, label="cam and linkage")
    ax.plot(deg, r.load.camshaft_torque, color=PALETTE[2], linewidth=0.8, linestyle=":",
            label="added by the linkage, T_crank dθ/dφ")
    ax.set_ylabel("camshaft torque [N·m]")
    _cam_axis(ax)
    ax.set_xlabel("cam angle φ [deg]")
    return _finish(ax, "Camshaft torque at the running speed")


def follower_linkage_sections(outcome: Any) -> list[tuple[str, str]]:
    """The ``[follower_linkage]`` section: the camshaft torque with and without the linkage, and its figures."""
    r = outcome.results
    s = outcome.scalars
    fig = _render("follower-linkage-torque", "Camshaft torque with the linkage", "The camshaft torque of the cam "
                  "and its follower alone, with the linkage the follower drives, and the linkage's part by power "
                  "balance (the torque driving the linkage's crank times the crank's angular velocity ratio).",
                  (8.0, 3.6), lambda f: plot_follower_linkage_torque(f.subplots(), r), margins=(0.8, 0.3, 0.5, 0.35))
    travel = "stroke" if r.slider else "swing"
    shown = (np.ptp(r.position) * 1e3, "mm") if r.slider else (np.degrees(np.ptp(r.position)), "deg")
    rows = [["output", f"{r.output} ({travel} {format_value(shown[0])} {shown[1]})"],
            ["peak |load| of the linkage on the follower (at the roller)",
             f"{format_value(float(np.max(np.abs(r.load.moment))) / r.cam.model.arm)} N"],
            ["peak |camshaft torque|, cam alone", f"{format_value(float(np.max(np.abs(r.cam_torque))))} N·m"],
            ["peak |camshaft torque|, with the linkage",
             f"{format_value(float(np.max(np.abs(r.total_torque))))} N·m"],
            ["smallest contact force with the linkage", f"{format_value(float(np.min(r.contact)))} N"]]
    if "follower_linkage.jump_speed" in s:
        rows.append(["follower jump speed with the linkage",
                     f"{format_value(float(s['follower_linkage.jump_speed']) * 30 / np.pi)} rpm"])
    intro = ("<p>The follower moves the linkage's crank (an oscillating follower's arm is the crank); its angle, speed "
             "and acceleration follow the cam's motion program. The camshaft supplies the linkage's driving torque "
             "through the follower, T_cam = T_crank dθ/dφ (power balance), and the contact force carries it "
             "too.</p>")
    return [("Linkage driven by the follower", intro + rows_html(rows, ("quantity", "value")) + figures_html([fig]))]
