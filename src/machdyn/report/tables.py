"""Linkage results as pandas DataFrames (one per time-series group) and as scalars with units.

Every frame has one row per crank angle; its first column is ``"crank_angle [deg]"`` and every column
header carries its unit in square brackets, e.g. ``"rocker.omega [rad/s]"``. For a mechanism with N design
variants the frames are in long form: a leading ``"design"`` column (0 .. N-1) and, for each design, one row
per crank angle (design-major order), so ``frame.groupby("design")`` gives the per-design tables.

:func:`analysis_scalars` gives every scalar result as ``{"value": float, "unit": str}``; for N design
variants ``value`` is a list of N floats (one per design).
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import numpy as np
import pandas as pd

from ..linkage import model as _model
from ..linkage.averages import time_mean, time_rms

ANGLE_COLUMN = "crank_angle [deg]"
DESIGN_COLUMN = "design"

GROUPS = ("motion", "joint_forces", "torque_power", "shaking", "energy")


# ------------------------------------------------------------------------------------------------ helpers


def mechanism_of(analysis: Any) -> _model.Mechanism | None:
    """The :class:`~machdyn.linkage.model.Mechanism` an analysis (or its kinematics) was computed for."""
    for obj in (analysis, getattr(analysis, "kinematics", None), getattr(analysis, "forces", None)):
        if obj is None:
            continue
        for attr in ("mechanism", "mech"):
            mech = getattr(obj, attr, None)
            if isinstance(mech, _model.Mechanism):
                return mech
    return None


def design_count(analysis: Any) -> int | None:
    """N for results of shape (N, M), None for a single design (shape (M,))."""
    torque = np.asarray(analysis.forces.driving_torque)
    return int(torque.shape[0]) if torque.ndim == 2 else None


class _Builder:
    """Collects columns of shape (M,) or (N, M) and lays them out as a long-form frame."""

    def __init__(self, crank_angle: np.ndarray, designs: int | None):
        self.angle = np.asarray(crank_angle, dtype=float).ravel()
        self.designs = designs
        self.columns: dict[str, np.ndarray] = {}

    @property
    def shape(self) -> tuple[int, ...]:
        m = self.angle.size
        return (m,) if self.designs is None else (self.designs, m)

    def add(self, name: str, unit: str, values: Any) -> None:
        arr = np.broadcast_to(np.asarray(values, dtype=float), self.shape)
        self.columns[f"{name} [{unit}]"] = arr.ravel()

    def frame(self) -> pd.DataFrame:
        data: dict[str, np.ndarray] = {}
        if self.designs is None:
            data[ANGLE_COLUMN] = np.degrees(self.angle)
        else:
            data[DESIGN_COLUMN] = np.repeat(np.arange(self.designs), self.angle.size)
            data[ANGLE_COLUMN] = np.tile(np.degrees(self.angle), self.designs)
        data.update(self.columns)
        return pd.DataFrame(data)


def _slider_bodies(mech: _model.Mechanism) -> list[str]:
    """Bodies that slide along a guide (the slide coordinate is reported for them)."""
    out: list[str] = []
    for d in mech.dyads:
        if isinstance(d, _model.RRP):
            out.append(d.b)
        elif isinstance(d, _model.RPR):
            out.append(d.a)
        elif isinstance(d, _model.PRP):
            out += [d.a, d.b]
    return out


def joint_list(forces: Any) -> list[tuple[str, str, str, str]]:
    """The joints of a kinetostatic result as (name, kind 'R'/'P', earlier body, later body) tuples."""
    out = []
    for j in forces.joints:
        if hasattr(j, "name"):
            out.append((j.name, j.kind, j.body_1, j.body_2))
        else:
            name, kind, body_1, body_2 = j
            out.append((name, kind, body_1, body_2))
    return out


def motion_points(mech: _model.Mechanism, kinematics: Any) -> list[str]:
    """Every distinct point of the moving bodies as ``"body.point"``; a joint shared by two bodies (same
    name, same position) is listed once, under the body placed first."""
    seen: dict[str, Any] = {}
    out: list[str] = []
    for body in mech.moving_bodies:
        for point in mech.body(body).points:
            ref = f"{body}.{point}"
            motion = kinematics.point(ref)
            if point in seen:
                prev = seen[point]
                if np.allclose(prev.x, motion.x, equal_nan=True) and np.allclose(
                    prev.y, motion.y, equal_nan=True
                ):
                    continue
            seen.setdefault(point, motion)
            out.append(ref)
    return out


# ------------------------------------------------------------------------------------------------- frames


def motion_frame(kinematics: Any, mechanism: _model.Mechanism, designs: int | None = None) -> pd.DataFrame:
    """Body angles, angular velocities and accelerations; slide coordinates of sliders; x/y, velocity and
    acceleration of every point of the moving bodies."""
    b = _Builder(kinematics.crank_angle, designs)
    for body in mechanism.moving_bodies:
        motion = kinematics.body(body)
        b.add(f"{body}.angle", "deg", np.degrees(motion.angle))
        b.add(f"{body}.omega", "rad/s", motion.omega)
        b.add(f"{body}.alpha", "rad/s^2", motion.alpha)
    for body in _slider_bodies(mechanism):
        slide = kinematics.slide(body)
        b.add(f"{body}.slide", "m", slide.s)
        b.add(f"{body}.slide_velocity", "m/s", slide.v)
        b.add(f"{body}.slide_acceleration", "m/s^2", slide.a)
    for ref in motion_points(mechanism, kinematics):
        p = kinematics.point(ref)
        b.add(f"{ref}.x", "m", p.x)
        b.add(f"{ref}.y", "m", p.y)
        b.add(f"{ref}.vx", "m/s", p.vx)
        b.add(f"{ref}.vy", "m/s", p.vy)
        b.add(f"{ref}.v", "m/s", p.speed)
        b.add(f"{ref}.ax", "m/s^2", p.ax)
        b.add(f"{ref}.ay", "m/s^2", p.ay)
        b.add(f"{ref}.a", "m/s^2", p.accel)
    return b.frame()


def joint_forces_frame(forces: Any, designs: int | None = None) -> pd.DataFrame:
    """The reaction of every joint: the force on the later body from the earlier one (x, y, magnitude) and,
    for prismatic joints, the normal force along the guide's left normal and the couple."""
    b = _Builder(forces.kinematics.crank_angle, designs)
    for name, kind, _body1, _body2 in joint_list(forces):
        r = forces.joint(name)
        b.add(f"{name}.fx", "N", r.fx)
        b.add(f"{name}.fy", "N", r.fy)
        b.add(f"{name}.magnitude", "N", r.magnitude)
        if kind == "P":
            if r.normal is not None:
                b.add(f"{name}.normal", "N", r.normal)
            if r.couple is not None:
                b.add(f"{name}.couple", "N*m", r.couple)
    return b.frame()


