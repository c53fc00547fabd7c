"""The catalogue of quantities: every result machdyn reports, declared once.

Each :class:`Quantity` gives a result's key, its label, its SI unit and the unit it is shown in, how it is
reduced over the crank positions of one design and how designs compare by it, and which problem kind, machine
or capability produces it. A run (results.json, the summary, the report), a ``[sweep]`` (its columns and
its ``objective``), an exploration's Parquet columns and ``[optimise]`` (objectives and constraints) all name a
result by the key declared here; the per-design values of a population come from one function,
:func:`machdyn.results.population.evaluate_population`.

Keys made at run time (``joint.B.max_force``, ``stroke.rocker``) are declared as patterns: ``<joint>`` stands
for one part of a key, ``<path*>`` for one or more parts.

Older names are still accepted where a result is named (``[sweep] objective``, ``[optimise]`` results) and
mapped to the key through :data:`ALIASES`, the one table of renamed results (see docs/results.md).
"""

from __future__ import annotations

import re
import warnings
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from functools import cache
from typing import Any

import numpy as np

from ..linkage.reductions import REDUCTIONS
from .labels import Label

#: How a quantity is reduced over the crank positions of one design: the reductions written once in
#: :mod:`machdyn.linkage.reductions`, by name ("scalar" for a figure that reduces no series).
OVER_POSITIONS = {name: r.text for name, r in REDUCTIONS.items()}
#: Which way a design is better by a quantity, each declared with every quantity (``Quantity.better``).
BETTER = {
    "lower": "the smaller value is better",
    "higher": "the larger value is better",
    "target": "the value nearest the one the designer sets is better",
    "none": "no better direction (a dimension, a speed, a count of the study)",
    "true": "a yes/no check: yes is better",
}

#: The groups of the population evaluator that compute a quantity for many designs at once (see
#: :mod:`machdyn.results.population`); "" for a result of a single design only.
GROUPS = {
    "forces": "the engine's sweep (kinetostatics summarised per design; the compiled path when available)",
    "motion": "kinematics of the designs over the crank positions",
    "geometry": "the link lengths alone",
    "analysis": "the full analysis of the designs (energy, reduced inertia, work balance, harmonics, loads' power)",
    "status": "the checks of each design (assembly, dead points, transmission angle)",
}


@dataclass(frozen=True)
class Quantity:
    """One result: ``key`` (or a pattern of keys), label ``text`` (with ``{name}`` for each pattern part),
    SI ``unit`` and ``display`` unit (the SI unit if None), the reductions ``over_positions`` and
    ``better`` (which way a design is better by it, a key of :data:`BETTER`), the ``producer`` (a problem
    kind, ``kind:machine`` or a capability's table), the
    ``group`` of the population evaluator that computes it for many designs ("" for single designs only, with
    ``why`` saying why), ``zero_below`` (a result whose magnitude sets this one's round-off scale), ``kind``
    ("number" or "text": a category such as the Grashof class, which can be a column but not an objective) and
    ``series``: the series over the crank positions (a key of :data:`machdyn.results.linkage.SERIES`, its
    pattern parts those of the key) that ``over_positions`` reduces, "" for a figure computed otherwise.
    ``over_positions`` and ``better`` are "" only for a quantity nobody declared (a test refuses it)."""

    key: str
    text: str
    unit: str = ""
    display: str | None = None
    over_positions: str = ""
    better: str = ""
    producer: str = "mechanism"
    group: str = ""
    why: str = ""
    zero_below: str | None = None
    kind: str = "number"
    series: str = ""

    @property
    def declared(self) -> bool:
        """Whether both the reduction and the better direction are declared (and known names)."""
        return self.over_positions in REDUCTIONS and self.better in BETTER

    @property
    def is_pattern(self) -> bool:
        return "<" in self.key

    def label(self, **parts: str) -> Label:
        """The :class:`~machdyn.results.labels.Label` of this quantity (pattern parts filled in)."""
        text = self.text.format(**parts) if parts else self.text
        return Label(text, self.unit, self.display, self.zero_below)


def _q(key, text, unit="", over_positions="", better="", group="", **kw) -> Quantity:
    return Quantity(key, text, unit, kw.pop("display", None), over_positions, better, group=group, **kw)


_SINGLE = "a figure of one analysed design"

