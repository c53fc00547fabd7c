"""Report section of a ``[shaft_line]`` problem: the shaft drawn with its planes, the force and couple polygons,
the loads over the turn before and after correction, the engine's orders, the grade check and field balancing."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..results.labels import display_factor
from ..shafts.balance import forward_first_harmonic
from .html import _render, figures_html, format_value, rows_html
from .plotkit import PALETTE, _finish


def plot_shaft(ax: Any, result: Any) -> Any:
    """Side view: the shaft along z, a plane per mass, cylinder and correction, bearings as triangles; each
    mass's stalk proportional to its unbalance m r and drawn at its angle's projection on y."""
    line = result.line
    items = [(m.position, m.mass * m.radius, m.angle, m.name, PALETTE[0]) for m in line.masses]
    items += [(c.position, (c.reciprocating_mass + c.rotating_mass) * c.crank, c.phase, c.name, PALETTE[2])
              for c in line.cylinders]
    if result.balance is not None:
        items += [(c.plane.position, c.unbalance, c.angle, f"corr. {c.plane.name}", PALETTE[1])
                  for c in result.balance.corrections]
    items += [(lk.position, 0.0, 0.0, f"linkage {lk.name}", PALETTE[3]) for lk in line.linkages]
    zs = [z for z, *_ in items] + [b.position for b in line.bearings] or [0.0]
    z0, z1 = min(zs), max(zs)
    span = max(z1 - z0, 1e-3)
    top = max([u for _, u, *_ in items] + [1e-12])
    ax.plot([z0 - 0.05 * span, z1 + 0.05 * span], [0, 0], color="#333333", linewidth=3, zorder=1)
    for z, u, a, name, colour in items:
        h = 0.9 * u / top * math.copysign(1.0, math.cos(a)) if u > 0 else 0.0
        ax.plot([z, z], [-1.0, 1.0], color="#cccccc", linewidth=0.8, zorder=0)
        ax.plot([z, z], [0, h], color=colour, linewidth=2.5, zorder=2)
        ax.plot([z], [h], "o", color=colour, zorder=3)
        ax.text(z, 1.05, name, ha="center", va="bottom", fontsize="x-small", rotation=90)
    for b in line.bearings:
        ax.plot([b.position], [-1.15], "^", color="#555555", markersize=10)
        ax.text(b.position, -1.45, b.name, ha="center", fontsize="x-small")
    ax.set_ylim(-1.7, 1.9)
    ax.set_yticks([])
    ax.set_xlabel("axial position [m]")
    return _finish(ax, "Shaft line (stalk: m·r, sign of cos of its angle)", legend=False)


def _polygon(ax: Any, vectors: list[tuple[complex, str, str]], title: str, unit: str) -> Any:
    p = 0j
    for v, name, colour in vectors:
        ax.annotate("", (p.real + v.real, p.imag + v.imag), (p.real, p.imag),
                    arrowprops={"arrowstyle": "->", "color": colour, "linewidth": 1.4})
        ax.text(p.real + v.real / 2, p.imag + v.imag / 2, name, fontsize="x-small", color=colour)
        p += v
    pts = np.cumsum([0j] + [v for v, *_ in vectors])
    ax.plot(pts.real, pts.imag, alpha=0)  # sets the limits
    ax.plot([0], [0], "k.", markersize=4)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(f"x [{unit}]")
    ax.set_ylabel(f"y [{unit}]")
    closing = abs(p)
    return _finish(ax, f"{title} (gap {format_value(closing)} {unit})", legend=False)


def _vectors(result: Any, moment: bool) -> list[tuple[complex, str, str]]:
    line = result.line
    ref = line.reference
    out = []
    for m in line.balanced_masses():
        out.append((m.unbalance * ((m.position - ref) if moment else 1.0), m.name, PALETTE[0]))
    if result.balance is not None and line.balance_target == "first_harmonic":
        a, cm = forward_first_harmonic(result.loads)
        w2 = result.loads.speed ** 2
        known = sum((m.unbalance * ((m.position - ref) if moment else 1.0) for m in line.balanced_masses()), 0j)
        rest = (cm if moment else a) / w2 - known
        if abs(rest) > 0:
            out.append((rest, "cylinders and linkages, forward 1x", PALETTE[3]))
    if result.balance is not None:
        for c in result.balance.corrections:
            m = c.as_mass()
            out.append((m.unbalance * ((m.position - ref) if moment else 1.0), m.name, PALETTE[1]))
    return [v for v in out if abs(v[0]) > 0]


def plot_loads(ax: Any, result: Any, couple: bool) -> Any:
    deg = np.degrees(result.loads.angle)
    before = result.loads.couple if couple else result.loads.force
    ax.plot(deg, before, color=PALETTE[0], label="as given, magnitude")
    ax.plot(deg, result.loads.my if couple else result.loads.fx, color=PALETTE[0], linestyle="--", linewidth=0.9,
            label="as given, " + ("about y" if couple else "x component"))
    if result.balance is not None:
        after = result.balance.after.couple if couple else result.balance.after.force
        ax.plot(deg, after, color=PALETTE[1], label="corrected, magnitude")
    ax.set_xlabel("shaft angle [deg]")
    ax.set_ylabel("|couple| [N·m]" if couple else "|force| [N]")
    ax.set_xlim(0, 360)
    ax.grid(True, alpha=0.35)
    return _finish(ax, "Resultant couple" if couple else "Resultant force")


def plot_orders(ax: Any, engine: Any) -> Any:
    k = engine.orders
    # orders that cancel leave round-off (1e-13 of the largest); drawn as zero
    force = np.where(engine.force_order > 1e-9 * max(float(engine.force_order.max()), 1e-300), engine.force_order, 0)
    couple = np.where(engine.couple_order > 1e-9 * max(float(engine.couple_order.max()), float(force.max()), 1e-300),
                      engine.couple_order, 0.0)
    ax.bar(k - 0.2, force, width=0.4, color=PALETTE[0], label="force [N]")
    ax2 = ax.twinx()
    ax2.bar(k + 0.2, couple, width=0.4, color=PALETTE[2], label="couple [N·m]")
    if not couple.any():
        ax2.set_ylim(0.0, 1.0)
    ax.set_xlabel("order of the shaft speed")
    ax.set_ylabel("largest force [N]")
    ax2.set_ylabel("largest couple [N·m]")
    ax.set_xticks(k)
    return _finish(ax, "Engine: exact harmonic orders (blue force, green couple)", legend=False)


def plot_readings(ax: Any, original: Any, trials: Any, unit: str = "") -> Any:
    """The 1x readings as vectors from the origin: the original run (solid) and each trial run (dashed), one
    colour per sensor; angles are the phase lags."""
    for j, o in enumerate(original):
        colour = PALETTE[j % len(PALETTE)]
        v = o.amplitude * np.exp(1j * o.phase)
        ax.annotate("", (v.real, v.imag), (0, 0), arrowprops={"arrowstyle": "->", "color": colour, "linewidth": 1.6})
        ax.text(v.real, v.imag, f"O{j + 1}", color=colour, fontsize="x-small")
        for k, t in enumerate(trials):
            r = t[j]
            u = r.amplitude * np.exp(1j * r.phase)
            ax.annotate("", (u.real, u.imag), (0, 0), arrowprops={"arrowstyle": "->", "color": colour,
                                                                  "linestyle": "--", "linewidth": 1.0})
            ax.text(u.real, u.imag, f"T{k + 1}", color=colour, fontsize="x-small")
    top = max([o.amplitude for o in original] + [r.amplitude for t in trials for r in t] + [1e-12]) * 1.15
    ax.set_xlim(-top, top)
    ax.set_ylim(-top, top)
    ax.set_aspect("equal")
    ax.axhline(0, color="#bbbbbb", linewidth=0.6)
    ax.axvline(0, color="#bbbbbb", linewidth=0.6)
    ax.set_xlabel(f"amplitude · cos(phase) {unit}".strip())
    ax.set_ylabel(f"amplitude · sin(phase) {unit}".strip())
    return _finish(ax, "1x readings (O original, T trial runs)", legend=False)


def plot_grade(ax: Any, grade: Any) -> Any:
    """Residual unbalance in each bearing plane beside its ISO 21940-11 allowance."""
    k = np.arange(len(grade.bearings))
    ax.bar(k - 0.2, np.asarray(grade.allowed) * 1e6, width=0.4, color="#bbbbbb", label="allowed")
    ax.bar(k + 0.2, np.asarray(grade.residual) * 1e6, width=0.4,
           color=[PALETTE[2] if r <= a else PALETTE[1] for r, a in zip(grade.residual, grade.allowed, strict=True)],
           label="residual")
    ax.set_xticks(k)
    ax.set_xticklabels([f"bearing {n}" for n in grade.bearings])
    ax.set_ylabel("unbalance [g·mm]")
    return _finish(ax, f"ISO 21940-11, G {format_value(grade.grade)}")


def _mass(mass: float, unit: str) -> str:
    """A mass [kg] written in ``unit`` (the unit the problem file writes masses in)."""
    return f"{format_value(mass * display_factor('kg', unit))} {unit}"


def record_sections(outcome: Any) -> list[tuple[str, str]]:
    """The ``[field_records]`` section: the 1x readings read from each record and the corrections."""
    r = outcome.results
    runs = [("original", r.original), *((f"trial in plane {k + 1}", t) for k, t in enumerate(r.trials))]
    rows = []
    for label, run in runs:
        text = "; ".join(f"sensor {j + 1}: {format_value(x.amplitude)} at {format_value(math.degrees(x.phase))}°"
                         for j, x in enumerate(run.readings))
        rows.append([f"{label} ({run.source.split('/')[-1]}, {run.revolutions} rev at "
                     f"{format_value(run.speed * 30 / math.pi)} rpm)", text])
    fb = r.balance
    for k, name in enumerate(r.names):
        split = ", ".join(f"hole {h + 1}: {_mass(m, r.mass_unit)}" for h, m in r.splits[k].items())
        rows.append([f"correction in plane {name}", f"{_mass(fb.correction_mass[k], r.mass_unit)} at "
                     f"{format_value(math.degrees(fb.correction_angle[k]))}°" + (f" ({split})" if split else "")])
    intro = ("<p>1x amplitude and phase lag (the angle the shaft turns from the reference pulse to the positive "
             "peak) of every channel, over the whole revolutions of each record; mass angles are measured from the "
             "reference mark against rotation.</p>")
    fig = _render("shaft-records", "1x readings of the runs", "Original (solid) and trial runs (dashed) at each "
                  "sensor, as read from the records.", (4.6, 4.2),
                  lambda f: plot_readings(f.subplots(1, 1), r.original.readings, [t.readings for t in r.trials]),
                  margins=(0.8, 0.3, 0.6, 0.45))
    return [("Field balancing from records", intro + figures_html([fig]) + rows_html(rows, ("run", "1x readings")))]


def sections(outcome: Any) -> list[tuple[str, str]]:
    """The shaft-line section."""
    result = outcome.results
    figs = []
    has_masses = bool(result.line.masses or result.line.cylinders or result.line.linkages)
    if has_masses:
        def draw(fig: Any) -> None:
            axes = fig.subplots(1, 3)
            plot_shaft(axes[0], result)
            _polygon(axes[1], _vectors(result, False), "Force polygon m·r", "kg·m")
            _polygon(axes[2], _vectors(result, True), "Couple polygon m·r·z", "kg·m²")

        figs.append(_render("shaft-line", "Shaft line, force and couple polygons",
                            "Left: the planes along the shaft (blue masses, green cylinders, orange corrections, "
                            "triangles bearings). Middle and right: the polygons of m·r and m·r·z about the "
                            "reference plane, corrections included; a closed polygon is balanced.",
                            (13.5, 4.0), draw, margins=(0.6, 0.3, 0.6, 0.45), wspace=0.35))

        def draw_loads(fig: Any) -> None:
            axes = fig.subplots(1, 2 + (result.engine is not None))
            plot_loads(axes[0], result, False)
            plot_loads(axes[1], result, True)
            if result.engine is not None:
                plot_orders(axes[2], result.engine)

        n = 2 + (result.engine is not None)
        figs.append(_render("shaft-loads", "Frame loads over the turn", "Resultant force and couple about the "
                            "reference plane, as given and after the corrections.", (4.6 * n, 3.4), draw_loads,
                            margins=(0.7, 0.6, 0.6, 0.45), wspace=0.45))
    small = []
    f = result.line.field
    if result.grade is not None:
        small.append(("grade", lambda ax: plot_grade(ax, result.grade)))
    if f is not None and result.line.field_runs:
        runs = result.line.field_runs
        small.append(("field", lambda ax: plot_readings(ax, runs[0], runs[1:])))
    if small:
        def draw_small(fig: Any) -> None:
            axes = np.atleast_1d(fig.subplots(1, len(small)))
            for ax, (_, fn) in zip(axes, small, strict=True):
                fn(ax)

        figs.append(_render("shaft-checks", "Grade check and field readings", "Residual unbalance against the "
                            "allowance of each bearing plane; 1x readings of the field-balancing runs.",
                            (4.8 * len(small), 3.8), draw_small, margins=(0.8, 0.3, 0.6, 0.45), wspace=0.4))
    rows: list[list[str]] = []
    unit = result.line.mass_unit
    if result.balance is not None:
        fitted = {m.name: m for m in result.applied}
        for c in result.balance.corrections:
            rows.append([f"correction in plane {c.plane.name} (z = {format_value(c.plane.position)} m)",
                         f"{_mass(c.mass, unit)} at {format_value(c.plane.radius * 1e3)} mm, "
                         f"{format_value(math.degrees(c.angle))}°"])
            if result.line.resolution is not None:
                parts = [m for name, m in fitted.items() if name.startswith((f"{c.plane.name} hole",
                                                                             f"correction {c.plane.name}"))]
                rows.append([f"as fitted in plane {c.plane.name}, rounded to {_mass(result.line.resolution, unit)}"
                             " (the residual uses these)", ", ".join(
                                 f"{m.name.removeprefix(c.plane.name + ' ')}: {_mass(m.mass, unit)} at "
                                 f"{format_value(math.degrees(m.angle))}°" for m in parts)])
    if result.grade is not None:
        g = result.grade
        rows.append([f"ISO 21940-11 grade G {format_value(g.grade)}",
                     f"U_per {format_value(g.u_per * 1e6)} g·mm; " + "; ".join(
                         f"{n}: residual {format_value(r * 1e6)} of {format_value(a * 1e6)} g·mm"
                         for n, r, a in zip(g.bearings, g.residual, g.allowed, strict=True))
                     + (" — passes" if g.passes else " — FAILS")])
    if result.locomotive is not None:
        lo = result.locomotive
        rows += [["locomotive: hammer blow", f"{format_value(lo.hammer_blow)} N"],
                 ["locomotive: variation of tractive effort", f"±{format_value(lo.tractive_effort_variation)} N"],
                 ["locomotive: swaying couple", f"±{format_value(lo.swaying_couple)} N·m"]]
    if result.frame_frequencies is not None:
        rows.append(["frame on its mounts: natural frequencies",
                     ", ".join(f"{format_value(v)} Hz" for v in result.frame_frequencies)])
        for name, force in result.frame_response.mount_force.items():
            rows.append([f"mount {name}: largest dynamic force", f"{format_value(force)} N"])
        for name, v in result.frame_response.rms_velocity.items():
            rows.append([f"frame point {name}: RMS velocity", f"{format_value(v * 1e3)} mm/s"])
    if f is not None:
        for name, m, a, eff in zip(result.line.field_names, f.correction_mass, f.correction_angle, f.trial_effect,
                                   strict=True):
            rows.append([f"field balancing, plane {name}",
                         f"{_mass(m, unit)} at {format_value(math.degrees(a))}° (trial effect "
                         f"{format_value(eff)})"])
    intro = ("<p>Angles are measured from the shaft's reference mark in the sense of rotation; couples about the "
             f"plane z = {format_value(result.line.reference)} m. Field-balancing phases and mass angles share the "
             "instrument's sense.</p>")
    body = intro + figures_html(figs) + (rows_html(rows, ("item", "value")) if rows else "")
    return [("Shaft line", body)]
