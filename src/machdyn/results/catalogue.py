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
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from functools import cache

from ..kinds import CAPABILITIES, KINDS, capability, kind
from .labels import Label

#: How a quantity is reduced over the crank positions of one design.
OVER_POSITIONS = {
    "max": "largest value",
    "min": "smallest value",
    "max_abs": "largest magnitude",
    "time_mean": "mean over time",
    "time_rms": "root mean square over time",
    "range": "largest minus smallest value",
    "cycle": "a figure of the whole cycle",
    "count": "a count over the cycle",
    "value": "one value per design (no reduction)",
}
#: How designs compare by a quantity: the better design has the lower ("min") or higher ("max") value; ""
#: for a figure with no better direction (a stroke, the time ratio), "all" for a yes/no status.
OVER_DESIGNS = ("min", "max", "", "all")

#: The groups of the population evaluator that compute a quantity for many designs at once (see
#: :mod:`machdyn.results.population`); "" for a result of a single design only.
GROUPS = {
    "forces": "the engine's sweep (kinetostatics summarised per design; the compiled path when available)",
    "motion": "kinematics of the designs over the crank positions",
    "geometry": "the link lengths alone",
    "analysis": "the full analysis of the designs (energy, reduced inertia, work balance)",
    "status": "the checks of each design (assembly, dead points, transmission angle)",
}


@dataclass(frozen=True)
class Quantity:
    """One result: ``key`` (or a pattern of keys), label ``text`` (with ``{name}`` for each pattern part),
    SI ``unit`` and ``display`` unit (the SI unit if None), the reductions ``over_positions`` and
    ``over_designs``, the ``producer`` (a problem kind, ``kind:machine`` or a capability's table), the
    ``group`` of the population evaluator that computes it for many designs ("" for single designs only, with
    ``why`` saying why), ``zero_below`` (a result whose magnitude sets this one's round-off scale) and ``kind``
    ("number" or "text": a category such as the Grashof class, which can be a column but not an objective)."""

    key: str
    text: str
    unit: str = ""
    display: str | None = None
    over_positions: str = "value"
    over_designs: str = ""
    producer: str = "mechanism"
    group: str = ""
    why: str = ""
    zero_below: str | None = None
    kind: str = "number"

    @property
    def is_pattern(self) -> bool:
        return "<" in self.key

    def label(self, **parts: str) -> Label:
        """The :class:`~machdyn.results.labels.Label` of this quantity (pattern parts filled in)."""
        text = self.text.format(**parts) if parts else self.text
        return Label(text, self.unit, self.display, self.zero_below)


def _q(key, text, unit="", over_positions="value", over_designs="", group="", **kw) -> Quantity:
    return Quantity(key, text, unit, kw.pop("display", None), over_positions, over_designs, group=group, **kw)


_SINGLE = "a figure of one analysed design"