#: The results of a linkage analysis (the ``mechanism`` and ``rotary_screen`` kinds). ``series`` names the series
#: of :data:`machdyn.results.linkage.SERIES` a quantity reduces; the reduction is ``over_positions``.
MECHANISM: tuple[Quantity, ...] = (
    _q("crank_speed.mean", "Crank speed, mean", "rad/s", "angle_mean", "none", "analysis", series="crank_speed"),
    _q("driving_torque.max_abs", "Driving torque, max |T|", "N*m", "max_abs", "lower", "forces",
       series="driving_torque"),
    _q("driving_torque.max", "Driving torque, maximum", "N*m", "max", "lower", "analysis", series="driving_torque"),
    _q("driving_torque.min", "Driving torque, minimum", "N*m", "min", "higher", "analysis", series="driving_torque"),
    _q("driving_torque.mean", "Driving torque, mean", "N*m", "time_mean", "lower", "analysis",
       zero_below="driving_torque.max_abs", series="driving_torque"),
    _q("driving_torque.rms", "Driving torque, RMS", "N*m", "time_rms", "lower", "forces", series="driving_torque"),
    _q("input_power.mean", "Input power, mean", "W", "time_mean", "lower", "forces", zero_below="input_power.max",
       series="input_power"),
    _q("input_power.max", "Input power, maximum", "W", "max", "lower", "analysis", series="input_power"),
    _q("input_power.min", "Input power, minimum (negative: power flows back into the drive)", "W", "min", "higher",
       "analysis", series="input_power"),
    _q("inertial_shaking_force.max", "Shaking force, inertial (-sum m a_G), max", "N", "max", "lower", "motion",
       series="inertial_shaking_force"),
    _q("inertial_shaking_moment.max_abs", "Shaking moment, inertial (of -m a_G and -I alpha), max |M|", "N*m",
       "max_abs", "lower", "motion", zero_below="driving_torque.max_abs", series="inertial_shaking_moment"),
    _q("frame_force.max", "Frame force, max (inertia, process loads and weight)", "N", "max", "lower", "forces",
       series="frame_force"),
    _q("shaking_moment.max_abs", "Shaking moment on the frame, max |M| (inertia, loads, weight, drive reaction)",
       "N*m", "max_abs", "lower", "forces", zero_below="driving_torque.max_abs", series="shaking_moment"),
    _q("shaking_moment.about_x", "Shaking moment reference point, x", "m", "scalar", "none",
       why="the point given in [output]"),
    _q("shaking_moment.about_y", "Shaking moment reference point, y", "m", "scalar", "none",
       why="the point given in [output]"),
    _q("kinetic_energy.max", "Kinetic energy, max", "J", "max", "lower", "analysis", series="kinetic_energy"),
    _q("kinetic_energy.min", "Kinetic energy, min", "J", "min", "none", "analysis", series="kinetic_energy"),
    _q("kinetic_energy.fluctuation", "Kinetic energy, fluctuation (max - min)", "J", "range", "lower", "analysis",
       series="kinetic_energy"),
    _q("reduced_inertia.min", "Reduced inertia at the crank, minimum", "kg*m^2", "min", "none", "analysis",
       series="reduced_inertia"),
    _q("reduced_inertia.max", "Reduced inertia at the crank, maximum", "kg*m^2", "max", "none", "analysis",
       series="reduced_inertia"),
    _q("reduced_inertia.mean", "Reduced inertia at the crank, mean", "kg*m^2", "angle_mean", "none", "analysis",
       series="reduced_inertia"),
    _q("flywheel.energy_fluctuation", "Energy to store in a flywheel (constant speed)", "J", "cycle", "lower",
       "analysis"),
    _q("work_balance.input_work", "Work balance: input work", "J", "cycle", "none", "analysis"),
    _q("work_balance.load_work", "Work balance: work of the loads", "J", "cycle", "none", "analysis"),
    _q("work_balance.energy_change", "Work balance: energy change", "J", "cycle", "none", "analysis"),
    _q("work_balance.residual", "Work balance: residual", "J", "cycle", "none", "analysis"),
    _q("work_balance.relative_residual", "Work balance, relative residual", "", "cycle", "lower", "analysis"),
    _q("time_ratio", "Time ratio (the longer over the shorter stroke time, >= 1)", "", "cycle", "none", "motion"),
    _q("transmission_angle.min", "Transmission angle, min", "rad", "min", "higher", "motion"),
    _q("transmission_angle.max", "Transmission angle, max", "rad", "max", "lower", "motion"),
    _q("transmission_angle.worst", "Transmission angle, worst (closest to 0 or 180 deg)", "rad", "worst", "higher",
       "motion"),
    _q("dead_positions.count", "Dead positions (count)", "", "count", "lower", "motion"),
    _q("grashof.margin", "Grashof margin s + l - (p + q) (negative: a link turns fully)", "m", "scalar", "lower",
       "geometry"),
    _q("grashof.class", "Grashof class", "", "scalar", "none", "geometry", kind="text"),
    _q("joint.<joint>.max_force", "Joint {joint}, max force", "N", "max", "lower", "forces",
       series="joint.<joint>.force"),
    _q("stroke.<body>", "Stroke of {body}", "m or rad", "range", "none", "motion"),
    _q("time_ratio.<body>", "Time ratio of {body} (the longer over the shorter stroke time, >= 1)", "", "cycle", "none",
       "motion"),
    _q("transmission_angle.<body>.min", "Transmission angle of the dyad driving {body}, min", "rad", "min", "higher",
       "motion"),
    _q("transmission_angle.<body>.max", "Transmission angle of the dyad driving {body}, max", "rad", "max", "lower",
       "motion"),
    _q("load.<load>.mean_power", "Load {load}, mean power (negative: the drive works against it)", "W",
       "time_mean", "none", "analysis", series="load.<load>.power"),
    _q("<series*>.harmonic_<order>.amplitude", "{series}, harmonic {order}, amplitude", "", "harmonic_amplitude",
       "lower", "analysis", series="<series*>"),
    _q("<series*>.harmonic_<order>.phase", "{series}, harmonic {order}, phase", "rad", "harmonic_phase", "none",
       "analysis", series="<series*>"),
)

