"""One screw conveyor analysed: the design for the duty, power by every method, loads and every check.

:func:`evaluate` returns a frozen :class:`ConveyorResult` in SI. It computes nothing itself beyond choosing
the screw: the quantities come from :func:`.screw.screw_states` (the cited formula functions), the coupling and
base-bolt checks from :mod:`.checks`.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import InputError
from . import checks as ck
from . import power as pw
from . import tables
from .beam import span_bending
from .design import ScrewDesign, design_screw, volume_capacity
from .model import ConveyorProblem
from .optimise import best_design
from .screw import CHECKS, screw_states


@dataclass(frozen=True)
class MethodPower:
    """One method's shaft power before drive losses [W], with its parts [W] and a note."""

    method: str
    label: str
    shaft_power: float
    parts: Mapping[str, float] = field(default_factory=dict)
    note: str = ""


@dataclass(frozen=True)
class ConveyorResult:
    """Everything a run computed, in SI: the design, the power by method, every scalar and every check.

    ``scalars`` maps result keys to SI floats (labels and display units in :data:`machdyn.conveyor.labels.LABELS`);
    ``checks`` are the verifications (value, limit, SI unit); ``warnings`` are said once each and do not repeat
    the failed checks (see :attr:`failed_checks`). ``bending`` is the span's bending along the screw
    (:class:`machdyn.conveyor.beam.SpanBending`) and ``ranking`` the candidates of a design search, if any.
    """

    problem: ConveyorProblem
    design: ScrewDesign
    powers: Mapping[str, MethodPower]
    selected_method: str
    scalars: Mapping[str, float]
    checks: tuple[ck.Check, ...]
    warnings: tuple[str, ...] = ()
    bending: Any = None
    ranking: Any = None

    @property
    def passed(self) -> bool:
        """True if every check passes."""
        return all(c.passed for c in self.checks)

    @property
    def failed_checks(self) -> tuple[str, ...]:
        """Each failed check, in the one wording of :meth:`Check.message`."""
        return tuple(c.message() for c in self.checks if not c.passed)

    @property
    def shaft_power(self) -> float:
        return self.scalars["shaft_power"]

    @property
    def torque(self) -> float:
        return self.scalars["torque"]

    @property
    def motor_rating(self) -> float:
        return self.scalars["motor_rating"]

    @property
    def motor_power_required(self) -> float:
        return self.scalars["motor_power_required"]


def standard_pipe_note(diameter: float) -> str:
    """The sentence that says which standard pipe a screw of ``diameter`` [m] was given (refused beyond the
    table, asking for the pipe)."""
    row = tables.standard_pipe_row(diameter)
    return (f"screw.pipe_outer_diameter not given; taken from CEMA 350's standard screw conveyor components: the "
            f"{float(row['screw_diameter_in']):g} in screw's {_inches(float(row['pipe_nps_in']))} in pipe, outer "
            f"diameter {float(row['pipe_outer_diameter_in']) * 25.4:.1f} mm, for the {diameter * 1000:.4g} mm screw.")


def _standard_pipe(diameter: float) -> float:
    """The standard pipe [m] of a screw of ``diameter`` [m]; below the smallest row (4 in) that row's, since the
    sizing only passes there on its way up to a standard size (100 mm counts as 4 in); refused above the table."""
    smallest = float(tables.standard_pipe_rows()[0][0])
    return tables.standard_pipe(max(diameter, smallest))


def _inches(value: float) -> str:
    """A nominal pipe size in inches with its fraction (2.5 -> "2½")."""
    whole, part = int(value), value - int(value)
    fraction = {0.25: "¼", 0.5: "½", 0.75: "¾"}.get(round(part, 2), "" if part == 0 else f"{part:g}")
    return f"{whole if whole else ''}{fraction}" if part else f"{whole}"


