"""Bench of the machine in time (:mod:`machdyn.transient`).

1. A 20 s run-up of the rotary screen (examples/rotary_screen_start_stop.toml) on its sprung base frame with its
   4 kW induction motor (crank, motor and the frame's three degrees of freedom). Target: <= 2 s on one core.
   Prints the time, the evaluations, the energy balance error and the passage figures.
2. Side by side with exudyn on the same coupled model: a slider-crank (crank 50 mm, rod 300 mm; 5, 8 and 60 kg)
   with a 2 kg*m^2 flywheel on a 600 kg frame (its centre off the crank's pivot) on four spring-dampers (two
   vertical, two horizontal), started from rest by a 1.5 kW induction motor through a 5:1 gear whose stator sits
   on the frame, through the frame's horizontal modes (3 Hz) to 31 rad/s in 1 s. exudyn builds it as a multibody
   system (four rigid bodies, three revolute joints and a prismatic joint on the frame body, Cartesian
   spring-dampers to the ground, the motor's torque between crank and frame by a user function) and integrates
   it with its generalised-alpha (Newmark, index 2) solver at a fixed step; machdyn integrates its four
   coordinates (phi, x, y, beta). Agreement: the largest difference over the run of the crank speed, the frame's
   displacements and the mounts' forces, relative to the largest value of each; times min/median/max over
   repeats (machdyn's including the model's build, exudyn's including its assembly). exudyn is in the ``bench``
   extra; without it this part is skipped with a line that says so.

    PYTHONPATH=src python bench/transient.py [--strict] [--quick] [--repeats N] [--steps N,N]
    (--strict: exit 1 above the 2 s target)

The last line printed is one JSON object.
"""

from __future__ import annotations

import argparse
import json
import math
import re
import statistics
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
try:
    import machdyn  # noqa: F401
except ImportError:
    sys.path.insert(0, str(ROOT / "src"))

from machdyn.dynamics import InductionMotor  # noqa: E402
from machdyn.linkage import kinematics, slider_crank  # noqa: E402
from machdyn.runner import run_problem  # noqa: E402
from machdyn.transient import Exciter, Scenario, coupled_model, run_scenario  # noqa: E402
from machdyn.transient.passage import passages  # noqa: E402
from machdyn.vibration.frame import Frame, Mount  # noqa: E402

EXAMPLE = ROOT / "examples" / "rotary_screen_start_stop.toml"
TARGET = 2.0  # [s] for the 20 s run-up

# the side-by-side model
RPM = math.pi / 30.0
CRANK, ROD = 0.05, 0.3  # m
MASSES, INERTIAS = (5.0, 8.0, 60.0), (0.01, 0.06, 0.5)  # kg, kg*m^2: crank, rod, slider
FLYWHEEL = 2.0  # kg*m^2
MOTOR = dict(rated_power=1500.0, rated_speed=1440 * RPM, synchronous_speed=1500 * RPM, breakdown_ratio=2.5,
             ratio=5.0)
FRAME_MASS, FRAME_INERTIA, FRAME_COM = 600.0, 150.0, (0.3, -0.2)
#: name, position [m], direction [deg] (0 or 90: exudyn's Cartesian spring-damper), stiffness [N/m], damping [N*s/m]
MOUNTS = (("v1", (0.8, -0.4), 90.0, 4e5, 2e3), ("v2", (-0.4, -0.4), 90.0, 4e5, 2e3),
          ("h1", (0.8, -0.4), 0.0, 1.2e5, 1.5e3), ("h2", (-0.4, -0.4), 0.0, 1.2e5, 1.5e3))
DURATION = 1.0  # s