#: The results of a compactor (``[mechanism] machine = "compactor"``: a four-bar whose coupler is the
#: compaction plate and whose coupler point is where it presses; seed 003, Asfandiyarov et al., 2019).
COMPACTOR: tuple[Quantity, ...] = tuple(
    Quantity(key, text, unit, None, over, better, "mechanism:compactor", "motion")
    for key, text, unit, over, better in (
        ("compactor.plate_angle.max", "Compactor: plate angle to the horizontal, max |gamma|", "rad", "max",
         "lower"),
        ("compactor.k1.min", "Compactor: crank force gain k1 = 1/cos alpha, min over the pressing window", "",
         "min", "higher"),
        ("compactor.k2", "Compactor: lever force gain k2 = l/a", "", "scalar", "higher"),
        ("compactor.force_gain.min", "Compactor: force gain k1 k2, min over the pressing window", "", "min",
         "higher"),
    )
)

#: The checks of each design of a population: columns of a sweep or exploration, the optimiser's built-in
#: constraint. ``regular`` is True only for a design with none of the faults.
STATUS: tuple[Quantity, ...] = tuple(
    Quantity(key, text, "", None, "scalar", better, "population", "status", kind=kind)
    for key, text, better, kind in (
        ("assembled", "Assembles at every crank angle", "true", "number"),
        ("assembled_fraction", "Share of the crank angles where the design assembles", "higher", "number"),
        ("dead_point", "Passes a dead (toggle) position at a sampled crank angle", "lower", "number"),
        ("branch_change", "Changes branch between neighbouring crank angles (a dyad's determinant changes sign)",
         "lower", "number"),
        ("near_dead_point", "Comes within about 1 deg of a dead position (a dyad's |det| below 1.75% of its "
                            "largest)", "lower", "number"),
        ("poor_transmission", "Transmission angle within the threshold of 0 or 180 deg", "lower", "number"),
        ("regular", "Regular: assembles everywhere, no dead point, branch change, near dead point or poor "
                    "transmission", "true", "number"),
        ("status", "Status of the design (regular or its first fault)", "none", "text"),
    )
)

