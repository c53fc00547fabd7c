"""The single unit registry of machdyn and the helpers that parse and format quantities.

Units live at the boundary only: problem files and the command line say ``"45 mm"``, ``"21 rad/s"``,
``"300 rpm"``, ``"1.2 t/m^3"``; the core computes in SI floats and never imports pint.
"""

from __future__ import annotations

import unicodedata
from functools import lru_cache
from typing import Any

import pint

from .errors import InputError
from .quantity_text import QuantitySyntaxError, parse

ureg: pint.UnitRegistry = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
ureg.formatter.default_format = "~P"
Q_ = ureg.Quantity

#: The SI unit in which the core computes each physical kind of quantity.
SI_UNITS: dict[str, str] = {
    "length": "m",
    "mass": "kg",
    "time": "s",
    "angle": "rad",
    "angular_velocity": "rad/s",
    "angular_acceleration": "rad/s^2",
    "velocity": "m/s",
    "acceleration": "m/s^2",
    "force": "N",
    "moment": "N*m",
    "torque": "N*m",
    "power": "W",
    "energy": "J",
    "inertia": "kg*m^2",
    "stiffness": "N/m",
    "density": "kg/m^3",
    "mass_flow": "kg/s",
    "volume_flow": "m^3/s",
    "pressure": "Pa",
    "stress": "Pa",
    "frequency": "Hz",
    "dimensionless": "",
}


#: The longest quantity text read (``"1.2 t/m^3"`` needs a dozen characters); longer text is refused before it
#: is parsed. Quantities are parsed by a bounded grammar (:mod:`machdyn.quantity_text`), never evaluated.
MAX_QUANTITY_TEXT = 100

#: The largest magnitude accepted for any quantity, in SI units: no machine part is 1e12 m long or turns at
#: 1e12 rad/s, and larger numbers overflow the products the analyses form.
MAX_MAGNITUDE = 1e12


def _invisible(text: str) -> str | None:
    """The first control or formatting character of ``text`` (a right-to-left override, a zero-width
    space ...) written as U+XXXX, or None: such characters make a value read differently from what it is."""
    for ch in text:
        if unicodedata.category(ch) in ("Cc", "Cf") and ch not in " \t":
            return f"U+{ord(ch):04X}"
    return None


@lru_cache(maxsize=256)
def _unit(unit: str) -> pint.Unit:
    return ureg.Unit(unit)


def parse_quantity(value: str | float | int, unit: str, *, field: str = "value") -> float:
    """Convert ``value`` (a string such as ``"45 mm"`` or a bare number already in ``unit``) to a float in ``unit``.

    Raises :class:`~machdyn.errors.InputError` naming ``field`` when the text is not a quantity, when its
    dimension does not match ``unit`` (a mass given in mm), or when it is NaN or infinite. Conversion factors are
    pint's (SI brochure, BIPM, 9th edition).

    Parameters
    ----------
    value : str or float or int
        A quantity with its unit, e.g. ``"45 mm"``; a bare number only where ``unit`` is dimensionless.
    unit : str
        Target unit, e.g. ``"m"`` (``""`` for a pure number).
    field : str
        Name of the input, used in error messages.

    Returns
    -------
    float
        The magnitude in ``unit``, finite and within ``MAX_MAGNITUDE``.

    Examples
    --------
    >>> parse_quantity("45 mm", "m")
    0.045
    >>> round(parse_quantity("300 rpm", "rad/s"), 6)
    31.415927
    >>> parse_quantity("45 kg", "m", field="crank radius")
    Traceback (most recent call last):
        ...
    machdyn.errors.InputError: The crank radius must be in units of [length] (like m); got '45 kg', which is [mass].
    """
    target = _unit(unit) if unit else ureg.dimensionless
    if isinstance(value, bool):
        raise InputError(f"The {field} must be a quantity in {unit or 'no unit'}; got {value!r}.")
    if isinstance(value, int | float):
        magnitude = float(value)
        if target != ureg.dimensionless:
            raise InputError(
                f"The {field} needs a unit (e.g. \"{value} {_hint_unit(target, unit)}\"); got the bare number "
                f"{value!r}."
            )
    else:
        text = str(value)
        if len(text) > MAX_QUANTITY_TEXT:
            raise InputError(f"The {field} is not a quantity: its text has {len(text)} characters, more than the "
                             f"{MAX_QUANTITY_TEXT} a quantity such as \"45 mm\" needs.")
        hidden = _invisible(text)
        if hidden is not None:
            raise InputError(f"The {field} contains the invisible character {hidden}; write the quantity in plain "
                             f"text; got {value!r}.")
        quantity: Any = quantity_of_text(text, field=field)
        if _is_angle(target) and not dict(quantity.to_root_units().unit_items()):
            # pint converts any pure number to radians: "40" would silently be 40 rad, "40 %" 0.4 rad.
            number = text.strip() if quantity.unitless else f"{quantity.magnitude:g}"
            raise InputError(
                f"The {field} is an angle and needs its unit (a bare number could be degrees or radians): "
                f"write '{number} deg' (or '{number} rad'); got {value!r}."
            )
        try:
            magnitude = float(quantity.to(target).magnitude)
        except pint.DimensionalityError:
            raise InputError(
                f"The {field} must be in units of {'an angle' if _is_angle(target) else _describe(target)} "
                f"(like {unit}); "
                f"got {value!r}, which is {_describe(quantity.units)}."
            ) from None
    if magnitude != magnitude or magnitude in (float("inf"), float("-inf")):
        raise InputError(f"The {field} must be a finite number; got {value!r}.")
    if abs(magnitude) > MAX_MAGNITUDE:
        raise InputError(f"The {field} must be at most {MAX_MAGNITUDE:g} {unit or ''} in magnitude (larger values "
                         f"are not physical for a machine and overflow the analysis); got {value!r}.")
    return magnitude


