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
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np
from pydantic import Field

from ..problem.fields import Angle, PositiveLength, Pressure, Stress
from ..problem.schema import Spec
from ..results.labels import Label
from .gear_teeth import contact_stress, elastic_coefficient, lewis_bending_stress, velocity_factor


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

    @property
    def utilisation(self) -> float | None:
        """The larger of root stress / allowable and contact stress / allowable (None: no allowable given)."""
        parts = []
        if self.allowable_bending is not None:
            parts.append(max(self.pinion_bending, self.gear_bending) / self.allowable_bending)
        if self.allowable_contact is not None:
            parts.append(self.contact / self.allowable_contact)
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
    return GearCheck(
        index, speed, velocity_factor(speed, teeth.manufacture), load,
        lewis_bending_stress(load, *args, teeth.pinion_teeth, speed, teeth.manufacture),
        lewis_bending_stress(load, *args, gear_teeth, speed, teeth.manufacture),
        contact_stress(load, teeth.face_width, pinion_diameter, pinion_diameter * gear_ratio, speed,
                       pressure_angle=teeth.pressure_angle, manufacture=teeth.manufacture, elastic=elastic),
        teeth.allowable_bending, teeth.allowable_contact)


FIGURES = {"tangential_load": ("tangential load on the teeth at the peak torque", "N", None),
           "pitch_speed": ("pitch-line speed", "m/s", None),
           "pinion_bending_stress": ("pinion's tooth root stress (Lewis)", "Pa", "MPa"),
           "gear_bending_stress": ("gear's tooth root stress (Lewis)", "Pa", "MPa"),
           "contact_stress": ("contact stress of the flanks (Hertz)", "Pa", "MPa"),
           "utilisation": ("utilisation (stress / allowable, the larger)", "", None)}


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
        for figure, value in values.items():
            text, unit, shown = FIGURES[figure]
            key = f"drivetrain.stage_{c.stage}.{figure}"
            scalars[key] = value
            labels[key] = Label(f"Drive train: gear stage {c.stage}, {text}", unit, shown)
    return scalars, labels
