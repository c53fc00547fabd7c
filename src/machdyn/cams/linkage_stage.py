"""The ``[follower_linkage]`` capability of a cam file: a linkage driven by the cam's follower.

The cam is analysed by its own kind (``[cam]``); this stage builds the linkage the follower drives (a dyad chain,
as a linkage file's custom ``[mechanism]``), moves it with the follower over the cam angles and computes, by the
relations of :mod:`machdyn.cams.follower_linkage`: the linkage's load on the follower, the camshaft torque it adds
(T_cam = T_crank dtheta/dphi, power balance), the total camshaft torque, the contact force with the linkage's load
and the jump speed with it, the output's stroke and the peak joint force. A ``[flywheel]`` in the same file sizes
the camshaft's flywheel and drive for the cam and the linkage together.

The cam's return spring is sized (or checked) by ``[cam.spring]`` for the follower alone; with the linkage the
contact force changes, and a design check fails when the follower would leave the cam below the spring's design
speed, running speed x (1 + margin); the message gives the spring that keeps contact.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..dynamics.contributions import ShaftContribution
from ..errors import InputError, ProblemFileError
from ..notebook import ShownInNotebook
from ..pipeline import Capability, Outcome, StageContext
from ..results.labels import Label
from .follower_linkage import (
    FOLLOWER,
    TABLE,
    VIRTUAL,
    LinkageLoad,
    follower_drive,
    jump_speed_with_linkage,
    linkage_load,
    linkage_mechanism,
    linkage_motion,
    output_body,
    spring_needed,
    with_linkage,
)
from .profile import cam_angles
from .schema import CamProblem, FollowerLinkageTable
from .stage import CamResult
from .stage import build as build_cam

P = f"{TABLE}."

LABELS: dict[str, Label] = {
    P + "camshaft_torque.max": Label("Camshaft torque with the linkage: peak |T|", "N*m", over="max_abs",
                                     better="lower"),
    P + "camshaft_torque.rms": Label("Camshaft torque with the linkage: RMS over the turn", "N*m", over="time_rms",
                                     better="lower"),
    P + "linkage_torque.max": Label("Camshaft torque the linkage adds: peak |T|", "N*m", over="max_abs",
                                    better="lower"),
    P + "follower_load.max": Label("The linkage's load on the follower, at the roller along its path: peak |F|",
                                   "N", over="max_abs", better="lower"),
    P + "work_per_cycle": Label("Camshaft work per turn the linkage adds (its loads' work)", "J",
                                zero_below=P + "linkage_torque.max", over="cycle", better="lower"),
    P + "mean_power": Label("Camshaft with the linkage: mean power", "W", zero_below=P + "peak_power",
                            over="time_mean", better="lower"),
    P + "peak_power": Label("Camshaft with the linkage: peak power |T omega|", "W", over="max_abs", better="lower"),
    P + "output_stroke": Label("Linkage output: stroke of the slider", "m", "mm", over="range", better="none"),
    P + "output_velocity.max": Label("Linkage output: peak |velocity| of the slider", "m/s", over="max_abs",
                                     better="lower"),
    P + "joint_force.max": Label("Linkage: peak joint force", "N", over="max", better="lower"),
    P + "min_contact_force": Label("Contact force with the linkage, along the follower's path: minimum", "N",
                                   over="min", better="higher"),
    P + "max_contact_force": Label("Contact force with the linkage, along the follower's path: maximum", "N",
                                   over="max", better="lower"),
    P + "max_normal_force": Label("Contact force with the linkage, along the common normal: maximum", "N", over="max",
                                  better="lower"),
    P + "jump_speed": Label("Follower jump with the linkage: lowest cam speed at which contact is lost", "rad/s",
                            "rpm", over="cycle", better="higher"),
    P + "jump_speed_ratio": Label("Follower jump speed with the linkage / running speed", "", over="cycle",
                                  better="higher"),
    P + "spring_rate_needed": Label("Return spring with the linkage: least rate at the spring's preload", "N/m",
                                    "N/mm", over="cycle", better="lower"),
    P + "spring_preload_needed": Label("Return spring with the linkage: least preload at the spring's rate", "N",
                                       over="cycle", better="lower"),
}

#: an output that turns (not a slider): its swing and angular velocity under the same keys
TURNING = {P + "output_stroke": Label("Linkage output: swing of the output body", "rad", "deg", over="range",
                                      better="none"),
           P + "output_velocity.max": Label("Linkage output: peak |angular velocity| of the output body", "rad/s",
                                            over="max_abs", better="lower")}

SUMMARY = tuple(P + k for k in ("output_stroke", "follower_load.max", "linkage_torque.max",
                                "camshaft_torque.max", "mean_power", "joint_force.max", "min_contact_force",
                                "max_normal_force", "jump_speed", "spring_rate_needed",
                                "spring_preload_needed"))


@dataclass(frozen=True)
class FollowerLinkageResult(ShaftContribution, ShownInNotebook):
    """What the stage computed (SI), for the report, the Python API and ``[flywheel]``.

    cam : the cam's own result; load : the linkage's kinetostatics and its load on the follower and the camshaft;
    output : the output body; cam_torque, total_torque : the camshaft torque of the cam alone and with the
    linkage [N*m]; contact : the contact force along the follower's path with the linkage [N] (at the roller);
    normal : along the common normal [N]; jump_speed [rad/s]; position, velocity : the output's travel [m|rad]
    and its rate [m/s|rad/s] over the cam angles; slider : whether the output is a slider.
    """

    cam: CamResult
    mechanism: Any
    load: LinkageLoad
    output: str
    cam_torque: np.ndarray
    total_torque: np.ndarray
    contact: np.ndarray
    normal: np.ndarray
    jump_speed: float
    position: np.ndarray
    velocity: np.ndarray
    slider: bool

    @property
    def cam_angle(self) -> np.ndarray:
        return self.load.drive.phi

    def added_to(self, machine: Any, positions: int) -> Any:
        """The cam's reduced machine with the linkage's reduced quantities added
        (:func:`~machdyn.cams.follower_linkage.with_linkage`)."""
        m = self.cam.model
        return with_linkage(machine, self.mechanism, m.program, m.follower, self.cam.clockwise, positions)


def _prepare(problem: CamProblem, table: FollowerLinkageTable,
             closes: bool = True) -> tuple[Any, Any, list[tuple[str, str]]]:
    """The cam model and the linkage's mechanism, or the problems found (each with its field); with ``closes``,
    also that the linkage closes over the follower's motion at the cam's and the flywheel's positions."""
    cam = problem.cam
    found: list[tuple[str, str]] = []
    if cam.dynamics is None:
        found.append(("cam.dynamics", "a follower that drives a linkage carries its load: give the follower train "
                                      "(mass ...)"))
    if found:
        return None, None, found
    model, problems = build_cam(problem)
    if model is None or problems:  # the cam's own problems are the kind's to report
        return None, None, []
    try:
        mech = linkage_mechanism(table, model.follower, cam.rotation == "cw", model.program)
        output_body(table, mech)
        grids = [cam.positions] if closes else []
        flywheel = getattr(problem, "flywheel", None)
        if flywheel is not None and closes:  # the flywheel's machine samples the linkage at its own positions
            grids.append(flywheel.positions)
        for positions in grids:
            drive = follower_drive(model.program, model.follower, cam.rotation == "cw", cam_angles(positions))
            linkage_motion(mech, drive, float(cam.speed))
    except ProblemFileError as exc:
        return None, None, list(exc.problems)
    except InputError as exc:
        return None, None, [(TABLE, str(exc))]
    return model, mech, []