def torque_power_frame(forces: Any, designs: int | None = None, energy: Any = None) -> pd.DataFrame:
    """Crank speed, driving torque and input power (and the torque from the energy balance if given)."""
    kin = forces.kinematics
    b = _Builder(kin.crank_angle, designs)
    b.add("crank_speed", "rad/s", kin.speed)
    b.add("driving_torque", "N*m", forces.driving_torque)
    b.add("input_power", "W", forces.input_power)
    if energy is not None:
        b.add("torque_from_energy", "N*m", energy.input_torque_from_energy)
    return b.frame()


def shaking_frame(
    forces: Any, designs: int | None = None, about: tuple[float, float] = (0.0, 0.0)
) -> pd.DataFrame:
    """The frame (shaking) force components and magnitude, and the shaking moment about ``about``."""
    b = _Builder(forces.kinematics.crank_angle, designs)
    fx, fy = forces.frame_force
    b.add("shaking_force.fx", "N", fx)
    b.add("shaking_force.fy", "N", fy)
    b.add("shaking_force.magnitude", "N", np.hypot(fx, fy))
    b.add("shaking_moment", "N*m", forces.shaking_moment(about=about))
    return b.frame()


def energy_frame(energy: Any, crank_angle: np.ndarray, designs: int | None = None) -> pd.DataFrame:
    """Kinetic energy per body and total, potential energies, total energy, reduced inertia and moment."""
    b = _Builder(crank_angle, designs)
    for name, values in energy.kinetic.items():
        b.add(f"kinetic.{name}", "J", values)
    b.add("kinetic_total", "J", energy.kinetic_total)
    b.add("potential_gravity", "J", energy.potential_gravity)
    b.add("potential_spring", "J", energy.potential_spring)
    b.add("total", "J", energy.total)
    b.add("reduced_inertia", "kg*m^2", energy.reduced_inertia)
    b.add("reduced_moment", "N*m", energy.reduced_moment)
    b.add("input_torque_from_energy", "N*m", energy.input_torque_from_energy)
    return b.frame()


