"""The scalar results of a linkage analysis, in SI, computed once for every output.

Extremes of the time series (torque, power, joint forces, frame force, inertial shaking force and moment, the
shaking moment on the frame, energy, reduced inertia),
time means and RMS, the energy a flywheel must store, the work balance, harmonics of the driving torque and the
shaking loads, the diagnostics (strokes, time ratio, transmission angles, dead positions) and the Grashof
margin and class of a four-bar. Every key is declared in :mod:`machdyn.results.catalogue`. For N design
variants each value is a list of N floats.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any

import numpy as np

from ..errors import InputError, SingularPositionError
from ..linkage import analyse, energy_fluctuation, harmonics, inertial_force
from ..linkage import model as _model
from ..linkage.analysis import analysed_range
from ..linkage.extremes import breakpoints, refine
from ..linkage.grashof import grashof_margin
from ..linkage.loads import applied_forces, applied_torques
from ..linkage.mass_centre import inertial_shaking_moment
from ..linkage.model import output_bodies
from ..linkage.motion import is_full_turn
from ..linkage.reductions import REDUCTIONS, reduce, worst_of
from .catalogue import MECHANISM, Quantity, labels
from .labels import Label
from .store import collect

#: Labels of the linkage results, from the catalogue (the keys made at run time are labelled by its patterns).
LINKAGE_LABELS: dict[str, Label] = labels(MECHANISM)

#: The keys of a linkage analysis shown in the summary, in order (joints and strokes follow).
LINKAGE_SUMMARY = (
    "driving_torque.max_abs", "driving_torque.rms", "driving_torque.mean", "input_power.mean", "input_power.max",
    "input_power.min", "inertial_shaking_force.max", "inertial_shaking_moment.max_abs", "frame_force.max",
    "shaking_moment.max_abs",
    "kinetic_energy.max", "kinetic_energy.min", "kinetic_energy.fluctuation", "flywheel.energy_fluctuation",
    "time_ratio", "transmission_angle.min", "transmission_angle.max", "work_balance.relative_residual",
)


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


def slider_bodies(mech: _model.Mechanism) -> list[str]:
    """Bodies that slide along a guide (the slide coordinate is reported for them)."""
    return [b for d in mech.dyads for b in d.drawing().sliders]


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


def _reduced(values: Any, how: str, kin: Any, designs: int | None) -> float | list[float]:
    """``values`` reduced over the positions by the catalogue's reduction ``how``, one float per design."""
    return _scalar(reduce(values, how, kin), designs)


def _scalar(value: Any, designs: int | None) -> float | list[float]:
    arr = np.asarray(value, dtype=float)
    if designs is None:
        return float(arr.ravel()[0]) if arr.size else float("nan")
    return [float(v) for v in np.broadcast_to(arr.ravel() if arr.size == designs else arr, (designs,))]


def full_uniform_cycle(angle: Any) -> bool:
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


def _flatten(items: Iterable) -> Iterable:
    for item in items:
        if isinstance(item, list | tuple | np.ndarray) and np.ndim(item) > 0:
            yield from _flatten(item)
        else:
            yield item


# ------------------------------------------------------------------------------------------------ series


def _joint_force(a: Any, about: tuple[float, float], joint: str) -> Any:
    return a.forces.joint(joint).magnitude


def _load_power(a: Any, about: tuple[float, float], load: str) -> Any:
    """P = F·v of the point for a force, T·ω of the body for a torque [W]."""
    kin = a.kinematics
    for f in applied_forces(kin):
        if f.name == load:
            return np.asarray(f.fx * f.motion.vx + f.fy * f.motion.vy, dtype=float)
    for t in applied_torques(kin):
        if t.name == load:
            return np.asarray(t.torque * kin.body(t.body).omega, dtype=float)
    raise KeyError(load)


