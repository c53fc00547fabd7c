"""The report sections of a linkage analysis: the diagnostics table and the standard plots."""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..linkage import model as _model
from ..results.linkage import LINKAGE_LABELS, joint_list, mechanism_of
from ..results.linkage import slider_bodies as _slider_bodies
from . import plots
from .animation import outcome_view
from .html import Figure, _render, figures_html, format_value, rows_html


@dataclass(frozen=True)
class HarmonicBars:
    """Amplitudes of the driving torque's harmonics (orders 1..K) and its mean, as the results stage gave them."""

    orders: np.ndarray
    amplitude: np.ndarray
    mean: float | None


def torque_harmonics(scalars: Any) -> HarmonicBars | None:
    """The driving torque's harmonics among a run's scalar results (None if the run has none)."""
    orders = sorted(int(k.split(".")[1].removeprefix("harmonic_")) for k in scalars
                    if k.startswith("driving_torque.harmonic_") and k.endswith(".amplitude"))
    if not orders:
        return None
    amp = np.array([scalars[f"driving_torque.harmonic_{k}.amplitude"] for k in orders], dtype=float)
    mean = scalars.get("driving_torque.mean")
    return HarmonicBars(np.asarray(orders, dtype=float), amp, None if mean is None else float(mean))


def sections(outcome: Any) -> list[tuple[str, str]]:
    """The diagnostics table and the plots of a linkage kind's outcome."""
    about = (float(outcome.scalars.get("shaking_moment.about_x", 0.0)),
             float(outcome.scalars.get("shaking_moment.about_y", 0.0)))
    out = analysis_sections(outcome.analysis, outcome.mechanism, shaking_about=about,
                            harmonics=torque_harmonics(outcome.scalars))
    view = outcome_view(outcome)
    return [("Motion", str(view)), *out] if view is not None else out


def analysis_sections(
    analysis: Any, mechanism: Any = None, *, shaking_about: tuple[float, float] = (0.0, 0.0),
    harmonics: HarmonicBars | None = None,
) -> list[tuple[str, str]]:
    """("Diagnostics", table) and ("Plots", figures) of an :func:`~machdyn.linkage.analyse` result; the
    torque's ``harmonics`` (from the results stage, see :func:`torque_harmonics`) add a bar chart."""
    mech = mechanism if mechanism is not None else mechanism_of(analysis)
    out = []
    rows = diagnostics_rows(analysis.diagnostics, mech)
    if rows:
        out.append(("Diagnostics", rows_html(rows)))
    figures = analysis_figures(analysis, mech, shaking_about=shaking_about, harmonics=harmonics)
    if figures:
        out.append(("Plots", figures_html(figures)))
    return out


def _deg(angle: Any) -> str:
    return format_value(np.degrees(np.asarray(angle, dtype=float)).tolist()) + "°"


def _ranges(ranges: Iterable) -> str:
    items = [f"{format_value(np.degrees(a))}° – {format_value(np.degrees(b))}°" for a, b in ranges]
    return "; ".join(items) if items else "none"


