"""The ``[screw_conveyor]`` problem file: schema, validation (every mistake at once) and the run.

``load_conveyor_problem(data)`` turns the parsed TOML of a whole file into a frozen
:class:`ConveyorProblem` (SI floats); ``run_conveyor(problem)`` designs the screw, computes the power by
every method, the loads and the checks, and returns a :class:`ConveyorResult`.
"""

from __future__ import annotations

import copy
import difflib
import math
import warnings as _warnings
from dataclasses import dataclass, field
from typing import Any

from pydantic import BaseModel, ConfigDict, ValidationError

from ..errors import InputError, MachdynWarning, ProblemFileError
from ..units import parse_quantity
from . import checks as ck
from . import power as pw
from . import tables
from .design import ScrewDesign, design_screw
from .plate import flight_max_stress

Qty = str | float | int


class _Section(BaseModel):
    model_config = ConfigDict(extra="forbid")


class MaterialIn(_Section):
    name: str = "bulk material"
    bulk_density: Qty
    filling: float
    speed_coefficient: float | None = None
    speed_class: str | None = None
    resistance: float | None = None
    resistance_group: str | None = None
    cema_material_factor: float | None = None
    cema_material: str | None = None
    friction_coefficient: float = 1.0


class ScrewIn(_Section):
    diameter: Qty | None = None
    speed: Qty | None = None
    pitch_ratio: float = 1.0
    inclination_factor: float | None = None
    pipe_outer_diameter: Qty | None = None
    pipe_wall: Qty | None = None
    flight_thickness: Qty | None = None
    hanger_spacing: Qty = "3 m"
    force_radius_ratio: float = 0.35
    lateral_load_factor: float = 0.7
    hanger_bearing: str = "bronze"
    flight_type: str = "standard"
    paddles: int = 0


class DriveIn(_Section):
    type: str | None = None
    efficiency: float | None = None
    coupling_service_factor: float = 1.8


class StrengthIn(_Section):
    shear_modulus: Qty = "80 GPa"
    elastic_modulus: Qty = "210 GPa"
    poisson_ratio: float = 0.3
    steel_density: Qty = "7850 kg/m^3"
    allowable_shear_stress: Qty = "40 MPa"
    allowable_stress: Qty = "100 MPa"
    allowable_twist: Qty = "0.25 deg/m"
    max_deflection: Qty = "6.35 mm"


class CouplingIn(_Section):
    rated_torque: Qty
    pins: int
    pin_circle_diameter: Qty
    pin_diameter: Qty
    bushing_length: Qty
    pin_lever: Qty
    allowable_bushing_stress: Qty = "2 MPa"
    allowable_pin_stress: Qty = "60 MPa"


class BaseBoltsIn(_Section):
    belt_force: Qty
    belt_preload: Qty = "0 N"
    lever: Qty
    spacing_a: Qty
    spacing_b: Qty
    allowable_tensile_stress: Qty = "120 MPa"
    friction: float = 0.2
    safety: float = 2.0
    bolt: str | None = None


class ConveyorIn(_Section):
    throughput: Qty
    length: Qty
    inclination: Qty = "0 deg"
    power_method: str = "iso7119"
    methods: list[str] = list(pw.METHODS)
    material: MaterialIn
    screw: ScrewIn = ScrewIn()
    drive: DriveIn = DriveIn()
    strength: StrengthIn = StrengthIn()
    coupling: CouplingIn | None = None
    base_bolts: BaseBoltsIn | None = None


class MetaIn(_Section):
    name: str = "screw conveyor"
    description: str = ""


class FileIn(_Section):
    meta: MetaIn = MetaIn()
    screw_conveyor: ConveyorIn


_SECTIONS: dict[str, type[BaseModel]] = {
    "": FileIn, "meta": MetaIn, "screw_conveyor": ConveyorIn, "screw_conveyor.material": MaterialIn,
    "screw_conveyor.screw": ScrewIn, "screw_conveyor.drive": DriveIn, "screw_conveyor.strength": StrengthIn,
    "screw_conveyor.coupling": CouplingIn, "screw_conveyor.base_bolts": BaseBoltsIn,
}


