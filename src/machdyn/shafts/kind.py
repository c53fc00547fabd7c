"""The ``[shaft_line]`` problem kind: masses and cylinders on one shaft, their forces and couples, balancing in
one or two planes, the ISO 21940-11 grade check, a locomotive's partial balance and field balancing."""

from __future__ import annotations

import math
from typing import Any

from ..pipeline import Outcome, ProblemKind, Step
from ..problem.dumper import dump_problem
from ..results.labels import Label, display_factor
from .model import analyse, build
from .rotating import unbalance
from .schema import ShaftLineProblem

LABELS = {
    "shaft.force.peak": Label("Shaft line: largest resultant force on the frame", "N", over="max", better="lower"),
    "shaft.couple.peak": Label("Shaft line: largest resultant couple about the reference plane", "N*m", over="max",
                               better="lower"),
    "shaft.linkages.torque.peak": Label("Linkages: largest shaking moment about the shaft axis (drive's reaction "
                                        "included)", "N*m", zero_below="shaft.linkages.torque.gross", over="max_abs",
                                        better="lower"),
    "shaft.linkages.torque.gross": Label("Linkages: sum of their largest shaking moments about the shaft axis",
                                         "N*m", over="scalar", better="none"),
    "shaft.unbalance": Label("Rotating masses: resultant unbalance sum(m r)", "kg*m", "g*mm",
                             zero_below="shaft.unbalance.gross", over="scalar", better="lower"),
    "shaft.unbalance.gross": Label("Rotating masses: sum of the unbalances |m r|", "kg*m", "g*mm", over="scalar",
                                   better="none"),
    "shaft.couple_unbalance": Label("Rotating masses: resultant couple unbalance sum(m r z) about the reference",
                                    "kg*m^2", zero_below="shaft.couple_unbalance.gross", over="scalar", better="lower"),
    "shaft.couple_unbalance.gross": Label("Rotating masses: sum of |m r z| about the reference", "kg*m^2",
                                          over="scalar", better="none"),
    "shaft.balance.after.force.peak": Label("After correction: largest resultant force", "N",
                                            zero_below="shaft.force.peak", over="max", better="lower"),
    "shaft.balance.after.couple.peak": Label("After correction: largest resultant couple", "N*m",
                                             zero_below="shaft.couple.peak", over="max", better="lower"),
    "shaft.engine.primary_force": Label("Engine: largest primary force, two-term (reciprocating)", "N",
                                    zero_below="shaft.engine.gross_force", over="max", better="lower"),
    "shaft.engine.secondary_force": Label("Engine: largest secondary force, two-term (reciprocating)", "N",
                                    zero_below="shaft.engine.gross_force", over="max", better="lower"),
    "shaft.engine.primary_couple": Label("Engine: largest primary couple, two-term (reciprocating)", "N*m",
                                     zero_below="shaft.engine.gross_couple", over="max", better="lower"),
    "shaft.engine.secondary_couple": Label("Engine: largest secondary couple, two-term (reciprocating)", "N*m",
                                     zero_below="shaft.engine.gross_couple", over="max", better="lower"),
    "shaft.engine.gross_force": Label("Engine: sum over the cylinders of m w^2 r (scale of its forces)", "N",
                                      over="scalar", better="none"),
    "shaft.engine.gross_couple": Label("Engine: sum over the cylinders of m w^2 r |z| (scale of its couples)", "N*m",
                                       over="scalar", better="none"),
    "shaft.engine.primary_direct": Label("Engine: primary direct-crank resultant m r", "kg*m", over="scalar",
                                         better="lower"),
    "shaft.engine.primary_reverse": Label("Engine: primary reverse-crank resultant m r", "kg*m", over="scalar",
                                          better="lower"),
    "shaft.engine.secondary_direct": Label("Engine: secondary direct-crank resultant m r / n", "kg*m", over="scalar",
                                           better="lower"),
    "shaft.engine.secondary_reverse": Label("Engine: secondary reverse-crank resultant m r / n", "kg*m",
                                            over="scalar", better="lower"),
    "shaft.grade.U_per": Label("ISO 21940-11: permissible residual unbalance U_per", "kg*m", "g*mm", over="scalar",
                               better="none"),
    "shaft.grade.margin": Label("ISO 21940-11: allowed / residual unbalance, worse bearing plane (>= 1 passes)", "",
                                over="scalar", better="higher"),
    "shaft.grade.achieved_G": Label("ISO 21940-11: grade the residual unbalance corresponds to", "m/s", "mm/s",
                                    over="scalar", better="lower"),
    "shaft.locomotive.hammer_blow": Label("Locomotive: hammer blow per wheel", "N", over="max", better="lower"),
    "shaft.locomotive.tractive_effort_variation": Label("Locomotive: largest variation of tractive effort", "N",
                                                        over="range", better="lower"),
    "shaft.locomotive.swaying_couple": Label("Locomotive: largest swaying couple", "N*m", over="max", better="lower"),
    "shaft.locomotive.lift_speed": Label("Locomotive: wheel speed at which the hammer blow equals the dead load",
                                         "rad/s", "rpm", over="scalar", better="higher"),
}


