"""Problem files the tests share, written once: import them as ``from problem_texts import four_bar``.

The four-bar is the crank-rocker most tests start from: crank 40 mm, coupler 120 mm, rocker 80 mm, ground 100 mm,
masses 0.2 / 0.5 / 0.4 kg, 10 rad/s and a resisting torque of 0.5 N*m on the crank — small and quick, Grashof,
assembled at every crank angle.
"""

from __future__ import annotations

import math


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


TABLE_CAM = """
[meta]
name = "table cam"

[cam]
speed = "200 rpm"
base_radius = "45 mm"

[cam.follower]
contact = "roller"
roller_radius = "12 mm"

[[cam.segments]]
motion = "rise"
angle = "120 deg"
lift = "25 mm"
law = "table"
{points}

[[cam.segments]]
motion = "dwell"
angle = "60 deg"

[[cam.segments]]
motion = "return"
angle = "120 deg"
lift = "25 mm"
law = "poly345"

[[cam.segments]]
motion = "dwell"
angle = "60 deg"
"""


def table_cam(points: str) -> str:
    """A roller-follower cam whose rise is a table law with the line ``points`` (``points = [[0.2, 0.06]]``) and
    whose return is the 3-4-5 polynomial, 25 mm at 200 rpm."""
    return TABLE_CAM.format(points=points)


CIRCULAR_ARC_CAM = """
[meta]
name = "circular arc cam"

[cam]
speed = "300 rpm"
base_radius = "20 mm"
positions = 3600

[cam.follower]
contact = "{contact}"

[[cam.segments]]
motion = "rise"
angle = "{angle} deg"
lift = "12 mm"
law = "circular_arc"
nose_radius = "5 mm"
flank_radius = "90 mm"

[[cam.segments]]
motion = "return"
angle = "{angle} deg"
lift = "12 mm"
law = "circular_arc"
nose_radius = "5 mm"
flank_radius = "90 mm"

[[cam.segments]]
motion = "dwell"
angle = "{dwell} deg"
"""


def circular_arc_cam(contact: str = "flat", angle: float | None = None) -> str:
    """The circular-arc cam of Khurmi & Gupta, 14th ed., §20.13 (r1 20 mm, r2 5 mm, lift 12 mm, flank 90 mm) with a
    ``contact`` follower, its rise and return over ``angle`` [deg] (the shape's own angle of rise if None)."""
    from machdyn.cams.geometric import rise_angle

    alpha = math.degrees(rise_angle("circular_arc", 0.02, 0.005, 0.012, 0.09))
    a = alpha if angle is None else angle
    return CIRCULAR_ARC_CAM.format(contact=contact, angle=repr(float(a)), dwell=repr(float(360.0 - 2 * a)))