#: The series over the crank positions that the quantities of the catalogue reduce (``Quantity.series``): each a
#: function of (analysis, point of the moments [m], the parts of its pattern), values shaped like the torque.
SERIES: dict[str, Callable[..., Any]] = {
    "crank_speed": lambda a, about: np.broadcast_to(np.asarray(a.kinematics.speed, dtype=float),
                                                    np.shape(a.forces.driving_torque)),
    "driving_torque": lambda a, about: a.forces.driving_torque,
    "input_power": lambda a, about: a.forces.input_power,
    "frame_force": lambda a, about: np.hypot(*a.forces.frame_force),
    "frame_force.fx": lambda a, about: a.forces.frame_force[0],
    "frame_force.fy": lambda a, about: a.forces.frame_force[1],
    "shaking_moment": lambda a, about: a.forces.shaking_moment(about=tuple(about)),
    # The inertial shaking force and moment alone (what balancing removes), apart from the process loads and the
    # weight the frame also carries: -M a_G of the whole moving mechanism and the moment of the d'Alembert loads
    # (zero for a massless, statics model).
    "inertial_shaking_force": lambda a, about: np.hypot(*inertial_force(a.kinematics)),
    "inertial_shaking_moment": lambda a, about: inertial_shaking_moment(a.kinematics, (about[0], about[1])),
    "kinetic_energy": lambda a, about: a.energy.kinetic_total,
    "reduced_inertia": lambda a, about: a.energy.reduced_inertia,
    "joint.<joint>.force": _joint_force,
    "load.<load>.power": _load_power,
}
#: The series whose harmonics a run reports when ``[output] harmonics`` asks for them, with their SI unit.
HARMONIC_SERIES = {"driving_torque": "N*m", "shaking_moment": "N*m", "frame_force.fx": "N", "frame_force.fy": "N"}


def series(analysis: Any, name: str, about: tuple[float, float] = (0.0, 0.0)) -> np.ndarray:
    """The series ``name`` (a key of :data:`SERIES`, or one of its patterns filled in: ``joint.B.force``) of an
    analysis over its crank positions."""
    if name in SERIES:
        return np.asarray(SERIES[name](analysis, about), dtype=float)
    for pattern, part in (("joint.<joint>.force", "joint."), ("load.<load>.power", "load.")):
        suffix = pattern.split(">")[1]
        if name.startswith(part) and name.endswith(suffix):
            return np.asarray(SERIES[pattern](analysis, about, name[len(part):-len(suffix)]), dtype=float)
    raise KeyError(f"'{name}' is not a series of a linkage analysis")


def _declared(quantity: Quantity, analysis: Any) -> list[tuple[str, str]]:
    """(key, series) of each result of ``quantity`` for this analysis (a pattern once per joint or load)."""
    if "<joint>" in quantity.key:
        names = [j[0] for j in joint_list(analysis.forces)]
        return [(quantity.key.replace("<joint>", j), quantity.series.replace("<joint>", j)) for j in names]
    if "<load>" in quantity.key:
        names = [f.name for f in applied_forces(analysis.kinematics)]
        names += [t.name for t in applied_torques(analysis.kinematics)]
        return [(quantity.key.replace("<load>", n), quantity.series.replace("<load>", n)) for n in names]
    return [(quantity.key, quantity.series)]


#: The quantities a run reduces from their series here (the others are figures of the cycle or of the
#: diagnostics, or the harmonics, formed below).
REDUCED = tuple(q for q in MECHANISM if q.series and REDUCTIONS[q.over_positions].function is not None)


# ------------------------------------------------------------------------------------------------ scalars


