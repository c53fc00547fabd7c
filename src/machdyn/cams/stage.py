"""The ``[cam]`` problem kind: build (program, follower, profile; bad input named by its field), check and
analyse (SVAJ, profile, checks, spring, contact force, camshaft torque, a forward simulation of the follower),
with its labels, summary, CSV series (``cam_svaj``, ``cam_profile``, ``cam_forces``) and the DXF profile."""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from ..dynamics.contributions import ReducedMachineSource
from ..errors import InputError, ProblemFileError
from ..pipeline import Outcome, ProblemKind, Step
from ..results.labels import Label
from .checks import check_cam, rim_speed_failure
from .dxf import profile_dxf
from .dynamics import FollowerTrain, Spring, cam_forces, cam_machine, simulate_follower, size_spring
from .followers import Follower
from .geometric import flank_radius_for_angle, nose_radius_for_angle
from .profile import cam_angles, profile
from .program import Segment, program
from .schema import CamProblem
from .strokes import FIGURES, Stroke, strokes

#: result key -> (text, SI unit for a translating follower, display) ; oscillating followers' lengths are angles
_FIXED = {
    "cam.speed": Label("Cam speed", "rad/s", "rpm", over="scalar", better="none"),
    "cam.max_pressure_angle": Label("Pressure angle: largest |phi| over the turn", "rad", "deg", over="max_abs",
                                    better="lower"),
    "cam.pressure_angle_limit": Label("Pressure angle: limit", "rad", "deg", over="scalar", better="none"),
    "cam.min_pitch_curvature_radius": Label("Pitch curve: smallest convex radius of curvature", "m", "mm", over="min",
                                            better="higher"),
    "cam.min_surface_curvature_radius": Label("Cam surface: smallest convex radius of curvature", "m", "mm",
                                              over="min", better="higher"),
    "cam.min_base_radius_pressure": Label("Smallest base circle radius meeting the pressure-angle limit", "m", "mm",
                                          over="scalar", better="lower"),
    "cam.min_base_radius_curvature": Label("Smallest base circle radius meeting the curvature limit (roller: convex "
                                           "pitch radius >= curvature factor x roller radius; flat face: no cusp)",
                                           "m", "mm", over="scalar", better="lower"),
    "cam.base_radius": Label("Base circle radius", "m", "mm", over="scalar", better="lower"),
    "cam.face_width": Label("Flat face: width needed (contact range + margins)", "m", "mm", over="scalar",
                            better="lower"),
    "cam.spring_preload": Label("Return spring: preload", "N", over="scalar", better="lower"),
    "cam.spring_rate": Label("Return spring: rate", "N/m", "N/mm", over="scalar", better="lower"),
    "cam.jump_speed": Label("Follower jump: lowest cam speed at which contact is lost", "rad/s", "rpm", over="cycle",
                            better="higher"),
    "cam.jump_speed_ratio": Label("Follower jump speed / running speed", "", over="cycle", better="higher"),
    "cam.min_contact_force": Label("Contact force along the follower's path: minimum", "N", over="min",
                                   better="higher"),
    "cam.max_contact_force": Label("Contact force along the follower's path: maximum", "N", over="max", better="lower"),
    "cam.max_normal_force": Label("Contact force along the common normal: maximum", "N", over="max", better="lower"),
    "cam.peak_torque": Label("Camshaft torque: peak |T|", "N*m", over="max_abs", better="lower"),
    "cam.rms_torque": Label("Camshaft torque: RMS over the turn", "N*m", over="time_rms", better="lower"),
    "cam.work_per_cycle": Label("Camshaft torque: work per turn (the damper's loss)", "J",
                                zero_below="cam.peak_torque", over="cycle", better="lower"),
    "cam.mean_power": Label("Camshaft: mean power", "W", zero_below="cam.peak_power", over="time_mean", better="lower"),
    "cam.peak_power": Label("Camshaft: peak power |T omega|", "W", over="max_abs", better="lower"),
    "cam.max_reduced_inertia": Label("Reduced inertia at the camshaft: largest", "kg*m^2", over="max", better="lower"),
    "cam.simulated_max_separation": Label("Simulated follower: largest lift-off from the cam", "m", "mm", over="max",
                                          better="lower"),
    "cam.jumps": Label("Jumps of velocity or acceleration in the program", "", over="count", better="lower"),
}