def quantity_of_text(text: str, *, field: str = "value") -> pint.Quantity:
    """The pint quantity written in ``text``, parsed by the bounded grammar of :mod:`machdyn.quantity_text`
    (pint only looks up each unit name), so that any text is decided in well under a millisecond.

    Parameters
    ----------
    text : str
        A quantity such as ``"1.2 t/m^3"``.
    field : str
        Name of the input, used in error messages.

    Returns
    -------
    pint.Quantity
        The magnitude in the units written (not converted).

    Examples
    --------
    >>> quantity_of_text("1.2 t/m^3").to("kg/m^3").magnitude
    1200.0
    >>> quantity_of_text("10**6 N")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
        ...
    machdyn.errors.InputError: The value is not a quantity with a unit; got '10**6 N' (a number may not be ...
    """
    try:
        magnitude, factors = parse(text)
    except QuantitySyntaxError as exc:
        raise InputError(f"The {field} is not a quantity with a unit; got {_shown(text)} ({exc}).") from None
    return Q_(magnitude, _unit_of(factors, text, f"{field} is not a quantity with a unit"))


def unit_of_text(text: str, *, field: str = "unit") -> pint.Unit:
    """The pint unit written in ``text`` (``"kg*m^2"``), parsed like a quantity's unit; no number allowed.

    Parameters
    ----------
    text : str
        A unit such as ``"N*m*s/rad"`` (``""`` for a pure number).
    field : str
        Name of the input, used in error messages.

    Returns
    -------
    pint.Unit
        The unit.

    Examples
    --------
    >>> unit_of_text("kg*m^2") == ureg.kilogram * ureg.metre**2
    True
    """
    try:
        magnitude, factors = parse(text) if text.strip() else (1.0, ())
    except QuantitySyntaxError as exc:
        raise InputError(f"The {field} is not a unit; got {_shown(text)} ({exc}).") from None
    if magnitude != 1.0:
        raise InputError(f"The {field} must be a unit without a number; got {_shown(text)}.")
    return _unit_of(factors, text, f"{field} is not a unit")


def _unit_of(factors: tuple[tuple[str, float], ...], text: str, what: str) -> pint.Unit:
    unit = ureg.dimensionless
    for name, power in factors:
        try:
            factor = _unit(name)
        except Exception:  # noqa: BLE001 - pint raises several exception types for an unknown name
            raise InputError(f"The {what}; got {_shown(text)} (the unit '{name[:40]}' is unknown).") from None
        try:
            unit = unit * factor ** (int(power) if power == int(power) else power)
        except Exception as exc:  # noqa: BLE001 - e.g. an offset unit (degC) in a product
            raise InputError(f"The {what}; got {_shown(text)} ({exc}).") from None
    return unit


def _shown(text: str) -> str:
    """``text`` quoted for a message, cut to 60 characters."""
    return repr(text if len(text) <= 60 else text[:57] + "...")


@lru_cache(maxsize=64)
def _is_angle(unit: pint.Unit) -> bool:
    """True for an angle unit (radian, degree): pint counts angles as pure numbers, so they need their own test."""
    return unit != ureg.dimensionless and dict(ureg.Quantity(1.0, unit).to_root_units().unit_items()) == {
        "radian": 1}


def _hint_unit(target: pint.Unit, unit: str) -> str:
    return "deg" if _is_angle(target) else unit


def _describe(unit) -> str:
    dims = ureg.Unit(unit).dimensionality if not isinstance(unit, pint.Unit) else unit.dimensionality
    text = str(dims)
    return "a pure number" if text == "dimensionless" else text


def convert(value: float, from_unit: str, to_unit: str) -> float:
    """Convert a float between two units (used by reports to show SI results in the user's units).

    Parameters
    ----------
    value : float
        Magnitude in ``from_unit``.
    from_unit : str
        Unit of ``value``, e.g. ``"rad/s"``.
    to_unit : str
        Target unit of the same dimension, e.g. ``"rpm"``.

    Returns
    -------
    float
        The magnitude in ``to_unit``.

    Examples
    --------
    >>> round(convert(31.41592653589793, "rad/s", "rpm"), 6)
    300.0
    """
    return float(Q_(value, from_unit).to(to_unit).magnitude)


def format_quantity(value: float, unit: str, digits: int = 4) -> str:
    """Format ``value`` (already in ``unit``) with ``digits`` significant digits and its unit symbol.

    Parameters
    ----------
    value : float
        Magnitude in ``unit``.
    unit : str
        Unit of ``value`` (``""`` for a pure number).
    digits : int
        Significant digits [-].

    Returns
    -------
    str
        The value and its unit symbol.

    Examples
    --------
    >>> format_quantity(0.045, "m")
    '0.045 m'
    """
    symbol = f"{_unit(unit):~P}" if unit else ""
    return f"{value:.{digits}g} {symbol}".strip()
