"""Report section and plots of machine dynamics (``[flywheel]``): the energy-mass diagram, reduced inertia and
moment over the cycle, the speed over the crank angle (steady state) and over time (start-up), the drive torque
against the load torque, and the flywheel table. Every plot takes an ``ax`` and returns it."""

from __future__ import annotations

from types import SimpleNamespace
from typing import Any

import numpy as np
from matplotlib.axes import Axes

from .animation import Curve, scene, view_html
from .html import _render, format_value, rows_html
from .plots import PALETTE

RPM = 30.0 / np.pi


def _row(values: Any, design: int = 0) -> np.ndarray:
    a = np.asarray(values, dtype=float)
    return a[design] if a.ndim > 1 else a


def plot_energy_mass(sizing: Any, ax: Axes, design: int = 0) -> Axes:
    """Wittenbauer's energy-mass diagram: the work excess W(phi) against the reduced inertia J(phi), with the
    two tangents of slopes omega_max^2/2 and omega_min^2/2 that fix the flywheel (seed 003, text after eq 19)."""
    j = _row(sizing.inertia_curve, design)
    w = _row(sizing.work_curve, design)
    ax.plot(j, w, color=PALETTE[0], lw=1.2, label="cycle")
    wm, d = sizing.mean_speed, sizing.delta
    wmax, wmin = wm * (1 + d / 2), wm * (1 - d / 2)
    jf = float(np.ravel(sizing.exact)[design])
    span = np.array([j.min(), j.max()])
    for slope, colour, name in ((0.5 * wmax**2, PALETTE[1], "ω_max²/2"), (0.5 * wmin**2, PALETTE[2], "ω_min²/2")):
        k = int(np.argmin(slope * j - w)) if colour == PALETTE[1] else int(np.argmax(slope * j - w))
        ax.plot(span, w[k] + slope * (span - j[k]), color=colour, lw=0.9, ls="--", label=f"tangent, slope {name}")
    ax.set_xlabel("reduced moment of inertia of the linkage J(φ) [kg·m²]")
    ax.set_ylabel("work excess W(φ) [J]")
    ax.set_title(f"Energy–mass diagram (flywheel {format_value(jf)} kg·m²)")
    ax.legend(fontsize=7)
    return ax


def plot_reduced_inertia_and_moment(run: Any, ax: Axes) -> Axes:
    """Reduced moment of inertia (with flywheel and rotor) and the reduced moment of the loads over the cycle."""
    s = run.steady
    deg = np.degrees(s.phi)
    ax.plot(deg, _row(s.inertia), color=PALETTE[0], label="J(φ) with flywheel")
    ax.set_xlabel("crank angle [°]")
    ax.set_ylabel("reduced inertia [kg·m²]", color=PALETTE[0])
    twin = ax.twinx()
    twin.plot(deg, _row(s.load_moment), color=PALETTE[1], label="M(φ) of the loads")
    twin.axhline(0.0, color="#999999", lw=0.6)
    twin.set_ylabel("reduced moment of the loads [N·m]", color=PALETTE[1])
    ax.set_title("Reduced inertia and reduced moment")
    return ax


def plot_speed_over_angle(steady: Any, ax: Axes) -> Axes:
    """Crank speed over the crank angle in the periodic steady state, with its mean (max + min)/2."""
    deg = np.degrees(steady.phi)
    w = _row(steady.omega)
    ax.plot(deg, w * RPM, color=PALETTE[0], label="steady state")
    ax.axhline(float(np.ravel(steady.mean_speed)[0]) * RPM, color="#999999", lw=0.8, ls="--", label="mean")
    ax.set_xlabel("crank angle [°]")
    ax.set_ylabel("crank speed [rpm]")
    ax.set_title(f"Speed at steady state (δ = {format_value(float(np.ravel(steady.delta)[0]))})")
    ax.legend(fontsize=7)
    return ax


def plot_start_up(start: Any, ax: Axes) -> Axes:
    """Crank speed over time from rest, with the time to steady running."""
    tr = start.trajectory
    ax.plot(tr.t, _row(tr.omega) * RPM, color=PALETTE[0], lw=0.9)
    t_s = float(np.ravel(start.time_to_steady)[0])
    ax.axvline(t_s, color=PALETTE[1], lw=0.8, ls="--", label=f"steady running after {format_value(t_s)} s")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("crank speed [rpm]")
    ax.set_title("Start-up from rest")
    ax.legend(fontsize=7)
    return ax