#: key -> (text, translating unit/display, oscillating unit/display, reduction, better)
_MOTION_LABELS = {
    "cam.stroke": ("Follower stroke", ("m", "mm"), ("rad", "deg"), "range", "none"),
    "cam.max_velocity": ("Follower velocity: peak |v|", ("m/s", None), ("rad/s", None), "max_abs", "lower"),
    "cam.max_acceleration": ("Follower acceleration: peak |a|", ("m/s^2", None), ("rad/s^2", None), "max_abs",
                             "lower"),
    "cam.max_jerk": ("Follower jerk: peak |j|", ("m/s^3", None), ("rad/s^3", None), "max_abs", "lower"),
}

LABELS: dict[str, Label] = {**_FIXED, **{k: Label(t, u[0], u[1], over=over, better=better)
                                         for k, (t, u, _, over, better) in _MOTION_LABELS.items()}}

SUMMARY = ("cam.stroke", "cam.max_velocity", "cam.max_acceleration", "cam.max_pressure_angle",
           "cam.pressure_angle_limit", "cam.min_pitch_curvature_radius", "cam.min_surface_curvature_radius",
           "cam.min_base_radius_pressure", "cam.min_base_radius_curvature", "cam.face_width", "cam.spring_rate",
           "cam.spring_preload", "cam.jump_speed", "cam.min_contact_force", "cam.max_normal_force",
           "cam.peak_torque", "cam.mean_power")


@dataclass(frozen=True)
class CamModel:
    """The built cam: its checked program, follower, the profile at the analysed angles and the follower train
    in the follower's own coordinate (None without ``[cam.dynamics]``)."""

    program: Any
    follower: Any
    profile: Any
    train: Any
    arm: float  # 1 for a translating follower, the arm length [m] for an oscillating one


@dataclass(frozen=True)
class CamResult(ReducedMachineSource):
    """Everything the analysis computed (SI), for the report and the Python API."""

    model: CamModel
    speed: float
    checks: Any
    spring: Any
    forces: Any
    simulation: Any
    clockwise: bool
    face_width_given: float | None = None
    strokes: tuple[Stroke, ...] = ()

    def machine(self, positions: int = 720):
        """The cam machine reduced to the camshaft (:func:`~machdyn.cams.dynamics.cam_machine`); a camshaft of
        constant inertia (zero without ``[cam.dynamics]``) otherwise."""
        m = self.model
        train = m.train if m.train is not None else FollowerTrain(mass=1e-300)
        spring = self.spring if self.spring is not None else Spring(0.0, 0.0)
        return cam_machine(m.program, train, spring, positions)


def _segments(problem: CamProblem, problems: list[tuple[str, str]]):
    osc = problem.cam.follower.motion == "oscillating"
    out = []
    for i, s in enumerate(problem.cam.segments):
        path = f"cam.segments[{i}]"
        lift = s.swing if osc else s.lift
        other = "lift" if osc else "swing"
        need = "swing" if osc else "lift"
        if getattr(s, other) is not None:
            problems.append((f"{path}.{other}", f"a {problem.cam.follower.motion} follower's segments give "
                                                f"{need}, not {other}"))
        if s.motion != "dwell" and lift is None:
            problems.append((f"{path}.{need}", f"a {s.motion} needs its {need}"))
            lift = 0.0
        out.append(Segment(s.motion, float(s.angle), float(lift or 0.0), s.law, s.start,
                           tuple((float(x), float(y)) for x, y in s.points), _contour(problem, s, path, problems)))
    return out