def _deg(a: float) -> str:
    return f"{math.degrees(a):.4g} deg"


def format_mass(mass: float, unit: str) -> str:
    """``mass`` [kg] written in ``unit`` (``0.0005, "g"`` -> ``"0.5 g"``)."""
    return f"{mass * display_factor('kg', unit):.6g} {unit}"


def outcome_of(result: Any, problem_text: Any = None) -> Outcome:
    """Scalars, labels, series, summary and checks of a :class:`~machdyn.shafts.model.ShaftLineResult`."""
    line, loads = result.line, result.loads
    sc: dict[str, Any] = {}
    labels: dict[str, Label] = {}
    summary: list[str] = []
    rotating = [*line.masses, *(c.crank_mass() for c in line.cylinders)]
    if rotating or line.linkages:
        sc |= {"shaft.force.peak": loads.peak_force, "shaft.couple.peak": loads.peak_couple}
        summary += ["shaft.force.peak", "shaft.couple.peak"]
    if result.linkage_torque is not None:
        sc["shaft.linkages.torque.peak"] = float(abs(result.linkage_torque.sum(axis=0)).max())
        sc["shaft.linkages.torque.gross"] = float(abs(result.linkage_torque).max(axis=1).sum())
        summary.append("shaft.linkages.torque.peak")
    if rotating:
        s0, s1 = unbalance(rotating, line.reference)
        sc["shaft.unbalance"], sc["shaft.couple_unbalance"] = abs(s0), abs(s1)
        sc["shaft.unbalance.gross"] = sum(abs(m.unbalance) for m in rotating)
        sc["shaft.couple_unbalance.gross"] = sum(abs(m.unbalance * (m.position - line.reference)) for m in rotating)
        summary += ["shaft.unbalance", "shaft.couple_unbalance"]
    series: dict[str, Any] = {}
    if rotating or line.linkages:
        series["shaft_loads"] = {"angle": (loads.angle, "rad"), "fx": (loads.fx, "N"), "fy": (loads.fy, "N"),
                                 "mx": (loads.mx, "N*m"), "my": (loads.my, "N*m")}
    if result.reactions is not None:
        r = result.reactions
        cols: dict[str, Any] = {"angle": (loads.angle, "rad")}
        for k, name in enumerate(r.names):
            key = f"shaft.bearing.{name}.peak"
            sc[key] = float(r.peak[k])
            labels[key] = Label(f"Bearing {name}: largest force", "N")
            summary.append(key)
            cols[f"{name}_fx"], cols[f"{name}_fy"] = (r.fx[k], "N"), (r.fy[k], "N")
        series["shaft_bearings"] = cols
    if result.engine is not None:
        e = result.engine
        sc |= {"shaft.engine.primary_force": e.primary_force, "shaft.engine.secondary_force": e.secondary_force,
               "shaft.engine.primary_couple": e.primary_couple, "shaft.engine.secondary_couple": e.secondary_couple,
               "shaft.engine.primary_direct": abs(e.primary_dr[0]),
               "shaft.engine.primary_reverse": abs(e.primary_dr[1]),
               "shaft.engine.secondary_direct": abs(e.secondary_dr[0]),
               "shaft.engine.secondary_reverse": abs(e.secondary_dr[1])}
        w2 = line.speed**2
        sc["shaft.engine.gross_force"] = sum(c.reciprocating_mass * c.crank * w2 for c in line.cylinders)
        sc["shaft.engine.gross_couple"] = sum(c.reciprocating_mass * c.crank * w2 * abs(c.position - line.reference)
                                              for c in line.cylinders)
        summary += ["shaft.engine.primary_force", "shaft.engine.secondary_force", "shaft.engine.primary_couple",
                    "shaft.engine.secondary_couple"]
        for k, f, c in zip(e.orders, e.force_order, e.couple_order, strict=True):
            fk, ck = f"shaft.engine.order{k}.force", f"shaft.engine.order{k}.couple"
            sc[fk], sc[ck] = float(f), float(c)
            labels[fk] = Label(f"Engine: largest force of order {k}, exact (all masses)", "N",
                               zero_below="shaft.force.peak")
            labels[ck] = Label(f"Engine: largest couple of order {k}, exact (all masses)", "N*m",
                               zero_below="shaft.couple.peak")
            if k <= 2:
                summary += [fk, ck]
        series["shaft_orders"] = {"order": (e.orders.astype(float), ""), "force": (e.force_order, "N"),
                                  "couple": (e.couple_order, "N*m")}
    mu = line.mass_unit
    if result.balance is not None:
        b = result.balance
        fitted = iter(result.applied)  # the masses as fitted (rounded to the resolution), in the order of the splits
        rounded = f", rounded to {format_mass(line.resolution, mu)}" if line.resolution is not None else ""
        for c, split in zip(b.corrections, result.splits, strict=True):
            mk, ak = f"shaft.balance.{c.plane.name}.mass", f"shaft.balance.{c.plane.name}.angle"
            sc[mk], sc[ak] = c.mass, c.angle
            labels[mk] = Label(f"Correction in plane {c.plane.name}: mass at {c.plane.radius * 1e3:g} mm", "kg", mu)
            labels[ak] = Label(f"Correction in plane {c.plane.name}: angle from the reference mark", "rad")
            summary += [mk, ak]
            for hole, m in split.items():
                hk = f"shaft.balance.{c.plane.name}.hole{hole + 1}.mass"
                sc[hk] = m
                labels[hk] = Label(f"Correction in plane {c.plane.name}: mass in hole {hole + 1}", "kg", mu)
                summary.append(hk)
            for hole in (split if split else (None,)):
                fit = next(fitted)
                if line.resolution is None:
                    continue
                fk = f"shaft.balance.{c.plane.name}.{'' if hole is None else f'hole{hole + 1}.'}fitted_mass"
                sc[fk] = fit.mass
                where = "" if hole is None else f" in hole {hole + 1}"
                labels[fk] = Label(f"Correction in plane {c.plane.name}: mass as fitted{where}{rounded} (used for "
                                   "the residual)", "kg", mu)
                summary.append(fk)
        sc["shaft.balance.after.force.peak"] = b.after.peak_force
        sc["shaft.balance.after.couple.peak"] = b.after.peak_couple
        summary += ["shaft.balance.after.force.peak", "shaft.balance.after.couple.peak"]
        series["shaft_loads"] = {**series["shaft_loads"], "fx_after": (b.after.fx, "N"), "fy_after": (b.after.fy, "N"),
                                 "mx_after": (b.after.mx, "N*m"), "my_after": (b.after.my, "N*m")}
        if result.reactions_after is not None:
            r = result.reactions_after
            for k, name in enumerate(r.names):
                key = f"shaft.bearing.{name}.peak_after"
                sc[key] = float(r.peak[k])
                labels[key] = Label(f"Bearing {name}: largest force after correction", "N",
                                    zero_below=f"shaft.bearing.{name}.peak")
    failed: list[str] = []
    if result.grade is not None:
        g = result.grade
        sc["shaft.grade.U_per"] = g.u_per
        sc["shaft.grade.achieved_G"] = g.achieved_grade * 1e-3
        summary += ["shaft.grade.U_per"]
        for name, allowed, residual in zip(g.bearings, g.allowed, g.residual, strict=True):
            ak, rk = f"shaft.grade.{name}.allowed", f"shaft.grade.{name}.residual"
            sc[ak], sc[rk] = allowed, residual
            labels[ak] = Label(f"ISO 21940-11: permissible unbalance allocated to bearing plane {name}", "kg*m", "g*mm")
            labels[rk] = Label(f"ISO 21940-11: residual unbalance in bearing plane {name}", "kg*m", "g*mm",
                               zero_below="shaft.grade.U_per")
            summary += [ak, rk]
        if math.isfinite(g.margin):
            sc["shaft.grade.margin"] = g.margin
            summary.append("shaft.grade.margin")
        summary.append("shaft.grade.achieved_G")
        if not g.passes:
            over = "; ".join(f"{name}: {res * 1e6:.4g} g*mm > {allowed * 1e6:.4g} g*mm" for name, allowed, res in
                             zip(g.bearings, g.allowed, g.residual, strict=True) if res > allowed * (1 + 1e-12))
            failed.append(f"the rotor misses balance grade G {g.grade:g} (ISO 21940-11), residual unbalance in "
                          f"the bearing planes: {over}")
    if result.locomotive is not None:
        lo = result.locomotive
        sc |= {"shaft.locomotive.hammer_blow": lo.hammer_blow,
               "shaft.locomotive.tractive_effort_variation": lo.tractive_effort_variation,
               "shaft.locomotive.swaying_couple": lo.swaying_couple}
        summary += ["shaft.locomotive.hammer_blow", "shaft.locomotive.tractive_effort_variation",
                    "shaft.locomotive.swaying_couple"]
        for side, m, a in zip(("left", "right"), lo.balance_mass, lo.balance_angle, strict=True):
            sc[f"shaft.locomotive.{side}.balance_mass"] = m
            sc[f"shaft.locomotive.{side}.balance_angle"] = a
            labels[f"shaft.locomotive.{side}.balance_mass"] = Label(f"Locomotive: balance mass, {side} wheel", "kg")
            labels[f"shaft.locomotive.{side}.balance_angle"] = Label(f"Locomotive: balance-mass angle, {side} wheel",
                                                                     "rad")
            summary += [f"shaft.locomotive.{side}.balance_mass", f"shaft.locomotive.{side}.balance_angle"]
        if lo.lift_speed is not None and math.isfinite(lo.lift_speed):
            sc["shaft.locomotive.lift_speed"] = lo.lift_speed
            summary.append("shaft.locomotive.lift_speed")
            if lo.lift_speed < line.speed:
                failed.append(f"the hammer blow lifts the wheel: it exceeds the dead load above "
                              f"{lo.lift_speed * 30 / math.pi:.4g} rpm of the wheels")
    if result.frame_frequencies is not None:
        for k, f in enumerate(result.frame_frequencies, start=1):
            key = f"shaft.frame.mode{k}.frequency"
            sc[key] = float(f)
            labels[key] = Label(f"Frame on its mounts: natural frequency {k}", "Hz")
            summary.append(key)
        resp = result.frame_response
        state = "after correction" if result.balance is not None else "as given"
        for name, force in resp.mount_force.items():
            key = f"shaft.frame.mount.{name}.force"
            sc[key] = force
            labels[key] = Label(f"Mount {name}: largest dynamic force ({state}, sum of the orders)", "N")
            summary.append(key)
        for name, v in resp.rms_velocity.items():
            key = f"shaft.frame.point.{name}.rms_velocity"
            sc[key] = v
            labels[key] = Label(f"Frame point {name}: RMS vibration velocity ({state})", "m/s", "mm/s")
            summary.append(key)
    files: dict[str, str] = {}
    if result.phases is not None:
        ps = result.phases
        for name, phase in ps.phases.items():
            key = f"shaft.phases.{name}.phase"
            sc[key] = phase
            labels[key] = Label(f"Best crank phase of cylinder {name} ({ps.objective.replace('_', ' ')})", "rad")
            summary.append(key)
        for k, what in enumerate(("primary_force", "secondary_force", "primary_couple", "secondary_couple")):
            unit = "N" if what.endswith("force") else "N*m"
            for state, values in (("given", ps.before), ("best", ps.after)):
                key = f"shaft.phases.{state}.{what}"
                sc[key] = float(values[k])
                labels[key] = Label(f"Crank phases {'as given' if state == 'given' else 'found'}: largest "
                                    f"{what.replace('_', ' ')}, two-term", unit,
                                    zero_below=f"shaft.engine.gross_{'force' if unit == 'N' else 'couple'}")
                summary.append(key)
        if problem_text is not None:
            files["best_phases.toml"] = problem_text(ps)
    warnings: list[str] = []
    if line.field is not None:
        f = line.field
        for k, (name, m, a, eff) in enumerate(zip(line.field_names, f.correction_mass, f.correction_angle,
                                                  f.trial_effect, strict=True)):
            mk, ak, ek = f"shaft.field.{name}.mass", f"shaft.field.{name}.angle", f"shaft.field.{name}.trial_effect"
            sc[mk], sc[ak], sc[ek] = m, a, eff
            labels[mk] = Label(f"Field balancing, plane {name}: correction mass (at the trial radius)", "kg", mu)
            labels[ak] = Label(f"Field balancing, plane {name}: correction angle from the reference mark", "rad")
            labels[ek] = Label(f"Field balancing, plane {name}: trial effect |change| / |reading|", "")
            summary += [mk, ak]
            for hole, hm in (result.field_splits[k] if result.field_splits else {}).items():
                hk = f"shaft.field.{name}.hole{hole + 1}.mass"
                sc[hk] = hm
                labels[hk] = Label(f"Field balancing, plane {name}: mass in hole {hole + 1}", "kg", mu)
                summary.append(hk)
            if eff < 0.3:
                warnings.append(f"the trial mass in plane {name} changed the readings by only {eff:.0%}; a trial "
                                "mass that changes them by 30 % or more gives a more reliable correction")
    return Outcome(results=result, scalars=sc, labels=labels, series=series, summary=tuple(summary),
                   warnings=tuple(warnings), failed_checks=tuple(failed), files=files)


