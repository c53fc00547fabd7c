"""A candidate written as a mechanism problem file that runs on its own (``machdyn run best_1.toml``).

The engine's model has the crank pivot at the origin, so the file's coordinates are the task's shifted by the
crank pivot's position (said in the file's description). Lengths are written in metres and angles in radians with
every digit of the float, so that the file's linkage is the candidate's to rounding.
"""

from __future__ import annotations

import numpy as np

from .candidate import TWO_PI, Candidate
from .rank import Drive


def _m(v: float) -> str:
    return f'"{float(v)!r} m"'


def _rad(v: float) -> str:
    return f'"{float(v)!r} rad"'


def problem_text(c: Candidate, drive: Drive, *, name: str, note: str = "", full_turn: bool = True) -> str:
    """The TOML text of a ``[mechanism]`` problem for the candidate, run as :mod:`.rank` ran it."""
    o = c.origin
    lines = [
        f"# {name}: synthesised by machdyn ({c.method}).",
        f"# The crank pivot O2 is at ({o.real:.6g} m, {o.imag:.6g} m) in the task's coordinates; here it is at",
        "# the origin, every other point shifted by the same amount.",
        "",
        "[meta]",
        f'name = "{name}"',
        f'description = """{note}"""' if note else 'description = ""',
        "",
        "[mechanism]",
        f'type = "{c.kind}"',
        f'branch = "{"open" if c.branch > 0 else "crossed"}"',
        f'linear_density = "{drive.linear_density!r} kg/m"',
    ]
    if c.kind == "slider_crank":
        lines += [f"offset = {_m(c.offset)}", f"slide_angle = {_rad(c.slide_angle)}", "",
                  "[mechanism.crank]", f"length = {_m(c.crank)}", "", "[mechanism.rod]", f"length = {_m(c.coupler)}"]
    else:
        u, v = c.coupler_point
        lines += [f"coupler_point = [{_m(u)}, {_m(v)}]", "",
                  "[mechanism.crank]", f"length = {_m(c.crank)}", "",
                  "[mechanism.coupler]", f"length = {_m(c.coupler)}", "",
                  "[mechanism.rocker]", f"length = {_m(c.rocker)}", "",
                  "[mechanism.ground]", f"length = {_m(c.ground)}", f"angle = {_rad(c.ground_angle)}"]
    lines += ["", "[drive]", f'speed = "{drive.speed * c.direction!r} rad/s"']
    if full_turn:
        lines += ["positions = 360"]
    else:
        span = c.working_angles(2)
        lo, hi = float(np.min(span)), float(np.max(span))
        if hi - lo >= TWO_PI:
            hi = lo + TWO_PI * (1 - 1e-9)
        lines += [f"positions = {max(drive.positions, 16)}", f"start = {_rad(lo)}", f"stop = {_rad(hi)}"]
    lines += ["", "[loads]", f'gravity = "{"on" if drive.gravity else "off"}"']
    if drive.load and c.kind == "four_bar":
        lines += ["", "[[loads.torques]]", 'name = "output"', 'body = "rocker"', f'torque = "{drive.load!r} N*m"']
    if drive.load and c.kind == "slider_crank":
        fx, fy = drive.load * np.cos(c.slide_angle), drive.load * np.sin(c.slide_angle)
        lines += ["", "[[loads.forces]]", 'name = "output"', 'point = "slider.B"', f'fx = "{float(fx)!r} N"',
                  f'fy = "{float(fy)!r} N"']
    return "\n".join(lines) + "\n"