def _contour(problem: CamProblem, s: Any, path: str, problems: list[tuple[str, str]]) -> tuple[float, ...]:
    """(base, nose, flank or roller) [m] of a contour law, its follower checked (a circular arc drives a flat
    face, a tangent cam a roller, both translating on a line through the cam's centre)."""
    if s.law not in ("circular_arc", "tangent") or s.motion == "dwell":
        for name in ("nose_radius", "flank_radius"):
            if getattr(s, name) is not None:
                problems.append((f"{path}.{name}", "belongs to the contour laws circular_arc and tangent only"))
        return ()
    f = problem.cam.follower
    want = "flat" if s.law == "circular_arc" else "roller"
    if f.contact != want or f.motion != "translating" or f.offset != 0.0:
        problems.append((f"{path}.law", f"a {s.law.replace('_', '-')} cam drives a translating {want} follower on "
                                        f"a line through the cam's centre; the follower is {f.motion}, "
                                        f"{f.contact}, offset {f.offset * 1e3:g} mm"))
    base, lift = float(problem.cam.base_radius), float(s.lift or 0.0)
    nose, size = s.nose_radius, (s.flank_radius if s.law == "circular_arc" else f.roller_radius)
    if s.law == "tangent" and s.flank_radius is not None:
        problems.append((f"{path}.flank_radius", "a tangent cam's flanks are straight: remove flank_radius"))
    # the books give the angle of rise instead of one radius: the missing radius follows from the segment's angle
    try:
        if s.law == "tangent" and nose is None and lift > 0:
            nose = nose_radius_for_angle(base, lift, float(s.angle))
        elif s.law == "circular_arc" and nose is not None and size is None and lift > 0:
            size = flank_radius_for_angle(base, float(nose), lift, float(s.angle))
    except InputError as exc:
        problems.append((f"{path}.angle", str(exc)))
        return ()
    if nose is None:
        problems.append((f"{path}.nose_radius", f"a {s.law.replace('_', '-')} cam needs its nose radius"))
    if s.law == "circular_arc" and size is None:
        problems.append((f"{path}.flank_radius", "a circular-arc cam needs its flank radius (or the nose radius "
                                                 "and its angle of rise, from which it follows)"))
    return (base, float(nose or 0.0), float(size or 0.0))


def _field(message: str, default: str) -> str:
    """The field a message of the cam modules names first (``cam.segments[2].angle ...``)."""
    head = message.split(" ", 1)[0].rstrip(":.")
    return head if head.startswith("cam.") else default


def build(problem: CamProblem) -> tuple[CamModel | None, list[tuple[str, str]]]:
    """The model, or the problems found, each with its field."""
    problems: list[tuple[str, str]] = []
    cam = problem.cam
    segs = _segments(problem, problems)
    if problems:
        return None, problems
    try:
        prog = program(segs)
    except InputError as exc:
        return None, [(_field(str(exc), "cam.segments"), str(exc))]
    f = cam.follower
    try:
        follower = Follower(f.motion, f.contact, float(cam.base_radius), float(f.roller_radius), float(f.offset),
                            float(f.pivot_distance), float(f.arm_length))
    except InputError as exc:
        return None, [(_field(str(exc), "cam.follower"), str(exc))]
    rc = cam.output.cutter_radius
    prof = profile(prog, follower, cam_angles(cam.positions), cutter_radius=None if rc is None else float(rc),
                   clockwise=cam.rotation == "cw")
    if follower.contact == "roller":
        rho = prof.pitch_curvature_radius
        convex = rho > 0
        if np.any(convex & (rho <= follower.roller_radius)):
            k = int(np.argmin(np.where(convex, rho, np.inf)))
            problems.append(("cam.follower.roller_radius",
                             f"the roller ({follower.roller_radius * 1e3:.4g} mm) is bigger than the smallest convex "
                             f"radius of curvature of the pitch curve, {rho[k] * 1e3:.4g} mm at cam angle "
                             f"{np.degrees(prof.svaj.theta[k]):.4g} deg: the cam would be undercut (a smaller "
                             "roller or a larger base circle)"))
    if follower.contact == "flat" and np.any(prof.surface_curvature_radius <= 0):
        k = int(np.argmin(prof.surface_curvature_radius))
        problems.append(("cam.base_radius", f"the base circle ({follower.base_radius * 1e3:.4g} mm) is too small "
                                            f"for the flat face: the cam has a cusp at cam angle "
                                            f"{np.degrees(prof.svaj.theta[k]):.4g} deg (R_b + s + a = "
                                            f"{prof.surface_curvature_radius[k] * 1e3:.4g} mm)"))
    flywheel = getattr(problem, "flywheel", None)
    if flywheel is not None and cam.dynamics is None:
        problems.append(("flywheel", "a cam machine's flywheel and drive need the follower train: add "
                                     "[cam.dynamics] (mass ...)"))
    if flywheel is not None and flywheel.dampers:
        problems.append(("flywheel.dampers", "a cam machine takes its damping from [cam.dynamics] damping; "
                                             "[[flywheel.dampers]] name linkage bodies"))
    train = None
    arm = f.arm_length if follower.motion == "oscillating" else 1.0
    if cam.dynamics is not None:
        d = cam.dynamics
        try:  # lumped at the roller; about the pivot: m l^2, c l^2, F l
            train = FollowerTrain(d.mass * arm**2, None, None, d.damping * arm**2, d.load * arm, d.cam_inertia)
        except InputError as exc:
            problems.append(("cam.dynamics", str(exc)))
    return (None if problems else CamModel(prog, follower, prof, train, arm)), problems