@dataclass(frozen=True)
class ConveyorProblem:
    """A validated screw-conveyor problem in SI floats (kg/s, kg/m³, m, rad, rpm, Pa, W)."""

    name: str
    description: str
    mass_flow: float
    length: float
    inclination: float
    power_method: str
    methods: tuple[str, ...]
    material_name: str
    bulk_density: float
    filling: float
    speed_coefficient: float
    resistance: float
    cema_material_factor: float | None
    friction_coefficient: float
    diameter: float | None
    speed: float | None
    pitch_ratio: float
    inclination_factor: float
    pipe_outer_diameter: float | None
    pipe_wall: float | None
    flight_thickness: float | None
    hanger_spacing: float
    force_radius_ratio: float
    lateral_load_factor: float
    hanger_bearing: str
    flight_type: str
    paddles: int
    drive_efficiency: float
    coupling_service_factor: float
    shear_modulus: float
    elastic_modulus: float
    poisson_ratio: float
    steel_density: float
    allowable_shear_stress: float
    allowable_stress: float
    allowable_twist: float
    max_deflection: float
    coupling: dict[str, float] | None = None
    base_bolts: dict[str, Any] | None = None
    source: str | None = None


# ------------------------------------------------------------------------------------- loading


def _pydantic_problems(exc: ValidationError) -> list[tuple[str, str]]:
    problems = []
    for err in exc.errors():
        loc = [str(x) for x in err["loc"] if not isinstance(x, int)]
        # pydantic reports union members as extra loc entries (e.g. 'str', 'float'); drop them
        loc = [x for x in loc if x not in ("str", "float", "int", "function-after")]
        path = ".".join(loc)
        if err["type"] == "extra_forbidden":
            parent, _, key = path.rpartition(".")
            model = _SECTIONS.get(parent)
            options = list(model.model_fields) if model else []
            close = difflib.get_close_matches(key, options, n=1)
            hint = f" Did you mean '{close[0]}'?" if close else f" Known keys: {', '.join(options)}."
            problems.append((path, f"Unknown key '{key}'.{hint}"))
        elif err["type"] == "missing":
            problems.append((path, "This value is required and missing."))
        else:
            problems.append((path, f"{err['msg']}; got {err.get('input')!r}."))
    # one message per path (unions report each member)
    seen: dict[str, str] = {}
    for path, msg in problems:
        seen.setdefault(path, msg)
    return list(seen.items())


class _Collector:
    def __init__(self) -> None:
        self.problems: list[tuple[str, str]] = []

    def qty(self, path: str, value, unit: str, rule: str | None = "positive", label: str | None = None):
        if value is None:
            return None
        label = label or path.rsplit(".", 1)[-1].replace("_", " ")
        try:
            x = parse_quantity(value, unit, field=label)
        except InputError as exc:
            self.problems.append((path, str(exc)))
            return None
        return self.rule(path, x, rule, label, unit, value)

    def rule(self, path: str, x, rule: str | None, label: str, unit: str = "", shown=None):
        shown = x if shown is None else shown
        if rule == "positive" and not x > 0:
            self.problems.append((path, f"The {label} must be > 0{' ' + unit if unit else ''}; got {shown}."))
            return None
        if rule == "nonneg" and not x >= 0:
            self.problems.append((path, f"The {label} must be >= 0{' ' + unit if unit else ''}; got {shown}."))
            return None
        if rule == "fraction" and not 0 < x <= 1:
            rel = "<= 1" if x > 1 else "> 0"
            self.problems.append((path, f"The {label} must be {rel}; got {shown}."))
            return None
        return x

    def call(self, path: str, fn, *args):
        try:
            return fn(*args)
        except InputError as exc:
            self.problems.append((path, str(exc)))
            return None


def _throughput(col: _Collector, value) -> float | None:
    """Mass flow [kg/s] from a mass flow or a volume flow (the latter needs the bulk density later)."""
    path = "screw_conveyor.throughput"
    try:
        return parse_quantity(value, "kg/s", field="throughput")
    except InputError:
        pass
    try:
        return -parse_quantity(value, "m^3/s", field="throughput")  # negative marks a volume flow
    except InputError:
        col.problems.append((path, f"The throughput must be a mass flow (like \"7.2 t/h\") or a volume flow "
                                   f"(like \"6 m^3/h\"); got {value!r}."))
        return None


