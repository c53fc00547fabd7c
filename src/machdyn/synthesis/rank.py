"""Ranking a population of candidates by their dynamics, evaluated by the engine for all of them at once.

Candidates of one kind and branch become one engine model whose link lengths, pivots and coupler points are
arrays over the designs (:mod:`machdyn.linkage.builders` broadcast over designs); each design is analysed over
its own working range (a whole turn when its crank turns fully and the task runs it round, else from the first
precision position to the last) at a constant crank speed, in chunks so that memory stays bounded. From the
engine's kinematics and kinetostatics (:func:`machdyn.linkage.kinematics`, :func:`machdyn.linkage.kinetostatics`)
each design gets:

- ``peak_torque`` [N*m]: the largest driving torque on the crank (inertia of uniform bars of the given linear
  density, gravity, and the output load if one is given);
- ``inertial_shaking_force`` [N]: the largest inertial shaking force |-sum m_i a_Gi| over the moving bodies
  (Norton, *Design of Machinery*, 5th ed., ch. 12, the shaking force of a linkage: what the frame feels from
  the motion alone, whatever the loads and the weight);
- ``frame_force`` [N]: the largest resultant force of the linkage on the frame (inertia, weight and loads);
- ``min_transmission`` [rad]: the smallest transmission angle of the engine's dyad;
- ``flywheel_energy`` [J]: the maximum fluctuation of energy over a turn (full-turn designs only, NaN others;
  :func:`machdyn.linkage.energy_fluctuation`);
- ``flywheel_inertia`` [kg*m^2]: the flywheel that holds the crank speed within the coefficient of fluctuation
  Cs, I = dE / (omega^2 Cs) (Khurmi & Gupta, *Theory of Machines*, ch. 16;
  :func:`machdyn.dynamics.flywheel.flywheel_inertia_classic`);
- ``error`` [m or rad]: the kinematic error at the precision positions (from :mod:`.defects`).

The population is ranked by the chosen quantity, defect-free designs first, then by kinematic error.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from ..dynamics.flywheel import flywheel_inertia_classic
from ..linkage import BodyTorque, PointForce, energy_fluctuation, four_bar, kinematics, kinetostatics, slider_crank
from ..linkage.reductions import reduce
from ..results.catalogue import find
from .candidate import TWO_PI, Candidate
from .defects import Report

#: The rankable quantities that are results of a mechanism: name -> the catalogue key whose unit, better
#: direction and reduction (:mod:`machdyn.linkage.reductions`) they are.
AS_RESULTS: dict[str, str] = {
    "peak_torque": "driving_torque.max_abs",
    "inertial_shaking_force": "inertial_shaking_force.max",
    "frame_force": "frame_force.max",
    "min_transmission": "transmission_angle.worst",
    "flywheel_energy": "flywheel.energy_fluctuation",
}
_SHORT = {"peak_torque": "Peak driving torque", "inertial_shaking_force": "Peak inertial shaking force",
          "frame_force": "Peak force on the frame", "min_transmission": "Worst transmission angle",
          "flywheel_energy": "Fluctuation of energy per turn"}


def _declared(name: str) -> tuple[str, str, bool]:
    found = find(AS_RESULTS[name])
    assert found is not None, AS_RESULTS[name]
    return _SHORT[name], found[0].unit, found[0].better == "higher"


#: Rankable quantities: key -> (label, SI unit, larger is better); those of :data:`AS_RESULTS` from the catalogue.
QUANTITIES: dict[str, tuple[str, str, bool]] = {
    **{name: _declared(name) for name in AS_RESULTS},
    "flywheel_inertia": ("Flywheel needed", "kg*m^2", False),
    "error": ("Kinematic error at the positions", "", False),
}

#: How each rankable quantity reduces its series over the positions (a name of
#: :data:`machdyn.linkage.reductions.REDUCTIONS`): the catalogue's, "scalar" for the flywheel and the error.
REDUCTION_OF: dict[str, str] = {
    **{name: find(key)[0].over_positions for name, key in AS_RESULTS.items()},  # type: ignore[index]
    "flywheel_inertia": "scalar",
    "error": "max_abs",
}

CHUNK_POSITIONS = 1 << 17


@dataclass(frozen=True)
class Drive:
    """How the candidates are run: crank ``speed`` [rad/s], bars of ``linear_density`` [kg/m], a resisting
    ``load`` on the output (a torque [N*m] on the rocker, counter-clockwise positive, or a force [N] on the
    slider along its line), ``positions`` per working range, ``full_turn`` (run full-turn cranks round) and the
    coefficient of speed fluctuation ``speed_fluctuation`` [-] a flywheel is sized for."""

    speed: float = 10.0
    linear_density: float = 1.0
    load: float = 0.0
    positions: int = 121
    full_turn: bool = True
    gravity: bool = True
    speed_fluctuation: float = 0.05


def _angles(c: Candidate, report: Report, drive: Drive) -> np.ndarray:
    start = float(c.angles[0]) if c.angles.size else 0.0
    if report.full_turn and drive.full_turn:
        return start + c.direction * np.linspace(0.0, TWO_PI, drive.positions, endpoint=False)
    return c.working_angles(drive.positions)


def _model(group: list[Candidate], drive: Drive) -> Any:
    """One engine model of candidates of one kind and branch (lengths as arrays over the designs)."""
    g = (0.0, -9.80665) if drive.gravity else (0.0, 0.0)
    first = group[0]

    def arr(attr: str) -> np.ndarray:
        return np.array([getattr(c, attr) for c in group], dtype=float)

    if first.kind == "slider_crank":
        mech = slider_crank(arr("crank"), arr("coupler"), arr("offset"), slide_angle=arr("slide_angle"),
                            branch=first.branch, linear_density=drive.linear_density, gravity=g,
                            name="candidates")
        if drive.load:
            direction = arr("slide_angle")
            mech = replace(mech, forces=(PointForce("load", "slider.B", drive.load * np.cos(direction)[:, None],
                                                    drive.load * np.sin(direction)[:, None]),))
        return mech
    cp = np.array([c.coupler_point for c in group], dtype=float)
    mech = four_bar(arr("crank"), arr("coupler"), arr("rocker"), arr("ground"), ground_angle=arr("ground_angle"),
                    branch=first.branch, coupler_point=(cp[:, 0], cp[:, 1]), linear_density=drive.linear_density,
                    gravity=g, name="candidates")
    if drive.load:
        mech = replace(mech, torques=(BodyTorque("load", "rocker", drive.load),))
    return mech


def _inertial_shaking(mech: Any, kin: Any) -> np.ndarray:
    """|-sum m a_G| [N] over the moving bodies at every position (designs x angles)."""
    fx: Any = 0.0
    fy: Any = 0.0
    for body in mech.bodies:
        g = kin.com(body.name)
        m = np.asarray(body.mass, dtype=float)
        m = m[:, None] if m.ndim else m  # one mass per design: a column against the crank angles
        fx = fx - m * g.ax
        fy = fy - m * g.ay
    return np.hypot(fx, fy)


def evaluate(cands: list[Candidate], reports: list[Report], drive: Drive = Drive(),
             chunk_positions: int = CHUNK_POSITIONS) -> dict[str, np.ndarray]:
    """The per-candidate quantities of :data:`QUANTITIES` (arrays in the candidates' order), by the engine."""
    n = len(cands)
    out = {k: np.full(n, np.nan) for k in QUANTITIES}
    out["error"] = np.array([max(r.position_error, r.angle_error) for r in reports], dtype=float)
    groups: dict[tuple[str, int, bool], list[int]] = {}
    for i, (c, r) in enumerate(zip(cands, reports, strict=True)):
        groups.setdefault((c.kind, c.branch, bool(r.full_turn and drive.full_turn)), []).append(i)
    per_chunk = max(1, chunk_positions // drive.positions)
    for (_, _, turns), members in groups.items():
        for start in range(0, len(members), per_chunk):
            idx = members[start:start + per_chunk]
            sub = [cands[i] for i in idx]
            if len(sub) == 1:
                sub = sub * 2  # the builders need arrays of at least two to keep a designs axis
            mech = _model(sub, drive)
            phi = np.array([_angles(cands[i], reports[i], drive) for i in idx] * (2 if len(idx) == 1 else 1))
            speed = drive.speed * np.array([c.direction for c in sub], dtype=float)
            with np.errstate(all="ignore"):
                kin = kinematics(mech, phi, speed, 0.0, on_fail="mask")
                forces = kinetostatics(mech, kinematics_result=kin)
                torque = np.asarray(forces.driving_torque)
                shake = np.asarray(forces.shaking_force)
                mu = np.asarray(kin.dyad_reports[0].transmission)
                inertial = _inertial_shaking(mech, kin)
            k = len(idx)
            bad = ~np.isfinite(torque[:k]).all(axis=1)
            # the catalogue's reductions, NaN skipped (a design that cannot close is NaN throughout)
            out["peak_torque"][idx] = np.where(bad, np.nan, reduce(torque[:k], "max_abs"))
            out["frame_force"][idx] = np.where(bad, np.nan, reduce(shake[:k], "max"))
            out["inertial_shaking_force"][idx] = np.where(bad, np.nan, reduce(inertial[:k], "max"))
            out["min_transmission"][idx] = np.where(bad, np.nan, reduce(mu[:k], "worst"))
            if turns:
                grid = np.linspace(0.0, TWO_PI, drive.positions, endpoint=False)
                de = energy_fluctuation(np.where(np.isfinite(torque[:k]), torque[:k], 0.0), grid)
                out["flywheel_energy"][idx] = np.where(bad, np.nan, de)
                out["flywheel_inertia"][idx] = np.where(bad, np.nan, flywheel_inertia_classic(
                    de, abs(drive.speed), drive.speed_fluctuation))
    return out


def order(values: dict[str, np.ndarray], reports: list[Report], by: str = "peak_torque") -> np.ndarray:
    """Candidate indices best first: defect-free before defective, then by ``by`` (smaller first, larger for the
    transmission angle; missing values last), then by kinematic error."""
    if by not in QUANTITIES:
        raise ValueError(f"unknown ranking quantity {by!r}; one of {', '.join(QUANTITIES)}")
    larger = QUANTITIES[by][2]
    v = np.asarray(values[by], dtype=float)
    key = np.where(np.isfinite(v), -v if larger else v, np.inf)
    defective = np.array([0 if r.ok else 1 for r in reports])
    err = np.nan_to_num(np.asarray(values["error"], dtype=float), nan=np.inf)
    return np.lexsort((err, key, defective))
