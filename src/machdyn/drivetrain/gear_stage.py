"""``[drivetrain.stages.teeth]``: a gear stage's teeth checked for root bending (Lewis with Barth's velocity factor)
and flank contact (Hertz) under the largest torque the stage carries over the cycle.

```toml
[[drivetrain.stages]]
kind = "gear"
ratio = 8.0
[drivetrain.stages.teeth]
module = "4 mm"
face_width = "50 mm"
pinion_teeth = 18                  # the smaller wheel; the other has ratio x as many
pressure_angle = "20 deg"
manufacture = "hobbed"             # "cast", "cut", "hobbed" or "ground" (Barth's K_v)
allowable_bending = "150 MPa"      # the root stress allowed (the design factor included)
allowable_contact = "600 MPa"      # the flank stress allowed
```

With ``method = "barth"`` or ``"buckingham"`` the teeth are also rated as forces, as the design books do: the
effective load (service factor × tangential load, with Barth's factor or Buckingham's dynamic increment) against
the beam strength m b σ_b Y (σ_b = ``allowable_bending``) and the wear strength b Q d_p K (K from
``surface_endurance``, ``bhn`` or ``load_stress_factor``), each with ``safety_factor``; Buckingham's method needs
``tooth_error`` and takes the deformation factor from the moduli (or ``deformation_factor``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np
from pydantic import Field, model_validator

from ..problem.fields import Angle, NonNegativeLength, PositiveLength, Pressure, Stress
from ..problem.schema import Spec
from ..results.labels import Label
from .gear_strength import (
    beam_strength,
    buckingham_increment,
    deformation_factor,
    load_stress_factor,
    load_stress_factor_from_hardness,
    wear_strength,
)
from .gear_teeth import contact_stress, elastic_coefficient, lewis_bending_stress, lewis_form_factor, velocity_factor


class GearTeethTable(Spec):
    """The teeth of a gear stage (spur, 20° full depth by default)."""

    module: PositiveLength
    face_width: PositiveLength
    pinion_teeth: int = Field(ge=12)
    pressure_angle: Angle = math.radians(20.0)
    manufacture: Literal["cast", "cut", "hobbed", "ground"] = "hobbed"
    allowable_bending: Stress | None = None
    allowable_contact: Stress | None = None
    elastic_modulus: Pressure = 207e9
    poisson: float = Field(0.3, ge=0.0, lt=0.5, allow_inf_nan=False)
    # the books' force rating: effective load against beam and wear strength
    method: Literal["lewis", "barth", "buckingham"] = "lewis"
    service_factor: float = Field(1.0, ge=1.0, allow_inf_nan=False)
    safety_factor: float = Field(1.0, ge=1.0, allow_inf_nan=False)
    tooth_error: NonNegativeLength | None = None
    deformation_factor: Pressure | None = None
    gear_elastic_modulus: Pressure | None = None      # None: elastic_modulus
    surface_endurance: Stress | None = None
    bhn: float | None = Field(None, gt=0.0, allow_inf_nan=False)
    load_stress_factor: Pressure | None = None

    @model_validator(mode="after")
    def _complete(self):
        problems = []
        wear = [k for k in ("surface_endurance", "bhn", "load_stress_factor") if getattr(self, k) is not None]
        if len(wear) > 1:
            problems.append(f"give one of surface_endurance, bhn and load_stress_factor; got {', '.join(wear)}")
        if self.method != "lewis" and self.allowable_bending is None:
            problems.append(f'method = "{self.method}" rates the beam strength m b σ_b Y with σ_b = '
                            "allowable_bending, which is missing")
        if self.method == "buckingham":
            if self.tooth_error is None:
                problems.append('method = "buckingham" needs tooth_error (the sum of both wheels\' errors)')
            degrees = round(math.degrees(self.pressure_angle), 3)
            if self.deformation_factor is None and degrees not in (14.5, 20.0):
                problems.append(f"Buckingham's deformation factor is tabulated for 14.5° and 20° teeth, not "
                                f"{degrees:g}°: give deformation_factor")
        if problems:
            raise ValueError("; ".join(problems))
        return self


@dataclass(frozen=True)
class GearStrength:
    """The books' force rating of a stage's teeth: the method ("barth" or "buckingham"), the effective load
    C_s W_t K_v or C_s W_t + P_d [N], the beam strength of the weaker wheel [N], the wear strength [N] (None
    without a surface input) and the factor of safety required."""

    method: str
    effective_load: float
    beam_strength: float
    wear_strength: float | None
    safety_factor: float

    @property
    def safety_bending(self) -> float:
        return self.beam_strength / self.effective_load if self.effective_load > 0 else math.inf

    @property
    def safety_wear(self) -> float | None:
        if self.wear_strength is None:
            return None
        return self.wear_strength / self.effective_load if self.effective_load > 0 else math.inf


@dataclass(frozen=True)
class GearCheck:
    """A gear stage's teeth under the peak torque: the stage's index, the pitch-line speed [m/s], Barth's K_v,
    the tangential load [N], the root bending stress of pinion and gear [Pa], the contact stress [Pa], and the
    allowable stresses [Pa] (None where not given)."""

    stage: int
    pitch_speed: float
    velocity_factor: float
    tangential_load: float
    pinion_bending: float
    gear_bending: float
    contact: float
    allowable_bending: float | None
    allowable_contact: float | None
    strength: GearStrength | None = None

    @property
    def utilisation(self) -> float | None:
        """The larger of root stress / allowable and contact stress / allowable (None: no allowable given)."""
        parts = []
        if self.allowable_bending is not None:
            parts.append(max(self.pinion_bending, self.gear_bending) / self.allowable_bending)
        if self.allowable_contact is not None:
            parts.append(self.contact / self.allowable_contact)
        if self.strength is not None:
            parts.append(self.strength.safety_factor / self.strength.safety_bending)
            if self.strength.safety_wear is not None:
                parts.append(self.strength.safety_factor / self.strength.safety_wear)
        return max(parts) if parts else None

    def failures(self) -> list[str]:
        out = []
        worst = max(self.pinion_bending, self.gear_bending)
        if self.allowable_bending is not None and worst > self.allowable_bending:
            out.append(f"gear stage {self.stage}: tooth root stress {worst / 1e6:.4g} MPa (Lewis) exceeds "
                       f"allowable_bending = {self.allowable_bending / 1e6:.4g} MPa")
        if self.allowable_contact is not None and self.contact > self.allowable_contact:
            out.append(f"gear stage {self.stage}: contact stress {self.contact / 1e6:.4g} MPa (Hertz) exceeds "
                       f"allowable_contact = {self.allowable_contact / 1e6:.4g} MPa")
        r = self.strength
        if r is not None:
            for name, strength, safety in (("beam", r.beam_strength, r.safety_bending),
                                           ("wear", r.wear_strength, r.safety_wear)):
                if strength is not None and safety is not None and safety < r.safety_factor:
                    out.append(f"gear stage {self.stage}: {name} strength {strength:.4g} N over the effective load "
                               f"{r.effective_load:.4g} N ({r.method}) is a factor of safety {safety:.3g}, "
                               f"below safety_factor = {r.safety_factor:g}")
        return out


def check_teeth(index: int, teeth: GearTeethTable, ratio: float, shaft_torques: np.ndarray, speed_ratios: Any,
                crank_speed: float) -> GearCheck:
    """The teeth of stage ``index`` (between shafts index and index + 1) under the largest |torque| of the shaft
    that carries the pinion (the input shaft for a reduction, ratio >= 1)."""
    pinion_shaft = index if ratio >= 1.0 else index + 1
    gear_ratio = ratio if ratio >= 1.0 else 1.0 / ratio
    pinion_diameter = teeth.module * teeth.pinion_teeth
    gear_teeth = teeth.pinion_teeth * gear_ratio
    torque = float(np.max(np.abs(shaft_torques[pinion_shaft])))
    load = torque / (0.5 * pinion_diameter)
    speed = abs(crank_speed) * float(speed_ratios[pinion_shaft]) * 0.5 * pinion_diameter
    args = (teeth.face_width, teeth.module)
    elastic = elastic_coefficient(teeth.elastic_modulus, teeth.poisson, teeth.elastic_modulus, teeth.poisson)
    strength = (None if teeth.method == "lewis"
                else rate_teeth(teeth, load, speed, pinion_diameter, gear_teeth))
    return GearCheck(
        index, speed, velocity_factor(speed, teeth.manufacture), load,
        lewis_bending_stress(load, *args, teeth.pinion_teeth, speed, teeth.manufacture),
        lewis_bending_stress(load, *args, gear_teeth, speed, teeth.manufacture),
        contact_stress(load, teeth.face_width, pinion_diameter, pinion_diameter * gear_ratio, speed,
                       pressure_angle=teeth.pressure_angle, manufacture=teeth.manufacture, elastic=elastic),
        teeth.allowable_bending, teeth.allowable_contact, strength)


def rate_teeth(teeth: GearTeethTable, load: float, speed: float, pinion_diameter: float,
               gear_teeth: float) -> GearStrength:
    """The books' force rating of the teeth under the tangential load ``load`` [N] at the pitch speed ``speed``
    [m/s]: Barth's C_s W_t K_v or Buckingham's C_s W_t + P_d against m b σ_b Y (the pinion's Y, the smaller, with
    one σ_b for both wheels) and b Q d_p K."""
    e_gear = teeth.gear_elastic_modulus or teeth.elastic_modulus
    if teeth.method == "buckingham":
        c = teeth.deformation_factor or deformation_factor(teeth.elastic_modulus, e_gear, teeth.pressure_angle)
        effective = teeth.service_factor * load + buckingham_increment(load, speed, teeth.face_width, c,
                                                                       teeth.tooth_error or 0.0)
    else:
        effective = teeth.service_factor * load * velocity_factor(speed, teeth.manufacture)
    beam = beam_strength(teeth.module, teeth.face_width, teeth.allowable_bending or 0.0,
                         lewis_form_factor(teeth.pinion_teeth))
    k = teeth.load_stress_factor
    if teeth.surface_endurance is not None:
        k = load_stress_factor(teeth.surface_endurance, teeth.elastic_modulus, e_gear, teeth.pressure_angle)
    elif teeth.bhn is not None:
        k = load_stress_factor_from_hardness(teeth.bhn)
    wear = (None if k is None
            else wear_strength(teeth.face_width, pinion_diameter, teeth.pinion_teeth, gear_teeth, k))
    return GearStrength(teeth.method, effective, beam, wear, teeth.safety_factor)


FIGURES = {"tangential_load": ("tangential load on the teeth at the peak torque", "N", None),
           "pitch_speed": ("pitch-line speed", "m/s", None),
           "pinion_bending_stress": ("pinion's tooth root stress (Lewis)", "Pa", "MPa"),
           "gear_bending_stress": ("gear's tooth root stress (Lewis)", "Pa", "MPa"),
           "contact_stress": ("contact stress of the flanks (Hertz)", "Pa", "MPa"),
           "utilisation": ("utilisation (stress / allowable, the larger)", "", None),
           "dynamic_load": ("effective (dynamic) load on the teeth", "N", None),
           "beam_strength": ("beam strength of a tooth (Lewis)", "N", None),
           "wear_strength": ("wear strength of the flanks (Buckingham)", "N", None),
           "safety_bending": ("factor of safety in bending (beam strength / load)", "", None),
           "safety_wear": ("factor of safety against pitting (wear strength / load)", "", None)}


def gear_results(checks: tuple[GearCheck, ...]) -> tuple[dict[str, float], dict[str, Label]]:
    """The results of every checked gear stage, keyed ``drivetrain.stage_<k>.<figure>``, and their labels."""
    scalars: dict[str, float] = {}
    labels: dict[str, Label] = {}
    for c in checks:
        values = {"tangential_load": c.tangential_load, "pitch_speed": c.pitch_speed,
                  "pinion_bending_stress": c.pinion_bending, "gear_bending_stress": c.gear_bending,
                  "contact_stress": c.contact}
        if c.utilisation is not None:
            values["utilisation"] = c.utilisation
        if c.strength is not None:
            values.update(dynamic_load=c.strength.effective_load, beam_strength=c.strength.beam_strength,
                          safety_bending=c.strength.safety_bending)
            if c.strength.wear_strength is not None and c.strength.safety_wear is not None:
                values.update(wear_strength=c.strength.wear_strength, safety_wear=c.strength.safety_wear)
            values = {k: v for k, v in values.items() if math.isfinite(v)}   # no load: no factor of safety
        for figure, value in values.items():
            text, unit, shown = FIGURES[figure]
            key = f"drivetrain.stage_{c.stage}.{figure}"
            scalars[key] = value
            labels[key] = Label(f"Drive train: gear stage {c.stage}, {text}", unit, shown)
    return scalars, labels