def analysis_frames(analysis: Any, mechanism: _model.Mechanism | None = None) -> dict[str, pd.DataFrame]:
    """One DataFrame per time-series group of an :func:`~machdyn.linkage.analyse` result.

    Keys: ``"motion"``, ``"joint_forces"``, ``"torque_power"``, ``"shaking"``, ``"energy"``. Each frame has
    one row per crank angle (per design for N design variants, with a ``"design"`` column first), the crank
    angle in degrees as ``"crank_angle [deg]"``, and the unit in every column header. ``mechanism`` is only
    needed if the analysis does not carry it.
    """
    mech = mechanism if mechanism is not None else mechanism_of(analysis)
    if mech is None:
        raise ValueError("analysis_frames needs the mechanism: pass mechanism=... (the analysis has none).")
    designs = design_count(analysis)
    kin, forces, energy = analysis.kinematics, analysis.forces, analysis.energy
    return {
        "motion": motion_frame(kin, mech, designs),
        "joint_forces": joint_forces_frame(forces, designs),
        "torque_power": torque_power_frame(forces, designs, energy),
        "shaking": shaking_frame(forces, designs),
        "energy": energy_frame(energy, kin.crank_angle, designs),
    }


def write_csv(frames: dict[str, pd.DataFrame], directory, prefix: str = "") -> list:
    """Write each frame to ``directory/<prefix><group>.csv`` (no index column); return the paths."""
    from pathlib import Path

    out_dir = Path(directory)
    out_dir.mkdir(parents=True, exist_ok=True)
    paths = []
    for name, frame in frames.items():
        path = out_dir / f"{prefix}{name}.csv"
        frame.to_csv(path, index=False, float_format="%.10g")
        paths.append(path)
    return paths


# ------------------------------------------------------------------------------------------------ scalars


def _reduce(values: Any, how: str, designs: int | None) -> float | list[float]:
    arr = np.asarray(values, dtype=float)
    if arr.ndim == 0:
        arr = arr.reshape(1)
    funcs = {
        "max": np.nanmax,
        "min": np.nanmin,
        "max_abs": lambda a, axis: np.nanmax(np.abs(a), axis=axis),
        "mean": np.nanmean,
        "rms": lambda a, axis: np.sqrt(np.nanmean(a * a, axis=axis)),
        "range": lambda a, axis: np.nanmax(a, axis=axis) - np.nanmin(a, axis=axis),
    }
    with np.errstate(all="ignore"), _quiet_nan():
        out = funcs[how](arr, axis=-1)
    if designs is None:
        return float(np.ravel(out)[0]) if np.ndim(out) else float(out)
    return [float(v) for v in np.broadcast_to(out, (designs,))]


class _quiet_nan:
    """Silence numpy's all-NaN slice warnings inside the reductions (an all-NaN result stays NaN)."""

    def __enter__(self):
        import warnings

        self._ctx = warnings.catch_warnings()
        self._ctx.__enter__()
        warnings.simplefilter("ignore", RuntimeWarning)

    def __exit__(self, *exc):
        return self._ctx.__exit__(*exc)


def _full_uniform_cycle(angle: np.ndarray) -> bool:
    """True if the crank angles are evenly spaced and cover one full turn (with or without the end point)."""
    a = np.asarray(angle, dtype=float).ravel()
    if a.size < 8:
        return False
    step = np.diff(a)
    if not np.allclose(step, step[0], rtol=1e-6, atol=1e-12) or step[0] <= 0:
        return False
    return includes_end_point(a) or bool(abs(a[-1] - a[0] + step[0] - 2 * np.pi) <= 0.5 * step[0])


def includes_end_point(angle: Any) -> bool:
    """True if evenly spaced crank angles repeat the first angle one turn later (span of 2 pi), judged against
    half a step so that fine samplings (a step below the tolerance of a relative test) are told apart."""
    a = np.asarray(angle, dtype=float).ravel()
    if a.size < 2:
        return False
    step = a[1] - a[0]
    return bool(abs(a[-1] - a[0] - 2 * np.pi) <= 0.5 * step)


def flywheel_energy_fluctuation(torque: Any, crank_angle: Any) -> np.ndarray:
    """max - min over the cycle of the work of the driving torque's fluctuation, integral (T - T_mean) dphi
    [J]: the energy a flywheel must store and return at constant speed. Needs a uniform full cycle."""
    phi = np.asarray(crank_angle, dtype=float).ravel()
    t = np.asarray(torque, dtype=float)
    step = phi[1] - phi[0]
    samples = t[..., :-1] if includes_end_point(phi) else t
    dev = samples - np.nanmean(samples, axis=-1, keepdims=True)
    work = np.cumsum(dev, axis=-1) * step
    work = np.concatenate([np.zeros(work.shape[:-1] + (1,)), work], axis=-1)
    return np.nanmax(work, axis=-1) - np.nanmin(work, axis=-1)


