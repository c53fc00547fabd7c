"""Standard tables of the screw-conveyor module, read from the CSV files in ``data/``.

Each table's source is in ``data/SOURCES.md``. Lookups by name raise :class:`~machdyn.errors.InputError`
naming the table and the value, with a "did you mean" when a close name exists.
"""

from __future__ import annotations

import csv
import difflib
import math
from functools import cache
from pathlib import Path

import numpy as np

from ..errors import InputError

DATA = Path(__file__).with_name("data")


@cache
def read_table(name: str) -> tuple[dict[str, str], ...]:
    """Rows of ``data/<name>.csv`` as dicts of strings (cached)."""
    with (DATA / f"{name}.csv").open(newline="", encoding="utf-8") as fh:
        return tuple(dict(row) for row in csv.DictReader(fh))


def _suggest(value: str, options: list[str]) -> str:
    close = difflib.get_close_matches(value, options, n=1)
    return f" Did you mean '{close[0]}'?" if close else ""


def lookup(name: str, key_column: str, key: str, value_column: str, *, what: str) -> float:
    """Value of ``value_column`` in the row of table ``name`` whose ``key_column`` is ``key``."""
    rows = read_table(name)
    options = [row[key_column] for row in rows]
    for row in rows:
        if row[key_column] == key:
            text = row[value_column]
            if text == "":
                raise InputError(f"The {what} '{key}' has no value for {value_column} (not recommended).")
            return float(text)
    raise InputError(
        f"The {what} must be one of {', '.join(options)}; got '{key}'.{_suggest(str(key), options)}"
    )


def standard_diameters() -> list[float]:
    """Nominal screw diameters [m], ascending (ISO 1050 / R10 series)."""
    return [float(row["diameter_mm"]) / 1000.0 for row in read_table("standard_diameters")]


def speed_coefficient(material_class: str) -> float:
    """Speed coefficient k in n = k/√D [rpm·m^0.5] of a material class (see ``speed_coefficient.csv``)."""
    return lookup("speed_coefficient", "material_class", material_class, "k_rpm_sqrt_m",
                  what="speed class")


def resistance_coefficient(group: str) -> float:
    """Progress resistance coefficient λ (ISO 7119) = C0 of the textbook method for a material group."""
    return lookup("resistance_coefficient", "material_group", group, "coefficient", what="material group")


def inclination_factor(inclination: float) -> float:
    """Capacity reduction factor C for an inclined screw, interpolated linearly in the table.

    inclination [rad], 0 ≤ β ≤ 20°. Source: Alexandrov, *Materials Handling Equipment* (Mir), screw
    conveyors; the same factors as seed 004 ("with β = 10° choose C = 0.8").
    """
    rows = read_table("inclination_factor")
    xs = [float(r["inclination_deg"]) for r in rows]
    ys = [float(r["factor"]) for r in rows]
    deg = math.degrees(inclination)
    if deg < 0 or deg > xs[-1] + 1e-9:
        raise InputError(
            f"The inclination factor table covers 0 to {xs[-1]:g} deg; got {deg:g} deg. "
            "Give screw.inclination_factor explicitly for steeper screws."
        )
    for x0, x1, y0, y1 in zip(xs, xs[1:], ys, ys[1:], strict=False):
        if x0 <= deg <= x1:
            return y0 + (y1 - y0) * (deg - x0) / (x1 - x0)
    return ys[-1]


