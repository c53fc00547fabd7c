"""The ``[screw_conveyor]`` problem file: its tables as pydantic models, the schema of the kind.

Quantities use the shared field types of :mod:`machdyn.problem.fields` (text with a unit in, SI float out, the
unit kept for the dumper), each with a plausibility bound so that no absurd value such as 1e300 m reaches the
formulas; speeds are read as angular speeds in rad/s (``"100 rpm"`` in the file). The loader validates a file
against :class:`ConveyorFile` like any other kind's schema (every mistake at once, with its path, the rule and
the value); the rules across fields that a single field cannot say are :func:`presence_problems` (on the raw
tables, so that they are said with every other mistake) and :func:`build` (on the valid tables), which makes
the frozen :class:`~machdyn.conveyor.model.ConveyorProblem` in SI the analysis works on.
"""

from __future__ import annotations

import math
from typing import Annotated, Any, Literal

from pydantic import AfterValidator, BeforeValidator, Field, ValidationError, model_validator
from pydantic_core import InitErrorDetails

from ..errors import InputError
from ..problem import fields as qf
from ..problem.errors import did_you_mean
from ..problem.fields import FieldError, Unit, to_si
from ..problem.schema import Meta, Spec
from ..reading import validate as validate_file
from . import tables
from .evaluate import choose_screw
from .model import BaseBolts, ConveyorProblem, Coupling, DesignSearch
from .power import ISO7119_MAX_INCLINATION, METHODS

#: The path of the kind's main table in the file.
MAIN = "screw_conveyor"


def _at_most(upper: float, unit: str, why: str) -> Any:
    """A plausibility bound on a validated SI value: larger values are refused, saying why."""

    def check(value: float) -> float:
        if abs(value) > upper:
            raise FieldError(f"must be <= {upper:g} {unit} ({why}); got {value:g} {unit}")
        return value

    return AfterValidator(check)


def _number(lo: float, hi: float, *, lo_open: bool = True, hi_open: bool = False) -> Any:
    def check(value: Any) -> float:
        if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
            raise FieldError(f"must be a finite number; got {value!r}")
        low_ok = value > lo if lo_open else value >= lo
        high_ok = value < hi if hi_open else value <= hi
        if not (low_ok and high_ok):
            left = "(" if lo_open else "["
            right = ")" if hi_open else "]"
            raise FieldError(f"must be in {left}{lo:g}, {hi:g}{right}; got {value!r}")
        return float(value)

    return BeforeValidator(check)


def _name_in(lookup: Any) -> Any:
    def check(value: str) -> str:
        lookup(value)  # raises InputError (a ValueError) naming the table, the value and the nearest name
        return value

    return AfterValidator(check)


def _method(value: str) -> str:
    if value not in METHODS:
        raise ValueError(f"must be one of {', '.join(METHODS)}; got {value!r}{did_you_mean(value, METHODS)}")
    return value


Method = Annotated[str, AfterValidator(_method)]
ScrewLength = Annotated[qf.PositiveLength, _at_most(1e4, "m", "longer than any screw conveyor")]
ScrewSize = Annotated[qf.PositiveLength, _at_most(10.0, "m", "larger than any screw")]
Lift = Annotated[qf.NonNegativeLength, _at_most(1e4, "m", "higher than any screw conveyor")]
Slope = Annotated[qf.NonNegativeAngle,
                  _at_most(math.pi / 2 * (1 - 1e-12), "rad", "a screw steeper than vertical")]
Density = Annotated[qf.Density, _at_most(3e4, "kg/m^3", "denser than any bulk material or metal")]
#: A screw's angular speed [rad/s]; ``"100 rpm"`` in the file.
Speed = Annotated[qf.PositiveAngularVelocity, _at_most(1e3, "rad/s", "faster than any screw")]
Stress = Annotated[qf.Stress, _at_most(1e12, "Pa", "beyond any steel")]
Modulus = Annotated[qf.Stress, _at_most(1e13, "Pa", "beyond any steel")]
TwistRate = Annotated[qf.TwistRate,
                      _at_most(10.0, "rad/m", "a twist of more than 10 rad per metre")]
