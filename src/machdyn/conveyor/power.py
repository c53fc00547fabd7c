"""Drive power of a screw conveyor by method: seed 004's textbook form, ISO 7119 and CEMA 350.

SI in and out: mass flow [kg/s], lengths [m], power [W]. The textbook and ISO forms are usually printed
in t/h and kW; the conversions are done here, once.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..constants import STANDARD_GRAVITY
from ..errors import InputError
from . import tables

G = STANDARD_GRAVITY  # [m/s²]
HP = 745.69987158227022  # mechanical horsepower [W]
_LB = 0.45359237  # [kg]
_FT = 0.3048  # [m]

#: ISO 7119 applies to horizontal and inclined screws up to this inclination [rad].
ISO7119_MAX_INCLINATION = math.radians(20.0)


def power_textbook_360(mass_flow: float, length: float, lift: float, resistance: float) -> float:
    """Shaft power by the textbook rule as printed in seed 004, eqs 2.81-2.82 [W].

    P = Q·H/360 + C0·Q·L/360 [kW] with Q in t/h, L and H in m, i.e. g taken as 10 m/s². The paper defines L as
    the *horizontal* length but substitutes the inclined length (21 m); pass whichever is intended.

    Parameters
    ----------
    mass_flow : float or array
        Throughput [kg/s].
    length : float
        L [m].
    lift : float
        H [m] (H = L·sin β).
    resistance : float
        C0 [-] (2.5 for salt).

    Returns
    -------
    float or array
        P [W].

    Examples
    --------
    >>> round(power_textbook_360(2.0, 21.0, 3.65, 2.5), 1)  # seed 004: 1.123 kW
    1123.0
    """
    q_th = mass_flow * 3.6
    return 1000.0 * (q_th * lift / 360.0 + resistance * q_th * length / 360.0)


def power_textbook_367(mass_flow: float, length: float, lift: float, resistance: float) -> float:
    """Shaft power by the usual textbook form P = Q·(C0·L + H)/367 [kW] (Q in t/h; 367 = 3600/g), in W.

    Source: Alexandrov, *Materials Handling Equipment* (Mir), screw conveyors (N = Q·(C0·L + H)/367). Equal to
    m·g·(C0·L + H) in SI.

    Parameters
    ----------
    mass_flow : float or array
        Throughput m [kg/s].
    length : float
        L [m].
    lift : float
        H [m].
    resistance : float
        C0 [-].

    Returns
    -------
    float or array
        P [W].

    Examples
    --------
    >>> round(power_textbook_367(25.447 / 3.6, 5.0, 0.3, 4.0) / 1000, 4)  # Alexandrov: 1.408 kW with the rounded 367
    1.4072
    """
    return mass_flow * G * (resistance * length + lift)


@dataclass(frozen=True)
class Iso7119Power:
    """ISO 7119 drive power and its three parts [W]."""

    progress: float  # P_H
    no_load: float  # P_N
    inclination: float  # P_st

    @property
    def total(self) -> float:
        return self.progress + self.no_load + self.inclination


def power_iso7119(mass_flow: float, length: float, inclination: float, diameter: float,
                  progress_resistance: float) -> Iso7119Power:
    """Drive power at the screw shaft by ISO 7119:1981, P = P_H + P_N + P_st.

    P_H = I_m·L·λ·g/3600 [kW] (I_m in t/h) → m·L·λ·g [W], the progress of the material;
    P_N = D·L/20 [kW] → 50·D·L [W], the screw running empty (D, L in m);
    P_st = I_m·H·g/3600 [kW], H = L·sin β → m·g·H [W], the lift (negative for a descending screw).

    Parameters
    ----------
    mass_flow : float or array
        m [kg/s].
    length : float
        Conveyor length L [m].
    inclination : float
        β [rad], |β| <= 20° (the standard excludes steeper and vertical screws).
    diameter : float or array
        Nominal diameter D [m].
    progress_resistance : float
        λ [-], about 1.2…4 (``data/resistance_coefficient.csv``).

    Returns
    -------
    Iso7119Power
        The three parts [W] and their total.

    Examples
    --------
    >>> r = power_iso7119(2.0, 21.0, 0.0, 0.2, 2.5)
    >>> round(r.progress, 3), round(r.no_load, 3), round(r.total, 3)
    (1029.698, 210.0, 1239.698)
    """
    if abs(inclination) > ISO7119_MAX_INCLINATION + 1e-12:
        raise InputError(
            f"ISO 7119 applies to inclinations up to 20 deg; got {math.degrees(inclination):.4g} deg."
        )
    lift = length * math.sin(inclination)
    return Iso7119Power(
        progress=mass_flow * length * progress_resistance * G,
        no_load=1000.0 * diameter * length / 20.0,
        inclination=mass_flow * G * lift,
    )


@dataclass(frozen=True)
class CemaPower:
    """CEMA 350 horsepower method, all in horsepower [hp] except ``total_watts``."""

    friction_hp: float  # HPf
    material_hp: float  # HPm
    lift_hp: float
    overload_factor: float  # Fo
    efficiency: float  # e
    total_hp: float

    @property
    def total_watts(self) -> float:
        return self.total_hp * HP

    @property
    def shaft_hp(self) -> float:
        """(HPf + HPm + lift)·Fo, before drive losses [hp]."""
        return self.total_hp * self.efficiency


def cema_friction_hp(length: float, speed: float, diameter_factor: float,
                     hanger_bearing_factor: float) -> float:
    """CEMA 350 friction horsepower HPf = L·N·Fd·Fb/1 000 000 [hp].

    length L [m] (converted to ft), speed ω [rad/s] (converted to N [rpm], the unit of the formula),
    diameter_factor Fd [-], hanger_bearing_factor Fb [-].
    Source: CEMA 350 *Screw Conveyors for Bulk Materials*, horsepower requirements.
    """
    return (length / _FT) * (speed * 30.0 / math.pi) * diameter_factor * hanger_bearing_factor / 1.0e6


def cema_material_hp(volume_flow: float, bulk_density: float, length: float, flight_factor: float,
                     material_factor: float, paddle_factor: float = 1.0) -> float:
    """CEMA 350 material horsepower HPm = C·L·W·Ff·Fm·Fp/1 000 000 [hp].

    volume_flow [m³/s] (→ C in ft³/h), bulk_density [kg/m³] (→ W in lb/ft³), length [m] (→ L in ft),
    flight_factor Ff, material_factor Fm, paddle_factor Fp [-].
    """
    c = volume_flow * 3600.0 / _FT**3
    w = bulk_density * _FT**3 / _LB
    return c * (length / _FT) * w * flight_factor * material_factor * paddle_factor / 1.0e6


def power_cema(*, volume_flow: float, bulk_density: float, length: float, speed: float,
               diameter_factor: float, hanger_bearing_factor: float, material_factor: float,
               flight_factor: float = 1.0, paddle_factor: float = 1.0, efficiency: float = 1.0,
               lift: float = 0.0) -> CemaPower:
    """CEMA 350 total horsepower (HPf + HPm + HP_lift)·Fo/e.

    HPf and HPm as in :func:`cema_friction_hp` and :func:`cema_material_hp`; Fo from the CEMA overload chart
    for HPf + HPm + HP_lift < 5.2 hp (:func:`tables.cema_overload_factor`); e the drive efficiency. CEMA's
    equations are for horizontal conveyors; for an inclined screw the lift power m·g·H is added before the
    overload factor (machdyn's choice, stated in the report).

    Parameters
    ----------
    volume_flow : float or array
        [m³/s].
    bulk_density : float
        [kg/m³].
    length : float
        L [m].
    speed : float or array
        ω [rad/s] (N = 30ω/π [rpm] in CEMA's formula).
    diameter_factor, hanger_bearing_factor, material_factor : float or array
        Fd, Fb, Fm [-] (CEMA 350 tables).
    flight_factor, paddle_factor : float or array
        Ff, Fp [-].
    efficiency : float
        e [-], 0 < e <= 1.
    lift : float
        H [m].

    Returns
    -------
    CemaPower
        Parts and total [hp]; ``total_watts`` [W].

    Examples
    --------
    >>> r = power_cema(volume_flow=0.01, bulk_density=800.0, length=10.0, speed=50 * math.pi / 30,
    ...                diameter_factor=55.0,
    ...                hanger_bearing_factor=1.7, material_factor=0.5)
    >>> round(float(r.total_hp), 4)
    2.2736
    """
    if not 0.0 < efficiency <= 1.0:
        raise InputError(f"The drive efficiency must be in (0, 1]; got {efficiency:g}.")
    hpf = cema_friction_hp(length, speed, diameter_factor, hanger_bearing_factor)
    hpm = cema_material_hp(volume_flow, bulk_density, length, flight_factor, material_factor, paddle_factor)
    hpl = volume_flow * bulk_density * G * lift / HP
    fo = tables.cema_overload_factor(hpf + hpm + hpl)
    total = (hpf + hpm + hpl) * fo / efficiency
    return CemaPower(hpf, hpm, hpl, fo, efficiency, total)


@dataclass(frozen=True)
class PowerResult:
    """One method's shaft power (before drive losses) [W], with its parts for the report."""

    method: str
    label: str
    shaft_power: float
    parts: dict[str, float] = field(default_factory=dict)  # name -> W
    note: str = ""


METHODS = ("textbook_360", "textbook_367", "iso7119", "cema")
LABELS = {
    "textbook_360": "Seed 004 textbook rule (as printed, /360)",
    "textbook_367": "Textbook rule Q(C0·L+H)/367",
    "iso7119": "ISO 7119 (P_H + P_N + P_st)",
    "cema": "CEMA 350 horsepower method",
}