#: The results of a linkage analysis (the ``mechanism`` and ``rotary_screen`` kinds).
MECHANISM: tuple[Quantity, ...] = (
    _q("crank_speed.mean", "Crank speed, mean", "rad/s", "time_mean", "", "analysis"),
    _q("driving_torque.max_abs", "Driving torque, max |T|", "N*m", "max_abs", "min", "forces"),
    _q("driving_torque.max", "Driving torque, maximum", "N*m", "max", "min", "analysis"),
    _q("driving_torque.min", "Driving torque, minimum", "N*m", "min", "max", "analysis"),
    _q("driving_torque.mean", "Driving torque, mean", "N*m", "time_mean", "min", "analysis",
       zero_below="driving_torque.max_abs"),
    _q("driving_torque.rms", "Driving torque, RMS", "N*m", "time_rms", "min", "forces"),
    _q("input_power.mean", "Input power, mean", "W", "time_mean", "min", "forces", zero_below="input_power.max"),
    _q("input_power.max", "Input power, maximum", "W", "max", "min", "analysis"),
    _q("input_power.min", "Input power, minimum (negative: power flows back into the drive)", "W", "min", "max",
       "analysis"),
    _q("inertial_shaking_force.max", "Shaking force, inertial (-sum m a_G), max", "N", "max", "min", "motion"),
    _q("inertial_shaking_moment.max_abs", "Shaking moment, inertial (of -m a_G and -I alpha), max |M|", "N*m",
       "max_abs", "min", "motion", zero_below="driving_torque.max_abs"),
    _q("frame_force.max", "Frame force, max (inertia, process loads and weight)", "N", "max", "min", "forces"),
    _q("shaking_moment.max_abs", "Shaking moment on the frame, max |M| (inertia, loads, weight, drive reaction)",
       "N*m", "max_abs", "min", "forces", zero_below="driving_torque.max_abs"),
    _q("shaking_moment.about_x", "Shaking moment reference point, x", "m", why="the point given in [output]"),
    _q("shaking_moment.about_y", "Shaking moment reference point, y", "m", why="the point given in [output]"),
    _q("kinetic_energy.max", "Kinetic energy, max", "J", "max", "min", "analysis"),
    _q("kinetic_energy.min", "Kinetic energy, min", "J", "min", "", "analysis"),
    _q("kinetic_energy.fluctuation", "Kinetic energy, fluctuation (max - min)", "J", "range", "min", "analysis"),
    _q("reduced_inertia.min", "Reduced inertia at the crank, minimum", "kg*m^2", "min", "", "analysis"),
    _q("reduced_inertia.max", "Reduced inertia at the crank, maximum", "kg*m^2", "max", "", "analysis"),
    _q("reduced_inertia.mean", "Reduced inertia at the crank, mean", "kg*m^2", "time_mean", "", "analysis"),
    _q("flywheel.energy_fluctuation", "Energy to store in a flywheel (constant speed)", "J", "cycle", "min",
       "analysis"),
    _q("work_balance.input_work", "Work balance: input work", "J", "cycle", "", "analysis"),
    _q("work_balance.load_work", "Work balance: work of the loads", "J", "cycle", "", "analysis"),
    _q("work_balance.energy_change", "Work balance: energy change", "J", "cycle", "", "analysis"),
    _q("work_balance.residual", "Work balance: residual", "J", "cycle", "", "analysis"),
    _q("work_balance.relative_residual", "Work balance, relative residual", "", "cycle", "min", "analysis"),
    _q("time_ratio", "Time ratio (advance / return)", "", "cycle", "", "motion"),
    _q("transmission_angle.min", "Transmission angle, min", "rad", "min", "max", "motion"),
    _q("transmission_angle.max", "Transmission angle, max", "rad", "max", "min", "motion"),
    _q("transmission_angle.worst", "Transmission angle, worst (closest to 0 or 180 deg)", "rad", "min", "max",
       "motion"),
    _q("dead_positions.count", "Dead positions (count)", "", "count", "min",
       why="a design with a dead position is flagged in a population (status dead_point)"),
    _q("grashof.margin", "Grashof margin s + l - (p + q) (negative: a link turns fully)", "m", "value", "min",
       "geometry"),
    _q("grashof.class", "Grashof class", "", "value", "", "geometry", kind="text"),
    _q("joint.<joint>.max_force", "Joint {joint}, max force", "N", "max", "min", "forces"),
    _q("stroke.<body>", "Stroke of {body}", "m or rad", "range", "", "motion"),
    _q("time_ratio.<body>", "Time ratio (advance / return) of {body}", "", "cycle", "", "motion"),
    _q("transmission_angle.<body>.min", "Transmission angle of the dyad driving {body}, min", "rad", "min", "max",
       "motion"),
    _q("transmission_angle.<body>.max", "Transmission angle of the dyad driving {body}, max", "rad", "max", "min",
       "motion"),
    _q("load.<load>.mean_power", "Load {load}, mean power (negative: the drive works against it)", "W",
       "time_mean", "", why=_SINGLE),
    _q("<series*>.harmonic_<order>.amplitude", "{series}, harmonic {order}, amplitude", "", "cycle",
       why="a spectrum of one design ([output] harmonics)"),
    _q("<series*>.harmonic_<order>.phase", "{series}, harmonic {order}, phase", "rad", "cycle",
       why="a spectrum of one design ([output] harmonics)"),
)