def linkage_scalars(
    analysis: Any,
    mechanism: _model.Mechanism | None = None,
    *,
    about: tuple[float, float] = (0.0, 0.0),
    harmonic_orders: int = 0,
    notes: list[str] | None = None,
    with_loads: bool = True,
    exact: bool = False,
) -> tuple[dict[str, Any], dict[str, str]]:
    """Every scalar result of an :func:`~machdyn.linkage.analyse` result in SI: (values, units of the keys made
    at run time). ``about`` [m] is the point of the shaking moment; ``harmonic_orders`` > 0 adds the amplitude
    and phase of that many harmonics of the driving torque, the shaking moment and the frame force components;
    ``notes`` collects why a result could not be formed (the energy fluctuation of a partial crank range);
    ``with_loads`` adds the mean power of each applied load (``load.<load>.mean_power``); ``exact`` makes
    the extremes of the series exact between the samples (:func:`exact_extremes`; a single design).

    The results that reduce a series (:data:`REDUCED`) are formed from their declaration alone: the catalogue
    names the series (:data:`SERIES`) and the reduction (:mod:`machdyn.linkage.reductions`)."""
    designs = design_count(analysis)
    kin, forces, energy = analysis.kinematics, analysis.forces, analysis.energy
    mech = mechanism if mechanism is not None else mechanism_of(analysis)
    out: dict[str, Any] = {}
    units: dict[str, str] = {}

    for quantity in REDUCED:
        if quantity.key.startswith("load.") and not with_loads:
            continue
        for key, name in _declared(quantity, analysis):
            out[key] = _reduced(series(analysis, name, about), quantity.over_positions, kin, designs)
    if exact:
        exact_extremes(analysis, out, about)
    if tuple(about) != (0.0, 0.0):
        out["shaking_moment.about_x"], out["shaking_moment.about_y"] = float(about[0]), float(about[1])
    torque = forces.driving_torque
    if np.all(np.isfinite(torque)):
        try:
            out["flywheel.energy_fluctuation"] = _scalar(energy_fluctuation(torque, kin.crank_angle), designs)
        except InputError as exc:
            if notes is not None:
                notes.append(f"No energy fluctuation for a flywheel: {exc}")
    try:
        wb = energy.work_balance()
    except Exception:  # noqa: BLE001 - a work balance that cannot be formed is simply not reported
        wb = None
    if wb is not None:
        out["work_balance.input_work"] = _scalar(wb.input_work, designs)
        out["work_balance.load_work"] = _scalar(wb.load_work, designs)
        out["work_balance.energy_change"] = _scalar(wb.energy_change, designs)
        out["work_balance.residual"] = _scalar(wb.residual, designs)
        out["work_balance.relative_residual"] = _scalar(wb.relative, designs)

    diag = getattr(analysis, "diagnostics", None)
    if diag is not None:
        sliders = {b for b, kind in output_bodies(mech) if kind == "slide"} if mech is not None else set()
        for body, stroke in (getattr(diag, "strokes", None) or {}).items():
            out[f"stroke.{body}"] = _scalar(stroke, designs)
            units[f"stroke.{body}"] = "m" if body in sliders else "rad"
        if getattr(diag, "time_ratio", None) is not None:
            out["time_ratio"] = _scalar(diag.time_ratio, designs)
        if getattr(diag, "transmission_angle_min", None) is not None:
            out["transmission_angle.min"] = _scalar(diag.transmission_angle_min, designs)
        if getattr(diag, "transmission_angle_max", None) is not None:
            out["transmission_angle.max"] = _scalar(diag.transmission_angle_max, designs)
        if getattr(diag, "transmission_angle_min", None) is not None and np.isfinite(diag.transmission_angle_min):
            out["transmission_angle.worst"] = _scalar(worst_of(diag.transmission_angle_min,
                                                               diag.transmission_angle_max), designs)
        # With more than one slider (the double slider-crank), each slider's own figures, named by it.
        per_slider = [b for b in (getattr(diag, "strokes", None) or {}) if b in sliders]
        if len(per_slider) > 1:
            for body in per_slider:
                ratio = (getattr(diag, "time_ratios", None) or {}).get(body)
                if ratio is not None:
                    out[f"time_ratio.{body}"] = _scalar(ratio, designs)
                extremes = (getattr(diag, "transmission_angles", None) or {}).get(body)
                if extremes is not None:
                    out[f"transmission_angle.{body}.min"] = _scalar(extremes[0], designs)
                    out[f"transmission_angle.{body}.max"] = _scalar(extremes[1], designs)
        # A result that does not exist for the machine (the transmission angle of a crank with no dyad, the time
        # ratio of a rotor) is absent, not NaN.
        for key in [k for k in out if k.startswith(("transmission_angle", "time_ratio", "stroke."))]:
            if isinstance(out[key], float) and not np.isfinite(out[key]):  # min/max over no dyad: +-inf
                del out[key]
        dead = getattr(diag, "dead_positions", None)
        if dead is not None:
            out["dead_positions.count"] = float(len(list(_flatten(dead))))
    if mech is not None:
        margin = grashof_margin(mech)
        if margin is not None:  # the class itself (text) is in the diagnostics and a sweep's columns
            out["grashof.margin"] = _scalar(margin, designs)
    if harmonic_orders > 0:
        values, hunits = harmonic_scalars(analysis, (float(about[0]), float(about[1])), harmonic_orders)
        out.update({k: _scalar(v, designs) for k, v in values.items()})
        units.update(hunits)
    return out, units


#: The reductions whose value is an extreme of the series, refined by :func:`exact_extremes`: each is the
#: extreme of the series it names (a range is its largest minus its smallest value).
_EXTREMES = {"max": ("max",), "min": ("min",), "max_abs": ("max_abs",), "range": ("max", "min")}