def run_up(repeats: int) -> dict[str, Any]:
    """The rotary screen's 20 s run-up (part 1)."""
    text = EXAMPLE.read_text(encoding="utf-8")
    # the run-up alone: no switch-off, no brake, a short run to build the model
    text = re.sub(r"(?m)^(switch_off|brake_time|brake_torque) = .*$", "", text)
    text = re.sub(r'(?m)^duration = .*$', 'duration = "0.5 s"', text)
    built = run_problem(text).outcomes["transient"].results
    model = built.run.model
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        run = run_scenario(model, Scenario(duration=20.0, rtol=1e-9))
        times.append(time.perf_counter() - start)
    found = passages(run, built.modes.angular_frequencies, built.point, built.direction)
    print(f"rotary screen, 20 s run-up on its mounts: min/median/max {min(times):.3f} / "
          f"{statistics.median(times):.3f} / {max(times):.3f} s over {repeats}, {run.evaluations} evaluations, "
          f"{run.t.size} samples, energy balance error {run.energy_error:.2e}, final speed "
          f"{run.omega[0, -1]:.4f} rad/s")
    for p in found:
        print(f"  mode {p.mode} ({p.frequency / (2 * math.pi):.3f} Hz) {p.direction} at {p.time:.3f} s: peak "
              f"{p.peak_amplitude * 1e3:.3f} mm, mount force {p.peak_mount_force:.1f} N, {p.time_in_band:.3f} s "
              "in the band")
    return {"seconds": stats(times), "target": TARGET, "evaluations": run.evaluations,
            "energy_error": run.energy_error}


def _parts():
    mech = slider_crank(CRANK, ROD, masses=MASSES, inertias=INERTIAS, gravity=(0.0, 0.0))
    frame = Frame(FRAME_MASS, FRAME_INERTIA, tuple(Mount(n, p, math.radians(d), k, c) for n, p, d, k, c in MOUNTS),
                  com=FRAME_COM)
    return mech, InductionMotor(**MOTOR), frame


def machdyn_side() -> dict[str, np.ndarray]:
    """machdyn's run of the side-by-side model, from the model's build."""
    mech, motor, frame = _parts()
    model = coupled_model([Exciter(mech, motor, FLYWHEEL)], frame)
    run = run_scenario(model, Scenario(duration=DURATION, rtol=1e-9))
    return {"t": run.t, "omega": run.omega[0], "q": run.q, "force": run.mount_force,
            "evaluations": np.array(run.evaluations), "energy_error": np.array(run.energy_error)}