ForceN = Annotated[qf.NonNegativeForce, _at_most(1e9, "N", "beyond any conveyor drive")]
TorqueNm = Annotated[qf.PositiveTorque, _at_most(1e9, "N*m", "beyond any conveyor drive")]
Fraction = Annotated[float, _number(0.0, 1.0)]
Positive = Annotated[float, _number(0.0, 1e6)]


def _throughput(value: Any) -> tuple[str, float]:
    """("mass", kg/s) or ("volume", m³/s) from a mass flow or a volume flow."""
    for unit, what, upper in (("kg/s", "mass", 1e5), ("m^3/s", "volume", 1e2)):
        try:
            si = to_si(value, Unit(unit, "flow"))
        except FieldError:
            continue
        if not si > 0:
            raise FieldError(f"must be > 0; got {value!r}")
        if si > upper:
            raise FieldError(f"must be <= {upper:g} {unit} (beyond any screw conveyor); got {value!r}")
        return what, si
    raise FieldError(f'must be a mass flow (like "7.2 t/h") or a volume flow (like "6 m^3/h"); got {value!r}')


def _throughput_text(value: Any) -> Any:
    """The throughput as written (a mass or a volume flow with its unit), after checking it; :func:`build`
    reads it. Kept as text so that the problem is written back exactly as it was given."""
    _throughput(value)
    return value


Throughput = Annotated[str, BeforeValidator(_throughput_text)]


class _Table(Spec):
    """A table of the file: unknown keys refused, frozen, plain text."""


class MaterialIn(_Table):
    name: str = "bulk material"
    bulk_density: Density
    filling: Fraction
    speed_coefficient: Positive | None = None
    speed_class: Annotated[str, _name_in(tables.speed_coefficient)] | None = None
    resistance: Positive | None = None
    resistance_group: Annotated[str, _name_in(tables.resistance_coefficient)] | None = None
    cema_material_factor: Positive | None = None
    cema_material: Annotated[str, _name_in(tables.cema_material_factor)] | None = None
    friction_coefficient: Positive = 1.0


class ScrewIn(_Table):
    diameter: ScrewSize | None = None
    speed: Speed | None = None
    pitch_ratio: Positive | None = None  # S/D; 1 (full pitch) when not given
    inclination_factor: Fraction | None = None
    pipe_outer_diameter: ScrewSize | None = None
    pipe_wall: ScrewSize | None = None
    flight_thickness: ScrewSize | None = None
    hanger_spacing: ScrewLength = 3.0
    force_radius_ratio: Annotated[float, Field(gt=0, le=0.5)] = 0.35
    lateral_load_factor: Positive = 0.7
    hanger_bearing: Annotated[str, _name_in(tables.cema_hanger_bearing_factor)] = "bronze"
    flight_type: Annotated[str, _name_in(lambda t: tables.cema_flight_factor(t, 0.95))] = "standard"
    paddles: Annotated[int, Field(ge=0, le=4)] = 0
    capacity_section: Literal["annulus", "circle"] = "annulus"
    flight_load: Literal["per_pitch", "one_turn"] = "per_pitch"


class DriveIn(_Table):
    type: Annotated[str, _name_in(tables.drive_efficiency)] | None = None
    efficiency: Fraction | None = None
    coupling_service_factor: Positive = 1.8


class StrengthIn(_Table):
    shear_modulus: Modulus = 80e9
    elastic_modulus: Modulus = 210e9
    poisson_ratio: Annotated[float, _number(0.0, 0.5, lo_open=False, hi_open=True)] = 0.3
    steel_density: Density = 7850.0
    allowable_shear_stress: Stress = 40e6
    allowable_stress: Stress = 100e6
    allowable_twist: TwistRate = math.radians(0.25)
    max_deflection: ScrewSize = 6.35e-3


class CouplingIn(_Table):
    rated_torque: TorqueNm
    pins: Annotated[int, Field(gt=0, le=100)]
    pin_circle_diameter: ScrewSize
    pin_diameter: ScrewSize
    bushing_length: ScrewSize
    pin_lever: ScrewSize
    allowable_bushing_stress: Stress = 2e6
    allowable_pin_stress: Stress = 60e6


def _bolt(value: str) -> str:
    names = [n for n, _ in tables.metric_bolts()]
    if value not in names:
        raise ValueError(f"must be one of {', '.join(names)}; got {value!r}{did_you_mean(value, names)}")
    return value