def exact_extremes(analysis: Any, values: dict[str, Any], about: tuple[float, float] = (0.0, 0.0),
                   keys: Iterable[str] | None = None) -> list[str]:
    """Replace in ``values`` each extreme of a series (:data:`REDUCED` quantities reduced by a maximum, a
    minimum, a largest magnitude or a range; only ``keys`` if given) by the exact extreme of the closed form
    between the samples and at the loads' breakpoints (:func:`machdyn.linkage.extremes.refine`), so that a
    peak does not depend on the number of positions. A single design at a constant crank speed and
    acceleration only (else the values stay as sampled). Returns the keys refined."""
    kin = analysis.kinematics
    mech = kin.mechanism
    phi = np.asarray(kin.crank_angle, dtype=float)
    speed, acceleration = np.asarray(kin.speed, dtype=float), np.asarray(kin.acceleration, dtype=float)
    constant = all(v.size and np.all(v == v.ravel()[0]) for v in (speed, acceleration))
    if design_count(analysis) is not None or phi.ndim != 1 or not constant:
        return []
    wanted = None if keys is None else set(keys)
    jobs: dict[str, tuple[str, str]] = {}  # "<series>|<extreme>" -> (series, extreme)
    refined: dict[str, tuple[str, tuple[str, ...]]] = {}
    for quantity in REDUCED:
        if quantity.over_positions not in _EXTREMES:
            continue
        for key, name in _declared(quantity, analysis):
            if key in values and (wanted is None or key in wanted):
                refined[key] = (name, _EXTREMES[quantity.over_positions])
                for how in _EXTREMES[quantity.over_positions]:
                    jobs[f"{name}|{how}"] = (name, how)
    if not jobs:
        return []
    names = sorted({name for name, _ in jobs.values()})
    sampled = {job: (series(analysis, name, about), how) for job, (name, how) in jobs.items()}

    def evaluate(angles: np.ndarray) -> dict[str, np.ndarray]:
        try:
            at = analyse(mech, angles, float(speed.ravel()[0]), float(acceleration.ravel()[0]), diagnostics=False)
        except (InputError, SingularPositionError):  # a searched angle at a dead position: that pass gives nothing
            return {job: np.full(angles.shape, np.nan) for job in jobs}
        found = {name: series(at, name, about) for name in names}
        return {job: found[name] for job, (name, _how) in jobs.items()}

    with np.errstate(all="ignore"):
        exact = refine(evaluate, phi, sampled, breakpoints(mech), periodic=analysed_range(phi) is None)
    done = []
    for key, (name, hows) in refined.items():
        if all(f"{name}|{how}" in exact for how in hows):
            found = [exact[f"{name}|{how}"] for how in hows]
            values[key] = float(found[0] - found[1]) if len(found) == 2 else float(found[0])
            done.append(key)
    return done


def harmonic_scalars(analysis: Any, about: tuple[float, float], orders: int) -> tuple[dict, dict]:
    """Amplitude [unit of the series] and phase [rad] of the first ``orders`` harmonics of each series of
    :data:`HARMONIC_SERIES` (the driving torque, the shaking moment about ``about``, the frame force components),
    over a uniform full cycle (else none); one value per design (an (N,) array for N designs)."""
    values: dict[str, Any] = {}
    units: dict[str, str] = {}
    phi = np.asarray(analysis.kinematics.crank_angle, dtype=float)
    n = phi.size
    if n < 4 or phi.ndim != 1 or not is_full_turn(phi) or orders >= n / 2:
        return values, units
    for name, unit in HARMONIC_SERIES.items():
        data = series(analysis, name, about)
        finite = np.all(np.isfinite(data), axis=-1)
        if not np.any(finite):
            continue
        h = harmonics(np.where(finite[..., None], data, 0.0) if data.ndim > 1 else data, phi, orders=orders)
        amplitude, phase = np.asarray(h.amplitude), np.asarray(h.phase)
        for i, k in enumerate(np.ravel(h.orders)):
            key = f"{name}.harmonic_{int(k)}"
            values[f"{key}.amplitude"] = np.where(finite, amplitude[..., i], np.nan)
            values[f"{key}.phase"] = np.where(finite, phase[..., i], np.nan)
            units[f"{key}.amplitude"], units[f"{key}.phase"] = unit, "rad"
    return values, units


def load_powers(analysis: Any) -> dict[str, tuple[float, float]]:
    """(time-mean, RMS) power [W] of each applied point force and body torque over the analysed positions
    (the series ``load.<load>.power`` of :data:`SERIES`). A negative mean is a load the drive works against; a
    positive mean is a load that drives the mechanism. Single designs only."""
    kin = analysis.kinematics
    names = [f.name for f in applied_forces(kin)] + [t.name for t in applied_torques(kin)]
    out: dict[str, tuple[float, float]] = {}
    for name in names:
        power = series(analysis, f"load.{name}.power")
        out[name] = (float(np.ravel(reduce(power, "time_mean", kin))[0]),
                     float(np.ravel(reduce(power, "time_rms", kin))[0]))
    return out


def analysis_scalars(analysis: Any, mechanism: _model.Mechanism | None = None) -> dict[str, dict[str, Any]]:
    """Every scalar result of an analysis as ``{key: {"value", "unit"}}`` in SI (``"shown"`` in the display unit
    where that differs: angles in degrees), as written to results.json; for N design variants each value is a
    list of N floats."""
    values, units = linkage_scalars(analysis, mechanism)
    return collect(values, LINKAGE_LABELS, units).as_json()