#: The results of a compactor (``[mechanism] machine = "compactor"``: a four-bar whose coupler is the
#: compaction plate and whose coupler point is where it presses; seed 003, Asfandiyarov et al., 2019).
COMPACTOR: tuple[Quantity, ...] = tuple(
    Quantity(key, text, unit, None, over, better, "mechanism:compactor", "motion")
    for key, text, unit, over, better in (
        ("compactor.plate_angle.max", "Compactor: plate angle to the horizontal, max |gamma|", "rad", "max", "min"),
        ("compactor.k1.min", "Compactor: crank force gain k1 = 1/cos alpha, min over the pressing window", "",
         "min", "max"),
        ("compactor.k2", "Compactor: lever force gain k2 = l/a", "", "value", "max"),
        ("compactor.force_gain.min", "Compactor: force gain k1 k2, min over the pressing window", "", "min",
         "max"),
    )
)

#: The checks of each design of a population: columns of a sweep or exploration, the optimiser's built-in
#: constraint. ``regular`` is True only for a design with none of the faults.
STATUS: tuple[Quantity, ...] = tuple(
    Quantity(key, text, "", None, over, "all" if key != "status" else "", "population", "status", kind=kind)
    for key, text, over, kind in (
        ("assembled", "Assembles at every crank angle", "value", "number"),
        ("assembled_fraction", "Share of the crank angles where the design assembles", "value", "number"),
        ("dead_point", "Passes a dead (toggle) position at a sampled crank angle", "value", "number"),
        ("branch_change", "Changes branch between neighbouring crank angles (a dyad's determinant changes sign)",
         "value", "number"),
        ("near_dead_point", "Comes within about 1 deg of a dead position (a dyad's |det| below 1.75% of its "
                            "largest)", "value", "number"),
        ("poor_transmission", "Transmission angle within the threshold of 0 or 180 deg", "value", "number"),
        ("regular", "Regular: assembles everywhere, no dead point, branch change, near dead point or poor "
                    "transmission", "value", "number"),
        ("status", "Status of the design (regular or its first fault)", "value", "text"),
    )
)