class BaseBoltsIn(_Table):
    belt_force: ForceN
    belt_preload: ForceN = 0.0
    lever: Lift
    spacing_a: ScrewSize
    spacing_b: ScrewSize
    allowable_tensile_stress: Stress = 120e6
    friction: Positive = 0.2
    safety: Positive = 2.0
    bolt: Annotated[str, AfterValidator(_bolt)] | None = None


def _objective(value: str) -> str:
    if value not in ("power", "cost"):
        raise ValueError(f"must be 'power' or 'cost'; got {value!r}{did_you_mean(value, ('power', 'cost'))}")
    return value


#: A candidate list of the design search: an empty list leaves nothing to search, so it is refused at the file.
_Candidates = Field(min_length=1)


class OptimiseIn(_Table):
    objective: Annotated[str, AfterValidator(_objective)] = "power"
    diameters: Annotated[list[ScrewSize], _Candidates] | None = None
    pitch_ratios: Annotated[list[Positive], _Candidates] = [1.0, 0.75, 0.5]
    speed_fractions: Annotated[list[Fraction], _Candidates] = [0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0]
    fillings: Annotated[list[Fraction], _Candidates] = [0.15, 0.25, 0.3, 0.4, 0.45]
    motor_mass_per_kw: Positive = 10.0


class ConveyorIn(_Table):
    throughput: Throughput | None = None
    length: ScrewLength
    inclination: Slope | None = None
    lift: Lift | None = None
    torque: TorqueNm | None = None
    power_method: Method = "iso7119"
    methods: list[Method] = list(METHODS)
    material: MaterialIn
    screw: ScrewIn = ScrewIn()
    drive: DriveIn = DriveIn()
    strength: StrengthIn = StrengthIn()
    coupling: CouplingIn | None = None
    base_bolts: BaseBoltsIn | None = None
    optimise: OptimiseIn | None = None


class ConveyorFile(_Table):
    """A whole ``[screw_conveyor]`` problem file: ``[meta]`` and ``[screw_conveyor]`` with its sub-tables."""

    meta: Meta = Meta(name="screw conveyor")
    screw_conveyor: ConveyorIn

    @model_validator(mode="wrap")
    @classmethod
    def _with_presence(cls, data: Any, handler: Any) -> Any:
        """Say the rules across fields of :func:`presence_problems` together with every mistake of the schema."""
        missing = presence_problems(data) if isinstance(data, dict) else []
        extra: list[InitErrorDetails] = [
            {"type": "value_error", "loc": tuple(path.split(".")), "input": _get(data, *path.split(".")),
             "ctx": {"error": FieldError(message)}} for path, message in missing]
        try:
            done = handler(data)
        except ValidationError as exc:
            if not extra:
                raise
            raise ValidationError.from_exception_data(cls.__name__, [*_details(exc), *extra]) from None
        if extra:
            raise ValidationError.from_exception_data(cls.__name__, extra)
        return done


def _details(exc: ValidationError) -> list[InitErrorDetails]:
    out: list[InitErrorDetails] = []
    for err in exc.errors(include_url=False):
        detail: InitErrorDetails = {"type": err["type"], "loc": err["loc"], "input": err.get("input")}
        if "ctx" in err:
            detail["ctx"] = err["ctx"]
        out.append(detail)
    return out


def _get(data: Any, *path: str) -> Any:
    for key in path:
        if not isinstance(data, dict):
            return None
        data = data.get(key)
    return data


