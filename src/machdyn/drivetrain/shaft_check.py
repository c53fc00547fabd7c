"""``[[drivetrain.shafts]]``: a shaft of the drive train checked at the wheel that bends it — DE fatigue factor of
safety under its torque over the cycle and the wheel's transverse force, its deflection there, and its first
critical speed against its running speed.

```toml
[[drivetrain.shafts]]
shaft = 1                          # the index of the train's shaft (0: motor)
diameter = "60 mm"
span = "400 mm"                    # between its two bearings (simply supported)
wheel_at = "120 mm"                # the gear or pulley whose force bends it, from a bearing
wheel_radius = "50 mm"             # its pitch radius: transverse force = force_factor x |T| / radius
force_factor = 1.064               # 1/cos 20 deg for a spur gear; about 1.5 to 2 for a V-belt
masses = ["40 kg", "15 kg"]        # wheels on it, for the critical speed
mass_at = ["120 mm", "300 mm"]
ultimate_strength = "700 MPa"
yield_strength = "500 MPa"
endurance_limit = "200 MPa"        # Se of the shaft, Marin factors applied
notch_factor = 1.7                 # K_f in bending at the wheel's seat (shoulder, keyway)
shear_notch_factor = 1.5           # K_fs in torsion
criterion = "goodman"              # DE-Goodman; or "gerber", "asme_elliptic", "soderberg"
min_safety = 1.5
critical_margin = 1.25             # the running speed must stay below (first critical speed)/margin
```
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np
from pydantic import Field, model_validator

from ..problem.fields import Density, Mass, PositiveLength, Pressure, Stress
from ..problem.schema import Spec
from ..results.labels import Label
from .shaft_design import critical_speeds, influence, section_stresses, shaft_safety, uniform_shaft_speed


class ShaftTable(Spec):
    """One shaft of ``[drivetrain]`` to check."""

    shaft: int = Field(ge=0)
    diameter: PositiveLength
    span: PositiveLength
    wheel_at: PositiveLength
    wheel_radius: PositiveLength
    force_factor: float = Field(1.064, ge=1.0, allow_inf_nan=False)
    masses: list[Mass] = []
    mass_at: list[PositiveLength] = []
    ultimate_strength: Stress
    yield_strength: Stress | None = None
    endurance_limit: Stress
    notch_factor: float = Field(1.0, ge=1.0, allow_inf_nan=False)
    shear_notch_factor: float = Field(1.0, ge=1.0, allow_inf_nan=False)
    criterion: Literal["goodman", "gerber", "asme_elliptic", "soderberg"] = "goodman"
    min_safety: float = Field(1.5, gt=0.0, allow_inf_nan=False)
    critical_margin: float = Field(1.25, ge=1.0, allow_inf_nan=False)
    elastic_modulus: Pressure = 207e9
    density: Density = 7850.0

    @model_validator(mode="after")
    def _consistent(self):
        if not self.wheel_at < self.span:
            raise ValueError(f"wheel_at {self.wheel_at:g} m must lie between the bearings (span {self.span:g} m)")
        if len(self.masses) != len(self.mass_at):
            raise ValueError(f"masses ({len(self.masses)}) and mass_at ({len(self.mass_at)}) must pair up")
        outside = [x for x in self.mass_at if not x < self.span]
        if outside:
            raise ValueError(f"mass_at must lie between the bearings (span {self.span:g} m); got {outside}")
        if self.criterion in ("soderberg", "asme_elliptic") and self.yield_strength is None:
            raise ValueError(f"the {self.criterion} criterion needs yield_strength")
        if not self.endurance_limit < self.ultimate_strength:
            raise ValueError("endurance_limit must be below ultimate_strength")
        return self


@dataclass(frozen=True)
class ShaftCheck:
    """A checked shaft: its index, the bending moment at the wheel [N·m] (fully reversed as the shaft turns), the
    torque's amplitude and mean [N·m], the fatigue and yield factors of safety, the deflection at the wheel [m],
    the first critical speed (Rayleigh, Dunkerley) and the running speed [rad/s]."""

    shaft: int
    moment: float
    torque_amplitude: float
    torque_mean: float
    fatigue_safety: float
    yield_safety: float
    deflection: float
    critical_rayleigh: float
    critical_dunkerley: float
    running_speed: float
    min_safety: float
    critical_margin: float

    @property
    def utilisation(self) -> float:
        """The larger of min_safety / n and (running speed × margin) / critical speed (1: at the limit)."""
        n = min(self.fatigue_safety, self.yield_safety)
        return max(self.min_safety / n if n > 0 else math.inf,
                   self.running_speed * self.critical_margin / self.critical_dunkerley)

    def failures(self) -> list[str]:
        out = []
        n = min(self.fatigue_safety, self.yield_safety)
        if n < self.min_safety:
            out.append(f"shaft {self.shaft}: factor of safety {n:.3g} at the wheel is below min_safety = "
                       f"{self.min_safety:g}")
        if self.running_speed * self.critical_margin > self.critical_dunkerley:
            out.append(f"shaft {self.shaft}: it runs at {self.running_speed * 30 / math.pi:.4g} rpm, too close to its "
                       f"first critical speed {self.critical_dunkerley * 30 / math.pi:.4g} rpm (Dunkerley) for "
                       f"critical_margin = {self.critical_margin:g}")
        return out


def check_shaft(table: ShaftTable, torque: np.ndarray, running_speed: float) -> ShaftCheck:
    """The shaft of ``table`` under the torque history of its shaft [N·m] at ``running_speed`` [rad/s]."""
    t = np.asarray(torque, dtype=float)
    amplitude, mean = 0.5 * float(t.max() - t.min()), 0.5 * float(t.max() + t.min())
    force = table.force_factor * float(np.max(np.abs(t))) / table.wheel_radius
    a, b = table.wheel_at, table.span - table.wheel_at
    moment = force * a * b / table.span
    stiffness = table.elastic_modulus * math.pi * table.diameter**4 / 64.0
    bending, torsion = (moment, 0.0), (amplitude, abs(mean))
    amp, mid = section_stresses(table.diameter, bending, torsion, table.notch_factor, table.shear_notch_factor)
    if amp + mid >= table.ultimate_strength:  # broken in the first cycle: a failed check, not a fatigue factor
        fatigue = yielding = table.ultimate_strength / (amp + mid)
    else:
        safety = shaft_safety(table.diameter, bending, torsion, table.endurance_limit, table.ultimate_strength,
                              table.yield_strength, kf=table.notch_factor, kfs=table.shear_notch_factor,
                              criterion=table.criterion)
        fatigue, yielding = safety.fatigue, safety.yielding
    deflection = force * influence(table.span, stiffness, a, a)
    per_length = table.density * math.pi * table.diameter**2 / 4.0
    if table.masses:
        rayleigh, dunkerley, _exact = critical_speeds(table.span, stiffness, table.masses, table.mass_at, per_length)
    else:  # the bare shaft: Rayleigh and Dunkerley are its own closed form
        rayleigh = dunkerley = uniform_shaft_speed(table.span, stiffness, per_length)
    return ShaftCheck(table.shaft, moment, amplitude, mean, fatigue, yielding, deflection, rayleigh,
                      dunkerley, abs(running_speed), table.min_safety, table.critical_margin)


FIGURES = {"bending_moment": ("bending moment at the wheel", "N*m", None),
           "fatigue_safety": ("DE fatigue factor of safety at the wheel", "", None),
           "deflection": ("deflection at the wheel", "m", "mm"),
           "critical_speed": ("first critical speed (Dunkerley, a lower bound)", "rad/s", "rpm"),
           "critical_speed_rayleigh": ("first critical speed (Rayleigh, an upper bound)", "rad/s", "rpm"),
           "utilisation": ("utilisation (min_safety / n, or speed x margin / critical speed)", "", None)}


def shaft_results(checks: tuple[ShaftCheck, ...]) -> tuple[dict[str, float], dict[str, Label]]:
    """Results keyed ``drivetrain.shaft_<k>.<figure>`` and their labels (a factor of safety only where finite)."""
    scalars: dict[str, float] = {}
    labels: dict[str, Label] = {}
    for c in checks:
        values = {"bending_moment": c.moment, "fatigue_safety": c.fatigue_safety, "deflection": c.deflection,
                  "critical_speed": c.critical_dunkerley, "critical_speed_rayleigh": c.critical_rayleigh,
                  "utilisation": c.utilisation}
        for figure, value in values.items():
            if not math.isfinite(value):  # an unloaded shaft has no finite factor of safety: no key
                continue
            text, unit, shown = FIGURES[figure]
            key = f"drivetrain.shaft_{c.shaft}.{figure}"
            scalars[key] = value
            labels[key] = Label(f"Drive train: shaft {c.shaft}, {text}", unit, shown)
    return scalars, labels
