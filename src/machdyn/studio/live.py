"""What the studio computes on each edit, and what it leaves to the explicit *Full run*.

A live edit must answer within a fraction of a second, so the tables whose stage integrates the machine's motion
in time — ``[flywheel]`` (the motor's choice and its start-up, the periodic steady state, the forces at the real
speed) and the tables that read its result (``[drivetrain]``, ``[parts]``, ``[transient]``) — are left out of the
live run (they take seconds: a few dozen ODE integrations). In their place a linkage file with ``[flywheel]``
gets the flywheel its run would size, from the constant-speed analysis the live run made anyway:

* the exact (energy-mass, Wittenbauer) flywheel of :func:`machdyn.dynamics.population_flywheel.
  exact_flywheel_inertia` on the run's own samples of the reduced moment M(phi) and inertia J(phi) (the
  population path of the studies, one vector pass), less the drive line's shafts, as the ``[flywheel]`` stage
  does for a drive that gives the mean torque at every angle (``size_for = "constant_torque"``);
* the flywheel part (disc or rim) of that inertia at the top speed of the target fluctuation, omega (1 + delta/2)
  (Khurmi & Gupta, *Theory of Machines*, ch. 16), instead of the top speed of the simulated steady state.

*Full run* computes the file as ``machdyn run`` does (its studies aside), with every table.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..dynamics.driveline_file import line_of
from ..dynamics.flywheel import disc_flywheel, rim_flywheel, rim_speed_limit
from ..dynamics.population_flywheel import exact_flywheel_inertia
from ..linkage.motion import is_full_turn

#: tables whose stages simulate the motion in time (seconds per run), deferred to *Full run*
DEFERRED = ("flywheel", "drivetrain", "parts", "transient")
#: tables of studies: never run by the studio (a whole study per edit); ``machdyn run`` runs them
STUDIES = ("sweep", "optimise")


def deferred_tables(spec: Any) -> list[str]:
    """What a live edit of the validated problem ``spec`` leaves out: its deferred tables (``[flywheel]`` ...) in
    :data:`DEFERRED` order, and a cam's forward simulation of its follower."""
    out = [f"[{t}]" for t in DEFERRED if getattr(spec, t, None) is not None]
    dynamics = getattr(getattr(spec, "cam", None), "dynamics", None)
    if dynamics is not None and dynamics.simulate:
        out.append("the simulation of the cam's follower")
    return out


def without_simulation(spec: Any) -> Any:
    """``spec`` with its cam's follower not simulated (``[cam.dynamics] simulate = false``): the closed-form
    contact force, jump speed and spring stay; the simulation took nine tenths of a cam's run."""
    cam: Any = getattr(spec, "cam", None)
    dynamics = getattr(cam, "dynamics", None)
    if cam is None or dynamics is None or not dynamics.simulate:
        return spec
    return spec.model_copy(update={"cam": cam.model_copy(update={"dynamics": dynamics.model_copy(
        update={"simulate": False})})})


def _row(label: str, value: float, unit: str) -> dict[str, Any]:
    return {"label": label, "value": float(value) if np.isfinite(value) else None, "unit": unit, "live": True}


def live_flywheel(problem: Any, analysis: Any) -> list[dict[str, Any]]:
    """Summary rows of the flywheel of a linkage file's ``[flywheel]`` from its constant-speed ``analysis``
    (empty when the file gives none or the analysis is not one evenly sampled full turn)."""
    table = getattr(problem, "flywheel", None)
    energy = getattr(analysis, "energy", None)
    if table is None or energy is None:
        return []
    phi = np.asarray(analysis.kinematics.crank_angle, dtype=float)
    speed = float(problem.drive.speed)
    if not (speed > 0 and is_full_turn(phi)):
        return []
    line = line_of(problem, table)
    added = line.shaft_inertia
    rows = []
    if table.inertia is not None:
        flywheel = line.at_crank(float(table.inertia), line.flywheel_shaft)
        delta = table.delta if table.delta is not None else 0.02
    else:
        delta = table.delta if table.delta is not None else 0.02
        exact = float(exact_flywheel_inertia(phi, energy.reduced_moment, energy.reduced_inertia, speed, delta)[0])
        flywheel = max(exact - added, 0.0)
        rows.append(_row("Flywheel sized by the energy-mass (Wittenbauer) method, constant-torque drive", exact,
                         "kg*m^2"))
    rows.append(_row("Flywheel: moment of inertia, referred to the crank", flywheel, "kg*m^2"))
    if flywheel > 0 and np.isfinite(flywheel):
        limit = table.rim_speed_limit or rim_speed_limit(table.allowable_stress, table.density, table.shape)
        i = line.ratio(line.flywheel_shaft)
        own = line.about_shaft(flywheel, line.flywheel_shaft)
        top = speed * (1.0 + delta / 2.0) * i
        if table.shape == "disc":
            part = disc_flywheel(own, top, width_ratio=table.width_ratio, density=table.density,
                                 rim_speed_limit=limit)
        else:
            part = rim_flywheel(own, speed * i, top, rim_speed=table.rim_speed or 0.8 * limit,
                                width_to_thickness=table.width_to_thickness, density=table.density,
                                rim_speed_limit=limit)
        rows += [_row("Flywheel: outer diameter", 1e3 * part.diameter, "mm"), _row("Flywheel: mass", part.mass, "kg")]
    return rows
