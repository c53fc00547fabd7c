"""Report sections of ``[transient]`` with its drive's own states: the machine in time
(:mod:`machdyn.report.transient`), then, for an induction motor's dq model (``[transient.motor]``), its
electromagnetic torque and stator current against time with the steady state's breakdown torque marked and the
run's electrical energy balance, and, for a drive line with torsionally stiff stages, the torque through each
against time. Every plot takes an ``ax`` and returns it."""

from __future__ import annotations

from typing import Any

from matplotlib.axes import Axes

from .html import format_value, render_figure, rows_html
from .plotkit import PALETTE
from .transient import sections as machine_sections


def _thin(size: int, limit: int = 8000) -> slice:
    return slice(None, None, max(1, size // limit))


def plot_motor_torque(motor: Any, ax: Axes) -> Axes:
    """Electromagnetic torque on the motor shaft over time, with the steady state's breakdown torque."""
    s = _thin(motor.t.size)
    ax.plot(motor.t[s], motor.torque[s], color=PALETTE[0], lw=0.7)
    ax.axhline(motor.breakdown_torque, color="#999999", lw=0.7, ls="--")
    ax.annotate("breakdown (steady state)", (motor.t[-1], motor.breakdown_torque), fontsize=7, ha="right",
                va="bottom", color="#666666")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("torque [N·m]")
    ax.set_title("Electromagnetic torque")
    return ax


def plot_motor_current(motor: Any, ax: Axes) -> Axes:
    """Amplitude of the stator phase current over time."""
    s = _thin(motor.t.size)
    ax.plot(motor.t[s], motor.current[s], color=PALETTE[1], lw=0.7)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("current amplitude [A]")
    ax.set_title("Stator current")
    return ax


def motor_rows(motor: Any, run: Any) -> list[tuple[str, str]]:
    """The electrical energy balance of the run [J]."""
    gear = motor.air_gap_work - float(run.works[0, -1])
    return [("electrical input", format_value(motor.electrical_input)),
            ("copper loss (stator and rotor)", format_value(motor.copper_loss)),
            ("magnetic energy lost at the switch-off", format_value(motor.switching_loss)),
            ("change of magnetic energy", format_value(motor.magnetic_energy_change)),
            ("gear loss", format_value(gear)),
            ("work of the drive at the crank", format_value(float(run.works[0, -1])))]


def plot_shaft_torques(torsion: Any, ax: Axes) -> Axes:
    """Torque through each stiff stage at its output shaft over time."""
    s = _thin(torsion.t.size)
    for i, (name, torque) in enumerate(zip(torsion.line.names, torsion.shaft_torque, strict=True)):
        ax.plot(torsion.t[s], torque[s], color=PALETTE[i % len(PALETTE)], lw=0.7, label=name)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("shaft torque [N·m]")
    ax.set_title("Torque through the stiff stages")
    ax.legend(fontsize=7)
    return ax


def _shafts_section(result: Any) -> tuple[str, str]:
    torsion = result.torsion
    fig = render_figure("transient-shafts", "Torque through the stiff stages", "", (6.5, 3.4),
                        lambda f: plot_shaft_torques(torsion, f.subplots()), margins=(0.9, 0.3, 0.6, 0.45))
    rows = [(name, format_value(peak)) for name, peak in zip(torsion.line.names, torsion.peak_torques, strict=True)]
    intro = ("<p>The drive line's shafts joined by the stiff stages' torsional springs, each rigid group of shafts "
             "integrated on its own; the torque each stage passes to its output shaft. The line's energy balance "
             f"closes to {torsion.energy_error:.2g}.</p>")
    body = intro + f"<figure class=\"plot\">{fig.svg}</figure>" + rows_html(rows, head=("stage", "peak torque [N·m]"))
    return "Torque through the drive line's stiff stages", body


def sections(outcome: Any) -> list[tuple[str, str]]:
    """The report sections of a ``[transient]`` outcome, with its motor's when it has electrical states and its
    drive line's when stages are stiff."""
    out = machine_sections(outcome)
    result = outcome.results
    if getattr(result, "torsion", None) is not None:
        out.append(_shafts_section(result))
    motor = getattr(result, "motor", None)
    if motor is None:
        return out

    def draw(fig):
        axes = fig.subplots(1, 2)
        plot_motor_torque(motor, axes[0])
        plot_motor_current(motor, axes[1])

    fig = render_figure("transient-motor", "The motor's electrical states", "", (11.0, 3.6), draw,
                        margins=(0.9, 0.3, 0.6, 0.45), wspace=0.3)
    error = outcome.scalars.get("transient.motor_energy_error", float("nan"))
    intro = (f"<p>The induction motor's dq model (stator and rotor flux linkages, {motor.motor.frame} reference "
             f"frame) integrated with the machine: peak electromagnetic torque "
             f"{format_value(motor.peak_torque)} N·m on the motor shaft (the steady state's breakdown torque is "
             f"{format_value(motor.breakdown_torque)} N·m, its starting torque "
             f"{format_value(motor.starting_torque)} N·m), peak stator current "
             f"{format_value(motor.peak_current)} A (amplitude). The electrical energy balance closes to "
             f"{error:.2g} of the electrical input.</p>")
    body = intro + f"<figure class=\"plot\">{fig.svg}</figure>" + rows_html(motor_rows(motor, result.run),
                                                                           head=("energy", "[J]"))
    return [*out, ("The motor's electrical states", body)]