def plot_drive_against_load(run: Any, ax: Axes) -> Axes:
    """The drive's torque at the crank against the torque the linkage takes (kinetostatics at the real speed)
    and at constant speed."""
    s = run.steady
    deg = np.degrees(s.phi)
    ax.plot(deg, _row(s.drive_torque), color=PALETTE[0], label=f"drive ({run.drive.name})")
    if run.real is not None:
        ax.plot(deg, _row(run.real.real.driving_torque), color=PALETTE[1], label="linkage, real speed")
        ax.plot(deg, _row(run.real.constant.driving_torque), color=PALETTE[2], ls="--", lw=0.9,
                label="linkage, constant speed")
    else:  # a cam machine: the load's reduced moment
        ax.plot(deg, -_row(s.load_moment), color=PALETTE[1], label="load (−reduced moment)")
    ax.axhline(0.0, color="#999999", lw=0.6)
    ax.set_xlabel("crank angle [°]")
    ax.set_ylabel("torque at the crank [N·m]")
    ax.set_title("Drive torque against load torque")
    ax.legend(fontsize=7)
    return ax


def plot_motor_duty(run: Any, ax: Axes) -> Axes:
    """The motor's duty (machdyn.dynamics.duty, IEC 60034-1): its torque at the crank over one steady cycle
    against time, its RMS over the cycle, the equivalent torque of its duty (S3/S6: the RMS over the duty period,
    the rest counted), the rated S1 torque and the torque it may carry while loaded in this duty — all at the
    crank. The motor passes its thermal check when the equivalent torque stays at or below the rated torque."""
    duty, s = run.duty, run.steady
    t = _row(s.time)
    ax.plot(t, _row(s.drive_torque), color=PALETTE[0], lw=1.1, label="motor torque at the crank")
    levels = [(duty.load_rms, "RMS over the cycle", PALETTE[1], "--"),
              (duty.equivalent, f"equivalent torque, duty {duty.duty}", PALETTE[2], "-."),
              (duty.rated, "rated torque (S1)", PALETTE[3], "-"),
              (duty.rated_for_duty, f"allowed while loaded in {duty.duty}", PALETTE[4], ":")]
    seen: set[float] = set()
    for value, label, colour, style in levels:
        if duty.duty == "S1" and label.startswith(("equivalent", "allowed")):
            continue  # in S1 these are the RMS and the rating themselves
        if round(value, 9) in seen:
            continue
        seen.add(round(value, 9))
        ax.axhline(value, color=colour, ls=style, lw=1.0, label=f"{label}: {format_value(value)} N·m")
    ax.set_xlabel("time over one steady cycle [s]")
    ax.set_ylabel("torque at the crank [N·m]")
    ax.set_title(f"Motor duty {duty.duty}: {format_value(duty.load_ratio * 100)} % of its rating", fontsize=9)
    ax.legend(fontsize=7, loc="best")
    return ax


def flywheel_rows(run: Any) -> list[list[str]]:
    """The flywheel table: sizing, the part, the drive."""
    sz, part = run.sizing, run.part
    line = run.line
    own = line.about_shaft(run.flywheel, line.flywheel_shaft)
    rows = [["flywheel on", line.describe(line.flywheel_shaft)],
            ["flywheel inertia about its own shaft", f"{format_value(own)} kg·m²"],
            ["flywheel inertia referred to the crank", f"{format_value(run.flywheel)} kg·m²"]]
    if line.declared:
        rows += [["drive-line shafts referred to the crank (counted with the flywheel)",
                  f"{format_value(run.line_inertia)} kg·m²"]]
    if run.table.delta is not None:
        rows += [
            ["target δ", format_value(run.table.delta)],
            ["energy–mass (exact) method", f"{format_value(float(sz.exact[0]))} kg·m²"],
            ["classic ΔE/(ω²δ) less mean J", f"{format_value(float(sz.classic[0]))} kg·m²"],
            ["classic / exact − 1", format_value(float(sz.difference[0]))],
            ["method used", run.table.method],
        ]
    rows += [["maximum fluctuation of energy ΔE", f"{format_value(float(sz.energy_fluctuation[0]))} J"],
             ["simulated δ", format_value(float(np.ravel(run.steady.delta)[0]))]]
    if part is not None:
        rows += [
            ["flywheel shaft speed / crank speed", format_value(line.ratio(line.flywheel_shaft))],
            ["inertia of the part on its shaft", f"{format_value(part.inertia)} kg·m²"],
            ["shape", "solid disc" if part.shape == "disc" else "rim"],
            ["outer diameter", f"{format_value(part.diameter * 1000)} mm"],
            ["width", f"{format_value(part.width * 1000)} mm"],
            ["mass", f"{format_value(part.mass)} kg"],
            ["rim speed / limit", f"{format_value(part.rim_speed)} / {format_value(part.rim_speed_limit)} m/s"],
        ]
    d = run.drive
    if d.name == "induction motor":
        rows += [["motor", f"{format_value(float(d.rated_power) / 1000)} kW, "
                           f"{format_value(float(d.rated_speed) * RPM)} rpm, gear {format_value(float(d.ratio))}:1"],
                 ["breakdown torque at the crank", f"{format_value(float(d.breakdown_torque))} N·m"]]
        rows += _duty_rows(run)
    else:
        rows += [["drive", d.name]]
    rows += [["peak / RMS drive torque", f"{format_value(float(run.steady.peak_drive_torque))} / "
                                         f"{format_value(float(run.steady.rms_drive_torque))} N·m"],
             ["mean power", f"{format_value(float(run.steady.mean_power))} W"]]
    if run.start_up is not None:
        rows += [["time to steady running", f"{format_value(float(run.start_up.time_to_steady))} s"]]
    return rows