#: The checks of ``[parts]``, one key per check: ``parts.<part kind>.<name>.<figure>`` (the name of the joint or
#: link); the keys built from the checks' labels before are read through :data:`PATTERN_ALIASES`.
PARTS: tuple[Quantity, ...] = tuple(
    Quantity(key, text, unit, display, over, better, producer="parts")
    for key, text, unit, display, over, better in (
        ("parts.bearing.<name>.rating_life", "Bearing {name}: rating life at its reliability", "s", "h", "scalar",
         "higher"),
        ("parts.bearing.<name>.peak_pressure", "Bearing {name}: peak pressure p", "Pa", "MPa", "max", "lower"),
        ("parts.bearing.<name>.mean_pv", "Bearing {name}: mean p·v over the cycle", "Pa*m/s", "MPa*m/s", "time_mean",
         "lower"),
        ("parts.pin.<name>.peak_shear_stress", "Pin {name}: peak shear stress", "Pa", "MPa", "max", "lower"),
        ("parts.pin.<name>.peak_bearing_pressure", "Pin {name}: peak bearing pressure", "Pa", "MPa", "max", "lower"),
        ("parts.link.<name>.fatigue_safety", "Link {name}: fatigue safety factor (by its criterion, modified "
         "Goodman unless the file names another)", "", None, "scalar", "higher"),
        ("parts.link.<name>.yield_safety", "Link {name}: yield safety factor (Langer)", "", None, "scalar", "higher"),
        ("parts.link.<name>.fatigue_damage", "Link {name}: fatigue damage over the required cycles (Miner)", "",
         None, "scalar", "lower"),
        ("parts.link.<name>.peak_stress", "Link {name}: peak stress (a point above the ultimate strength)", "Pa",
         "MPa", "max", "lower"),
    )
)

#: The shaft line's results whose keys are made from the file's names (planes, bearings, frame points,
#: cylinders), each with its SI unit; matched before the general patterns below them.
SHAFT_LINE: tuple[Quantity, ...] = tuple(
    Quantity(key, text, unit, display, over, better, producer=producer)
    for key, text, unit, display, over, better, producer in (
        ("shaft.balance.<plane>.mass", "Correction in plane {plane}: mass", "kg", None, "scalar", "lower",
         "shaft_line"),
        ("shaft.balance.<plane>.angle", "Correction in plane {plane}: angle from the reference mark", "rad", None,
         "scalar", "none",
         "shaft_line"),
        ("shaft.balance.<plane>.hole<hole>.mass", "Correction in plane {plane}: mass in hole {hole}", "kg", None,
         "scalar", "lower",
         "shaft_line"),
        ("shaft.field.<plane>.mass", "Field balancing, plane {plane}: correction mass", "kg", "g", "scalar", "lower",
         "shaft_line"),
        ("shaft.field.<plane>.angle", "Field balancing, plane {plane}: correction angle", "rad", None, "scalar",
         "none", "shaft_line"),
        ("shaft.field.<plane>.trial_effect", "Field balancing, plane {plane}: trial effect", "", None, "scalar",
         "higher", "shaft_line"),
        ("shaft.field.<plane>.hole<hole>.mass", "Field balancing, plane {plane}: mass in hole {hole}", "kg", "g",
         "scalar", "lower",
         "shaft_line"),
        ("shaft.records.<plane>.mass", "Field balancing from records, plane {plane}: correction mass", "kg", "g",
         "scalar", "lower",
         "field_records"),
        ("shaft.records.<plane>.angle", "Field balancing from records, plane {plane}: correction angle", "rad", None,
         "scalar", "none",
         "field_records"),
        ("shaft.records.<plane>.hole<hole>.mass", "Field balancing from records, plane {plane}: mass in hole {hole}",
         "kg", "g", "scalar", "lower", "field_records"),
        ("shaft.records.original.sensor<index>.phase", "Original run, sensor {index}: 1x phase lag", "rad", None,
         "scalar", "none",
         "field_records"),
        ("shaft.bearing.<bearing>.peak", "Bearing {bearing}: largest force", "N", None, "max", "lower", "shaft_line"),
        ("shaft.bearing.<bearing>.peak_after", "Bearing {bearing}: largest force after correction", "N", None, "max",
         "lower",
         "shaft_line"),
        ("shaft.engine.order<order>.force", "Engine: largest force of order {order}, exact", "N", None, "max", "lower",
         "shaft_line"),
        ("shaft.engine.order<order>.couple", "Engine: largest couple of order {order}, exact", "N*m", None, "max",
         "lower",
         "shaft_line"),
        ("shaft.frame.mode<order>.frequency", "Frame on its mounts: natural frequency {order}", "Hz", None, "scalar",
         "none",
         "shaft_line"),
        ("shaft.frame.mount.<mount>.force", "Mount {mount}: largest dynamic force", "N", None, "max", "lower",
         "shaft_line"),
        ("shaft.frame.point.<point>.rms_velocity", "Frame point {point}: RMS vibration velocity", "m/s", "mm/s",
         "time_rms", "lower",
         "shaft_line"),
        ("shaft.grade.<plane>.allowed", "ISO 21940-11: permissible unbalance of bearing plane {plane}", "kg*m",
         "g*mm", "scalar", "none", "shaft_line"),
        ("shaft.grade.<plane>.residual", "ISO 21940-11: residual unbalance in bearing plane {plane}", "kg*m", "g*mm",
         "scalar", "lower",
         "shaft_line"),
        ("shaft.locomotive.<side>.balance_mass", "Locomotive: balance mass, {side} wheel", "kg", None, "scalar",
         "lower", "shaft_line"),
        ("shaft.locomotive.<side>.balance_angle", "Locomotive: balance-mass angle, {side} wheel", "rad", None,
         "scalar", "none",
         "shaft_line"),
    )
)