def choose_screw(p: ConveyorProblem) -> ScrewDesign:
    """The screw for the duty, or the given screw with its capacity as the duty (check mode)."""
    mass_flow = p.mass_flow
    # the pipe deducted from the capacity: the given one, else the standard pipe of the screw's size (CEMA 350's
    # standard components, as the checks assume)
    annulus = p.capacity_section == "annulus"
    pipe = (p.pipe_outer_diameter or 0.0) if annulus else 0.0
    standard = _standard_pipe if annulus and p.pipe_outer_diameter is None else None
    if mass_flow is None:
        if p.diameter is None or p.speed is None:
            raise InputError("The throughput is required unless screw.diameter and screw.speed are given.")
        deducted = pipe or (standard(p.diameter) if standard is not None else 0.0)
        mass_flow = volume_capacity(p.diameter, p.pitch_ratio * p.diameter, angular_speed=p.speed, filling=p.filling,
                                    inclination_factor=p.inclination_factor,
                                    pipe_diameter=min(deducted, p.diameter)) * p.bulk_density
    return design_screw(mass_flow=mass_flow, bulk_density=p.bulk_density, filling=p.filling,
                        speed_coefficient=p.speed_coefficient, pitch_ratio=p.pitch_ratio,
                        inclination_factor=p.inclination_factor, diameter=p.diameter, angular_speed=p.speed,
                        pipe_diameter=pipe, pipe_of=standard)


def evaluate(problem: ConveyorProblem, *, bending: bool = True) -> ConveyorResult:
    """Analyse a screw conveyor: design, power by every method, loads, every check (and the design search).

    Raises :class:`~machdyn.errors.InputError` naming the input when the problem cannot be analysed (a duty
    beyond the largest standard screw, a power method that does not apply, a pipe that does not fit, a result
    that is not finite).
    """
    p = problem
    if p.search is not None:
        ranking = best_design(p)
        chosen = ranking.best
        p = p.replace(diameter=chosen["diameter"], speed=chosen["speed"], pitch_ratio=chosen["pitch_ratio"],
                      filling=chosen["filling"], search=None, pipe_outer_diameter=None, pipe_wall=None,
                      flight_thickness=None)  # the search scales pipe and flight with each candidate
        result = evaluate(p, bending=bending)
        return _with(result, ranking=ranking, problem=problem)
    warnings: list[str] = []
    if not 0.3 <= p.force_radius_ratio <= 0.4:
        warnings.append(f"screw.force_radius_ratio {p.force_radius_ratio:g} is outside 0.3…0.4, the range of the "
                        f"radius R = (0.3…0.4)·D where the material's friction force acts (seed 004, eq 2.87).")
    design = choose_screw(p)
    if p.pipe_outer_diameter is not None and p.pipe_outer_diameter >= design.diameter:
        raise InputError(f"The pipe ({p.pipe_outer_diameter * 1000:g} mm) must fit inside the screw "
                         f"({design.diameter * 1000:g} mm): screw.pipe_outer_diameter must be smaller.")
    if p.pipe_outer_diameter is None:
        warnings.append(standard_pipe_note(design.diameter))
    if p.pipe_wall is None:
        d_o = p.pipe_outer_diameter if p.pipe_outer_diameter is not None else tables.standard_pipe(design.diameter)
        warnings.append(f"screw.pipe_wall not given; assumed {d_o * 1000 / 12:.1f} mm (d_o/12).")
    st = screw_states(p, design.diameter, design.pitch, design.speed, p.filling, design.mass_flow)
    powers: dict[str, MethodPower] = {}
    for method, entry in st["_powers"].items():
        value = float(entry["power"])
        if entry["skip"] or not math.isfinite(value):
            warnings.append(entry["skip"] or f"{pw.LABELS[method]} skipped: not applicable to this screw.")
            continue
        powers[method] = MethodPower(method, pw.LABELS[method], value,
                                     {k: float(v) for k, v in entry["parts"].items()}, _note(p, method, design))
    if p.power_method not in powers:
        raise InputError(f"The power method '{p.power_method}' that sizes the drive is not applicable here "
                         f"({'; '.join(w for w in warnings if 'skipped' in w)}); choose another power_method.")
    if p.torque is not None:
        derived = ck.torque_from_power(powers[p.power_method].shaft_power, angular_speed=design.speed)
        warnings.append(f"Torque given directly ({p.torque:.4g} N*m) is used for the loads and the shaft checks; "
                        f"the power method gives {derived:.4g} N*m.")
    scalars = {k: float(v) for k, v in st.items() if not k.startswith(("_", "check.", "limit.", "power."))}
    scalars.update({
        "inclination": p.inclination, "lift": p.lift_height, "inclination_factor": design.inclination_factor,
        "diameter_required": design.diameter_required, "drive_efficiency": p.drive_efficiency,
    })
    for method, mp in powers.items():
        scalars[f"power_{method}"] = mp.shaft_power
    checks = [ck.Check(name, float(st[f"check.{key}"]), float(st[f"limit.{key}"]), unit, basis, display)
              for key, (name, unit, display, basis) in CHECKS.items()]
    checks += _coupling_checks(p, scalars)
    checks += _bolt_checks(p, scalars)
    for c in checks:
        scalars[_check_key(c.name)] = c.utilisation
    bad = sorted(k for k, v in scalars.items() if not math.isfinite(v))
    if bad:
        raise InputError(f"The results {', '.join(bad)} are not finite numbers: check the magnitudes of the "
                         f"inputs (lengths, throughput, speed, moduli).")
    span = None
    if bending:
        span = span_bending(p, st)
        scalars.update(span.scalars())
    return ConveyorResult(problem=p, design=design, powers=powers, selected_method=p.power_method, scalars=scalars,
                          checks=tuple(checks), warnings=tuple(warnings), bending=span)