def cema_diameter_factor(diameter: float) -> float:
    """CEMA 350 conveyor diameter factor Fd for a screw diameter [m].

    Tabulated for the inch sizes 4…24 in (``cema_diameter_factor.csv``); a metric size between two of
    them (e.g. 200 mm = 7.87 in) is interpolated linearly in diameter, which machdyn states in the report.
    """
    rows = read_table("cema_diameter_factor")
    xs = [float(r["diameter_in"]) for r in rows]
    ys = [float(r["Fd"]) for r in rows]
    inches = diameter / 0.0254
    if inches < xs[0] * 0.99 or inches > xs[-1] * 1.01:
        raise InputError(
            f"The CEMA diameter factor Fd is tabulated for {xs[0]:g} to {xs[-1]:g} in screws; got "
            f"{inches:.3g} in ({diameter * 1000:g} mm). Give cema.diameter_factor explicitly."
        )
    inches = min(max(inches, xs[0]), xs[-1])
    for x0, x1, y0, y1 in zip(xs, xs[1:], ys, ys[1:], strict=False):
        if x0 <= inches <= x1:
            return y0 + (y1 - y0) * (inches - x0) / (x1 - x0)
    return ys[-1]


#: A screw this close to a row of ``cema_standard_pipes.csv`` (relative) counts as that size (100 mm is 4 in).
PIPE_SIZE_TOLERANCE = 0.02


def standard_pipe_rows() -> tuple[np.ndarray, np.ndarray]:
    """Screw diameters [m] and their standard pipes' outer diameters [m] (``cema_standard_pipes.csv``)."""
    rows = read_table("cema_standard_pipes")
    return (np.array([float(r["screw_diameter_in"]) for r in rows]) * 0.0254,
            np.array([float(r["pipe_outer_diameter_in"]) for r in rows]) * 0.0254)


def standard_pipes(diameter):
    """The outer diameter [m] of the standard pipe of screws of ``diameter`` [m] (array), NaN beyond the table.

    CEMA 350's standard screw conveyor components (``cema_standard_pipes.csv``, see ``data/SOURCES.md``): the
    pipe of the row's size, or of the next size up for a diameter between two rows (a metric 200 mm = 7.87 in
    screw takes the 9 in screw's pipe); a diameter within 2 % of a row counts as that row.
    """
    sizes, pipes = standard_pipe_rows()
    d = np.asarray(diameter, dtype=float)
    i = np.searchsorted(sizes, d / (1.0 + PIPE_SIZE_TOLERANCE), side="left")
    inside = (d >= sizes[0] * (1.0 - PIPE_SIZE_TOLERANCE)) & (i < sizes.size)
    return np.where(inside, pipes[np.minimum(i, sizes.size - 1)], np.nan)


def standard_pipe(diameter: float) -> float:
    """:func:`standard_pipes` of one screw [m]; refused beyond the table, asking for the pipe."""
    return float(standard_pipe_row(diameter)["pipe_outer_diameter_in"]) * 0.0254


def standard_pipe_row(diameter: float) -> dict[str, str]:
    """The row of ``cema_standard_pipes.csv`` whose pipe a screw of ``diameter`` [m] takes (:func:`standard_pipes`);
    refused beyond the table, asking for the pipe."""
    sizes, _ = standard_pipe_rows()
    i = int(np.searchsorted(sizes, diameter / (1.0 + PIPE_SIZE_TOLERANCE), side="left"))
    if not (math.isfinite(diameter) and diameter >= sizes[0] * (1.0 - PIPE_SIZE_TOLERANCE) and i < sizes.size):
        sizes, _ = standard_pipe_rows()
        raise InputError(
            f"The screw diameter {diameter * 1000:.4g} mm ({diameter / 0.0254:.3g} in) is outside CEMA's standard "
            f"screw conveyor components ({sizes[0] / 0.0254:g} to {sizes[-1] / 0.0254:g} in), from which the pipe "
            "is taken when none is given: give screw.pipe_outer_diameter (and screw.pipe_wall).")
    return read_table("cema_standard_pipes")[i]


def cema_diameter_is_tabulated(diameter: float) -> bool:
    """True if ``diameter`` [m] is one of the CEMA inch sizes (within 1 %)."""
    inches = diameter / 0.0254
    return any(abs(float(r["diameter_in"]) - inches) <= 0.01 * inches for r in read_table("cema_diameter_factor"))


def cema_hanger_bearing_factor(bearing: str) -> float:
    """CEMA 350 hanger bearing factor Fb of a hanger bearing type."""
    return lookup("cema_hanger_bearing_factor", "bearing", bearing, "Fb", what="hanger bearing")


