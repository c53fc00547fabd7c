"""Report section of the machine in time (``[transient]``): crank speed, frame displacement and mount forces over
time, the amplitude against the crank speed with the frame's natural frequencies marked, and a table of the
resonance passages. Every plot takes an ``ax`` and returns it."""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.axes import Axes

from .html import _render, format_value, rows_html
from .plots import PALETTE
from .transient_view import transient_view

RPM = 30.0 / np.pi


def _thin(t: np.ndarray, limit: int = 6000) -> slice:
    return slice(None, None, max(1, t.size // limit))


def plot_speed(result: Any, ax: Axes) -> Axes:
    """Crank speed over time, with the frame's natural frequencies as speeds of the first order."""
    run = result.run
    s = _thin(run.t)
    for k in range(run.omega.shape[0]):
        ax.plot(run.t[s], run.omega[k, s] * RPM, color=PALETTE[k % len(PALETTE)], lw=0.9)
    if result.modes is not None:
        for j, wn in enumerate(result.modes.angular_frequencies, start=1):
            ax.axhline(wn * RPM, color="#999999", lw=0.7, ls="--")
            ax.annotate(f"mode {j}", (run.t[-1], wn * RPM), fontsize=7, ha="right", va="bottom", color="#666666")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("crank speed [rpm]")
    ax.set_title("Crank speed")
    return ax


def plot_displacement(result: Any, ax: Axes) -> Axes:
    """Displacement of the watched frame point over time (along the direction, or its two components)."""
    run = result.run
    s = _thin(run.t)
    u = run.point_displacement(result.point) * 1e3
    if result.direction is None:  # its components: x and y on a planar frame, x, y and z in space
        for k, axis in enumerate("xyz"[:u.shape[0]]):
            ax.plot(run.t[s], u[k, s], color=PALETTE[k], lw=0.6, label=axis)
        ax.legend(fontsize=7)
    else:
        d = result.direction
        ax.plot(run.t[s], (np.cos(d) * u[0] + np.sin(d) * u[1])[s], color=PALETTE[0], lw=0.6)
    ax.set_xlabel("time [s]")
    ax.set_ylabel(f"displacement at {result.point_name} [mm]")
    ax.set_title("Frame displacement")
    return ax


def plot_mount_forces(result: Any, ax: Axes) -> Axes:
    """Dynamic force of each mount over time."""
    run = result.run
    s = _thin(run.t)
    for i, (m, f) in enumerate(zip(run.model.frame.mounts, run.mount_force, strict=True)):
        ax.plot(run.t[s], f[s] / 1e3, color=PALETTE[i % len(PALETTE)], lw=0.6, label=m.name)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("mount force [kN]")
    ax.set_title("Mount forces")
    ax.legend(fontsize=6, ncol=2)
    return ax


def plot_amplitude_speed(result: Any, ax: Axes) -> Axes:
    """Amplitude against crank speed (one point per turn), the run-up and the run-down, with the frame's natural
    frequencies marked and each passage's peak."""
    c = result.curve
    if c.speed.size:
        top = int(np.argmax(c.speed))  # up to the highest speed: the run-up; after it, if it slows: the run-down
        slows = bool(np.min(c.speed[top:]) < 0.8 * c.speed[top])
        if not slows:
            top = c.speed.size - 1
        ax.plot(c.speed[:top + 1] * RPM, c.amplitude[:top + 1] * 1e3, color=PALETTE[0], lw=0.9, marker=".", ms=2,
                label="run-up")
        if slows:
            ax.plot(c.speed[top:] * RPM, c.amplitude[top:] * 1e3, color=PALETTE[2], lw=0.9, marker=".", ms=2,
                    label="run-down")
        ax.legend(fontsize=7)
    if result.modes is not None:
        for j, wn in enumerate(result.modes.angular_frequencies, start=1):
            ax.axvline(wn * RPM, color="#999999", lw=0.7, ls="--")
            ax.annotate(f"mode {j}", (wn * RPM, ax.get_ylim()[1]), fontsize=7, rotation=90, va="top", ha="right",
                        color="#666666")
    for p in result.passages:
        ax.plot([p.frequency * RPM], [p.peak_amplitude * 1e3], "o", color=PALETTE[1], ms=4)
    ax.set_xlabel("crank speed [rpm]")
    ax.set_ylabel(f"largest displacement at {result.point_name} per turn [mm]")
    ax.set_title("Amplitude against speed")
    return ax


def passage_rows(result: Any) -> list[tuple[str, ...]]:
    """One row per passage: mode, direction, time, peak displacement, peak mount force, time in the band."""
    return [(f"{p.mode} ({format_value(p.frequency / (2 * np.pi))} Hz)", p.direction, format_value(p.time),
             format_value(p.peak_amplitude * 1e3), format_value(p.peak_mount_force / 1e3),
             format_value(p.time_in_band)) for p in result.passages]


def sections(outcome: Any) -> list[tuple[str, str]]:
    """The report section of a ``[transient]`` outcome."""
    result = outcome.results
    if result is None:
        return []
    run = result.run
    framed = run.q.shape[0] > 0

    def draw(fig):
        if not framed:
            plot_speed(result, fig.subplots())
            return
        axes = fig.subplots(2, 2)
        plot_speed(result, axes[0, 0])
        plot_displacement(result, axes[0, 1])
        plot_mount_forces(result, axes[1, 0])
        plot_amplitude_speed(result, axes[1, 1])

    size = (11.0, 8.0) if framed else (6.0, 3.4)
    fig = _render("transient", "The machine in time", "", size, draw, margins=(0.9, 0.3, 0.6, 0.45), wspace=0.35,
                  hspace=0.45)
    state = {"duration": "ran to its end", "stopped": "ended when the crank came to rest",
             "rolled back": "ended when the crank rolled back under its drive"}[run.ended]
    machine = "shaft line" if run.q.shape[0] == 6 else "mechanism"
    intro = (f"<p>The motor, the {machine} and the frame on its mounts simulated together over "
             f"{format_value(float(run.t[-1]))} s (the run {state}); final crank speed "
             f"{format_value(result.final_speed * RPM)} rpm. The energy balance of the run (motor work = change "
             f"of kinetic and potential energy + dissipation + work on the loads) closes to "
             f"{run.energy_error:.2g} of the largest energy that flows.")
    if result.captured:
        intro += (" <strong>The drive is captured by a frame resonance</strong> (Sommerfeld effect): it would run at "
                  f"{format_value(result.free_speed * RPM)} rpm on a rigid frame.")
    intro += "</p>"
    moving = transient_view(result) if framed else None  # the frame and the machine on it, moving in time
    body = intro + (str(moving) if moving is not None else "") + f"<figure class=\"plot\">{fig.svg}</figure>"
    if result.passages:
        body += rows_html(passage_rows(result), head=("mode", "direction", "time [s]", "peak displacement [mm]",
                                                      "peak mount force [kN]", "time in band [s]"))
    return [("The machine in time", body)]
