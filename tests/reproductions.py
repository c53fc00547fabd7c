"""Problem files that reproduce faults an adversarial pass found, written once: each fault's own test imports its
file from here to check what check and run say, and the fuzz's seed set (tests/fuzz/test_fuzz_known_faults.py)
runs every one of them through check and run before the generated files. Import as
``from reproductions import feeder_with``.

Each is a shipped example with the smallest change that shows the fault.
"""

from __future__ import annotations

import re
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def example(name: str) -> str:
    """The text of the shipped example ``name`` (without ``.toml``)."""
    return (EXAMPLES / f"{name}.toml").read_text(encoding="utf-8")


def replaced(text: str, old: str, new: str) -> str:
    """``text`` with the first ``old`` replaced by ``new``; ``old`` must be there (an example that changed fails
    here rather than testing the unchanged file)."""
    assert old in text, old
    return text.replace(old, new, 1)


# ------------------------------------------------------------------------------------------------------ cams


def kinematic(text: str) -> str:
    """A cam file without its dynamics: the kinematic checks alone, quick."""
    return text[:text.index("[cam.dynamics]")] + text[text.index("[cam.output]"):]


def feeder_with(rise: str, dwell: str, positions: int, roller: str = "12 mm") -> str:
    """The feeder cam, kinematics only, with its first rise over ``rise`` and the following dwell ``dwell``."""
    text = replaced(example("feeder_cam"), 'angle = "110 deg"', f'angle = "{rise}"')
    text = replaced(text, 'angle = "70 deg"', f'angle = "{dwell}"').replace("positions = 720",
                                                                          f"positions = {positions}")
    return kinematic(text.replace('roller_radius = "12 mm"', f'roller_radius = "{roller}"'))


def steep_rise() -> str:
    """30 mm over 0.3 deg at 720 positions: the samples never see the rise (passed at exit 0)."""
    return feeder_with("0.3 deg", "179.7 deg", 720)


def huge_base_radius() -> str:
    """A base circle of 1e9 m (passed at exit 0)."""
    return kinematic(replaced(example("feeder_cam"), 'base_radius = "45 mm"', 'base_radius = "1e9 m"'))


def fast_cam() -> str:
    """The feeder cam at 1e9 rpm: a contact force of 3.9e15 N (passed at exit 0)."""
    return kinematic(replaced(example("feeder_cam"), 'speed = "200 rpm"', 'speed = "1e9 rpm"'))


TINY_SEGMENTS = '''
[[cam.segments]]
motion = "rise"
angle = "1e-300 deg"
lift = "1 mm"

[[cam.segments]]
motion = "return"
angle = "1e-300 deg"
lift = "1 mm"

[cam.checks]'''


def tiny_cam_segments() -> str:
    """Two cam segments of 1e-300 deg (an internal error, exit 4)."""
    return replaced(example("feeder_cam"), "\n[cam.checks]", TINY_SEGMENTS)


# ---------------------------------------------------------------------------------------------- shaft lines

SHAFT = example("shaft_inline_four_phases_optimise")
#: The in-line four's shaft line without its [optimise] table, and that table.
SHAFT_LINE, SHAFT_OPTIMISE = SHAFT[: SHAFT.index("[optimise]")], SHAFT[SHAFT.index("[optimise]"):]


def shaft_column(key: str) -> str:
    """The in-line four swept over a crank phase with the column ``key``."""
    return SHAFT_LINE + ('[sweep]\nparameter = "cylinders[1].phase"\nvalues = ["90 deg", "180 deg"]\n'
                         f'columns = ["{key}"]\n')


def shaft_objective(key: str) -> str:
    """The in-line four's phase optimisation with its first objective on ``key``."""
    return SHAFT_LINE + replaced(SHAFT_OPTIMISE, 'result = "shaft.engine.primary_couple"', f'result = "{key}"')


def vibration_reference() -> str:
    """Field balancing from records with a vibration channel as the phase reference (333 g at 158 deg instead of
    24 g at 70 deg, exit 0)."""
    return replaced(example("shaft_field_records"), 'reference = "key"', 'reference = "drive_end"')


def tiny_trial() -> str:
    """Field balancing whose trial mass changed one reading by 0.0001 mm/s: a nearly singular influence matrix
    (a 1.74 t correction, exit 0)."""
    text = replaced(example("shaft_field_balancing"), '{ amplitude = 5.2, phase = "101 deg" }',
                    '{ amplitude = 8.6001, phase = "62 deg" }')
    return replaced(text, '{ amplitude = 5.0, phase = "165 deg" }', '{ amplitude = 6.1, phase = "147 deg" }')