def _scalar(value: Any, designs: int | None) -> float | list[float]:
    arr = np.asarray(value, dtype=float)
    if designs is None:
        return float(arr.ravel()[0]) if arr.size else float("nan")
    return [float(v) for v in np.broadcast_to(arr.ravel() if arr.size == designs else arr, (designs,))]


def _entry(value: Any, unit: str) -> dict[str, Any]:
    return {"value": value, "unit": unit}


def analysis_scalars(analysis: Any, mechanism: _model.Mechanism | None = None) -> dict[str, dict[str, Any]]:
    """Every scalar result of an analysis as ``{key: {"value": float, "unit": str}}``.

    Extremes of the time series (torque, power, joint forces, shaking force and moment, energy, reduced
    inertia), the work balance over the cycle and the diagnostics (stroke, time ratio, transmission angle,
    dead positions). For N design variants each ``value`` is a list of N floats.
    """
    designs = design_count(analysis)
    kin, forces, energy = analysis.kinematics, analysis.forces, analysis.energy
    mech = mechanism if mechanism is not None else mechanism_of(analysis)
    out: dict[str, dict[str, Any]] = {}

    def put(key: str, value: Any, unit: str) -> None:
        out[key] = _entry(value, unit)

    speed = np.asarray(kin.speed, dtype=float)
    put(
        "crank_speed.mean",
        _reduce(np.broadcast_to(speed, np.shape(forces.driving_torque)), "mean", designs),
        "rad/s",
    )
    torque = forces.driving_torque
    put("driving_torque.max_abs", _reduce(torque, "max_abs", designs), "N*m")
    put("driving_torque.max", _reduce(torque, "max", designs), "N*m")
    put("driving_torque.min", _reduce(torque, "min", designs), "N*m")
    # Means and RMS over time, not over crank angle: they differ when the crank speed varies.
    put("driving_torque.mean", _scalar(time_mean(torque, kin), designs), "N*m")
    put("driving_torque.rms", _scalar(time_rms(torque, kin), designs), "N*m")
    put("input_power.mean", _scalar(time_mean(forces.input_power, kin), designs), "W")
    put("input_power.max", _reduce(forces.input_power, "max", designs), "W")
    put("input_power.min", _reduce(forces.input_power, "min", designs), "W")
    for name, _kind, _b1, _b2 in joint_list(forces):
        put(f"joint.{name}.max_force", _reduce(forces.joint(name).magnitude, "max", designs), "N")
    fx, fy = forces.frame_force
    put("shaking_force.max", _reduce(np.hypot(fx, fy), "max", designs), "N")
    put("shaking_moment.max_abs", _reduce(forces.shaking_moment(about=(0.0, 0.0)), "max_abs", designs), "N*m")

    put("kinetic_energy.max", _reduce(energy.kinetic_total, "max", designs), "J")
    put("kinetic_energy.min", _reduce(energy.kinetic_total, "min", designs), "J")
    put("kinetic_energy.fluctuation", _reduce(energy.kinetic_total, "range", designs), "J")
    put("reduced_inertia.min", _reduce(energy.reduced_inertia, "min", designs), "kg*m^2")
    put("reduced_inertia.max", _reduce(energy.reduced_inertia, "max", designs), "kg*m^2")
    put("reduced_inertia.mean", _reduce(energy.reduced_inertia, "mean", designs), "kg*m^2")
    if _full_uniform_cycle(kin.crank_angle) and np.all(np.isfinite(torque)):
        put(
            "flywheel.energy_fluctuation",
            _scalar(flywheel_energy_fluctuation(torque, kin.crank_angle), designs),
            "J",
        )
    try:
        wb = energy.work_balance()
    except Exception:  # noqa: BLE001 - a work balance that cannot be formed is simply not reported
        wb = None
    if wb is not None:
        put("work_balance.input_work", _scalar(wb.input_work, designs), "J")
        put("work_balance.load_work", _scalar(wb.load_work, designs), "J")
        put("work_balance.energy_change", _scalar(wb.energy_change, designs), "J")
        put("work_balance.residual", _scalar(wb.residual, designs), "J")
        put("work_balance.relative_residual", _scalar(wb.relative, designs), "")

    diag = getattr(analysis, "diagnostics", None)
    if diag is not None:
        sliders = set(_slider_bodies(mech)) if mech is not None else set()
        for body, stroke in (getattr(diag, "strokes", None) or {}).items():
            if body in sliders:
                put(f"stroke.{body}", _scalar(stroke, designs), "m")
            else:
                put(f"stroke.{body}", _scalar(np.degrees(stroke), designs), "deg")
        if getattr(diag, "time_ratio", None) is not None:
            put("time_ratio", _scalar(diag.time_ratio, designs), "")
        for attr in ("transmission_angle_min", "transmission_angle_max"):
            if getattr(diag, attr, None) is not None:
                put(
                    attr.replace("_angle_", "_angle."),
                    _scalar(np.degrees(diag.__getattribute__(attr)), designs),
                    "deg",
                )
        dead = getattr(diag, "dead_positions", None)
        if dead is not None:
            put("dead_positions.count", float(len(list(_flatten(dead)))), "")
    return out