#: Each rise's and return's own extremes (:mod:`machdyn.cams.strokes`), by the segment's number, of a cam file's
#: cam and of a cam on a linkage's crank shaft; the units of a translating follower (an oscillating follower's run
#: labels its own in rad/s ...).
CAM_STROKES: tuple[Quantity, ...] = tuple(
    Quantity(f"{prefix}.segment<segment>.{figure}", f"{title}Segment {{segment}}: {text}", unit, display,
             over_positions=over, better=better, producer=prefix)
    for prefix, title in (("cam", ""), ("shaft_cam", "Shaft cam: "))
    for figure, text, unit, display, over, better in (
        ("max_velocity", "peak |v|", "m/s", None, "max_abs", "lower"),
        ("max_acceleration", "peak |a|", "m/s^2", None, "max_abs", "lower"),
        ("max_jerk", "peak |j|", "m/s^3", None, "max_abs", "lower"),
        ("max_pressure_angle", "largest |pressure angle|", "rad", "deg", "max_abs", "lower"),
        ("min_pitch_curvature_radius", "smallest convex radius of curvature of the pitch curve", "m", "mm", "min",
         "higher"),
        ("min_surface_curvature_radius", "flat face: smallest radius of curvature R_b + s + a", "m", "mm", "min",
         "higher"),
        ("max_contact_force", "largest contact force along the follower's path", "N", None, "max_abs", "lower"),
        ("max_normal_force", "largest contact force along the common normal", "N", None, "max_abs", "lower"),
        ("peak_torque", "peak camshaft torque |T|", "N*m", None, "max_abs", "lower"),
    )
)