def load_conveyor_problem(data: dict, source: str | None = None) -> ConveyorProblem:
    """Validate the parsed TOML ``data`` of a ``[screw_conveyor]`` problem file.

    Collects every mistake and raises :class:`~machdyn.errors.ProblemFileError` listing each as
    (path, message); unknown keys get a "did you mean".
    """
    structural: list[tuple[str, str]] = []
    try:
        f = FileIn.model_validate(data)
    except ValidationError as exc:
        structural = _pydantic_problems(exc)
        extra = [e["loc"] for e in exc.errors() if e["type"] == "extra_forbidden"]
        if len(extra) < len(exc.errors()):
            raise ProblemFileError(structural, source) from None
        # only unknown keys: drop them and go on, so that the value rules are reported in the same pass
        cleaned = copy.deepcopy(data)
        for loc in extra:
            node = cleaned
            for part in loc[:-1]:
                node = node[part]
            node.pop(loc[-1], None)
        f = FileIn.model_validate(cleaned)
    c = f.screw_conveyor
    m = c.material
    s = c.screw
    st = c.strength
    col = _Collector()
    col.problems.extend(structural)
    p = "screw_conveyor"

    flow = _throughput(col, c.throughput)
    length = col.qty(f"{p}.length", c.length, "m")
    inclination = col.qty(f"{p}.inclination", c.inclination, "rad", rule=None)
    if inclination is not None and not 0 <= inclination < math.pi / 2:
        col.problems.append((f"{p}.inclination", f"The inclination must be >= 0 deg and < 90 deg; got "
                                                 f"{c.inclination!r}."))
        inclination = None
    if c.power_method not in pw.METHODS:
        close = difflib.get_close_matches(c.power_method, pw.METHODS, n=1)
        hint = f" Did you mean '{close[0]}'?" if close else ""
        col.problems.append((f"{p}.power_method", f"The power method must be one of {', '.join(pw.METHODS)}; "
                                                  f"got '{c.power_method}'.{hint}"))
    for i, meth in enumerate(c.methods):
        if meth not in pw.METHODS:
            close = difflib.get_close_matches(meth, pw.METHODS, n=1)
            hint = f" Did you mean '{close[0]}'?" if close else ""
            col.problems.append((f"{p}.methods[{i}]", f"The power method must be one of "
                                                      f"{', '.join(pw.METHODS)}; got '{meth}'.{hint}"))
    methods = tuple(dict.fromkeys([*c.methods, c.power_method]))

    mp = f"{p}.material"
    rho = col.qty(f"{mp}.bulk_density", m.bulk_density, "kg/m^3", label="bulk density")
    filling = col.rule(f"{mp}.filling", m.filling, "fraction", "filling coefficient")
    if m.speed_coefficient is not None:
        k_v = col.rule(f"{mp}.speed_coefficient", m.speed_coefficient, "positive", "speed coefficient")
    elif m.speed_class is not None:
        k_v = col.call(f"{mp}.speed_class", tables.speed_coefficient, m.speed_class)
    else:
        k_v = None
        col.problems.append((f"{mp}.speed_coefficient", "Give the speed coefficient k of n = k/sqrt(D) "
                             "(speed_coefficient, rpm*m^0.5) or a speed_class."))
    if m.resistance is not None:
        resistance = col.rule(f"{mp}.resistance", m.resistance, "positive", "resistance coefficient")
    elif m.resistance_group is not None:
        resistance = col.call(f"{mp}.resistance_group", tables.resistance_coefficient, m.resistance_group)
    else:
        resistance = None
        col.problems.append((f"{mp}.resistance", "Give the resistance coefficient C0 = lambda (resistance) "
                             "or a resistance_group."))
    fm = None
    if m.cema_material_factor is not None:
        fm = col.rule(f"{mp}.cema_material_factor", m.cema_material_factor, "positive", "CEMA material factor")
    elif m.cema_material is not None:
        fm = col.call(f"{mp}.cema_material", tables.cema_material_factor, m.cema_material)
    friction = col.rule(f"{mp}.friction_coefficient", m.friction_coefficient, "positive",
                        "friction coefficient")

    sp = f"{p}.screw"
    diameter = col.qty(f"{sp}.diameter", s.diameter, "m")
    speed = col.qty(f"{sp}.speed", s.speed, "rpm")
    pitch_ratio = col.rule(f"{sp}.pitch_ratio", s.pitch_ratio, "positive", "pitch ratio")
    if s.inclination_factor is not None:
        c_inc = col.rule(f"{sp}.inclination_factor", s.inclination_factor, "fraction", "inclination factor")
    elif inclination is not None:
        c_inc = col.call(f"{p}.inclination", tables.inclination_factor, inclination)
    else:
        c_inc = None
    pipe_od = col.qty(f"{sp}.pipe_outer_diameter", s.pipe_outer_diameter, "m")
    pipe_wall = col.qty(f"{sp}.pipe_wall", s.pipe_wall, "m")
    flight_t = col.qty(f"{sp}.flight_thickness", s.flight_thickness, "m")
    span = col.qty(f"{sp}.hanger_spacing", s.hanger_spacing, "m")
    r_ratio = col.rule(f"{sp}.force_radius_ratio", s.force_radius_ratio, "positive", "force radius ratio")
    if r_ratio is not None and r_ratio > 0.5:
        col.problems.append((f"{sp}.force_radius_ratio", f"The force radius ratio R/D must be <= 0.5; got "
                                                         f"{r_ratio:g}."))
    k_lat = col.rule(f"{sp}.lateral_load_factor", s.lateral_load_factor, "positive", "lateral load factor")
    col.call(f"{sp}.hanger_bearing", tables.cema_hanger_bearing_factor, s.hanger_bearing)
    col.call(f"{sp}.paddles", tables.cema_paddle_factor, s.paddles)
    col.call(f"{sp}.flight_type", tables.cema_flight_factor, s.flight_type, 0.95)

    dp = f"{p}.drive"
    if c.drive.efficiency is not None:
        eta = col.rule(f"{dp}.efficiency", c.drive.efficiency, "fraction", "drive efficiency")
    else:
        eta = col.call(f"{dp}.type", tables.drive_efficiency, c.drive.type or "shaft_mount_v_belt")
    k_coupling = col.rule(f"{dp}.coupling_service_factor", c.drive.coupling_service_factor, "positive",
                          "coupling service factor")

    tp = f"{p}.strength"
    g_mod = col.qty(f"{tp}.shear_modulus", st.shear_modulus, "Pa")
    e_mod = col.qty(f"{tp}.elastic_modulus", st.elastic_modulus, "Pa")
    nu = st.poisson_ratio
    if not 0 <= nu < 0.5:
        col.problems.append((f"{tp}.poisson_ratio", f"The Poisson ratio must be >= 0 and < 0.5; got {nu:g}."))
    steel_rho = col.qty(f"{tp}.steel_density", st.steel_density, "kg/m^3")
    tau_allow = col.qty(f"{tp}.allowable_shear_stress", st.allowable_shear_stress, "Pa")
    sig_allow = col.qty(f"{tp}.allowable_stress", st.allowable_stress, "Pa")
    twist_allow = col.qty(f"{tp}.allowable_twist", st.allowable_twist, "rad/m")
    defl_allow = col.qty(f"{tp}.max_deflection", st.max_deflection, "m")

    coupling = None
    if c.coupling is not None:
        cp = f"{p}.coupling"
        cu = c.coupling
        coupling = {
            "rated_torque": col.qty(f"{cp}.rated_torque", cu.rated_torque, "N*m"),
            "pins": col.rule(f"{cp}.pins", cu.pins, "positive", "number of pins"),
            "pin_circle_diameter": col.qty(f"{cp}.pin_circle_diameter", cu.pin_circle_diameter, "m"),
            "pin_diameter": col.qty(f"{cp}.pin_diameter", cu.pin_diameter, "m"),
            "bushing_length": col.qty(f"{cp}.bushing_length", cu.bushing_length, "m"),
            "pin_lever": col.qty(f"{cp}.pin_lever", cu.pin_lever, "m"),
            "allowable_bushing_stress": col.qty(f"{cp}.allowable_bushing_stress", cu.allowable_bushing_stress,
                                                "Pa"),
            "allowable_pin_stress": col.qty(f"{cp}.allowable_pin_stress", cu.allowable_pin_stress, "Pa"),
        }
    bolts = None
    if c.base_bolts is not None:
        bp = f"{p}.base_bolts"
        b = c.base_bolts
        bolts = {
            "belt_force": col.qty(f"{bp}.belt_force", b.belt_force, "N", rule="nonneg"),
            "belt_preload": col.qty(f"{bp}.belt_preload", b.belt_preload, "N", rule="nonneg"),
            "lever": col.qty(f"{bp}.lever", b.lever, "m", rule="nonneg"),
            "spacing_a": col.qty(f"{bp}.spacing_a", b.spacing_a, "m"),
            "spacing_b": col.qty(f"{bp}.spacing_b", b.spacing_b, "m"),
            "allowable_tensile_stress": col.qty(f"{bp}.allowable_tensile_stress", b.allowable_tensile_stress,
                                                "Pa"),
            "friction": col.rule(f"{bp}.friction", b.friction, "positive", "joint friction coefficient"),
            "safety": col.rule(f"{bp}.safety", b.safety, "positive", "safety factor"),
            "bolt": b.bolt,
        }
        if b.bolt is not None and b.bolt not in dict(tables.metric_bolts()):
            names = [n for n, _ in tables.metric_bolts()]
            close = difflib.get_close_matches(b.bolt, names, n=1)
            hint = f" Did you mean '{close[0]}'?" if close else ""
            col.problems.append((f"{bp}.bolt", f"The bolt must be one of {', '.join(names)}; got '{b.bolt}'.{hint}"))

    if col.problems:
        raise ProblemFileError(col.problems, source)

    mass_flow = flow if flow >= 0 else -flow * rho
    return ConveyorProblem(
        name=f.meta.name, description=f.meta.description, mass_flow=mass_flow, length=length,
        inclination=inclination, power_method=c.power_method, methods=methods, material_name=m.name,
        bulk_density=rho, filling=filling, speed_coefficient=k_v, resistance=resistance,
        cema_material_factor=fm, friction_coefficient=friction, diameter=diameter, speed=speed,
        pitch_ratio=pitch_ratio, inclination_factor=c_inc, pipe_outer_diameter=pipe_od, pipe_wall=pipe_wall,
        flight_thickness=flight_t, hanger_spacing=span, force_radius_ratio=r_ratio, lateral_load_factor=k_lat,
        hanger_bearing=s.hanger_bearing, flight_type=s.flight_type, paddles=s.paddles, drive_efficiency=eta,
        coupling_service_factor=k_coupling, shear_modulus=g_mod, elastic_modulus=e_mod, poisson_ratio=nu,
        steel_density=steel_rho, allowable_shear_stress=tau_allow, allowable_stress=sig_allow,
        allowable_twist=twist_allow, max_deflection=defl_allow, coupling=coupling, base_bolts=bolts,
        source=source,
    )


