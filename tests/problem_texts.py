"""Problem files the tests share, written once: import them as ``from problem_texts import four_bar``.

The four-bar is the crank-rocker most tests start from: crank 40 mm, coupler 120 mm, rocker 80 mm, ground 100 mm,
masses 0.2 / 0.5 / 0.4 kg, 10 rad/s and a resisting torque of 0.5 N*m on the crank — small and quick, Grashof,
assembled at every crank angle.
"""

from __future__ import annotations


def four_bar(name: str = "four-bar", positions: int = 36) -> str:
    """The shared four-bar problem file named ``name``, sampled at ``positions`` crank angles."""
    return f"""
[meta]
name = "{name}"

[mechanism]
type = "four_bar"
crank = {{length = "40 mm", mass = "0.2 kg"}}
coupler = {{length = "120 mm", mass = "0.5 kg"}}
rocker = {{length = "80 mm", mass = "0.4 kg"}}
ground = {{length = "100 mm"}}

[drive]
speed = "10 rad/s"
positions = {positions}

[[loads.torques]]
body = "crank"
torque = "-0.5 N*m"
"""