#: Results of the capabilities and kinds whose keys are made at run time (their fixed keys are declared in each
#: capability's ``labels``, gathered by :func:`machdyn.kinds.catalogue`).
RUN_TIME: tuple[Quantity, ...] = (
    Quantity("sweep.lowest_<column*>", "Sweep: lowest {column}", over_positions="scalar", better="none",
             producer="sweep"),
    Quantity("sweep.best.<column*>", "Sweep: best design, {column}", over_positions="scalar", better="none",
             producer="sweep"),
    Quantity("sweep.<column*>", "Sweep: {column} of each design", over_positions="scalar", better="none",
             producer="sweep"),
    Quantity("optimise.best.variable.<name>", "Best design: {name}", over_positions="scalar", better="none",
             producer="optimise"),
    Quantity("optimise.best.<result*>", "Best design: {result}", over_positions="scalar", better="none",
             producer="optimise"),
    Quantity("balance.<part>.mass", "Balance: {part}, mass", "kg", over_positions="scalar", better="lower",
             producer="balance"),
    Quantity("balance.<part>.x", "Balance: {part}, x in its body's frame", "m", over_positions="scalar",
             better="none", producer="balance"),
    Quantity("balance.<part>.y", "Balance: {part}, y in its body's frame", "m", over_positions="scalar",
             better="none", producer="balance"),
    Quantity("frame.mode_<order>.frequency", "Frame: natural frequency of mode {order}", "Hz",
             over_positions="scalar", better="none", producer="frame"),
    Quantity("frame.mode_<order>.damping_ratio", "Frame: damping ratio of mode {order}", over_positions="scalar",
             better="none", producer="frame"),
    Quantity("frame.<figure>.<when>.<where>", "Frame: {figure} at {where}, {when} balancing",
             over_positions="max_abs", better="lower", producer="frame"),
    Quantity("frame.transmitted_force.<when>.<support>.<direction>",
             "Frame: force through {support} ({direction}), {when} balancing", "N", over_positions="max_abs",
             better="lower", producer="frame"),
    Quantity("frame.acceleration_reduction.<where>", "Frame: acceleration reduction at {where}", "", "%",
             over_positions="scalar", better="higher", producer="frame"),
    Quantity("signals.<figure>.<when>.<where>", "Signals: {figure} at {where}, {when} balancing",
             over_positions="time_rms", better="lower", producer="signals"),
    Quantity("signals.reduction.<where>", "Signals: reduction at {where}", "", "%", over_positions="scalar",
             better="higher", producer="signals"),
    Quantity("signals.<figure>.<when>", "Signals: {figure}, {when} balancing", over_positions="time_rms",
             better="lower", producer="signals"),
    Quantity("signals.mean_reduction", "Signals: mean reduction", "", "%", over_positions="scalar", better="higher",
             producer="signals"),
    Quantity("frame.mean_acceleration_reduction", "Frame: mean acceleration reduction", "", "%",
             over_positions="scalar", better="higher", producer="frame"),
    Quantity("drivetrain.shaft_<index>.torque.max_abs", "Drive train: shaft {index}, max |torque|", "N*m",
             over_positions="max_abs", better="lower", producer="drivetrain"),
    Quantity("drivetrain.shaft_<index>.<figure>", "Drive train: shaft {index}, {figure}", over_positions="scalar",
             better="none", producer="drivetrain"),
    Quantity("drivetrain.stage_<index>.<figure>", "Drive train: gear stage {index}, {figure}",
             over_positions="scalar", better="none", producer="drivetrain"),
    *PARTS,
    Quantity("rotary_screen.<figure>.<source>", "Rotary screen: {figure} ({source})", over_positions="cycle",
             better="none", producer="rotary_screen"),
    Quantity("synthesis.best.<figure>", "Synthesis: best candidate, {figure}", over_positions="scalar", better="none",
             producer="synthesis"),
    *SHAFT_LINE,
    Quantity("hoist.<drum>.cage_acceleration", "Hoist: {drum}, cage acceleration (up)", "m/s^2",
             over_positions="scalar", better="higher", producer="hoist"),
    Quantity("hoist.<drum>.rope_tension", "Hoist: {drum}, rope tension at the cage", "N", over_positions="scalar",
             better="lower", producer="hoist"),
    Quantity("shaft.balance.<plane>.<figure*>", "Shaft line: balance in plane {plane}, {figure}",
             over_positions="scalar", better="none", producer="shaft_line"),
    Quantity("shaft.records.<what>.<figure*>", "Shaft line: from the records, {what}, {figure}",
             over_positions="scalar", better="none", producer="shaft_line"),
    *CAM_STROKES,
    Quantity("transient.passage_<index>.<figure>", "Transient: resonance passage {index}, {figure}",
             over_positions="scalar", better="none", producer="transient"),
    Quantity("transient.stage_<index>.peak_torque", "Transient: peak torque through stiff stage {index}", "N*m",
             over_positions="max_abs", better="lower", producer="transient"),
    Quantity("transient.mount.<mount>.peak_force", "Transient: largest dynamic force of mount {mount}", "N",
             over_positions="max_abs", better="lower", producer="transient"),
    Quantity("check_<name*>_utilisation", "Check {name}, utilisation", over_positions="scalar", better="lower",
             producer="screw_conveyor"),
)