def check(problem: Any, table: FollowerLinkageTable, source: str | None) -> list[tuple[str, str]]:
    """The table's validations beyond its schema: the follower's train, bodies and points that exist, and a linkage
    that closes without a dead position over the follower's whole motion, at the cam's positions and the
    flywheel's."""
    return _prepare(problem, table)[2]


def _output(load: LinkageLoad, body: str) -> tuple[np.ndarray, np.ndarray, bool]:
    """The output's travel along its guide [m] and rate [m/s] for a slider, else its angle [rad] and angular
    velocity [rad/s] (unwrapped over the cam angles)."""
    kin = load.forces.kinematics
    if body in kin.slides:
        sm = kin.slide(body)
        return np.asarray(sm.s, dtype=float), np.asarray(sm.v, dtype=float), True
    st = kin.body(body)
    return np.unwrap(np.asarray(st.angle, dtype=float)), np.asarray(st.omega, dtype=float), False


def _linkage_joints(load: LinkageLoad) -> list[Any]:
    """The joints of the linkage itself: not those of the follower's massless drive, nor the follower's own
    pivot or guide (which also carry the cam's contact force, not computed here)."""
    return [j for j in load.forces.joints if not {j.body_1, j.body_2} & set(VIRTUAL)
            and not (j.body_1 == "ground" and j.body_2 == FOLLOWER)]