# ----------------------------------------------------------------------------------------- result


@dataclass(frozen=True)
class Quantity:
    """One reported quantity, in the unit it is shown in."""

    key: str
    label: str
    value: float
    unit: str


@dataclass
class ConveyorResult:
    """Everything ``run_conveyor`` computed: design, power by method, loads, checks and warnings."""

    problem: ConveyorProblem
    design: ScrewDesign
    powers: dict[str, pw.PowerResult]
    selected_method: str
    shaft_power: float
    motor_power_required: float
    motor_rating: float
    torque: float
    quantities: list[Quantity]
    checks: list[ck.Check]
    warnings: list[str] = field(default_factory=list)

    @property
    def passed(self) -> bool:
        """True if every check passes."""
        return all(c.passed for c in self.checks)

    def quantity(self, key: str) -> Quantity:
        for q in self.quantities:
            if q.key == key:
                return q
        raise KeyError(key)

    def summary_rows(self) -> list[tuple[str, str, str]]:
        """(quantity, value, unit) rows for a console table."""
        rows = [(q.label, f"{q.value:.4g}", q.unit) for q in self.quantities]
        for key, res in self.powers.items():
            rows.append((f"Shaft power, {pw.LABELS[key]}", f"{res.shaft_power / 1000:.4g}", "kW"))
        for c in self.checks:
            rows.append((f"Check: {c.name}", f"{c.value:.4g} / {c.limit:.4g} ({'pass' if c.passed else 'FAIL'})",
                         c.unit))
        return rows

    def scalars(self) -> dict[str, dict]:
        """name -> {"value": float, "unit": str} for results.json."""
        out = {q.key: {"value": float(q.value), "unit": q.unit} for q in self.quantities}
        for key, res in self.powers.items():
            out[f"power_{key}"] = {"value": res.shaft_power / 1000.0, "unit": "kW"}
        for c in self.checks:
            slug = c.name.lower().replace(" ", "_").replace(",", "").replace("/", "_")
            out[f"check_{slug}_utilisation"] = {"value": float(c.utilisation), "unit": ""}
        return out

    def to_html_section(self) -> str:
        """The report section: design, power-by-method and checks tables (an HTML fragment)."""
        from .report import conveyor_html_section

        return conveyor_html_section(self)