def _spring(problem: CamProblem, model: CamModel):

    s = problem.cam.spring
    arm = model.arm
    train = replace(model.train, spring_rate=None if s.rate is None else s.rate * arm**2,
                    preload=None if s.rate is not None and s.preload is None else (s.preload or 0.0) * arm)
    try:
        return train, size_spring(model.program, train, float(problem.cam.speed), s.margin, 3600)
    except InputError as exc:
        raise ProblemFileError([("cam.spring.preload", str(exc))]) from None


def check(problem: CamProblem, model: CamModel | None) -> list[str]:
    """Every validation the analysis relies on; returns the program's jumps as warnings."""
    if model is None:
        return []
    if model.train is not None:
        _spring(problem, model)
    return jump_warnings(model)


def jump_warnings(model: CamModel) -> list[str]:
    """The program's jumps of velocity or acceleration, each said once, in the unit of the follower's lift."""
    unit = "rad" if model.follower.motion == "oscillating" else "m"
    return [f"the motion program has {j.describe(unit)}" for j in model.program.jumps]


def analyse(problem: CamProblem, model: CamModel, step: Step) -> Outcome:
    step("profile and checks")
    cam = problem.cam
    prof = model.profile
    limit = cam.checks.pressure_angle_limit
    chk = check_cam(prof, model.program, pressure_limit=None if limit is None else float(limit),
                    curvature_factor=cam.checks.curvature_factor, face_margin=float(cam.checks.face_margin),
                    face_width=None if cam.checks.face_width is None else float(cam.checks.face_width))
    speed = float(cam.speed)
    m = prof.svaj
    v, a, j = m.per_second(speed)
    osc = model.follower.motion == "oscillating"
    values: dict[str, Any] = {
        "cam.speed": speed, "cam.base_radius": float(cam.base_radius), "cam.stroke": model.program.stroke,
        "cam.max_velocity": float(np.max(np.abs(v))), "cam.max_acceleration": float(np.max(np.abs(a))),
        "cam.max_jerk": float(np.max(np.abs(j))), "cam.max_pressure_angle": chk.max_pressure_angle,
        "cam.pressure_angle_limit": chk.pressure_angle_limit, "cam.jumps": float(len(model.program.jumps)),
    }
    flat = model.follower.contact == "flat"
    if np.isfinite(chk.min_pitch_radius) and not flat:  # a flat face's "pitch curve" is the surface itself
        values["cam.min_pitch_curvature_radius"] = chk.min_pitch_radius
    if np.isfinite(chk.min_surface_radius):
        values["cam.min_surface_curvature_radius"] = chk.min_surface_radius
    warnings = jump_warnings(model) + list(chk.warnings)
    failed = list(chk.failed)
    rim = rim_speed_failure(float(np.max(np.hypot(prof.surface[0], prof.surface[1]))), speed)
    if rim is not None:
        failed.insert(0, rim)
    for key, val in (("cam.min_base_radius_pressure", chk.min_base_radius_pressure),
                     ("cam.min_base_radius_curvature", chk.min_base_radius_curvature)):
        if flat and key == "cam.min_base_radius_pressure":
            continue  # the face is square to the path: the pressure angle is 0 whatever the base circle
        if np.isfinite(val):
            values[key] = val
        else:
            warnings.append(f"no base circle that assembles with this follower meets the limit ({key})")
    if model.follower.contact == "flat":
        values["cam.face_width"] = chk.face_width
    spring = forces = sim = sized = None
    if model.train is not None:
        step("spring, forces and simulation")
        train, spring = _spring(problem, model)
        sized = train
        forces = cam_forces(model.program, train, spring, speed, m.theta, prof.pressure_angle,
                            model.arm if osc else None)
        arm = model.arm
        values |= {"cam.spring_rate": spring.rate / arm**2, "cam.spring_preload": spring.preload / arm,
                   "cam.min_contact_force": float(np.min(forces.contact)) / arm,
                   "cam.max_contact_force": float(np.max(forces.contact)) / arm,
                   "cam.max_normal_force": float(np.max(forces.normal)),
                   "cam.peak_torque": float(np.max(np.abs(forces.torque))),
                   "cam.rms_torque": float(np.sqrt(np.mean(forces.torque**2))),
                   "cam.work_per_cycle": forces.work_per_cycle,
                   "cam.mean_power": forces.work_per_cycle * speed / (2 * np.pi),
                   "cam.peak_power": float(np.max(np.abs(forces.torque))) * speed,
                   "cam.max_reduced_inertia": float(np.max(train.cam_inertia + train.mass * m.v**2))}
        if np.isfinite(forces.jump_speed):
            values["cam.jump_speed"] = forces.jump_speed
            values["cam.jump_speed_ratio"] = forces.jump_speed / speed
        need = 1.0 + cam.spring.margin
        if forces.jump_speed < need * speed * (1 - 1e-9):
            failed.append(f"follower jump: the spring keeps contact only up to {forces.jump_speed * 30 / np.pi:.4g} "
                          f"rpm, below the running speed x {need:g} = {need * speed * 30 / np.pi:.4g} rpm")
        if cam.dynamics is not None and cam.dynamics.simulate:
            sim = simulate_follower(model.program, train, spring, speed)
            values["cam.simulated_max_separation"] = max(sim.max_separation, 0.0) * (arm if osc else 1.0)
            if not sim.kept_contact:
                failed.append(f"the simulated follower leaves the cam by {sim.max_separation * 1e3:.3g} "
                              f"{'mrad' if osc else 'mm'} at the running speed")
    labels = {}
    if osc:
        labels = {k: Label(t, u[0], u[1], over=over, better=better)
                  for k, (t, _, u, over, better) in _MOTION_LABELS.items()}
    each = strokes(model.program, model.follower, speed, sized, spring, model.arm)
    for stroke in each:
        values |= {stroke.key(name): value for name, value in stroke.figures.items()}
    for name in ("max_velocity", "max_acceleration", "max_jerk"):  # the turn's peak is its strokes' exact one
        exact = [stroke.figures[name] for stroke in each if name in stroke.figures]
        if exact:
            values[f"cam.{name}"] = max(values[f"cam.{name}"], *exact)
    labels |= stroke_labels(each, osc)
    result = CamResult(model, speed, chk, spring, forces, sim, cam.rotation == "cw",
                       None if cam.checks.face_width is None else float(cam.checks.face_width), each)
    return Outcome(results=result, scalars=values, labels=labels, series=_series(result, osc),
                   files=_files(problem, prof), summary=tuple(k for k in SUMMARY if k in values),
                   warnings=tuple(warnings), failed_checks=tuple(failed))


