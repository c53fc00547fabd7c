"""Report section of the ``[hoist]`` kind: where the motor's torque goes (each shaft's own need referred to the
motor, split into accelerating and steady parts, and the stages' loss)."""

from __future__ import annotations

from typing import Any

import numpy as np

from .html import _render, figures_html, format_value, rows_html
from .plotkit import PALETTE, _finish


def plot_torque(ax: Any, result: Any, steady: dict[str, float]) -> Any:
    """Stacked bars: each shaft's steady (load and friction) and accelerating share of the motor torque."""
    names = list(result.shaft_demand)
    total = np.array([result.shaft_demand[n] for n in names] + [result.loss_torque])
    still = np.array([steady[n] for n in names] + [0.0])
    x = np.arange(len(names) + 1)
    ax.bar(x, still, color=PALETTE[1], label="load and friction")
    ax.bar(x, total - still, bottom=still, color=PALETTE[0], label="accelerating")
    ax.bar(x[-1:], total[-1:], color="#999999", label="stages' loss")
    ax.set_xticks(x, [*names, "loss"])
    ax.set_ylabel("torque at the motor [N·m]")
    return _finish(ax, "Where the motor's torque goes")


def sections(outcome: Any) -> list[tuple[str, str]]:
    """The hoist section: the torque bars and a table per shaft."""
    res = outcome.results.result
    steady = outcome.results.steady.shaft_demand

    def draw(fig: Any) -> None:
        plot_torque(fig.subplots(1, 1), res, steady)

    figures = [_render("hoist", "Motor torque", "Each shaft's own need referred to the motor without loss "
                       "(its speed ratio times its torque), steady and accelerating parts, and what the stages "
                       "lose; the bars add up to the motor's torque.", (7.0, 4.0), draw)]
    rows = [[n, format_value(res.speed_ratio[n]), format_value(res.shaft_demand[n])] for n in res.shaft_demand]
    rows.append(["stages' loss", "", format_value(res.loss_torque)])
    intro = (f"<p>Motor torque {format_value(res.motor_torque)} N·m at a motor acceleration of "
             f"{format_value(res.motor_acceleration)} rad/s²; inertia at the motor "
             f"{format_value(res.equivalent_inertia)} kg·m².</p>")
    return [("Hoist", intro + figures_html(figures)
             + rows_html(rows, ["shaft", "speed / motor speed", "torque at the motor [N·m]"]))]