def cema_flight_factor(flight_type: str, loading: float) -> float:
    """CEMA 350 flight factor Ff for a flight type and trough loading (fraction; 15, 30, 45, 95 % columns).

    The loading is rounded up to the next tabulated column.
    """
    columns = [(0.15, "loading_15"), (0.30, "loading_30"), (0.45, "loading_45"), (0.95, "loading_95")]
    for limit, column in columns:
        if loading <= limit + 1e-9:
            return lookup("cema_flight_factor", "flight_type", flight_type, column, what="flight type")
    raise InputError(f"The trough loading for the CEMA flight factor must be <= 0.95; got {loading:g}.")


def cema_paddle_factor(paddles: int) -> float:
    """CEMA 350 paddle factor Fp for 0…4 paddles per pitch."""
    return lookup("cema_paddle_factor", "paddles_per_pitch", str(int(paddles)), "Fp",
                  what="number of paddles per pitch")


def cema_overload_factor(horsepower):
    """CEMA 350 overload factor Fo for (HPf + HPm) [hp] (a float or an array).

    The CEMA chart is a straight line on a log scale of horsepower from Fo = 3.0 at 0.2 hp to Fo = 1.0 at
    5.2 hp; Fo = 3.0 below 0.2 hp and 1.0 from 5.2 hp on. The end points are in ``cema_overload_factor.csv``.
    """
    rows = read_table("cema_overload_factor")
    (h0, f0), (h1, f1) = ((float(r["horsepower"]), float(r["Fo"])) for r in rows)
    hp = np.clip(np.asarray(horsepower, dtype=float), h0, h1)
    fo = f0 + (f1 - f0) * np.log(hp / h0) / math.log(h1 / h0)
    return float(fo) if fo.ndim == 0 else fo


def cema_diameter_factors(diameter):
    """:func:`cema_diameter_factor` of an array of diameters [m] (NaN outside the tabulated 4…24 in)."""
    rows = read_table("cema_diameter_factor")
    xs = np.array([float(r["diameter_in"]) for r in rows])
    ys = np.array([float(r["Fd"]) for r in rows])
    inches = np.asarray(diameter, dtype=float) / 0.0254
    inside = (inches >= xs[0] * 0.99) & (inches <= xs[-1] * 1.01)
    return np.where(inside, np.interp(inches, xs, ys), np.nan)


def cema_flight_factors(flight_type: str, loading):
    """:func:`cema_flight_factor` of an array of loadings (NaN where the table has no value)."""
    row = next((r for r in read_table("cema_flight_factor") if r["flight_type"] == flight_type), None)
    if row is None:
        cema_flight_factor(flight_type, 0.1)  # raises with the list of types
    assert row is not None
    cols = [(0.15, "loading_15"), (0.30, "loading_30"), (0.45, "loading_45"), (0.95, "loading_95")]
    values = [float(row[c]) if row[c] else np.nan for _, c in cols]
    load = np.asarray(loading, dtype=float)
    out = np.full(load.shape, np.nan)
    for (limit, _), value in reversed(list(zip(cols, values, strict=True))):
        out = np.where(load <= limit + 1e-9, value, out)
    return out


def cema_material_factor(material: str) -> float:
    """CEMA 350 material factor Fm of a listed material."""
    return lookup("cema_materials", "material", material, "Fm", what="CEMA material")


def drive_efficiency(drive: str) -> float:
    """Typical overall efficiency of a drive arrangement (``drive_efficiency.csv``)."""
    return lookup("drive_efficiency", "drive", drive, "efficiency", what="drive")


def metric_bolts() -> list[tuple[str, float]]:
    """ISO metric coarse bolts as (designation, minor diameter d3 [m]), ascending."""
    return [(r["designation"], float(r["minor_d3_mm"]) / 1000.0) for r in read_table("iso_metric_bolts")]