def diagnostics_rows(diagnostics: Any, mechanism: Any = None) -> list[tuple[str, str]]:
    """(item, text) rows describing the mechanism's diagnostics: Grashof type, assembly, dead and limit
    positions, strokes, time ratio and transmission-angle extremes."""
    if diagnostics is None:
        return []
    rows: list[tuple[str, str]] = []
    g = getattr(diagnostics, "grashof", None)
    if g is not None:
        rows.append(("Grashof type", str(g)))
    non = getattr(diagnostics, "non_assembly_ranges", None)
    if non is not None:
        rows.append(("Crank ranges where it cannot assemble", _ranges(non)))
    dead = getattr(diagnostics, "dead_positions", None)
    if dead is not None:
        dead = list(dead)
        rows.append(("Dead (toggle) positions of the crank", _deg(dead) if dead else "none"))
    sliders = set(_slider_bodies(mechanism)) if mechanism is not None else set()
    limits = getattr(diagnostics, "limit_positions", None)
    if limits:
        by_body: dict[str, list[str]] = {}
        for item in limits:
            body = getattr(item, "body", "")
            angle = getattr(item, "crank_angle", item)
            value = getattr(item, "value", None)
            text = f"φ = {format_value(float(np.degrees(float(angle))))}°"
            if value is not None:
                if body in sliders:
                    text += f" (s = {format_value(float(value))} m)"
                else:
                    text += f" (θ = {format_value(float(np.degrees(float(value))))}°)"
            by_body.setdefault(body, []).append(text)
        for body, texts in by_body.items():
            rows.append((f"Limit positions of {body}" if body else "Limit positions", ", ".join(texts)))
    for body, stroke in (getattr(diagnostics, "strokes", None) or {}).items():
        if body in sliders:
            rows.append((f"Stroke of {body}", f"{format_value(np.asarray(stroke, dtype=float).tolist())} m"))
        else:
            rows.append((f"Swing of {body}", _deg(stroke)))
    window = getattr(diagnostics, "crank_range", None)
    if window is not None:
        rows.append(("Crank range described", f"{np.degrees(window[0]):.1f}°–{np.degrees(window[0] + window[1]):.1f}°"))
    ratios = getattr(diagnostics, "time_ratios", None) or {}
    angles = getattr(diagnostics, "transmission_angles", None) or {}
    several = len([b for b in (getattr(diagnostics, "strokes", None) or {}) if b in sliders]) > 1
    tr = getattr(diagnostics, "time_ratio", None)
    if window is not None:
        rows.append((LINKAGE_LABELS["time_ratio"].text, "needs a full turn of the crank (not analysed)"))
    elif several:
        for body, ratio in ratios.items():
            if body in sliders and ratio is not None:
                rows.append((f"{LINKAGE_LABELS['time_ratio'].text} of {body}", format_value(float(ratio))))
    elif tr is not None:
        rows.append((LINKAGE_LABELS["time_ratio"].text, format_value(np.asarray(tr, float).tolist())))
    if several:
        for body, (lo_b, hi_b) in angles.items():
            if body in sliders:
                rows.append((f"Transmission angle of the dyad driving {body}", f"{_deg(lo_b)} – {_deg(hi_b)}"))
        return rows
    lo = getattr(diagnostics, "transmission_angle_min", None)
    hi = getattr(diagnostics, "transmission_angle_max", None)
    if lo is not None:
        rows.append(("Transmission angle, minimum", _deg(lo)))
    if hi is not None:
        rows.append(("Transmission angle, maximum", _deg(hi)))
    return rows


# ---------------------------------------------------------------------------------------------- figures


def _mechanism_height(mech: Any, kin: Any, *, axes_width: float, extra: float) -> float:
    """A figure height [in] that fits the mechanism's bounding box at equal axis scales, between 2.4 and
    4.8 in (long, flat mechanisms get a flat figure)."""
    xs, ys = [], []
    for body in mech.moving_bodies:
        for point in mech.body(body).points:
            p = kin.point(f"{body}.{point}")
            xs.append(np.ravel(p.x))
            ys.append(np.ravel(p.y))
    x, y = np.concatenate(xs), np.concatenate(ys)
    with np.errstate(all="ignore"):
        dx, dy = float(np.nanmax(x) - np.nanmin(x)), float(np.nanmax(y) - np.nanmin(y))
    if not (np.isfinite(dx) and np.isfinite(dy)) or dx <= 0:
        return 4.6
    pad = 0.15 * max(dx, dy)
    return float(np.clip(axes_width * (dy + pad) / (dx + pad) + extra, 2.4, 4.8))


def _output_bodies(mechanism: Any) -> list[str]:
    """The bodies whose motion is the mechanism's output: its sliders, else the last body placed."""
    sliders = _slider_bodies(mechanism)
    if sliders:
        return sliders
    return [mechanism.moving_bodies[-1]] if len(mechanism.moving_bodies) > 1 else []


