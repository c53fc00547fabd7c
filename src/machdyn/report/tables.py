"""Linkage results as pandas DataFrames, one per time-series group, with the unit in every column header.

Every frame has one row per crank angle; its first column is ``"crank_angle [deg]"`` and every column
header carries its unit in square brackets, e.g. ``"rocker.omega [rad/s]"``. For a mechanism with N design
variants the frames are in long form: a leading ``"design"`` column (0 .. N-1) and, for each design, one row
per crank angle (design-major order), so ``frame.groupby("design")`` gives the per-design tables.

The scalar results are computed by :mod:`machdyn.results.linkage`.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from ..linkage import model as _model
from ..results.linkage import design_count, joint_list, mechanism_of
from ..results.linkage import slider_bodies as _slider_bodies

ANGLE_COLUMN = "crank_angle [deg]"
DESIGN_COLUMN = "design"

GROUPS = ("motion", "joint_forces", "torque_power", "shaking", "energy")


# ------------------------------------------------------------------------------------------------ helpers


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
    out_dir = Path(directory)
    out_dir.mkdir(parents=True, exist_ok=True)
    paths = []
    for name, frame in frames.items():
        path = out_dir / f"{prefix}{name}.csv"
        frame.to_csv(path, index=False, float_format="%.10g")
        paths.append(path)
    return paths


def series_frame(columns: Any) -> pd.DataFrame:
    """A table of a stage's series (column -> (values, SI unit)) as a DataFrame, the unit in each header.

    Angles are written in degrees, as in every other table (``crank_angle [deg]``); rates stay in rad/s."""
    out = {}
    for name, (values, unit) in columns.items():
        data = np.asarray(values).ravel()
        if unit == "rad":
            data, unit = np.degrees(data), "deg"
        out[f"{name} [{unit}]" if unit else name] = data
    return pd.DataFrame(out)


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