#: Renamed results: old name -> key. Accepted wherever a result is named, and mapped once here.
ALIASES: dict[str, str] = {
    "max_driving_torque": "driving_torque.max_abs",
    "rms_driving_torque": "driving_torque.rms",
    "mean_input_power": "input_power.mean",
    "max_shaking_force": "frame_force.max",
    "max_shaking_moment": "shaking_moment.max_abs",
    "shaking_force.max": "frame_force.max",
}
#: Renamed key prefixes: old prefix -> new (the frame force's harmonics).
PREFIX_ALIASES: dict[str, str] = {"shaking_force.fx.": "frame_force.fx.", "shaking_force.fy.": "frame_force.fy."}
#: Renamed keys that follow a pattern: (old key's regular expression, the new key's template).
PATTERN_ALIASES: tuple[tuple[re.Pattern, str], ...] = (
    (re.compile(r"(parts\.bearing\.[^.]+)\.rating_life_(?:l\d+(?:_\d+)?_p_\d+(?:_\d+)?|no_requirement)"),
     r"\1.rating_life"),
    (re.compile(r"(parts\.bearing\.[^.]+)\.peak_pressure_p"), r"\1.peak_pressure"),
    (re.compile(r"(parts\.bearing\.[^.]+)\.mean_p_v_over_the_cycle"), r"\1.mean_pv"),
    (re.compile(r"(parts\.link\.[^.]+)\.fatigue_safety_factor_modified_goodman"), r"\1.fatigue_safety"),
)
#: Prefixes of capability keys that carry a result's name after them (``sweep.best.<result>``).
_CARRIERS = ("sweep.best.", "sweep.lowest_", "optimise.best.", "sweep.")

#: The engine's per-design sweep summaries (:class:`machdyn.linkage.sweep.SweepResult` attributes) by key.
ENGINE_SUMMARIES: dict[str, str] = {
    "driving_torque.max_abs": "max_driving_torque",
    "driving_torque.rms": "rms_driving_torque",
    "input_power.mean": "mean_input_power",
    "frame_force.max": "max_shaking_force",
    "shaking_moment.max_abs": "max_shaking_moment",
}


def canonical(name: str) -> str:
    """The key of a result named ``name``: itself, or the key an old name (:data:`ALIASES`) was renamed to;
    the names carried by ``sweep.``, ``sweep.best.``, ``sweep.lowest_`` and ``optimise.best.`` keys too."""
    if name in ALIASES:
        return ALIASES[name]
    for old, new in PREFIX_ALIASES.items():
        if name.startswith(old):
            return new + name[len(old):]
    for regex, template in PATTERN_ALIASES:
        m = regex.fullmatch(name)
        if m:
            return m.expand(template)
    for carrier in _CARRIERS:
        if name.startswith(carrier):
            rest = name[len(carrier):]
            mapped = canonical(rest)
            if mapped != rest:
                return carrier + mapped
    return name


def _regex(pattern: str) -> re.Pattern:
    parts = re.split(r"(<\w+\*?>)", pattern)
    out = []
    for part in parts:
        m = re.fullmatch(r"<(\w+)(\*?)>", part)
        if m:
            out.append(f"(?P<{m.group(1)}>.+)" if m.group(2) else f"(?P<{m.group(1)}>[^.]+)")
        else:
            out.append(re.escape(part))
    return re.compile("".join(out))


@cache
def _patterns(entries: tuple[Quantity, ...]) -> tuple[tuple[re.Pattern, Quantity], ...]:
    return tuple((_regex(q.key), q) for q in entries if q.is_pattern)


@cache
def _exact(entries: tuple[Quantity, ...]) -> dict[str, Quantity]:
    return {q.key: q for q in entries if not q.is_pattern}


OWN = MECHANISM + COMPACTOR + STATUS
"""The quantities this module declares itself: the linkage results, the compactor's and the population checks.
The whole catalogue, with every registered kind's and capability's declared results, is
:func:`machdyn.kinds.catalogue` (the registry sits above the catalogue)."""


def find(key: str, entries: tuple[Quantity, ...] = OWN) -> tuple[Quantity, dict[str, str]] | None:
    """The quantity ``key`` names and the parts of its pattern (``{}`` for an exact key), else None."""
    exact = _exact(entries)
    if key in exact:
        return exact[key], {}
    for regex, q in _patterns(entries):
        m = regex.fullmatch(key)
        if m:
            return q, m.groupdict()
    return None