def _flatten(items: Iterable) -> Iterable:
    for item in items:
        if isinstance(item, list | tuple | np.ndarray) and np.ndim(item) > 0:
            yield from _flatten(item)
        else:
            yield item


def scalars_frame(scalars: dict[str, dict[str, Any]]) -> pd.DataFrame:
    """The scalars as a table with columns quantity, value, unit (one row per design for list values)."""
    rows = []
    for key, entry in scalars.items():
        value = entry["value"]
        if isinstance(value, list):
            rows += [
                {"quantity": key, "design": i, "value": v, "unit": entry["unit"]} for i, v in enumerate(value)
            ]
        else:
            rows.append({"quantity": key, "value": value, "unit": entry["unit"]})
    return pd.DataFrame(rows)


_LABELS = {
    "crank_speed.mean": "Crank speed (mean)",
    "driving_torque.max_abs": "Driving torque, max |T|",
    "driving_torque.max": "Driving torque, maximum",
    "driving_torque.min": "Driving torque, minimum",
    "driving_torque.mean": "Driving torque, mean",
    "driving_torque.rms": "Driving torque, RMS",
    "input_power.mean": "Input power, mean",
    "input_power.max": "Input power, maximum",
    "input_power.min": "Input power, minimum",
    "shaking_force.max": "Shaking force, maximum",
    "shaking_moment.max_abs": "Shaking moment about the origin, max |M|",
    "kinetic_energy.max": "Kinetic energy, maximum",
    "kinetic_energy.min": "Kinetic energy, minimum",
    "kinetic_energy.fluctuation": "Kinetic energy, max - min",
    "reduced_inertia.min": "Reduced inertia at the crank, minimum",
    "reduced_inertia.max": "Reduced inertia at the crank, maximum",
    "reduced_inertia.mean": "Reduced inertia at the crank, mean",
    "flywheel.energy_fluctuation": "Energy fluctuation for a flywheel",
    "work_balance.input_work": "Work balance: input work",
    "work_balance.load_work": "Work balance: work of the loads",
    "work_balance.energy_change": "Work balance: energy change",
    "work_balance.residual": "Work balance: residual",
    "work_balance.relative_residual": "Work balance: relative residual",
    "time_ratio": "Time ratio",
    "transmission_angle.min": "Transmission angle, minimum",
    "transmission_angle.max": "Transmission angle, maximum",
    "dead_positions.count": "Dead positions (count)",
}


def scalar_label(key: str) -> str:
    """A readable label for a key of :func:`analysis_scalars` (the key itself if it has none)."""
    if key in _LABELS:
        return _LABELS[key]
    parts = key.split(".")
    if parts[0] == "joint" and len(parts) == 3 and parts[2] == "max_force":
        return f"Joint {parts[1]}: maximum force"
    if parts[0] == "stroke" and len(parts) == 2:
        return f"Stroke of {parts[1]}"
    return key


def summary_rows(scalars: dict[str, dict[str, Any]]) -> list[tuple[str, Any, str]]:
    """(label, value, unit) rows for :func:`~machdyn.report.render_report` from :func:`analysis_scalars`.

    Means of the driving torque and input power below 1e-9 of their family's largest magnitude are
    round-off and shown as 0 (the work-balance residuals are kept as they are: they are the check).
    """
    scale: dict[str, float] = {}
    for key, entry in scalars.items():
        family = key.split(".")[0]
        values = np.abs(np.atleast_1d(np.asarray(entry["value"], dtype=float)))
        if values.size and np.any(np.isfinite(values)):
            scale[family] = max(scale.get(family, 0.0), float(np.nanmax(values)))
    rows = []
    for key, entry in scalars.items():
        value = entry["value"]
        family = key.split(".")[0]
        if family in ("driving_torque", "input_power") and key.endswith(".mean"):
            limit = 1e-9 * scale.get(family, 0.0)
            if isinstance(value, list):
                value = [0.0 if abs(v) <= limit else v for v in value]
            elif abs(value) <= limit:
                value = 0.0
        rows.append((scalar_label(key), value, entry["unit"]))
    return rows
