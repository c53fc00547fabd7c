"""Benchmark: the periodic steady state of the benchmark four-bar under an induction motor with a flywheel,
machdyn against a full multibody simulation of the same machine by exudyn.

The machine: the four-bar of ``bench/peers.py`` (crank 40, coupler 120, rocker 80, ground 100 mm; uniform bars of
1 kg/m; gravity), a flywheel on the crank, a viscous rotary damper on the rocker (the load), and a 4-pole cage motor
(Kloss characteristic) through a 15:1 gear. machdyn finds the periodic steady state directly (shooting on the
reduced one-degree-of-freedom machine); exudyn integrates the three rigid bodies with their joints (redundant
coordinates, index-2 implicit trapezoidal rule) from machdyn's steady state at phi = 0 through one cycle. The speed
traces are compared as functions of the crank angle; the period times too. Timings: min/median/max over repeats,
machdyn's including the reduction of the linkage, exudyn's including the model build.

Usage: ``python bench/dynamics.py [--quick] [--repeats N] [--steps N]``. The last line printed is one JSON object.
"""

from __future__ import annotations

import argparse
import json
import math
import statistics
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parent.parent

CRANK, COUPLER, ROCKER, GROUND = 0.040, 0.120, 0.080, 0.100  # m
DENSITY = 1.0  # kg/m, uniform bars
G = 9.80665
FLYWHEEL = 0.04  # kg*m^2 on the crank
DAMPER = 0.01  # N*m*s/rad on the rocker, relative to the frame
RPM = math.pi / 30.0
MOTOR = dict(rated_power=10.0, rated_speed=1440 * RPM, synchronous_speed=1500 * RPM, breakdown_ratio=2.5,
             ratio=15.0)
TARGET_AGREEMENT = 1e-6  # relative to the mean speed
TARGET_SPEEDUP = 20.0


def import_machdyn():
    try:
        import machdyn.dynamics as dyn
    except ImportError:
        sys.path.insert(0, str(ROOT / "src"))
        import machdyn.dynamics as dyn
    return dyn


def machdyn_steady():
    dyn = import_machdyn()
    from machdyn.linkage import four_bar

    mech = four_bar(CRANK, COUPLER, ROCKER, GROUND, linear_density=DENSITY)
    machine = dyn.equivalent_machine(mech, 360, speed_loads=(dyn.RotaryDamper("damper", "rocker", DAMPER),))
    motor = dyn.InductionMotor(**MOTOR)
    return mech, dyn.steady_state(machine, motor, FLYWHEEL)