# -------------------------------------------------------------------------------------------- run


def _warn(messages: list[str], text: str) -> None:
    messages.append(text)
    _warnings.warn(text, MachdynWarning, stacklevel=3)


def compute_powers(problem: ConveyorProblem, design: ScrewDesign, messages: list[str]) -> dict:
    """Shaft power by each requested method (methods out of their range are skipped with a warning)."""
    length, beta = problem.length, problem.inclination
    lift = length * math.sin(beta)
    m_dot = design.mass_flow
    out: dict[str, pw.PowerResult] = {}
    for method in problem.methods:
        if method == "textbook_360":
            p = pw.power_textbook_360(m_dot, length, lift, problem.resistance)
            out[method] = pw.PowerResult(method, pw.LABELS[method], p, {
                "lift Q·H/360": 1000 * m_dot * 3.6 * lift / 360, "resistance C0·Q·L/360":
                1000 * problem.resistance * m_dot * 3.6 * length / 360},
                note="g taken as 10 m/s^2 as printed in seed 004; L = conveyor length")
        elif method == "textbook_367":
            p = pw.power_textbook_367(m_dot, length, lift, problem.resistance)
            out[method] = pw.PowerResult(method, pw.LABELS[method], p, {
                "lift Q·H/367": m_dot * pw.G * lift, "resistance C0·Q·L/367": m_dot * pw.G * problem.resistance
                * length}, note="Alexandrov's form, 367 = 3600/g")
        elif method == "iso7119":
            if beta > pw.ISO7119_MAX_INCLINATION + 1e-12:
                _warn(messages, f"ISO 7119 skipped: it applies to inclinations up to 20 deg; got "
                                f"{math.degrees(beta):.4g} deg.")
                continue
            r = pw.power_iso7119(m_dot, length, beta, design.diameter, problem.resistance)
            out[method] = pw.PowerResult(method, pw.LABELS[method], r.total, {
                "P_H progress": r.progress, "P_N no load": r.no_load, "P_st inclination": r.inclination},
                note="lambda = resistance coefficient")
        elif method == "cema":
            if problem.cema_material_factor is None:
                _warn(messages, "CEMA method skipped: give material.cema_material_factor (Fm) or "
                                "material.cema_material.")
                continue
            try:
                fd = tables.cema_diameter_factor(design.diameter)
            except InputError as exc:
                _warn(messages, f"CEMA method skipped: {exc}")
                continue
            loading = min(design.filling_actual, 0.95)
            r = pw.power_cema(
                volume_flow=design.volume_flow, bulk_density=problem.bulk_density, length=length,
                speed_rpm=design.speed, diameter_factor=fd,
                hanger_bearing_factor=tables.cema_hanger_bearing_factor(problem.hanger_bearing),
                material_factor=problem.cema_material_factor,
                flight_factor=tables.cema_flight_factor(problem.flight_type, loading),
                paddle_factor=tables.cema_paddle_factor(problem.paddles), efficiency=1.0, lift=lift)
            note = f"Fd = {fd:.4g}, Fo = {r.overload_factor:.3g}"
            if not tables.cema_diameter_is_tabulated(design.diameter):
                note += " (Fd interpolated between CEMA inch sizes)"
            if lift:
                note += "; lift power m·g·H added before Fo"
            out[method] = pw.PowerResult(method, pw.LABELS[method], r.total_watts, {
                "HPf friction": r.friction_hp * pw.HP, "HPm material": r.material_hp * pw.HP,
                "lift": r.lift_hp * pw.HP,
                "overload allowance (Fo - 1)": (r.overload_factor - 1) * (r.friction_hp + r.material_hp
                                                                           + r.lift_hp) * pw.HP}, note=note)
    return out