def stroke_labels(each: tuple[Stroke, ...], osc: bool) -> dict[str, Label]:
    """The labels of the strokes' results (``cam.segment<n>.<figure>``), in the follower's units."""
    out = {}
    for stroke in each:
        for name in stroke.figures:
            text, translating, oscillating = FIGURES[name]
            unit = oscillating if osc else translating
            smallest = name.startswith("min_")
            out[stroke.key(name)] = Label(f"Segment {stroke.number} ({stroke.motion}): {text}", unit,
                                          DISPLAY.get(unit), over="min" if smallest else "max_abs",
                                          better="higher" if smallest else "lower")
    return out


def result_keys(problem: CamProblem) -> dict[str, str]:
    """{key: SI unit} of the results a run of ``problem`` may report: the cam's declared results and its strokes'
    (``cam.segment<n>.<figure>``, found on the built program without forces, which a follower train adds); {}
    for a file whose cam cannot be built (its problems are reported by the build)."""
    model, problems = build(problem)
    if problems or model is None:
        return {}
    osc = model.follower.motion == "oscillating"
    each = strokes(model.program, model.follower, float(problem.cam.speed))
    out = {key: lab.unit for key, lab in LABELS.items()}
    force_figures = ("max_contact_force", "max_normal_force", "peak_torque") if model.train is not None else ()
    for stroke in each:
        for name in (*stroke.figures, *force_figures):
            out[stroke.key(name)] = FIGURES[name][2 if osc else 1]
    return out