def exudyn_side(steps: int) -> dict[str, np.ndarray]:
    """exudyn's run of the side-by-side model, from its build: crank speed relative to the frame, the frame's
    reference point (its origin) and rotation, the mounts' forces along their lines."""
    import exudyn as exu
    from exudyn.itemInterface import (
        LoadTorqueVector,
        MarkerBodyPosition,
        MarkerBodyRigid,
        NodeRigidBody2D,
        ObjectConnectorCartesianSpringDamper,
        ObjectGround,
        ObjectJointPrismatic2D,
        ObjectJointRevolute2D,
        ObjectRigidBody2D,
        SensorNode,
        SensorObject,
    )

    mech, motor, _ = _parts()
    kin = kinematics(mech, 0.0, 0.0, 0.0)
    mbs = exu.SystemContainer().AddSystem()
    ground = mbs.AddObject(ObjectGround())
    cf = np.asarray(FRAME_COM, dtype=float)
    frame_node = mbs.AddNode(NodeRigidBody2D(referenceCoordinates=[cf[0], cf[1], 0.0]))
    frame_body = mbs.AddObject(ObjectRigidBody2D(mass=FRAME_MASS, inertia=FRAME_INERTIA, nodeNumber=frame_node))

    def on_frame(point, rigid=False):
        kind = MarkerBodyRigid if rigid else MarkerBodyPosition
        return mbs.AddMarker(kind(bodyNumber=frame_body, localPosition=[point[0] - cf[0], point[1] - cf[1], 0.0]))

    nodes, bodies = {}, {}
    for b in mech.bodies:  # each body at its place at phi = 0, the flywheel on the crank
        com, angle = kin.com(b.name), float(np.ravel(kin.body(b.name).angle)[0])
        inertia = float(b.inertia) + (FLYWHEEL if b.name == mech.crank.body else 0.0)
        nodes[b.name] = mbs.AddNode(NodeRigidBody2D(
            referenceCoordinates=[float(np.ravel(com.x)[0]), float(np.ravel(com.y)[0]), angle]))
        bodies[b.name] = mbs.AddObject(ObjectRigidBody2D(mass=float(b.mass), inertia=inertia,
                                                         nodeNumber=nodes[b.name]))

    def on_body(name, point, rigid=False):
        body = next(b for b in mech.bodies if b.name == name)
        local = np.asarray(body.points[point], dtype=float) - np.asarray(body.com, dtype=float)
        kind = MarkerBodyRigid if rigid else MarkerBodyPosition
        return mbs.AddMarker(kind(bodyNumber=bodies[name], localPosition=[local[0], local[1], 0.0]))

    pivot, slide = mech.ground["O"], mech.ground["S"]
    mbs.AddObject(ObjectJointRevolute2D(markerNumbers=[on_frame(pivot), on_body("crank", "O")]))
    mbs.AddObject(ObjectJointRevolute2D(markerNumbers=[on_body("crank", "A"), on_body("rod", "A")]))
    mbs.AddObject(ObjectJointRevolute2D(markerNumbers=[on_body("rod", "B"), on_body("slider", "B")]))
    mbs.AddObject(ObjectJointPrismatic2D(markerNumbers=[on_frame(slide, True), on_body("slider", "B", True)],
                                         axisMarker0=[1.0, 0.0, 0.0], normalMarker1=[0.0, 1.0, 0.0],
                                         constrainRotation=True))
    mount_sensors = []
    for _, position, degrees, rate, damping in MOUNTS:
        fixed = mbs.AddMarker(MarkerBodyPosition(bodyNumber=ground, localPosition=[position[0], position[1], 0.0]))
        line = np.array([math.cos(math.radians(degrees)), math.sin(math.radians(degrees))]).round(12)
        spring = mbs.AddObject(ObjectConnectorCartesianSpringDamper(
            markerNumbers=[fixed, on_frame(position)], stiffness=[rate * line[0] ** 2, rate * line[1] ** 2, 0.0],
            damping=[damping * line[0] ** 2, damping * line[1] ** 2, 0.0]))
        mount_sensors.append((line, mbs.AddSensor(SensorObject(objectNumber=spring, storeInternal=True,
                                                               outputVariableType=exu.OutputVariableType.Force))))
    crank_node = nodes[mech.crank.body]
    spin = exu.OutputVariableType.AngularVelocity

    def torque(mbs_):  # the motor's torque at the crank's speed relative to the frame (its stator)
        return float(motor.torque_at(mbs_.GetNodeOutput(crank_node, spin)[2] - mbs_.GetNodeOutput(frame_node, spin)[2]))

    on_crank: Any = lambda mbs_, t, load: [0.0, 0.0, torque(mbs_)]  # noqa: E731
    on_stator: Any = lambda mbs_, t, load: [0.0, 0.0, -torque(mbs_)]  # noqa: E731
    mbs.AddLoad(LoadTorqueVector(markerNumber=on_body("crank", "O", True), loadVector=[0.0, 0.0, 0.0],
                                 loadVectorUserFunction=on_crank))
    mbs.AddLoad(LoadTorqueVector(markerNumber=on_frame(pivot, True), loadVector=[0.0, 0.0, 0.0],
                                 loadVectorUserFunction=on_stator))
    kinds = {"crank_w": (crank_node, spin), "frame_w": (frame_node, spin),
             "frame_p": (frame_node, exu.OutputVariableType.Position),
             "frame_r": (frame_node, exu.OutputVariableType.Rotation)}
    sensors = {key: mbs.AddSensor(SensorNode(nodeNumber=n, storeInternal=True, outputVariableType=v))
               for key, (n, v) in kinds.items()}
    mbs.Assemble()
    settings = exu.SimulationSettings()
    settings.timeIntegration.numberOfSteps = steps
    settings.timeIntegration.endTime = DURATION
    settings.timeIntegration.generalizedAlpha.spectralRadius = 1.0
    settings.timeIntegration.generalizedAlpha.useIndex2Constraints = True
    settings.timeIntegration.generalizedAlpha.useNewmark = True
    settings.timeIntegration.newton.relativeTolerance = 1e-10
    settings.timeIntegration.newton.absoluteTolerance = 1e-12
    settings.timeIntegration.verboseMode = 0
    settings.solution.file.write = False
    settings.solution.sensors.writePeriod = DURATION / steps
    exu.SolveDynamic(mbs, simulationSettings=settings)
    data = {key: np.asarray(mbs.GetSensorStoredData(s)) for key, s in sensors.items()}
    beta = data["frame_r"][:, -1]
    centre = data["frame_p"][:, 1:3]
    # the frame's reference point from its centre: centre = origin + R(beta) c
    qx = centre[:, 0] - (np.cos(beta) * cf[0] - np.sin(beta) * cf[1])
    qy = centre[:, 1] - (np.sin(beta) * cf[0] + np.cos(beta) * cf[1])
    forces = np.stack([np.asarray(mbs.GetSensorStoredData(s))[:, 1:3] @ line for line, s in mount_sensors])
    return {"t": data["crank_w"][:, 0], "omega": data["crank_w"][:, 3] - data["frame_w"][:, 3],
            "q": np.stack([qx, qy, beta]), "force": forces}