#: Results of the capabilities and kinds whose keys are made at run time (their fixed keys are declared in each
#: capability's ``labels``, gathered by :func:`catalogue`).
RUN_TIME: tuple[Quantity, ...] = (
    Quantity("sweep.lowest_<column*>", "Sweep: lowest {column}", producer="sweep"),
    Quantity("sweep.best.<column*>", "Sweep: best design, {column}", producer="sweep"),
    Quantity("sweep.<column*>", "Sweep: {column} of each design", producer="sweep"),
    Quantity("optimise.best.variable.<name>", "Best design: {name}", producer="optimise"),
    Quantity("optimise.best.<result*>", "Best design: {result}", producer="optimise"),
    Quantity("balance.<part>.mass", "Balance: {part}, mass", "kg", producer="balance"),
    Quantity("balance.<part>.x", "Balance: {part}, x in its body's frame", "m", producer="balance"),
    Quantity("balance.<part>.y", "Balance: {part}, y in its body's frame", "m", producer="balance"),
    Quantity("frame.mode_<order>.frequency", "Frame: natural frequency of mode {order}", "Hz", producer="frame"),
    Quantity("frame.mode_<order>.damping_ratio", "Frame: damping ratio of mode {order}", producer="frame"),
    Quantity("frame.<figure>.<when>.<where>", "Frame: {figure} at {where}, {when} balancing", producer="frame"),
    Quantity("frame.transmitted_force.<when>.<support>.<direction>",
             "Frame: force through {support} ({direction}), {when} balancing", "N", producer="frame"),
    Quantity("frame.acceleration_reduction.<where>", "Frame: acceleration reduction at {where}", producer="frame"),
    Quantity("signals.<figure>.<when>.<where>", "Signals: {figure} at {where}, {when} balancing",
             producer="signals"),
    Quantity("signals.reduction.<where>", "Signals: reduction at {where}", producer="signals"),
    Quantity("signals.<figure>.<when>", "Signals: {figure}, {when} balancing", producer="signals"),
    Quantity("signals.mean_reduction", "Signals: mean reduction", producer="signals"),
    Quantity("frame.mean_acceleration_reduction", "Frame: mean acceleration reduction", producer="frame"),
    Quantity("drivetrain.shaft_<index>.torque.max_abs", "Drive train: shaft {index}, max |torque|", "N*m",
             producer="drivetrain"),
    Quantity("drivetrain.shaft_<index>.<figure>", "Drive train: shaft {index}, {figure}", producer="drivetrain"),
    Quantity("drivetrain.stage_<index>.<figure>", "Drive train: gear stage {index}, {figure}", producer="drivetrain"),
    Quantity("parts.<part>.<name>.<figure>", "Parts: {part} {name}, {figure}", producer="parts"),
    Quantity("rotary_screen.<figure>.<source>", "Rotary screen: {figure} ({source})", producer="rotary_screen"),
    Quantity("synthesis.best.<figure>", "Synthesis: best candidate, {figure}", producer="synthesis"),
    Quantity("hoist.<drum>.cage_acceleration", "Hoist: {drum}, cage acceleration (up)", "m/s^2", producer="hoist"),
    Quantity("hoist.<drum>.rope_tension", "Hoist: {drum}, rope tension at the cage", "N", producer="hoist"),
    Quantity("shaft.balance.<plane>.<figure*>", "Shaft line: balance in plane {plane}, {figure}",
             producer="shaft_line"),
    Quantity("shaft.field.<plane>.<figure*>", "Shaft line: field balancing, plane {plane}, {figure}",
             producer="shaft_line"),
    Quantity("shaft.records.<what>.<figure*>", "Shaft line: from the records, {what}, {figure}",
             producer="shaft_line"),
    Quantity("shaft.bearing.<bearing>.<figure>", "Shaft line: bearing {bearing}, {figure}", "N",
             producer="shaft_line"),
    Quantity("shaft.engine.<order>.<figure>", "Shaft line: engine {order}, {figure}", producer="shaft_line"),
    Quantity("shaft.frame.<what>.<figure*>", "Shaft line: frame, {what}, {figure}", producer="shaft_line"),
    Quantity("shaft.grade.<plane>.<figure>", "Shaft line: balance grade, plane {plane}, {figure}",
             producer="shaft_line"),
    Quantity("shaft.locomotive.<side>.<figure>", "Shaft line: locomotive, {side}, {figure}",
             producer="shaft_line"),
    Quantity("check_<name*>_utilisation", "Check {name}, utilisation", producer="screw_conveyor"),
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


_OWN = MECHANISM + COMPACTOR + STATUS


def find(key: str, entries: tuple[Quantity, ...] = _OWN) -> tuple[Quantity, dict[str, str]] | None:
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


@cache
def catalogue() -> tuple[Quantity, ...]:
    """Every quantity: the linkage results, the compactor's, the population checks, and each registered problem
    kind's and capability's declared results (their ``labels``), producer = the kind or the capability's table."""
    out = list(_OWN)
    seen = {q.key for q in out}
    for name in KINDS:
        out += _declared(kind(name).labels, name, seen)
    for table in CAPABILITIES:
        out += _declared(capability(table).labels, table, seen)
    return tuple(out) + RUN_TIME


def _declared(known: Mapping[str, Label], producer: str, seen: set[str]) -> list[Quantity]:
    out = []
    for key, lab in known.items():
        if key not in seen:
            seen.add(key)
            out.append(Quantity(key, lab.text, lab.unit, lab.display, producer=producer, zero_below=lab.zero_below))
    return out


def population_quantities(machine: str | None = None) -> tuple[Quantity, ...]:
    """The numeric quantities the population evaluator computes for a mechanism (of ``machine``, if any)."""
    own = MECHANISM + (COMPACTOR if machine == "compactor" else ())
    return tuple(q for q in own if q.group and q.kind == "number")


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