def _duty_rows(run: Any) -> list[list[str]]:
    """The motor's duty (IEC 60034-1 S1, S3 or S6) and its starts per hour (machdyn.dynamics.duty)."""
    duty = run.duty
    if duty is None:
        return []
    name = duty.duty if duty.duty == "S1" else f"{duty.duty}, cyclic duration factor {format_value(duty.cdf * 100)} %"
    if duty.duty == "S6":
        name += f", no-load torque {format_value(duty.no_load_torque)} N·m"
    rows = [["duty (IEC 60034-1)", name],
            ["equivalent torque / rated torque at the crank",
             f"{format_value(duty.equivalent)} / {format_value(duty.rated)} N·m "
             f"({format_value(duty.load_ratio * 100)} %)"],
            ["torque allowed while loaded in this duty", f"{format_value(duty.rated_for_duty)} N·m"]]
    if np.isfinite(duty.start_loss):
        asked = "" if duty.starts_required is None else f" (asked for: {format_value(duty.starts_required)})"
        rows += [["rotor loss of one start", f"{format_value(duty.start_loss)} J"],
                 ["starts per hour it stands", format_value(duty.starts_allowed) + asked]]
    return rows


def _real_speed_view(run: Any) -> str:
    """The machine moving at its simulated speed, with the speed and the driving torque at that speed under it
    (empty for a stacked run of several designs)."""
    if run.real is None:
        return ""
    forces = run.real.real
    kin = forces.kinematics
    if np.ndim(kin.crank_angle) != 1:
        return ""
    played = SimpleNamespace(kinematics=kin, forces=forces, energy=None, diagnostics=None)
    speed = np.broadcast_to(np.asarray(kin.speed, dtype=float) * RPM, np.shape(kin.crank_angle))
    data = scene(played, forces.mechanism, curves=[Curve("Crank speed (steady state)", "rpm", speed, from_zero=False)])
    return str(view_html(data, caption=(
        "The machine at its real speed in the periodic steady state with the flywheel and drive above: the joint "
        "reactions, the inertial shaking force and the driving torque include the speed fluctuation.")))


def sections(outcome: Any) -> list[tuple[str, str]]:
    """The report section of a ``[flywheel]`` outcome."""
    run = outcome.results
    if run is None:  # the drive cannot carry the machine: no steady state to show, the failed check says why
        return []

    def draw(fig):
        axes = fig.subplots(2, 2)
        plot_energy_mass(run.sizing, axes[0, 0])
        plot_reduced_inertia_and_moment(run, axes[0, 1])
        plot_speed_over_angle(run.steady, axes[1, 0])
        plot_drive_against_load(run, axes[1, 1])

    figs = [_render("flywheel", "Flywheel and drive", "", (11.0, 8.0), draw, margins=(0.9, 0.9, 0.6, 0.45),
                    wspace=0.55, hspace=0.5)]
    if run.duty is not None:
        figs.append(_render("motor-duty", "Motor duty", "", (6.5, 3.6),
                            lambda fig: plot_motor_duty(run, fig.subplots()), margins=(0.8, 0.25, 0.55, 0.45)))
    if run.start_up is not None:
        figs.append(_render("start-up", "Start-up", "", (6.0, 3.4), lambda fig: plot_start_up(run.start_up,
                                                                                             fig.subplots()),
                            margins=(0.8, 0.25, 0.55, 0.4)))
    intro = (f"<p>The machine under its real drive: flywheel {format_value(run.flywheel)} kg·m², simulated "
             f"coefficient of speed fluctuation {format_value(float(np.ravel(run.steady.delta)[0]))}.")
    if run.real is not None:
        change_joint, change = run.real.largest_change()
        intro += (f" At the real speed the peak force of joint {change_joint} changes by "
                  f"{format_value(change * 100)} % against the constant-speed analysis.")
    intro += "</p>"
    body = intro + _real_speed_view(run) + "".join(f"<figure class=\"plot\">{f.svg}</figure>" for f in figs)
    body += rows_html(flywheel_rows(run), head=("quantity", "value"))
    return [("Flywheel and drive", body)]
