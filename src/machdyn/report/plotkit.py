"""What the report's plots share: the colour palette, one series per design, crank-angle axes, titles."""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.axes import Axes
from matplotlib.ticker import MultipleLocator

#: Line colours (colour-blind safe, Okabe-Ito order).
PALETTE = ("#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#F0E442", "#000000")


def _rows(values: Any, design: int | None) -> list[tuple[int | None, np.ndarray]]:
    """(design index or None, 1-D series) for each design to draw."""
    arr = np.asarray(values, dtype=float)
    if arr.ndim <= 1:
        return [(None, np.atleast_1d(arr))]
    if design is not None:
        return [(design, arr[design])]
    return [(i, arr[i]) for i in range(arr.shape[0])]


def _label(base: str, design: int | None) -> str:
    return base if design is None else f"{base} (design {design})"


def _angle_deg(kinematics: Any) -> np.ndarray:
    return np.degrees(np.asarray(kinematics.crank_angle, dtype=float).ravel())


def _crank_axis(ax: Axes, deg: np.ndarray, zero_line: bool = True) -> None:
    ax.set_xlabel("Crank angle φ [deg]")
    lo, hi = float(np.nanmin(deg)), float(np.nanmax(deg))
    if hi > lo:
        ax.set_xlim(lo, hi)
    span = hi - lo
    ax.xaxis.set_major_locator(MultipleLocator(60 if span > 240 else 30 if span > 90 else 10))
    ax.grid(True, which="major", alpha=0.35, linewidth=0.6)
    if zero_line:
        ax.axhline(0.0, color="#888888", linewidth=0.6, zorder=0)


def _finish(ax: Axes, title: str | None, legend: bool = True) -> Axes:
    if title:
        ax.set_title(title, fontsize="medium", loc="left", fontweight="bold")
    handles, _labels = ax.get_legend_handles_labels()
    if legend and len(handles) > 1:
        ax.legend(fontsize="small", framealpha=0.85)
    return ax