def label(key: str, unit: str | None = None) -> Label | None:
    """The label of a result ``key`` of the catalogue (its pattern filled in), None for an unknown key;
    ``unit`` the SI unit of a key whose unit is known only at run time (a stroke, a harmonic amplitude)."""
    found = find(key)
    if found is None:
        return None
    q, parts = found
    shown = {k: v.replace("_", " ").replace(".", " ") if k == "series" else v for k, v in parts.items()}
    if "series" in shown:
        shown["series"] = shown["series"].capitalize()
    lab = q.label(**shown)
    if unit is not None and unit != lab.unit:
        return Label(lab.text, unit, None, lab.zero_below)
    if lab.unit == "m or rad":
        return Label(lab.text, unit or "", None, lab.zero_below)
    return lab


def labels(entries: Iterable[Quantity]) -> dict[str, Label]:
    """The labels of the exact keys of ``entries`` (patterns are labelled by :func:`label`)."""
    return {q.key: q.label() for q in entries if not q.is_pattern}


def declared(known: Mapping[str, Label], producer: str, seen: set[str]) -> list[Quantity]:
    """The quantities of the declared ``labels`` of a problem kind or capability (``producer``) whose keys are
    not in ``seen`` yet (added to it)."""
    out = []
    for key, lab in known.items():
        if key not in seen:
            seen.add(key)
            out.append(Quantity(key, lab.text, lab.unit, lab.display, lab.over, lab.better, producer=producer,
                                zero_below=lab.zero_below))
    return out


def population_quantities(machine: str | None = None) -> tuple[Quantity, ...]:
    """The numeric quantities the population evaluator computes for a mechanism (of ``machine``, if any)."""
    own = MECHANISM + (COMPACTOR if machine == "compactor" else ())
    return tuple(q for q in own if q.group and q.kind == "number")


def better_of(key: str, entries: tuple[Quantity, ...] = OWN) -> str:
    """The declared better direction of the result ``key`` (a key of :data:`BETTER`; "none" for a key
    ``entries`` does not know)."""
    found = find(canonical(key), entries)
    return found[0].better if found is not None else "none"


def against(sense: str, better: str) -> bool:
    """Whether an objective to ``sense`` ("minimise" or "maximise") a result works against its declared
    ``better`` direction: minimising a "higher" result or maximising a "lower" one ("target", "none" and
    "true" results are never questioned)."""
    return (sense, better) in {("minimise", "higher"), ("maximise", "lower")}


def as_cost(values: Any, better: str) -> np.ndarray:
    """``values`` as costs, the lowest best: negated for a "higher" result; as given otherwise (a result with no
    direction ranks lowest first)."""
    arr = np.asarray(values, dtype=float)
    return -arr if better == "higher" else arr


def best_index(values: Any, better: str) -> int:
    """The index of the best of ``values`` (one per design) by the declared ``better`` direction: the smallest
    of a "lower" result, the largest of a "higher" one, the smallest otherwise; NaN never wins."""
    costs = as_cost(values, better)
    return int(np.argmin(np.where(np.isnan(costs), np.inf, costs)))


def worst(values: Any, better: str, axis: int = -1) -> np.ndarray:
    """The worst of ``values`` along ``axis`` by the declared ``better`` direction (over the operating states
    or the designs of one quantity): the largest of a "lower" result, the smallest of a "higher" one; NaN is
    left out unless every value is NaN. Refused for a result with no direction ("none", "target", "true")."""
    if better not in ("lower", "higher"):
        raise ValueError(f"'worst' needs a result whose better direction is lower or higher; got '{better}'.")
    arr = np.asarray(values, dtype=float)
    with np.errstate(all="ignore"), warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # an all-NaN slice stays NaN
        return np.nanmax(arr, axis=axis) if better == "lower" else np.nanmin(arr, axis=axis)


def label_for(key: str, labels: Mapping[str, Label], unit: str | None = None) -> Label:
    """The label of ``key``: from ``labels`` (a stage's own), else the catalogue, else the key itself in
    ``unit``."""
    if key in labels:
        found = labels[key]
        if unit is not None and found.unit != unit:
            return Label(found.text, unit, None, found.zero_below)
        return found
    known = label(key, unit)
    if known is not None:
        return known
    return Label(key, unit or "")
