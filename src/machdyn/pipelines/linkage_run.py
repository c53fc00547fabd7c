"""What every kind built on a linkage shares: assemble at every crank angle, analyse, collect the results."""

from __future__ import annotations

import warnings as _warnings
from typing import Any

import numpy as np

from ..errors import InputError, SingularPositionError
from ..linkage import analyse, diagnose, kinematics
from ..linkage.analysis import analysed_range
from ..pipeline import Outcome, Step
from ..problem.build import crank_angles
from ..results.linkage import LINKAGE_SUMMARY, full_uniform_cycle, linkage_scalars, load_powers
from ..results.population import compactor_results


def crank_range(problem: Any) -> tuple[Any, float, float]:
    """(crank angles [rad], speed [rad/s], acceleration [rad/s^2]) of a problem's ``[drive]``."""
    return crank_angles(problem), problem.drive.speed, problem.drive.acceleration


def check_assembly(problem: Any, mech: Any) -> list[str]:
    """Assemble the linkage at every requested crank angle (raises the engine's error if it cannot close);
    returns the diagnostics' warnings (dead positions, ...)."""
    angles, speed, accel = crank_range(problem)
    kinematics(mech, angles, speed, accel, on_fail="raise")
    try:
        return list(diagnose(mech, crank_range=analysed_range(angles)).warnings)
    except (InputError, SingularPositionError):
        return []


def analyse_linkage(problem: Any, mech: Any, step: Step, warnings: list[str] | None = None) -> Outcome:
    """The constant-speed analysis of ``mech`` over the problem's crank range and its scalar results."""
    angles, speed, accel = crank_range(problem)
    step("analysis")
    with _warnings.catch_warnings(record=True) as caught:
        _warnings.simplefilter("always")
        analysis = analyse(mech, angles, speed, accel)
    said = list(warnings or []) + [str(w.message) for w in caught if issubclass(w.category, UserWarning)]
    about = tuple(problem.output.shaking_moment_about)
    notes: list[str] = []
    values, units = linkage_scalars(analysis, mech, about=about, harmonic_orders=problem.output.harmonics,
                                    notes=notes, exact=True)
    said += notes
    if getattr(problem.mechanism, "machine", None) == "compactor" and np.ndim(analysis.forces.driving_torque) == 1:
        values.update(compactor_results(mech, analysis.kinematics))  # the figures a sweep of it reports
    balance = float(np.max(np.atleast_1d(analysis.work_balance.relative)))
    if not balance < 1e-6:
        said.append(
            f"The work-energy balance over the analysed crank angles is off by {balance:.2g} (relative): the "
            "crank speed and acceleration given are not consistent (a constant speed needs zero acceleration), "
            "or the crank angles are too coarse for the trapezoidal rule over a partial range."
        )
    for w in getattr(analysis.diagnostics, "warnings", None) or []:
        if str(w) not in said:
            said.append(str(w))
    if np.ndim(analysis.forces.driving_torque) == 1:
        for name, (mean, rms) in load_powers(analysis).items():
            # Over a whole turn a process load takes work out of the machine; one that puts work in has
            # most likely been given the wrong sign.
            if full_uniform_cycle(analysis.kinematics.crank_angle) and mean > 1e-3 * rms:
                said.append(f"The load '{name}' does positive work over the cycle (mean power {mean:.4g} W): it "
                            "drives the mechanism instead of resisting it. If it is a process load (a cutting, "
                            "pressing or compaction force), reverse its sign or its active window.")
    joints = [k for k in values if k.startswith("joint.")]
    strokes = [k for k in values if k.startswith("stroke.")]
    return Outcome(
        results=analysis, scalars=values, units=units, summary=(*LINKAGE_SUMMARY, *joints, *strokes),
        warnings=tuple(dict.fromkeys(said)), mechanism=mech, analysis=analysis,
    )