def agreement(mine: dict[str, np.ndarray], theirs: dict[str, np.ndarray]) -> dict[str, float]:
    """Largest difference over the run relative to the largest value, each channel (exudyn's fine fixed-step
    output interpolated to machdyn's times)."""
    t = mine["t"]

    def rel(a, b):
        return float(np.max(np.abs(a - np.interp(t, theirs["t"], b))) / np.max(np.abs(a)))

    out = {"crank_speed": rel(mine["omega"], theirs["omega"])}
    for i, name in enumerate(("x", "y", "beta")):
        out[f"frame_{name}"] = rel(mine["q"][i], theirs["q"][i])
    for i, mount in enumerate(MOUNTS):
        out[f"mount_{mount[0]}"] = rel(mine["force"][i], theirs["force"][i])
    return out


def side_by_side(repeats: int, steps: list[int]) -> dict[str, Any]:
    """Part 2: machdyn against exudyn on the same coupled model, exudyn at each of ``steps`` fixed steps."""
    try:
        import exudyn  # noqa: F401
    except ImportError as exc:
        print(f"exudyn side by side: skipped, exudyn cannot be imported ({exc}); install the bench extra "
              "(pip install -e .[bench])")
        return {"skipped": str(exc)}
    holder: dict[str, Any] = {}
    machdyn_side()  # warm-up: imports and caches, as in any repeated use
    t_md = timed(lambda: holder.__setitem__("md", machdyn_side()), repeats)
    md = holder["md"]
    print(f"side by side, a slider-crank on a 600 kg sprung frame, {DURATION:g} s from rest to "
          f"{md['omega'][-1]:.3f} rad/s, largest frame rotation {np.max(np.abs(md['q'][2])):.2e} rad:")
    print(f"  machdyn {int(md['evaluations'])} evaluations, energy balance {float(md['energy_error']):.1e}; time "
          f"min/median/max {min(t_md):.3f} / {statistics.median(t_md):.3f} / {max(t_md):.3f} s")
    out: dict[str, Any] = {"duration": DURATION, "machdyn_s": stats(t_md), "exudyn": []}
    for n in steps:
        t_ex = timed(lambda n=n: holder.__setitem__("ex", exudyn_side(n)), repeats)
        agree = agreement(md, holder["ex"])
        ratio = {"min": min(t_ex) / max(t_md), "median": statistics.median(t_ex) / statistics.median(t_md),
                 "max": max(t_ex) / min(t_md)}
        print(f"  exudyn {n} steps (final speed {holder['ex']['omega'][-1]:.3f} rad/s): time min/median/max "
              f"{min(t_ex):.3f} / {statistics.median(t_ex):.3f} / {max(t_ex):.3f} s; exudyn / machdyn "
              f"{ratio['min']:.1f} / {ratio['median']:.1f} / {ratio['max']:.1f}x")
        print("    agreement (largest difference over the run / largest value): "
              + ", ".join(f"{k} {v:.1e}" for k, v in agree.items()))
        out["exudyn"].append({"steps": n, "seconds": stats(t_ex), "ratio": ratio, "agreement": agree})
    return out


def timed(fn, repeats: int) -> list[float]:
    out = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        out.append(time.perf_counter() - start)
    return out


def stats(values: list[float]) -> dict[str, float]:
    return {"min": min(values), "median": statistics.median(values), "max": max(values)}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--strict", action="store_true", help="exit 1 when the run-up is above its target")
    parser.add_argument("--quick", action="store_true", help="one repeat of each")
    parser.add_argument("--repeats", type=int, default=None)
    parser.add_argument("--steps", default="1000,10000",
                        help="exudyn's fixed steps over the side-by-side run, comma-separated (default 1000,10000: "
                             "its step error below the models' difference, and converged to 1e-7)")
    args = parser.parse_args()
    repeats = args.repeats or (1 if args.quick else 3)
    result: dict[str, Any] = {"bench": "transient", "run_up": run_up(repeats),
                              "exudyn": side_by_side(repeats, [int(v) for v in args.steps.split(",")])}
    print(json.dumps(result))
    if args.strict and result["run_up"]["seconds"]["min"] > TARGET:
        sys.exit(1)


if __name__ == "__main__":
    main()