def exudyn_cycle(mech, omega0: float, period: float, steps: int) -> dict[str, Any]:
    """Simulate with exudyn for ``period`` [s] in ``steps`` steps from phi = 0 at crank speed ``omega0`` (the
    steady state's, or 0 for a start from rest); returns time, crank angle and speed."""
    import exudyn as exu
    from exudyn.itemInterface import (
        LoadForceVector,
        LoadTorqueVector,
        MarkerBodyPosition,
        MarkerBodyRigid,
        MarkerNodeCoordinate,
        NodePointGround,
        NodeRigidBody2D,
        ObjectConnectorCoordinateSpringDamper,
        ObjectGround,
        ObjectJointRevolute2D,
        ObjectRigidBody2D,
        SensorNode,
    )

    from machdyn.linkage import kinematics

    kin = kinematics(mech, 0.0, omega0, 0.0)
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    ground = mbs.AddObject(ObjectGround())
    nodes, bodies = {}, {}
    lengths = {"crank": CRANK, "coupler": COUPLER, "rocker": ROCKER}
    for name, length in lengths.items():
        com, body = kin.com(name), kin.body(name)
        mass = DENSITY * length
        inertia = mass * length**2 / 12.0 + (FLYWHEEL if name == "crank" else 0.0)
        theta = float(np.ravel(body.angle)[0])
        node = mbs.AddNode(NodeRigidBody2D(referenceCoordinates=[float(com.x), float(com.y), theta],
                                           initialVelocities=[float(com.vx), float(com.vy),
                                                              float(np.ravel(body.omega)[0])]))
        b = mbs.AddObject(ObjectRigidBody2D(physicsMass=mass, physicsInertia=inertia, nodeNumber=node))
        nodes[name], bodies[name] = node, b
        m_mass = mbs.AddMarker(MarkerBodyRigid(bodyNumber=b, localPosition=[0.0, 0.0, 0.0]))
        mbs.AddLoad(LoadForceVector(markerNumber=m_mass, loadVector=[0.0, -G * mass, 0.0]))

    def pin(body, along):  # a point on a bar at distance 'along' from its first joint (COM at mid-length)
        return mbs.AddMarker(MarkerBodyPosition(bodyNumber=bodies[body],
                                                localPosition=[along - lengths[body] / 2.0, 0.0, 0.0]))

    def ground_pin(x, y):
        return mbs.AddMarker(MarkerBodyPosition(bodyNumber=ground, localPosition=[x, y, 0.0]))

    mbs.AddObject(ObjectJointRevolute2D(markerNumbers=[ground_pin(0.0, 0.0), pin("crank", 0.0)]))
    mbs.AddObject(ObjectJointRevolute2D(markerNumbers=[pin("crank", CRANK), pin("coupler", 0.0)]))
    mbs.AddObject(ObjectJointRevolute2D(markerNumbers=[pin("coupler", COUPLER), pin("rocker", ROCKER)]))
    mbs.AddObject(ObjectJointRevolute2D(markerNumbers=[ground_pin(GROUND, 0.0), pin("rocker", 0.0)]))
    # the rocker's damper: a coordinate damper on its rotation against a fixed coordinate
    fixed = mbs.AddNode(NodePointGround())
    m_fixed = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=fixed, coordinate=0))
    m_rot = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=nodes["rocker"], coordinate=2))
    mbs.AddObject(ObjectConnectorCoordinateSpringDamper(markerNumbers=[m_fixed, m_rot], stiffness=0.0,
                                                        damping=DAMPER))
    # the motor: Kloss torque of the crank speed through the gear
    dyn = import_machdyn()
    motor = dyn.InductionMotor(**MOTOR)
    crank_node = nodes["crank"]

    def motor_torque(mbs_, t, load):
        w = mbs_.GetNodeOutput(crank_node, exu.OutputVariableType.AngularVelocity)[2]
        return [0.0, 0.0, float(motor.torque_at(w))]

    m_crank = mbs.AddMarker(MarkerBodyRigid(bodyNumber=bodies["crank"], localPosition=[0.0, 0.0, 0.0]))
    mbs.AddLoad(LoadTorqueVector(markerNumber=m_crank, loadVector=[0.0, 0.0, 0.0],
                                 loadVectorUserFunction=motor_torque))
    s_pos = mbs.AddSensor(SensorNode(nodeNumber=crank_node, storeInternal=True,
                                     outputVariableType=exu.OutputVariableType.Rotation))
    s_vel = mbs.AddSensor(SensorNode(nodeNumber=crank_node, storeInternal=True,
                                     outputVariableType=exu.OutputVariableType.AngularVelocity))
    mbs.Assemble()
    settings = exu.SimulationSettings()
    settings.timeIntegration.numberOfSteps = steps
    settings.timeIntegration.endTime = period
    settings.timeIntegration.generalizedAlpha.spectralRadius = 1.0
    settings.timeIntegration.generalizedAlpha.useIndex2Constraints = True
    settings.timeIntegration.generalizedAlpha.useNewmark = True
    settings.timeIntegration.newton.relativeTolerance = 1e-12
    settings.timeIntegration.newton.absoluteTolerance = 1e-12
    settings.timeIntegration.verboseMode = 0
    settings.solutionSettings.writeSolutionToFile = False
    settings.solutionSettings.sensorsWritePeriod = period / steps
    exu.SolveDynamic(mbs, simulationSettings=settings)
    rot = np.asarray(mbs.GetSensorStoredData(s_pos))
    vel = np.asarray(mbs.GetSensorStoredData(s_vel))
    return {"t": rot[:, 0], "phi": np.unwrap(rot[:, -1]), "omega": vel[:, 3]}


def compare(ss, ex, last_cycle: bool = False) -> dict[str, float]:
    """The exudyn speed trace against machdyn's steady state omega(phi), relative to the mean speed (over the
    last full turn only for a start from rest), and the time exudyn takes for that turn against the period."""
    curve = ss.speed_curve()
    phi, t, omega = ex["phi"], ex["t"], ex["omega"]
    start = 2 * np.pi * (np.floor(phi[-1] / (2 * np.pi)) - 1) if last_cycle else 0.0
    keep = (phi >= start) & (phi <= start + 2 * np.pi)
    mean = float(ss.mean_speed)
    diff = np.abs(omega[keep] - curve(phi[keep])) / mean
    turn = float(np.interp(start + 2 * np.pi, phi, t) - np.interp(start, phi, t))
    return {"speed_max_rel": float(np.max(diff)), "period_rel": abs(turn / float(ss.period_time) - 1.0)}


def machdyn_batch(designs: int):
    """``designs`` flywheels from 0.02 to 0.08 kg*m^2, all in one steady-state call."""
    dyn = import_machdyn()
    from machdyn.linkage import four_bar

    mech = four_bar(CRANK, COUPLER, ROCKER, GROUND, linear_density=DENSITY)
    machine = dyn.equivalent_machine(mech, 360, speed_loads=(dyn.RotaryDamper("damper", "rocker", DAMPER),))
    return dyn.steady_state(machine, dyn.InductionMotor(**MOTOR), np.linspace(0.02, 0.08, designs))


def timed(fn, repeats: int) -> list[float]:
    out = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        out.append(time.perf_counter() - t0)
    return out