#: A record named in a problem file that is a private file beside it: its first line must never be echoed.
SECRET = "API_KEY=s3cr3t-value-of-the-user"


def private_record() -> str:
    """Field balancing whose first record is ``.env`` beside the problem file (its first line was echoed)."""
    return replaced(example("shaft_field_records"), '"machdyn:examples/field_records/original.csv"', '".env"')


# --------------------------------------------------------------------------------------- drive trains, parts


def swapped_strengths() -> str:
    """A link whose ultimate strength (120 MPa) is below its endurance limit (150 MPa) (exit 0)."""
    return replaced(example("crank_press_drive"), 'ultimate_strength = "600 MPa"', 'ultimate_strength = "120 MPa"')


def press_with_brake(overhauling_torque: str) -> str:
    """The crank press of the drive-train example with only its drive train and brake, and a torque on the crank
    that drives it (an overhauling load); 2000 N*m is more than its brake can hold (three minutes, then exit 2)."""
    text = example("crank_press_drive")
    text = text[: text.index("[flywheel]")] + text[text.index("[drivetrain]"):]
    text = text[: text.index("[drivetrain.clutch]")] + text[text.index("[drivetrain.brake]"):]
    text = text[: text.index("[drivetrain.single_stroke]")]
    return replaced(text, "[drive]", f'[[loads.torques]]\nname = "overhauling"\nbody = "crank"\n'
                                     f'torque = "{overhauling_torque}"\n\n[drive]')


def stalling_compactor() -> str:
    """The compactor's 0.75 kW motor against a 200 N*m*s/rad damper: it stalls in the cycle (check said OK, run
    exited 2)."""
    text = replaced(example("compactor_flywheel"), 'coefficient = "0.5 N*m*s/rad"', 'coefficient = "200 N*m*s/rad"')
    text = replaced(text, 'kind = "select"              # an induction motor from the IEC 60072-1 ratings',
                    'kind = "induction"\nrated_power = "0.75 kW"\nrated_speed = "1440 rpm"')
    return replaced(text, "[flywheel.motor]", "start_up = false\n\n[flywheel.motor]")


#: A four-bar with a ball bearing at O, a plain bearing at A and a pin at B: the parts its [parts] declares.
PARTS = example("four_bar") + '''
[[parts.bearings]]
joint = "O"
kind = "ball"
capacity = "5 kN"

[[parts.bearings]]
joint = "A"
kind = "plain"
diameter = "10 mm"
length = "12 mm"
max_pressure = "20 MPa"

[[parts.pins]]
joint = "B"
diameter = "8 mm"
length = "12 mm"
shear_planes = 2
allowable_shear = "80 MPa"
'''


def parts_column(key: str) -> str:
    """The four-bar with parts, its crank swept, with the column ``key``."""
    return PARTS + ('\n[sweep]\nparameter = "mechanism.crank.length"\nvalues = ["30 mm", "40 mm"]\n'
                    f'columns = ["{key}"]\n')


def parts_objective(key: str) -> str:
    """The four-bar with parts, its crank length optimised, with the objective ``key``."""
    return PARTS + ('\n[[optimise.variables]]\nparameter = "mechanism.crank.length"\nlower = "30 mm"\n'
                    f'upper = "45 mm"\n\n[[optimise.objectives]]\nresult = "{key}"\n')


# ------------------------------------------------------------------------------- studies, conveyor, synthesis


def empty_speed_fractions() -> str:
    """A conveyor design search over no speed fraction (exit 4 at check, 1 at run)."""
    return re.sub(r"speed_fractions = \[.*\]", "speed_fractions = []", example("conveyor_best_design"))


def compactor_derived(formula: str) -> str:
    """The compactor's optimisation with its derived load ``formula`` (one that overflows or divides by zero
    passed check, then exit 4)."""
    return replaced(example("compactor_optimise"), '"loads.forces[0].fy" = "2000 * 0.1 / l"',
                    f'"loads.forces[0].fy" = "{formula}"')


def synthesis(function: str, x_range: str) -> str:
    """A function generator for ``function`` over ``x_range`` (one undefined over its range passed check, then
    exit 1 with a raw LinAlgError)."""
    text = replaced(example("synthesis_function_log10"), 'function = "log10"', f'function = "{function}"')
    return replaced(text, "x_range = [1.0, 2.0]", f"x_range = {x_range}")
