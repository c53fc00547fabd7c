"""Plots of linkage results for reports and for use from Python: every function takes a matplotlib ``ax``,
draws on it and returns it, so the caller owns the figure (pyplot, a notebook or a plain
:class:`matplotlib.figure.Figure`).

For results of N design variants (arrays of shape (N, M)) a function draws every design unless
``design=i`` picks one. Crank angles are shown in degrees; every axis is labelled with its unit.

Example (see docs/report.md)::

    import matplotlib.pyplot as plt
    from machdyn.linkage import analyse, crank_angles, four_bar
    from machdyn.report import plots

    res = analyse(four_bar(0.05, 0.15, 0.12, 0.14), crank_angles(360), speed=20.0)
    fig, ax = plt.subplots()
    plots.plot_torque_power(ax, res.forces)
    pax = plt.figure().add_subplot(projection="polar")
    plots.plot_joint_polar(pax, res.forces, "B")
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.axes import Axes
from matplotlib.ticker import MaxNLocator

from .drawing import plot_mechanism as plot_mechanism  # drawn in its own module, offered here too
from .plotkit import PALETTE, _angle_deg, _crank_axis, _finish, _label, _rows
from .tables import joint_list

_QUANTITY = {
    "displacement": ("Displacement", 0),
    "velocity": ("Velocity", 1),
    "acceleration": ("Acceleration", 2),
}


def plot_point_motion(
    ax: Axes,
    kinematics: Any,
    point: str,
    quantity: str = "displacement",
    *,
    design: int | None = None,
    title: str | None = None,
) -> Axes:
    """Displacement, velocity or acceleration over the crank angle.

    ``point`` is ``"body.point"`` (x and y components, and the magnitude for velocity and acceleration), or
    a body name: a slider's slide coordinate along its guide [m, m/s, m/s^2], or a rotating body's angle,
    angular velocity and angular acceleration [deg, rad/s, rad/s^2].
    """
    if quantity not in _QUANTITY:
        raise ValueError(f"quantity must be one of {', '.join(_QUANTITY)}; got {quantity!r}.")
    name, level = _QUANTITY[quantity]
    deg = _angle_deg(kinematics)
    curves: list[tuple[str, Any]] = []
    if "." in point:
        p = kinematics.point(point)
        unit = ("m", "m/s", "m/s²")[level]
        if level == 0:
            curves = [(f"{point} x", p.x), (f"{point} y", p.y)]
        elif level == 1:
            curves = [(f"{point} vx", p.vx), (f"{point} vy", p.vy), (f"{point} |v|", p.speed)]
        else:
            curves = [(f"{point} ax", p.ax), (f"{point} ay", p.ay), (f"{point} |a|", p.accel)]
    else:
        slide = None
        try:
            slide = kinematics.slide(point)
        except Exception:  # noqa: BLE001 - not a slider: fall back to the body rotation
            slide = None
        if slide is not None:
            unit = ("m", "m/s", "m/s²")[level]
            curves = [(f"{point} {('s', 'ṡ', 's̈')[level]}", (slide.s, slide.v, slide.a)[level])]
        else:
            b = kinematics.body(point)
            unit = ("deg", "rad/s", "rad/s²")[level]
            # A rocker swinging through +-180 deg would jump by 360 deg: draw the continuous angle.
            angle = np.degrees(np.unwrap(np.asarray(b.angle, dtype=float), axis=-1)) if level == 0 else None
            values = (angle, b.omega, b.alpha)[level]
            curves = [(f"{point} {('θ', 'ω', 'α')[level]}", values)]
    n_before = len(ax.get_lines())
    for k, (label, values) in enumerate(curves):
        for d, series in _rows(values, design):
            ax.plot(
                deg,
                series,
                color=PALETTE[(n_before + k) % len(PALETTE)] if d is None else None,
                linewidth=1.6,
                label=_label(label, d),
                linestyle="--" if label.endswith(("|v|", "|a|")) else "-",
            )
    _crank_axis(ax, deg, zero_line=level > 0)
    ax.set_ylabel(f"{name} [{unit}]")
    return _finish(ax, title if title is not None else f"{name} of {point}")


# ------------------------------------------------------------------------------------------------- forces


def _polar_locus(ax: Axes, fx: Any, fy: Any, label: str, colour: str, design: int | None) -> None:
    polar = getattr(ax, "name", "") == "polar"
    for d, (x, y) in zip(
        [d for d, _ in _rows(fx, design)],
        zip((s for _, s in _rows(fx, design)), (s for _, s in _rows(fy, design)), strict=True),
        strict=True,
    ):
        c = colour if d is None else None
        if polar:
            theta, r = np.arctan2(y, x), np.hypot(x, y)
            (line,) = ax.plot(theta, r, color=c, linewidth=1.5, label=_label(label, d))
            ax.plot(theta[:1], r[:1], marker="o", color=line.get_color(), markersize=5, linestyle="none")
        else:
            (line,) = ax.plot(x, y, color=c, linewidth=1.5, label=_label(label, d))
            ax.plot(x[:1], y[:1], marker="o", color=line.get_color(), markersize=5, linestyle="none")
    if polar:
        ax.set_rlabel_position(67.5)  # type: ignore[attr-defined]  # between the 45 and 90 deg labels
        ax.tick_params(axis="y", labelsize=7)
        ax.set_thetagrids(  # type: ignore[attr-defined]
range(0, 360, 45), ["0°", "", "90°", "", "180°", "", "270°", ""])
        ax.yaxis.set_major_locator(MaxNLocator(3))
        ax.tick_params(labelsize="small")
        ax.grid(True, alpha=0.4, linewidth=0.6)
        ax.set_ylim(bottom=0)
    else:
        ax.set_aspect("equal", adjustable="datalim")
        ax.axhline(0.0, color="#888888", linewidth=0.6)
        ax.axvline(0.0, color="#888888", linewidth=0.6)
        ax.set_xlabel("Fx [N]")
        ax.set_ylabel("Fy [N]")
        ax.grid(True, alpha=0.35, linewidth=0.6)


def plot_joint_polar(
    ax: Axes, forces: Any, joint: str, *, design: int | None = None, title: str | None = None
) -> Axes:
    """Polar diagram of a joint reaction: the locus of the force vector's tip over the cycle (radius =
    magnitude in N, angle = direction in the global frame), the dot marking the first crank position.

    The force is the one on the later body from the earlier body of the joint. On Cartesian axes the
    same locus is drawn as Fy over Fx (a hodograph).
    """
    r = forces.joint(joint)
    info = next((j for j in joint_list(forces) if j[0] == joint), None)
    if title is None:
        title = f"Joint {joint}" + (f": on {info[3]} from {info[2]} [N]" if info else " [N]")
    _polar_locus(ax, r.fx, r.fy, f"joint {joint}", PALETTE[0], design)
    return _finish(ax, title)


def plot_shaking_force_polar(
    ax: Axes, forces: Any, *, design: int | None = None, title: str | None = "Shaking force on the frame [N]"
) -> Axes:
    """Polar diagram of the frame (shaking) force: the total force the mechanism exerts on the frame."""
    fx, fy = forces.frame_force
    _polar_locus(ax, fx, fy, "shaking force", PALETTE[1], design)
    return _finish(ax, title)


def _clean(value: float, scale: float) -> float:
    """``value`` with round-off below 1e-9 of ``scale`` shown as zero."""
    return 0.0 if abs(value) <= 1e-9 * abs(scale) else value


def plot_torque_power(
    ax: Axes,
    forces: Any,
    *,
    design: int | None = None,
    power: bool = True,
    title: str | None = "Driving torque and input power",
) -> Axes:
    """The driving torque on the crank [N*m] with its mean, and the input power [W] on the right axis.

    At constant crank speed the power is the torque times the speed, so the right axis is a second scale of
    the same curve; with a varying speed the power is drawn as its own dashed curve on a twin axis
    (``ax.power_axis``). Returns ``ax`` (the torque axis).
    """
    kin = forces.kinematics
    deg = _angle_deg(kin)
    for d, series in _rows(forces.driving_torque, design):
        ax.plot(
            deg,
            series,
            color=PALETTE[0] if d is None else None,
            linewidth=1.7,
            label=_label("driving torque", d),
        )
        if d is None:
            mean = _clean(float(np.nanmean(series)), float(np.nanmax(np.abs(series))))
            ax.axhline(mean, color=PALETTE[1], linewidth=1.0, linestyle="--", label=f"mean {mean:.4g} N·m")
    _crank_axis(ax, deg)
    ax.set_ylabel("Driving torque [N·m]")
    speed = np.asarray(kin.speed, dtype=float)
    speed = speed[design] if (speed.ndim == 2 and design is not None) else speed
    omega = float(speed.ravel()[0]) if speed.size else 0.0
    constant = bool(speed.size) and np.allclose(speed, omega) and omega != 0.0
    if power and constant:
        sec = ax.secondary_yaxis("right", functions=(lambda t: np.multiply(t, omega), lambda p: np.divide(p, omega)))
        sec.set_ylabel(f"Input power [W] at ω = {omega:.4g} rad/s")
        ax.power_axis = sec  # type: ignore[attr-defined]  # the power axis travels with the torque axis
    elif power:
        pax = ax.twinx()
        for d, series in _rows(forces.input_power, design):
            pax.plot(
                deg,
                series,
                color=PALETTE[2] if d is None else None,
                linewidth=1.3,
                linestyle="-.",
                label=_label("input power", d),
            )
        pax.set_ylabel("Input power [W]")
        _align_zero(ax, pax)
        ax.power_axis = pax  # type: ignore[attr-defined]
        h1, l1 = ax.get_legend_handles_labels()
        h2, l2 = pax.get_legend_handles_labels()
        if title:
            ax.set_title(title, fontsize="medium", loc="left", fontweight="bold")
        ax.legend(h1 + h2, l1 + l2, fontsize="small", framealpha=0.85, loc="best")
        return ax
    return _finish(ax, title)


def _align_zero(ax1: Axes, ax2: Axes) -> None:
    """Scale two y axes so that their zeros line up."""
    lo1, hi1 = ax1.get_ylim()
    lo2, hi2 = ax2.get_ylim()
    if not (lo1 < 0 < hi1 and lo2 < 0 < hi2):
        lo1, hi1 = min(lo1, 0.0), max(hi1, 0.0)
        lo2, hi2 = min(lo2, 0.0), max(hi2, 0.0)
    f1 = -lo1 / (hi1 - lo1) if hi1 > lo1 else 0.5
    f2 = -lo2 / (hi2 - lo2) if hi2 > lo2 else 0.5
    f = max(f1, f2)
    if 0 < f < 1:
        ax1.set_ylim(min(lo1, -f * hi1 / (1 - f)), max(hi1, -lo1 * (1 - f) / f))
        ax2.set_ylim(min(lo2, -f * hi2 / (1 - f)), max(hi2, -lo2 * (1 - f) / f))


def plot_shaking_moment(
    ax: Axes,
    forces: Any,
    about: tuple[float, float] = (0.0, 0.0),
    *,
    design: int | None = None,
    title: str | None = None,
) -> Axes:
    """The shaking moment on the frame [N*m] about the point ``about`` [m] over the crank angle."""
    deg = _angle_deg(forces.kinematics)
    moment = forces.shaking_moment(about=about)
    for d, series in _rows(moment, design):
        ax.plot(
            deg,
            series,
            color=PALETTE[2] if d is None else None,
            linewidth=1.7,
            label=_label("shaking moment", d),
        )
    _crank_axis(ax, deg)
    ax.set_ylabel("Shaking moment [N·m]")
    if title is None:
        title = f"Shaking moment about ({about[0]:g}, {about[1]:g}) m"
    return _finish(ax, title)


# ------------------------------------------------------------------------------------------------- energy


def plot_energy(
    ax: Axes,
    energy: Any,
    crank_angle: Any = None,
    *,
    design: int | None = None,
    per_body: bool = True,
    legend: bool = True,
    title: str | None = "Energy",
) -> Axes:
    """Kinetic energy (per body and total), potential energy of gravity and springs, and the total [J].

    The crank angles come from ``energy.kinematics`` when it has them, else pass ``crank_angle`` [rad].
    """
    if crank_angle is None:
        kin = getattr(energy, "kinematics", None)
        if kin is None:
            raise ValueError(
                "plot_energy needs crank_angle=... (the energy result does not carry kinematics)."
            )
        crank_angle = kin.crank_angle
    deg = np.degrees(np.asarray(crank_angle, dtype=float).ravel())
    curves: list[tuple[str, Any, dict]] = []
    if per_body:
        for k, (name, values) in enumerate(energy.kinetic.items()):
            if np.nanmax(np.abs(values)) > 0:
                curves.append(
                    (
                        f"kinetic {name}",
                        values,
                        {"linewidth": 0.9, "alpha": 0.8, "color": PALETTE[(k + 3) % len(PALETTE)]},
                    )
                )
    curves.append(("kinetic total", energy.kinetic_total, {"linewidth": 1.8, "color": PALETTE[0]}))
    for label, values, colour in (
        ("potential (gravity)", energy.potential_gravity, PALETTE[2]),
        ("potential (springs)", energy.potential_spring, PALETTE[4]),
    ):
        if np.nanmax(np.abs(values)) > 0:
            curves.append((label, values, {"linewidth": 1.4, "linestyle": "--", "color": colour}))
    curves.append(("total", energy.total, {"linewidth": 2.0, "color": PALETTE[7]}))
    for label, values, style in curves:
        for d, series in _rows(values, design):
            kw = dict(style)
            if d is not None:
                kw.pop("color", None)
            ax.plot(deg, series, label=_label(label, d), **kw)
    _crank_axis(ax, deg)
    ax.set_ylabel("Energy [J]")
    return _finish(ax, title, legend=legend)


def plot_reduced_inertia(
    ax: Axes,
    energy: Any,
    crank_angle: Any,
    *,
    design: int | None = None,
    title: str | None = "Reduced moment of inertia at the crank",
) -> Axes:
    """The moment of inertia of the mechanism reduced to the crank, 2 T / ω² [kg*m^2]."""
    deg = np.degrees(np.asarray(crank_angle, dtype=float).ravel())
    for d, series in _rows(energy.reduced_inertia, design):
        ax.plot(
            deg,
            series,
            color=PALETTE[3] if d is None else None,
            linewidth=1.7,
            label=_label("reduced inertia", d),
        )
    _crank_axis(ax, deg)
    ax.set_ylabel("Reduced inertia [kg·m²]")
    return _finish(ax, title)


def plot_harmonics(
    ax: Axes,
    harmonics: Any,
    *,
    unit: str = "",
    label: str = "amplitude",
    design: int | None = None,
    title: str | None = "Harmonic content",
) -> Axes:
    """Bar chart of the harmonic amplitudes over the order (multiples of the crank frequency); the mean value
    (``harmonics.mean``, if present) is drawn as order 0 in grey. For N designs the bars of each design
    stand side by side unless ``design`` picks one."""
    orders = np.asarray(harmonics.orders, dtype=float).ravel()
    amp = np.asarray(harmonics.amplitude, dtype=float)
    mean = getattr(harmonics, "mean", None)
    mean = None if mean is None else np.atleast_1d(np.asarray(mean, dtype=float))
    rows = [amp] if amp.ndim == 1 else list(amp)
    means = [None] * len(rows) if mean is None else list(np.broadcast_to(mean, (len(rows),)))
    if design is not None and amp.ndim == 2:
        rows, means = [rows[design]], [means[design]]
    width = 0.8 / len(rows)
    for k, (row, m) in enumerate(zip(rows, means, strict=True)):
        offset = (k - (len(rows) - 1) / 2) * width
        name = label if len(rows) == 1 else f"{label} (design {k if design is None else design})"
        colour = PALETTE[k % len(PALETTE)]
        ax.bar(
            orders + offset,
            np.abs(row),
            width=width,
            color=colour,
            label=name,
            edgecolor="#333333",
            linewidth=0.5,
        )
        if m is not None:
            ax.bar(
                [offset],
                [abs(float(m))],
                width=width,
                color="#aaaaaa",
                edgecolor="#333333",
                linewidth=0.5,
                hatch="//" if k else None,
                label="|mean|" if k == 0 else None,
            )
    ticks = np.concatenate([[0.0], orders]) if mean is not None else orders
    ax.set_xticks(ticks)
    ax.set_xlabel("Harmonic order (multiples of the crank frequency)")
    ax.set_ylabel(f"Amplitude [{unit}]" if unit else "Amplitude")
    ax.grid(True, axis="y", alpha=0.35, linewidth=0.6)
    ax.set_axisbelow(True)
    return _finish(ax, title)


def plot_sweep(
    ax: Axes,
    values: Any,
    summary: Any,
    *,
    parameter: str,
    parameter_unit: str,
    quantity: str,
    unit: str,
    regular: Any = None,
    colour: str = PALETTE[0],
) -> Axes:
    """A per-design summary of a design sweep (:func:`machdyn.linkage.sweep`) against the swept parameter.

    Designs that are not regular (cannot assemble, pass or near a dead position, change branch, transmit
    poorly) have no summary and are marked with a cross at the foot of the axes, so that the value axis scales
    to the regular designs alone."""
    x = np.asarray(values, dtype=float)
    y = np.asarray(summary, dtype=float)
    ok = np.isfinite(y) if regular is None else np.asarray(regular, dtype=bool) & np.isfinite(y)
    ax.plot(x[ok], y[ok], color=colour, linewidth=1.7, marker="o" if ok.sum() <= 40 else None, markersize=3.5,
            label=quantity)
    if np.any(~ok):
        ax.plot(x[~ok], np.full(int((~ok).sum()), 0.02), linestyle="none", marker="x", color=PALETTE[1],
                transform=ax.get_xaxis_transform(), label="not regular (no summary)")
    ax.set_xlabel(f"{parameter} [{parameter_unit}]")
    ax.set_ylabel(f"{quantity} [{unit}]")
    ax.grid(True, alpha=0.35)
    return _finish(ax, quantity, legend=bool(np.any(~ok)))