def presence_problems(data: dict[str, Any]) -> list[tuple[str, str]]:
    """Rules across fields that hold whatever else is wrong in the file (checked on the raw tables)."""
    out: list[tuple[str, str]] = []
    p = "screw_conveyor"
    m = _get(data, p, "material") or {}
    s = _get(data, p, "screw") or {}
    if not isinstance(m, dict) or not isinstance(s, dict):
        return out
    if m.get("speed_coefficient") is None and m.get("speed_class") is None:
        out.append((f"{p}.material.speed_coefficient",
                    "required: the speed coefficient k of n = k/sqrt(D) (speed_coefficient, rpm*m^0.5) or a "
                    "speed_class"))
    if m.get("resistance") is None and m.get("resistance_group") is None:
        out.append((f"{p}.material.resistance",
                    "required: the resistance coefficient C0 = lambda (resistance) or a resistance_group"))
    sc = _get(data, p) or {}
    if isinstance(sc, dict) and sc.get("throughput") is None and sc.get("optimise") is None and (
            s.get("diameter") is None or s.get("speed") is None):
        out.append((f"{p}.throughput", "required unless the screw is given (screw.diameter and screw.speed: "
                                       "its capacity is then the duty)"))
    if isinstance(sc, dict) and sc.get("optimise") is not None and sc.get("throughput") is None:
        out.append((f"{p}.throughput", "required to choose a design (the duty every candidate must meet)"))
    if isinstance(sc, dict) and sc.get("optimise") is not None:
        # the search sets these for every candidate: a value given here would be silently replaced
        for key in ("diameter", "speed", "pitch_ratio", "pipe_outer_diameter", "pipe_wall", "flight_thickness"):
            if key in s:
                out.append((f"{p}.screw.{key}", f"is chosen by [{p}.optimise] for every candidate, so the value "
                                                f"given would be ignored; got {s[key]!r}. Remove it, or remove "
                                                f"[{p}.optimise] to check this screw"))
    if isinstance(sc, dict) and sc.get("inclination") is not None and sc.get("lift") is not None:
        out.append((f"{p}.lift", "give either the lift or the inclination, not both"))
    return out


def _after(c: ConveyorIn) -> tuple[list[tuple[str, str]], dict[str, Any]]:
    """Rules that need several validated fields; returns the problems and the derived values."""
    p = "screw_conveyor"
    out: list[tuple[str, str]] = []
    got: dict[str, Any] = {}
    beta = c.inclination or 0.0
    if c.lift is not None:
        if c.lift > c.length:
            out.append((f"{p}.lift", f"must be <= the length {c.length:g} m; got {c.lift:g} m"))
        else:
            beta = math.asin(c.lift / c.length)
    got["inclination"] = beta
    m = c.material
    if c.power_method == "cema" and m.cema_material_factor is None and m.cema_material is None:
        out.append((f"{p}.power_method", "'cema' sizes the drive but the CEMA material factor is missing: give "
                                         "material.cema_material_factor (Fm) or material.cema_material"))
    if c.power_method == "iso7119" and beta > ISO7119_MAX_INCLINATION + 1e-12:
        out.append((f"{p}.power_method", f"'iso7119' applies to inclinations up to 20 deg; got "
                                         f"{math.degrees(beta):.4g} deg: choose another power_method"))
    if c.screw.inclination_factor is not None:
        got["inclination_factor"] = c.screw.inclination_factor
    else:
        try:
            got["inclination_factor"] = tables.inclination_factor(beta)
        except InputError as exc:
            out.append((f"{p}.inclination", str(exc)))
    s = c.screw
    if s.pipe_outer_diameter is not None and s.diameter is not None and s.pipe_outer_diameter >= s.diameter:
        out.append((f"{p}.screw.pipe_outer_diameter",
                    f"must be < the screw diameter {s.diameter:g} m; got {s.pipe_outer_diameter:g} m"))
    if s.pipe_wall is not None and s.pipe_outer_diameter is not None and 2 * s.pipe_wall >= s.pipe_outer_diameter:
        out.append((f"{p}.screw.pipe_wall",
                    f"must be < half the pipe's outer diameter {s.pipe_outer_diameter:g} m; got {s.pipe_wall:g} m"))
    return out, got


def build(spec: ConveyorFile) -> tuple[ConveyorProblem | None, list[tuple[str, str]]]:
    """The frozen :class:`ConveyorProblem` (SI) of a valid file, and the problems of the rules across fields
    (a lift longer than the screw, a power method that does not apply, a screw that does not exist ...)."""
    c = spec.screw_conveyor
    problems, got = _after(c)
    if problems:
        return None, problems
    problem = _problem(spec, got)
    problems = _feasible(problem)
    return (None, problems) if problems else (problem, [])


def validate(data: dict[str, Any], source: str | None = None) -> ConveyorProblem:
    """Validate the parsed TOML ``data`` of a whole ``[screw_conveyor]`` problem file, as the loader does for
    every kind, and return the :class:`ConveyorProblem` the analysis works on.

    Raises :class:`~machdyn.errors.ProblemFileError` listing every mistake as (path, message).
    """
    _spec, problem = validate_file(data, MAIN, source)
    return problem


