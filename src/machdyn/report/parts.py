"""Report section of ``[parts]``: the checks with their utilisation, the bearing loads over the cycle with their
mean effective load, and the extreme-fibre stress of each link over the cycle."""

from __future__ import annotations

from typing import Any

import numpy as np

from ..drivetrain.fatigue import failure_amplitude
from ..results.labels import display_factor
from .html import _render, figures_html, format_value, rows_html
from .plotkit import PALETTE, _finish

_SHOWN = {"s": "h", "Pa": "MPa", "Pa*m/s": "MPa*m/s"}


def plot_bearing_loads(ax: Any, result: Any) -> Any:
    """|F| of each bearing over the crank angle, with its mean effective (equal-life) load dashed."""
    phi = np.degrees(result.crank_angle)
    for k, (joint, (load, equivalent)) in enumerate(result.bearing_loads.items()):
        colour = PALETTE[k % len(PALETTE)]
        ax.plot(phi, np.asarray(load) / 1e3, color=colour, label=f"{joint}")
        if equivalent is not None:
            ax.axhline(float(equivalent) / 1e3, color=colour, linestyle="--", linewidth=0.9)
    ax.set_xlabel("crank angle [deg]")
    ax.set_ylabel("bearing load [kN]")
    return _finish(ax, "Bearing loads (dashed: equal-life load)")


def plot_link_stress(ax: Any, result: Any) -> Any:
    """Axial plus bending stress at both extreme fibres of each link over the crank angle."""
    phi = np.degrees(result.crank_angle)
    for k, (body, (top, bottom)) in enumerate(result.link_stress.items()):
        colour = PALETTE[k % len(PALETTE)]
        ax.plot(phi, np.asarray(top) / 1e6, color=colour, label=f"{body}, fibre 1")
        ax.plot(phi, np.asarray(bottom) / 1e6, color=colour, linestyle=":", label=f"{body}, fibre 2")
    ax.axhline(0.0, color="#999999", linewidth=0.6)
    ax.set_xlabel("crank angle [deg]")
    ax.set_ylabel("stress [MPa]")
    return _finish(ax, "Link stresses (axial + inertial bending)")


def plot_haigh(ax: Any, result: Any) -> Any:
    """The Haigh (σ_m, σ_a) diagram of each link: its fatigue criterion's line, Langer's yield line (with S_y),
    the compressive side σ_a = S_e, and the link's point (its notch factor applied)."""
    top = 0.0
    for k, (body, p) in enumerate(result.link_fatigue.items()):
        colour = PALETTE[k % len(PALETTE)]
        se, su, sy = p.endurance / 1e6, p.ultimate / 1e6, (p.yield_strength or 0.0) / 1e6
        mean = np.linspace(0.0, su, 200)
        # the criterion's line: the amplitude at which the factor of safety is 1, for each mean
        amp = [failure_amplitude(m * 1e6, p.endurance, p.ultimate, p.yield_strength, p.criterion) / 1e6
               for m in mean]
        ax.plot(mean, amp, color=colour, label=f"{body}: {p.criterion.replace('_', ' ')}")
        ax.plot([-su, 0.0], [se, se], color=colour)
        if sy:
            ax.plot([-sy, 0.0, sy], [0.0, sy, 0.0], color=colour, linestyle="--", linewidth=0.9,
                    label=f"{body}: Langer yield")
        ax.plot([p.mean / 1e6], [p.amplitude / 1e6], "o", color=colour)
        top = max(top, se * 1.3, p.amplitude / 1e6 * 1.2, sy * 1.05)
    ax.set_ylim(0.0, top or 1.0)
    ax.set_xlabel("mean stress σm [MPa]")
    ax.set_ylabel("stress amplitude σa [MPa]")
    return _finish(ax, "Links: fatigue (Haigh) diagram")


def sections(outcome: Any) -> list[tuple[str, str]]:
    """The ``[parts]`` section: checks table and plots."""
    result = outcome.results
    rows = []
    for c in result.checks:
        unit = _SHOWN.get(c.unit, c.unit)
        f = display_factor(c.unit, unit) if c.unit else 1.0
        limit = format_value(c.limit * f) if c.limit else "–"
        rows.append([c.part, c.quantity, f"{format_value(c.value * f)} {unit}".strip(),
                     f"{limit} {unit}".strip(), f"{100 * c.utilisation:.0f} %", "pass" if c.passed else "FAIL"])
    table = rows_html(rows, ["part", "check", "value", "limit", "utilisation", ""])
    panels = [p for p in (plot_bearing_loads if result.bearing_loads else None,
                          plot_link_stress if result.link_stress else None,
                          plot_haigh if getattr(result, "link_fatigue", None) else None) if p is not None]
    figures = []
    if panels:
        def draw(fig):
            axes = np.atleast_1d(fig.subplots(1, len(panels)))
            for ax, panel in zip(axes, panels, strict=True):
                panel(ax, result)

        figures.append(_render("parts", "Loads on the parts over the cycle", "", (4.8 * len(panels), 3.4), draw,
                               margins=(0.75, 0.3, 0.6, 0.45), wspace=0.35))
    failed = len(result.failed)
    intro = (f"<p>{len(result.checks)} checks, {failed} failed. Utilisation: value / limit for a load, "
             "limit / value for a life or a safety factor.</p>")
    return [("Parts", intro + table + figures_html(figures))]