def stats(values: list[float]) -> dict[str, float]:
    return {"min": min(values), "median": statistics.median(values), "max": max(values)}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="fewer repeats")
    parser.add_argument("--repeats", type=int, default=None)
    parser.add_argument("--steps", type=int, default=500, help="exudyn time steps per cycle")
    parser.add_argument("--designs", type=int, default=64, help="design variants of the batched run")
    args = parser.parse_args()
    repeats = args.repeats or (3 if args.quick else 7)
    mech, ss = machdyn_steady()  # warm-up and the reference
    t_md = timed(machdyn_steady, repeats)
    batch = machdyn_batch(args.designs)
    t_batch = timed(lambda: machdyn_batch(args.designs), max(1, repeats // 2))
    single = machdyn_batch(1)
    reference = np.atleast_2d(single.omega)[0]
    batch_check = float(np.max(np.abs(batch.omega[0] - reference)) / float(np.ravel(single.mean_speed)[0]))
    per_design = [t / args.designs for t in t_batch]
    result: dict[str, Any] = {
        "case": "four-bar 40/120/80/100 mm, flywheel 0.04 kg*m^2, rocker damper 0.01 N*m*s/rad, 10 W 4-pole "
                "motor 15:1",
        "machdyn": {"mean_speed": float(ss.mean_speed), "delta": float(ss.delta), "period": float(ss.period_time),
                    "iterations": ss.iterations, "periodicity": float(ss.residual), "time_s": stats(t_md),
                    "batch": {"designs": args.designs, "time_s": stats(t_batch), "per_design_s": stats(per_design),
                              "first_design_vs_single_rel": batch_check}},
    }
    try:
        import exudyn  # noqa: F401
    except ImportError as exc:
        result["exudyn"] = {"error": f"exudyn cannot be imported ({exc}); install the bench extra"}
    else:
        period = float(ss.period_time)
        holder: dict[str, Any] = {}

        def cycle():
            holder["cycle"] = exudyn_cycle(mech, float(ss.omega[0]), period * 1.01, int(args.steps * 1.01))

        cycles_from_rest = 6

        def from_rest():
            holder["rest"] = exudyn_cycle(mech, 0.0, period * cycles_from_rest, args.steps * cycles_from_rest)

        t_cycle = timed(cycle, repeats)
        t_rest = timed(from_rest, max(1, repeats // 2))
        one = compare(ss, holder["cycle"])
        rest = compare(ss, holder["rest"], last_cycle=True)
        result["exudyn"] = {
            "steps_per_cycle": args.steps,
            "one_cycle_from_machdyn_state": {**one, "time_s": stats(t_cycle)},
            "start_from_rest": {"cycles": cycles_from_rest, **rest, "time_s": stats(t_rest)},
        }

        def ratio(ex_times, md_times):
            return {"min": min(ex_times) / max(md_times), "median": statistics.median(ex_times) /
                    statistics.median(md_times), "max": max(ex_times) / min(md_times)}

        result["speedup"] = {
            "one_cycle_vs_steady_state": ratio(t_cycle, t_md),
            "from_rest_vs_steady_state": ratio(t_rest, t_md),
            "one_cycle_vs_batched_per_design": ratio(t_cycle, per_design),
        }
        result["targets"] = {"agreement": TARGET_AGREEMENT, "speedup": TARGET_SPEEDUP,
                             "agreement_met": one["speed_max_rel"] <= TARGET_AGREEMENT}
    md = result["machdyn"]
    print(f"machdyn steady state: mean speed {md['mean_speed']:.6f} rad/s, delta {md['delta']:.6f}, "
          f"period {md['period']:.6f} s, {md['iterations']} shooting steps (0: Fourier collocation), "
          f"periodicity or truncation {md['periodicity']:.1e}")
    ms = {k: v * 1e3 for k, v in md["time_s"].items()}
    print(f"  one design: time min/median/max {ms['min']:.1f} / {ms['median']:.1f} / {ms['max']:.1f} ms")
    b = md["batch"]
    pd = {k: v * 1e3 for k, v in b["per_design_s"].items()}
    print(f"  {b['designs']} designs in one call: per design min/median/max {pd['min']:.2f} / {pd['median']:.2f} / "
          f"{pd['max']:.2f} ms (first design vs a single run: {b['first_design_vs_single_rel']:.1e})")
    ex = result["exudyn"]
    if "error" in ex:
        print(f"exudyn: {ex['error']}")
    else:
        for key, text in (("one_cycle_from_machdyn_state", "one cycle from machdyn's state"),
                          ("start_from_rest", f"{ex['start_from_rest']['cycles']} cycles from rest, last cycle")):
            e = ex[key]
            print(f"exudyn {text} ({ex['steps_per_cycle']} steps per cycle): speed trace within "
                  f"{e['speed_max_rel']:.2e} of the mean speed, period within {e['period_rel']:.2e}; time "
                  f"min/median/max {e['time_s']['min']:.3f} / {e['time_s']['median']:.3f} / {e['time_s']['max']:.3f} s")
        for key, text in (("one_cycle_vs_steady_state", "exudyn one cycle / machdyn steady state"),
                          ("from_rest_vs_steady_state", "exudyn from rest / machdyn steady state"),
                          ("one_cycle_vs_batched_per_design", "exudyn one cycle / machdyn batched per design")):
            sp = result["speedup"][key]
            print(f"{text}: min/median/max {sp['min']:.1f} / {sp['median']:.1f} / {sp['max']:.1f}x")
    print(json.dumps(result))


if __name__ == "__main__":
    main()