def _with(result: ConveyorResult, **changes: Any) -> ConveyorResult:
    return dataclasses.replace(result, **changes)


def _check_key(name: str) -> str:
    """The results.json key of a check's utilisation (kept as the first releases wrote it)."""
    slug = name.lower().replace(" ", "_").replace(",", "").replace("/", "_")
    return f"check_{slug}_utilisation"


def _note(p: ConveyorProblem, method: str, design: ScrewDesign) -> str:
    if method == "textbook_360":
        return "g taken as 10 m/s^2 as printed in seed 004; L = conveyor length"
    if method == "textbook_367":
        return "Alexandrov's form, 367 = 3600/g"
    if method == "iso7119":
        return "lambda = resistance coefficient"
    fd = float(tables.cema_diameter_factors(design.diameter))
    note = f"Fd = {fd:.4g}"
    if not tables.cema_diameter_is_tabulated(design.diameter):
        note += " (Fd interpolated between CEMA inch sizes)"
    if p.lift_height:
        note += "; lift power m·g·H added before Fo"
    return note


def _coupling_checks(p: ConveyorProblem, scalars: dict[str, float]) -> list[ck.Check]:
    cu = p.coupling
    if cu is None:
        return []
    t, k = scalars["torque"], p.coupling_service_factor
    return [
        ck.Check("Coupling torque k·T", ck.coupling_design_torque(t, k), cu.rated_torque, "N*m",
                 "seed 004, eq 2.97", "N*m"),
        ck.Check("Coupling bush bearing stress",
                 ck.bushing_bearing_stress(t, k, cu.pins, cu.pin_circle_diameter, cu.pin_diameter, cu.bushing_length),
                 cu.allowable_bushing_stress, "Pa", "seed 004, eq 2.98", "MPa"),
        ck.Check("Coupling pin bending stress",
                 ck.pin_bending_stress(t, k, cu.pins, cu.pin_circle_diameter, cu.pin_diameter, cu.pin_lever),
                 cu.allowable_pin_stress, "Pa", "seed 004, eq 2.98", "MPa"),
    ]


def _bolt_checks(p: ConveyorProblem, scalars: dict[str, float]) -> list[ck.Check]:
    b = p.base_bolts
    if b is None:
        return []
    f_max = ck.base_bolt_max_force(b.belt_force, b.belt_preload, b.lever, b.spacing_a, b.spacing_b)
    d3 = ck.bolt_minor_diameter_required(f_max, b.allowable_tensile_stress, b.friction, b.safety)
    scalars["bolt_force"] = f_max
    scalars["bolt_d3_required"] = d3
    bolts = tables.metric_bolts()
    if b.bolt is not None:
        name, have = b.bolt, dict(bolts)[b.bolt]
    else:
        name, have = next(((nm, dd) for nm, dd in bolts if dd >= d3), bolts[-1])
    return [ck.Check(f"Base bolt {name} minor diameter", d3, have, "m", "seed 004, eqs 2.72-2.80", "mm")]


def screw_profile_arrays(result: ConveyorResult) -> dict[str, np.ndarray]:
    """The bending along one span as arrays (x [m], moment [N·m], deflection [m], stress [Pa])."""
    b = result.bending
    if b is None:
        return {}
    return {"x": b.x, "moment": b.moment, "deflection": b.deflection, "stress": b.equivalent_stress}