#: How the strokes' results are shown: SI unit -> display unit.
DISPLAY = {"rad": "deg", "m": "mm"}


def _series(r: CamResult, osc: bool) -> dict[str, Any]:
    m = r.model.profile.svaj
    v, a, j = m.per_second(r.speed)
    u = "rad" if osc else "m"
    p = r.model.profile
    out: dict[str, Any] = {
        "cam_svaj": {"cam_angle": (m.theta, "rad"), "s": (m.s, u), "v": (m.v, f"{u}/rad"),
                     "a": (m.a, f"{u}/rad^2"), "j": (m.j, f"{u}/rad^3"), "velocity": (v, f"{u}/s"),
                     "acceleration": (a, f"{u}/s^2"), "jerk": (j, f"{u}/s^3")},
        "cam_profile": {"cam_angle": (m.theta, "rad"), "surface_x": (p.surface[0], "m"),
                        "surface_y": (p.surface[1], "m"), "pitch_x": (p.pitch[0], "m"), "pitch_y": (p.pitch[1], "m"),
                        "cutter_x": (p.cutter[0], "m"), "cutter_y": (p.cutter[1], "m"),
                        "pressure_angle": (p.pressure_angle, "rad"),
                        "pitch_curvature_radius": (np.clip(p.pitch_curvature_radius, -1e9, 1e9), "m"),
                        "surface_curvature_radius": (np.clip(p.surface_curvature_radius, -1e9, 1e9), "m")},
    }
    if r.forces is not None:
        f = r.forces
        arm = r.model.arm
        out["cam_forces"] = {"cam_angle": (m.theta, "rad"), "contact_force": (f.contact / arm, "N"),
                             "normal_force": (f.normal, "N"), "spring_force": (f.spring / arm, "N"),
                             "inertia_force": (f.inertia / arm, "N"), "camshaft_torque": (f.torque, "N*m")}
    return out


def _files(problem: CamProblem, prof: Any) -> dict[str, str]:
    if not problem.cam.output.dxf:
        return {}
    curves = {"CAM": prof.surface}
    if prof.follower.contact == "roller":
        curves["PITCH"] = prof.pitch
    curves["CUTTER"] = prof.cutter
    return {"cam_profile.dxf": profile_dxf(curves)}


KIND = ProblemKind(
    name="cam",
    schema=CamProblem,
    build=build,
    check=check,
    analyse=analyse,
    title=lambda problem: problem.meta.name,
    steps=("profile and checks", "spring, forces and simulation"),
    labels=LABELS,
    report="machdyn.report.cams:sections",
    result_keys=result_keys,
    population="machdyn.cams.kind_population:population",
)