def analysis_figures(
    analysis: Any,
    mechanism: Any = None,
    *,
    positions: int = 4,
    shaking_about: tuple[float, float] = (0.0, 0.0),
    harmonics: HarmonicBars | None = None,
) -> list[Figure]:
    """The standard plots of an analysis, rendered to inline SVG (the shaking moment about
    ``shaking_about`` [m])."""
    mech = mechanism if mechanism is not None else mechanism_of(analysis)
    kin, forces, energy = analysis.kinematics, analysis.forces, analysis.energy
    designs = np.ndim(forces.driving_torque) == 2
    pick = 0 if designs else None
    out: list[Figure] = []
    note = " Design variant 0 of the sweep is shown." if designs else ""

    if mech is not None:
        out.append(
            _render(
                "mechanism",
                "Mechanism",
                f"The linkage at {positions} crank positions (first one solid, the others faded) with "
                f"the paths of its moving points (dotted).{note}",
                (7.4, _mechanism_height(mech, kin, axes_width=7.4 - 0.7 - 1.25, extra=0.85)),
                lambda fig: plots.plot_mechanism(fig.add_subplot(), mech, kin, positions, design=0),
                margins=(0.7, 1.25, 0.5, 0.35),
            )
        )
        outputs = _output_bodies(mech)
        if outputs:

            def draw_motion(fig):
                axes = fig.subplots(3, 1, sharex=True)
                for ax, quantity in zip(axes, ("displacement", "velocity", "acceleration"), strict=True):
                    for body in outputs:
                        plots.plot_point_motion(ax, kin, body, quantity, design=pick, title="")
                    if ax is not axes[-1]:
                        ax.set_xlabel("")
                axes[0].set_title(
                    f"Output motion: {', '.join(outputs)}", loc="left", fontweight="bold", fontsize="medium"
                )

            kinds = ["slide along its guide" if b in _slider_bodies(mech) else "rotation" for b in outputs]
            out.append(
                _render(
                    "motion",
                    "Output motion",
                    "Displacement, velocity and acceleration of the output "
                    + ", ".join(f"{b} ({k})" for b, k in zip(outputs, kinds, strict=True))
                    + f".{note}",
                    (7.4, 5.2),
                    draw_motion,
                    margins=(0.85, 0.25, 0.5, 0.35),
                    hspace=0.12,
                )
            )

    joints = [j[0] for j in joint_list(forces)]
    if mech is not None:
        order = [j[0] for j in _model.joints(mech)]
        joints.sort(key=lambda name: order.index(name) if name in order else len(order))
    ncols = 2 if len(joints) == 4 else min(3, max(1, len(joints)))  # room for the radial tick labels
    nrows = math.ceil(len(joints) / ncols)

    def draw_joints(fig):
        for k, name in enumerate(joints):
            ax = fig.add_subplot(nrows, ncols, k + 1, projection="polar")
            plots.plot_joint_polar(ax, forces, name, design=pick, title="")
            ax.set_title(f"Joint {name}", loc="center", fontsize="medium", fontweight="bold", pad=14)

    out.append(
        _render(
            "joints",
            "Joint reactions",
            "Polar diagrams of the joint reactions: the tip of the force vector on the later body from "
            "the earlier body over one cycle (radius = magnitude in N, angle = direction in the global "
            f"frame); the dot marks the first crank position.{note}",
            (7.4, 3.1 * nrows),
            draw_joints,
            margins=(0.4, 0.4, 0.25, 0.5),
            wspace=0.65,
            hspace=0.6,
        )
    )

    out.append(
        _render(
            "torque",
            "Driving torque and power",
            f"Torque the motor must apply to the crank (left axis) and the input power (right axis).{note}",
            (7.4, 3.2),
            lambda fig: plots.plot_torque_power(fig.add_subplot(), forces, design=pick),
            margins=(0.8, 1.0, 0.5, 0.35),
        )
    )

    def draw_shaking(fig):
        ax1 = fig.add_subplot(1, 2, 1, projection="polar")
        plots.plot_shaking_force_polar(ax1, forces, design=pick)
        ax2 = fig.add_subplot(1, 2, 2)
        plots.plot_shaking_moment(ax2, forces, about=shaking_about, design=pick)

    out.append(
        _render(
            "shaking",
            "Shaking force and moment",
            "Left: the total force the moving mechanism exerts on the frame (polar locus). Right: the "
            f"shaking moment on the frame about ({shaking_about[0]:g}, {shaking_about[1]:g}) m, including "
            f"the motor's reaction torque.{note}",
            (7.4, 3.3),
            draw_shaking,
            margins=(0.35, 0.2, 0.5, 0.45),
            wspace=0.3,
        )
    )

    def draw_energy(fig):
        ax1, ax2 = fig.subplots(2, 1, sharex=True, height_ratios=(1.6, 1.0))
        plots.plot_energy(ax1, energy, kin.crank_angle, design=pick, legend=False)
        ax1.set_xlabel("")
        ax1.legend(
            fontsize="small", loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0, frameon=False
        )
        plots.plot_reduced_inertia(
            ax2, energy, kin.crank_angle, design=pick, title="Reduced moment of inertia at the crank"
        )

    out.append(
        _render(
            "energy",
            "Energy",
            "Top: kinetic energy of each body and in total, potential energy and the total mechanical "
            f"energy. Bottom: the moment of inertia of the whole mechanism reduced to the crank, 2T/ω².{note}",
            (7.4, 5.0),
            draw_energy,
            margins=(0.8, 1.75, 0.5, 0.35),
            hspace=0.3,
        )
    )

    if harmonics is not None:
        bars = harmonics
        out.append(
            _render(
                "harmonics",
                "Harmonics of the driving torque",
                f"Amplitudes of the Fourier series of the driving torque over the crank angle, orders 1 to "
                f"{int(bars.orders.max())} as asked for by [output] harmonics (order 0 is the mean).",
                (7.4, 2.7),
                lambda fig: plots.plot_harmonics(
                    fig.add_subplot(),
                    bars,
                    unit="N·m",
                    label="driving torque",
                    title="Harmonics of the driving torque",
                ),
            )
        )
    return out