def run_conveyor(problem: ConveyorProblem) -> ConveyorResult:
    """Design the screw for the duty, compute power by every method, the loads and all checks."""
    messages: list[str] = []
    p = problem
    design = design_screw(
        mass_flow=p.mass_flow, bulk_density=p.bulk_density, filling=p.filling,
        speed_coefficient=p.speed_coefficient, pitch_ratio=p.pitch_ratio,
        inclination_factor=p.inclination_factor, diameter=p.diameter, speed=p.speed,
    )
    d = design.diameter
    powers = compute_powers(p, design, messages)
    if p.power_method not in powers:
        raise InputError(f"The power method '{p.power_method}' that sizes the drive is not applicable here "
                         f"(see the warnings); choose another power_method.")
    shaft_power = powers[p.power_method].shaft_power
    motor_required = shaft_power / p.drive_efficiency
    motor = pw.select_motor(motor_required)
    n = design.speed
    torque = ck.torque_from_power(shaft_power, n)

    # pipe and flight (assumed if not given)
    d_o = p.pipe_outer_diameter
    if d_o is None:
        d_o = 0.5 * d
        _warn(messages, f"screw.pipe_outer_diameter not given; assumed half the screw diameter, "
                        f"{d_o * 1000:.0f} mm.")
    wall = p.pipe_wall
    if wall is None:
        wall = d_o / 12.0
        _warn(messages, f"screw.pipe_wall not given; assumed {wall * 1000:.1f} mm (d_o/12).")
    d_i = d_o - 2 * wall
    if not 0 <= d_i < d_o < d:
        raise InputError(f"The pipe ({d_o * 1000:g} mm, wall {wall * 1000:g} mm) must fit inside the screw "
                         f"({d * 1000:g} mm) with a wall thinner than its radius.")
    t_f = p.flight_thickness if p.flight_thickness is not None else max(0.003, d / 50.0)
    span, length = p.hanger_spacing, p.length

    radius = p.force_radius_ratio * d
    alpha = ck.helix_angle(design.pitch, radius)
    f_axial = ck.axial_force(torque, radius, alpha, p.friction_coefficient)
    p_lat = ck.lateral_load(torque, span, p.lateral_load_factor, d, length)
    dist = ck.distributed_loads(f_axial, p_lat, torque, span, length)
    jp = ck.polar_moment_tube(d_o, d_i)
    twist_total = ck.torsion_angle_distributed(dist["m_0"], length, p.shear_modulus, jp)
    twist_rate = torque / (p.shear_modulus * jp)
    tau = ck.shear_stress_tube(torque, d_o, d_i)
    mass_len = ck.screw_mass_per_length(d, d_o, d_i, t_f, design.pitch, p.steel_density)
    q_v = mass_len * pw.G
    q = math.hypot(q_v, dist["p_n"])
    second_moment = jp / 2.0
    m_b = ck.span_bending_moment(q, span)
    sigma_b = m_b * (d_o / 2) / second_moment
    area = math.pi / 4 * (d_o**2 - d_i**2)
    sigma_ax = f_axial / area
    sigma_eq = math.sqrt((sigma_b + sigma_ax) ** 2 + 4 * tau**2)
    deflection = ck.span_deflection(q, span, p.elastic_modulus, second_moment)
    flight_pressure = f_axial / (math.pi * ((d / 2) ** 2 - (d_o / 2) ** 2))
    sigma_flight = flight_max_stress(flight_pressure, d / 2, d_o / 2, t_f, p.poisson_ratio)

    checks = [
        ck.Check("Screw speed n <= k/sqrt(D)", n, design.speed_limit, "rpm", "seed 004, n = k/sqrt(D)"),
        ck.Check("Throughput <= capacity", design.mass_flow * 3.6, design.capacity_mass * 3.6, "t/h",
                 "seed 004, eq 2.83"),
        ck.Check("Motor load", motor_required / 1000, motor / 1000, "kW", "IEC 60072-1 rating"),
        ck.Check("Pipe twist rate at the drive", math.degrees(twist_rate), math.degrees(p.allowable_twist),
                 "deg/m", "T/(G·Jp), pipe section"),
        ck.Check("Pipe torsional shear stress", tau / 1e6, p.allowable_shear_stress / 1e6, "MPa",
                 "T·(d_o/2)/Jp"),
        ck.Check("Pipe equivalent stress (Tresca)", sigma_eq / 1e6, p.allowable_stress / 1e6, "MPa",
                 "seed 004, eq 2.48, pipe section"),
        ck.Check("Deflection between hangers", deflection * 1000, p.max_deflection * 1000, "mm",
                 "5ql^4/(384EI), simply supported span"),
        ck.Check("Flight bending stress at the pipe", sigma_flight / 1e6, p.allowable_stress / 1e6, "MPa",
                 "seed 004, eqs 2.66-2.70 (corrected)"),
    ]
    quantities = [
        Quantity("mass_flow", "Throughput (mass)", design.mass_flow * 3.6, "t/h"),
        Quantity("volume_flow", "Throughput (volume)", design.volume_flow * 3600, "m^3/h"),
        Quantity("inclination", "Inclination", math.degrees(p.inclination), "deg"),
        Quantity("lift", "Lift H", length * math.sin(p.inclination), "m"),
        Quantity("inclination_factor", "Inclination factor C", design.inclination_factor, ""),
        Quantity("diameter_required", "Diameter required", design.diameter_required * 1000, "mm"),
        Quantity("diameter", "Diameter (standard)", d * 1000, "mm"),
        Quantity("pitch", "Pitch", design.pitch * 1000, "mm"),
        Quantity("speed_limit", "Speed limit k/sqrt(D)", design.speed_limit, "rpm"),
        Quantity("speed", "Speed", n, "rpm"),
        Quantity("capacity", "Capacity at this speed", design.capacity_mass * 3.6, "t/h"),
        Quantity("filling_actual", "Filling at the duty", design.filling_actual, ""),
        Quantity("shaft_power", f"Shaft power ({p.power_method})", shaft_power / 1000, "kW"),
        Quantity("drive_efficiency", "Drive efficiency", p.drive_efficiency, ""),
        Quantity("motor_power_required", "Motor power required", motor_required / 1000, "kW"),
        Quantity("motor_rating", "Motor (IEC rating)", motor / 1000, "kW"),
        Quantity("torque", "Screw torque", torque, "N*m"),
        Quantity("helix_angle", "Helix angle at R", math.degrees(alpha), "deg"),
        Quantity("axial_force", "Axial force", f_axial, "N"),
        Quantity("lateral_load", "Lateral load per span", p_lat, "N"),
        Quantity("p_d", "Axial force per length p_d", dist["p_d"], "N/m"),
        Quantity("p_n", "Lateral load per length p_n", dist["p_n"], "N/m"),
        Quantity("m_0", "Torque per length m_0", dist["m_0"], "N*m/m"),
        Quantity("twist_total", "Twist over the length", twist_total, "rad"),
        Quantity("screw_mass_per_length", "Screw mass per length", mass_len, "kg/m"),
        Quantity("deflection", "Deflection between hangers", deflection * 1000, "mm"),
        Quantity("flight_pressure", "Flight pressure (all axial force on one turn)", flight_pressure / 1000,
                 "kPa"),
    ]
    if p.coupling is not None:
        cu = p.coupling
        t_t = ck.coupling_design_torque(torque, p.coupling_service_factor)
        s_d = ck.bushing_bearing_stress(torque, p.coupling_service_factor, cu["pins"], cu["pin_circle_diameter"],
                                        cu["pin_diameter"], cu["bushing_length"])
        s_u = ck.pin_bending_stress(torque, p.coupling_service_factor, cu["pins"], cu["pin_circle_diameter"],
                                    cu["pin_diameter"], cu["pin_lever"])
        checks += [
            ck.Check("Coupling torque k·T", t_t, cu["rated_torque"], "N*m", "seed 004, eq 2.97"),
            ck.Check("Coupling bush bearing stress", s_d / 1e6, cu["allowable_bushing_stress"] / 1e6, "MPa",
                     "seed 004, eq 2.98"),
            ck.Check("Coupling pin bending stress", s_u / 1e6, cu["allowable_pin_stress"] / 1e6, "MPa",
                     "seed 004, eq 2.98"),
        ]
    if p.base_bolts is not None:
        b = p.base_bolts
        f_max = ck.base_bolt_max_force(b["belt_force"], b["belt_preload"], b["lever"], b["spacing_a"],
                                       b["spacing_b"])
        d3 = ck.bolt_minor_diameter_required(f_max, b["allowable_tensile_stress"], b["friction"], b["safety"])
        quantities += [Quantity("bolt_force", "Largest base-bolt shear force", f_max, "N"),
                       Quantity("bolt_d3_required", "Bolt minor diameter required", d3 * 1000, "mm")]
        bolts = tables.metric_bolts()
        if b["bolt"] is not None:
            name, have = b["bolt"], dict(bolts)[b["bolt"]]
        else:
            name, have = next(((nm, dd) for nm, dd in bolts if dd >= d3), bolts[-1])
        checks.append(ck.Check(f"Base bolt {name} minor diameter", d3 * 1000, have * 1000, "mm",
                               "seed 004, eqs 2.72-2.80"))
    for c in checks:
        if not c.passed:
            _warn(messages, f"Check failed: {c.name}: {c.value:.4g} {c.unit} > limit {c.limit:.4g} {c.unit}.")
    return ConveyorResult(
        problem=p, design=design, powers=powers, selected_method=p.power_method, shaft_power=shaft_power,
        motor_power_required=motor_required, motor_rating=motor, torque=torque, quantities=quantities,
        checks=checks, warnings=messages,
    )