def _build(problem: Any) -> tuple[Any, list[tuple[str, str]]]:
    return build(problem)


def _analyse(problem: Any, line: Any, step: Step) -> Outcome:
    step("shaft line")

    def best_phases(search: Any) -> str:
        """The problem with the cylinders' phases found, as a problem file (without the search)."""
        cylinders = [c.model_copy(update={"phase": search.phases.get(c.name, c.phase)}) for c in problem.cylinders]
        return dump_problem(problem.model_copy(update={"cylinders": cylinders, "phase_search": None}))

    return outcome_of(analyse(problem, line), best_phases)


def result_keys(problem: Any) -> dict[str, str]:
    """{key: SI unit} of every result a run of ``problem`` reports (its bearings', frame points', planes' ...):
    the shaft line analysed once, as the run does; {} for a file whose line cannot be built (its problems are
    reported by the build)."""
    line, problems = build(problem)
    if problems or line is None:
        return {}
    done = outcome_of(analyse(problem, line))
    return {key: (done.labels.get(key) or LABELS.get(key) or Label(key)).unit for key in done.scalars}


KIND = ProblemKind(
    name="shaft_line",
    schema=ShaftLineProblem,
    build=_build,
    check=lambda problem, line: [],
    analyse=_analyse,
    title=lambda problem: problem.meta.name,
    steps=("shaft line",),
    labels=LABELS,
    report="machdyn.report.shafts:sections",
    result_keys=result_keys,
    population="machdyn.shafts.kind_population:population",
)