def _problem(f: ConveyorFile, got: dict[str, Any]) -> ConveyorProblem:
    c = f.screw_conveyor
    m, s, st, d = c.material, c.screw, c.strength, c.drive
    rho = m.bulk_density
    mass_flow = None
    if c.throughput is not None:
        what, value = _throughput(c.throughput)
        mass_flow = value if what == "mass" else value * rho
    k_v = m.speed_coefficient if m.speed_coefficient is not None else tables.speed_coefficient(str(m.speed_class))
    resistance = m.resistance if m.resistance is not None else tables.resistance_coefficient(str(m.resistance_group))
    fm = m.cema_material_factor
    if fm is None and m.cema_material is not None:
        fm = tables.cema_material_factor(m.cema_material)
    eta = d.efficiency if d.efficiency is not None else tables.drive_efficiency(d.type or "shaft_mount_v_belt")
    coupling = Coupling(**c.coupling.model_dump()) if c.coupling is not None else None
    bolts = BaseBolts(**c.base_bolts.model_dump()) if c.base_bolts is not None else None
    search = None
    if c.optimise is not None:
        o = c.optimise
        search = DesignSearch(
            objective=o.objective, diameters=tuple(o.diameters or tables.standard_diameters()),
            pitch_ratios=tuple(o.pitch_ratios), speed_fractions=tuple(o.speed_fractions),
            fillings=tuple(o.fillings), motor_mass_per_kw=o.motor_mass_per_kw)
    return ConveyorProblem(
        name=f.meta.name, description=f.meta.description, mass_flow=mass_flow, length=c.length,
        inclination=got["inclination"], lift=c.lift, torque=c.torque, power_method=c.power_method,
        methods=tuple(dict.fromkeys([*c.methods, c.power_method])), material_name=m.name, bulk_density=rho,
        filling=m.filling, speed_coefficient=k_v, resistance=resistance, cema_material_factor=fm,
        friction_coefficient=m.friction_coefficient, diameter=s.diameter, speed=s.speed,
        pitch_ratio=s.pitch_ratio if s.pitch_ratio is not None else 1.0, inclination_factor=got["inclination_factor"],
        pipe_outer_diameter=s.pipe_outer_diameter, pipe_wall=s.pipe_wall, flight_thickness=s.flight_thickness,
        hanger_spacing=s.hanger_spacing, force_radius_ratio=s.force_radius_ratio,
        lateral_load_factor=s.lateral_load_factor, hanger_bearing=s.hanger_bearing, flight_type=s.flight_type,
        paddles=s.paddles, capacity_section=s.capacity_section, flight_load=s.flight_load,
        drive_efficiency=eta, coupling_service_factor=d.coupling_service_factor,
        shear_modulus=st.shear_modulus, elastic_modulus=st.elastic_modulus, poisson_ratio=st.poisson_ratio,
        steel_density=st.steel_density, allowable_shear_stress=st.allowable_shear_stress,
        allowable_stress=st.allowable_stress, allowable_twist=st.allowable_twist,
        max_deflection=st.max_deflection, coupling=coupling, base_bolts=bolts, search=search,
    )


def _feasible(problem: ConveyorProblem) -> list[tuple[str, str]]:
    """The screw the run will choose exists, its pipe fits, and the selected power method applies to it."""
    if problem.search is not None:
        return []  # each candidate is judged by the search itself
    p = "screw_conveyor"
    try:
        design = choose_screw(problem)
        if problem.pipe_outer_diameter is None:
            tables.standard_pipe(design.diameter)  # the pipe is taken from the standard components' table
    except InputError as exc:
        where = "screw.pipe_outer_diameter" if "standard screw conveyor components" in str(exc) else "throughput"
        return [(f"{p}.{where}", str(exc))]
    out = []
    if problem.pipe_outer_diameter is not None and problem.pipe_outer_diameter >= design.diameter:
        out.append((f"{p}.screw.pipe_outer_diameter", f"must be < the screw diameter {design.diameter:g} m; got "
                                                      f"{problem.pipe_outer_diameter:g} m"))
    if problem.power_method == "cema" and not math.isfinite(float(tables.cema_diameter_factors(design.diameter))):
        out.append((f"{p}.power_method", f"'cema' has no diameter factor Fd for a {design.diameter * 1000:g} mm screw "
                                         f"(tabulated 4 to 24 in): choose another power_method"))
    return out