def run(ctx: StageContext) -> Outcome:
    """The stage (module docstring)."""
    problem: CamProblem = ctx.problem
    table: FollowerLinkageTable = ctx.table
    model, mech, problems = _prepare(problem, table, closes=False)  # the file's check solved the motion
    cam = ctx.result_of("cam", CamResult)
    if problems or cam is None or cam.forces is None or model is None:
        raise ProblemFileError(problems or [(TABLE, "the cam's analysis gave no forces")], ctx.source)
    speed = float(cam.speed)
    drive = follower_drive(model.program, model.follower, cam.clockwise, cam.model.profile.svaj.theta)
    try:
        load = linkage_load(mech, drive, speed)
    except InputError as exc:
        raise ProblemFileError([(TABLE, str(exc))], ctx.source) from None
    arm = cam.model.arm
    f = cam.forces
    total = f.torque + load.camshaft_torque
    along = f.contact + load.moment  # follower coordinate [N*m]
    contact = along / arm
    normal = along / (arm * np.cos(cam.model.profile.pressure_angle))
    train, spring = cam.model.train, cam.spring
    jump = jump_speed_with_linkage(f.svaj, train, spring, load.inertial, load.static)
    body = output_body(table, mech)
    position, velocity, slider = _output(load, body)
    peak_joint = max(float(np.max(load.forces.joint(j.name).magnitude)) for j in _linkage_joints(load))
    values: dict[str, Any] = {
        P + "camshaft_torque.max": float(np.max(np.abs(total))),
        P + "camshaft_torque.rms": float(np.sqrt(np.mean(total**2))),
        P + "linkage_torque.max": float(np.max(np.abs(load.camshaft_torque))),
        P + "follower_load.max": float(np.max(np.abs(load.moment))) / arm,
        P + "work_per_cycle": float(np.mean(load.camshaft_torque) * 2.0 * np.pi),
        P + "mean_power": float(np.mean(total)) * speed,
        P + "peak_power": float(np.max(np.abs(total))) * speed,
        P + "output_stroke": float(np.ptp(position)),
        P + "output_velocity.max": float(np.max(np.abs(velocity))),
        P + "joint_force.max": peak_joint,
        P + "min_contact_force": float(np.min(contact)),
        P + "max_contact_force": float(np.max(contact)),
        P + "max_normal_force": float(np.max(normal)),
    }
    if np.isfinite(jump):
        values[P + "jump_speed"] = jump
        values[P + "jump_speed_ratio"] = jump / speed
    failed: list[str] = []
    margin = problem.cam.spring.margin
    design = speed * (1.0 + margin)
    rate, preload = spring_needed(f.svaj, train, spring, load.inertial, load.static, design, model.program.stroke)
    if np.isfinite(rate):
        values[P + "spring_rate_needed"] = rate / arm**2
    values[P + "spring_preload_needed"] = preload / arm
    if jump < design * (1 - 1e-9):
        rpm = 30.0 / np.pi
        fix = (f"a rate of {rate / arm**2 / 1e3:.4g} N/mm at the preload of {spring.preload / arm:.4g} N"
               if np.isfinite(rate) else "a larger preload")
        failed.append(f"follower jump with the linkage: the spring keeps contact only up to {jump * rpm:.4g} rpm, "
                      f"below the running speed x {1 + margin:g} = {design * rpm:.4g} rpm; the spring needs {fix}, "
                      f"or a preload of {preload / arm:.4g} N at its rate of {spring.rate / arm**2 / 1e3:.4g} N/mm "
                      "([cam.spring] rate and preload)")
    result = FollowerLinkageResult(cam, mech, load, body, f.torque, total, contact, normal, jump, position, velocity,
                                   slider)
    unit = ("m", "m/s") if slider else ("rad", "rad/s")
    series = {"follower_linkage": {
        "cam_angle": (drive.phi, "rad"), "follower_load": (load.moment / arm, "N"), "cam_torque": (f.torque, "N*m"),
        "linkage_torque": (load.camshaft_torque, "N*m"), "camshaft_torque": (total, "N*m"),
        "contact_force": (contact, "N"), "output_position": (position, unit[0]),
        "output_velocity": (velocity, unit[1])}}
    return Outcome(results=result, scalars=values, labels={} if slider else TURNING, series=series,
                   summary=tuple(k for k in SUMMARY if k in values), failed_checks=tuple(failed))


CAPABILITY = Capability(
    table=TABLE,
    schema=FollowerLinkageTable,
    run=run,
    step="linkage driven by the follower",
    kinds=("cam",),
    labels=LABELS,
    report="machdyn.report.cams:follower_linkage_sections",
    check=check,
    result_type=FollowerLinkageResult,
)
