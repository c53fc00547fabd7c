"""Run a problem (linkage, rotary screen or screw conveyor) and collect what the user sees.

>>> import machdyn.runner as r
>>> result = r.run_problem(r.load_problem("examples/slider_crank.toml"))     # doctest: +SKIP
>>> result.summary_rows[:2]                                                  # doctest: +SKIP
>>> result.frames["torque_power"].head()                                     # doctest: +SKIP
>>> result.write("out")                                                      # doctest: +SKIP

:class:`RunResult` holds the summary rows (quantity, value, unit), every scalar with its unit, the time series
as pandas DataFrames (one row per crank angle, the unit in each column header), the warnings, and writes
``results.json``, one CSV per time series and ``report.html``.
"""

from __future__ import annotations

import math
import os
import warnings as _warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .errors import AssemblyError, InputError, ProblemFileError, SingularPositionError
from .problem import load_problem

__all__ = ["RunResult", "check_problem", "load_problem", "run_problem"]

Step = Callable[[str], None]


def _no_step(_label: str) -> None:
    return None


@dataclass
class RunResult:
    """What a run computed, ready to print, convert or write.

    ``summary_rows`` (quantity, value, unit) for the console and the report; ``scalars`` every scalar result
    as ``{"value", "unit"}``; ``frames`` the time series as DataFrames (computed on first use); ``warnings``;
    ``analysis`` and ``mechanism`` for linkages (None for a screw conveyor); ``details`` the machine-specific
    result (rotary screen energy figures, the conveyor result).
    """

    kind: str
    title: str
    problem: Any
    problem_text: str
    summary_rows: list[tuple[str, Any, str]]
    scalars: dict[str, dict[str, Any]]
    warnings: list[str] = field(default_factory=list)
    analysis: Any = None
    mechanism: Any = None
    details: Any = None
    extra_html_sections: list[Any] = field(default_factory=list)
    sweep_frame: Any = None
    _frames: dict[str, Any] | None = field(default=None, repr=False)

    @property
    def frames(self) -> dict[str, Any]:
        """Time series as pandas DataFrames by name (``motion``, ``joint_forces``, ``torque_power``,
        ``shaking``, ``energy``; ``sweep`` with one row per design variant when the problem has a sweep);
        empty for problems without a crank cycle."""
        if self._frames is None:
            if self.analysis is None:
                self._frames = {}
            else:
                from .report.tables import analysis_frames, shaking_frame

                frames = analysis_frames(self.analysis, self.mechanism)
                about = tuple(self.problem.output.shaking_moment_about)
                if about != (0.0, 0.0):
                    frames["shaking"] = shaking_frame(self.analysis.forces, None, about=about)
                if self.sweep_frame is not None:
                    frames["sweep"] = self.sweep_frame  # one row per design variant
                self._frames = frames
        return self._frames

    def summary_frame(self):
        """The summary rows as a DataFrame with columns quantity, value, unit."""
        import pandas as pd

        return pd.DataFrame(self.summary_rows, columns=["quantity", "value", "unit"])

    def scalars_frame(self):
        """Every scalar as a DataFrame with columns quantity, value, unit."""
        import pandas as pd

        return pd.DataFrame(
            [(k, v["value"], v["unit"]) for k, v in self.scalars.items()], columns=["quantity", "value", "unit"]
        )

    def results(self) -> dict[str, Any]:
        """The content of results.json: the problem's name and kind, every scalar with its unit, warnings."""
        from . import __version__

        return {
            "machdyn_version": __version__,
            "problem": self.title,
            "kind": self.kind,
            "scalars": self.scalars,
            "warnings": list(self.warnings),
        }

    def report_html(self) -> str:
        """The self-contained HTML report (input echoed, summary tables, warnings, plots)."""
        from .report import render_report

        return render_report(
            title=self.title,
            problem_text=self.problem_text,
            summary_rows=self.summary_rows,
            warnings=self.warnings,
            analysis=self.analysis,
            mechanism=self.mechanism,
            extra_html_sections=tuple(self.extra_html_sections),
        )

    def write(self, out_dir: str | os.PathLike, *, step: Step = _no_step) -> list[Path]:
        """Write ``results.json``, ``<series>.csv`` per time series and ``report.html`` into ``out_dir``
        (created if missing); each file atomically. Returns the paths written."""
        from .outputs import atomic_write_text, write_frame_csv, write_json

        out = Path(out_dir)
        if out.exists() and not out.is_dir():
            raise OSError(f"the output path '{out}' exists and is not a directory")
        out.mkdir(parents=True, exist_ok=True)
        paths = [write_json(out / "results.json", self.results())]
        if self.analysis is not None:
            step("tables")
        for name, frame in self.frames.items():
            paths.append(write_frame_csv(out / f"{name}.csv", frame))
        step("report")
        paths.append(atomic_write_text(out / "report.html", self.report_html()))
        return paths


# ------------------------------------------------------------------------------------------- linkages


def _angles_and_speed(problem) -> tuple[Any, float, float]:
    from .problem.build import crank_angles

    return crank_angles(problem), problem.drive.speed, problem.drive.acceleration


def check_problem(problem: Any) -> list[str]:
    """Check that a validated problem can be analysed: build its model and assemble it at every crank angle
    asked for. Returns warnings (e.g. dead positions); raises :class:`~machdyn.errors.ProblemFileError` for a
    model the engine refuses and :class:`~machdyn.errors.AssemblyError` for a linkage that cannot close."""
    kind = problem_kind_of(problem)
    if kind == "screw_conveyor":
        return []
    from .linkage import diagnose, kinematics

    mech = _mechanism_of(problem)
    angles, speed, accel = _angles_and_speed(problem)
    kinematics(mech, angles, speed, accel, on_fail="raise")
    if getattr(problem, "sweep", None) is not None:
        _sweep_variants(problem)  # every value valid and every variant buildable
    try:
        return list(diagnose(mech).warnings)
    except (InputError, SingularPositionError):
        return []


def problem_kind_of(problem: Any) -> str:
    from .problem.rotary import RotaryScreenProblem
    from .problem.schema import LinkageProblem

    if isinstance(problem, LinkageProblem):
        return "mechanism"
    if isinstance(problem, RotaryScreenProblem):
        return "rotary_screen"
    return "screw_conveyor"


def _mechanism_of(problem: Any):
    from .problem.build import build_mechanism
    from .problem.rotary import RotaryScreenProblem

    if isinstance(problem, RotaryScreenProblem):
        return problem.mechanism()
    return build_mechanism(problem)


def _summary_from_scalars(scalars: dict[str, dict[str, Any]], about: tuple[float, float]) -> list[tuple]:
    labels = [
        ("driving_torque.max_abs", "Driving torque, max |T|"),
        ("driving_torque.rms", "Driving torque, RMS"),
        ("driving_torque.mean", "Driving torque, mean"),
        ("input_power.mean", "Input power, mean"),
        ("input_power.max", "Input power, peak"),
        ("input_power.min", "Input power, minimum (negative: power flows back into the drive)"),
        ("shaking_force.max", "Shaking force, max"),
        ("shaking_moment.max_abs", f"Shaking moment about ({about[0]:g}, {about[1]:g}) m, max |M|"),
        ("kinetic_energy.max", "Kinetic energy, max"),
        ("kinetic_energy.min", "Kinetic energy, min"),
        ("kinetic_energy.fluctuation", "Kinetic energy, fluctuation"),
        ("flywheel.energy_fluctuation", "Energy to store in a flywheel (constant speed)"),
        ("time_ratio", "Time ratio (advance / return)"),
        ("transmission_angle.min", "Transmission angle, min"),
        ("transmission_angle.max", "Transmission angle, max"),
        ("work_balance.relative_residual", "Work balance, relative residual"),
    ]
    # Values that vanish in exact arithmetic (the mean torque and power over a loss-free cycle, the shaking
    # moment of a mechanism with constant angular momentum) come out as round-off; show those as 0.
    def scale(key):
        return abs(float(scalars.get(key, {}).get("value", 0.0) or 0.0))

    roundoff = {
        "driving_torque.mean": scale("driving_torque.max_abs"),
        "input_power.mean": scale("input_power.max"),
        "shaking_moment.max_abs": scale("driving_torque.max_abs"),
    }
    rows = []
    for key, label in labels:
        if key in scalars:
            value = scalars[key]["value"]
            if key in roundoff and isinstance(value, float) and abs(value) <= 1e-9 * roundoff[key]:
                value = 0.0
            rows.append((label, value, scalars[key]["unit"]))
    for key, entry in scalars.items():
        if key.startswith("joint.") and key.endswith(".max_force"):
            rows.append((f"Joint {key[6:-10]}, max force", entry["value"], entry["unit"]))
        elif key.startswith("stroke."):
            rows.append((f"Stroke of {key[7:]}", entry["value"], entry["unit"]))
    return rows


def _harmonic_scalars(analysis, about, orders: int) -> dict[str, dict[str, Any]]:
    import numpy as np

    from .linkage import harmonics

    out: dict[str, dict[str, Any]] = {}
    phi = np.asarray(analysis.kinematics.crank_angle, dtype=float)
    n = phi.size
    if n < 4 or not np.allclose(np.diff(phi), 2 * math.pi / n, rtol=1e-9, atol=1e-12) or orders >= n / 2:
        return out
    series = {
        "driving_torque": (analysis.forces.driving_torque, "N*m"),
        "shaking_moment": (analysis.forces.shaking_moment(about=about), "N*m"),
        "shaking_force.fx": (analysis.forces.frame_force[0], "N"),
        "shaking_force.fy": (analysis.forces.frame_force[1], "N"),
    }
    for name, (values, unit) in series.items():
        if not np.all(np.isfinite(values)):
            continue
        h = harmonics(values, phi, orders=orders)
        for k, amp, ph in zip(np.ravel(h.orders), np.ravel(h.amplitude), np.ravel(h.phase), strict=True):
            out[f"{name}.harmonic_{int(k)}.amplitude"] = {"value": float(amp), "unit": unit}
            out[f"{name}.harmonic_{int(k)}.phase"] = {"value": float(np.degrees(ph)), "unit": "deg"}
    return out


def _analyse(problem, mech, step: Step):
    from .linkage import analyse

    angles, speed, accel = _angles_and_speed(problem)
    step("analysis")
    with _warnings.catch_warnings(record=True) as caught:
        _warnings.simplefilter("always")
        analysis = analyse(mech, angles, speed, accel)
    messages = [str(w.message) for w in caught if issubclass(w.category, UserWarning)]
    return analysis, messages


def _linkage_result(problem, mech, analysis, messages, text: str, kind: str) -> RunResult:
    import numpy as np

    from .report.tables import analysis_scalars

    about = tuple(problem.output.shaking_moment_about)
    scalars = analysis_scalars(analysis, mech)
    if about != (0.0, 0.0):
        moment = analysis.forces.shaking_moment(about=about)
        scalars["shaking_moment.max_abs"] = {"value": float(np.nanmax(np.abs(moment))), "unit": "N*m"}
        scalars["shaking_moment.about_x"] = {"value": about[0], "unit": "m"}
        scalars["shaking_moment.about_y"] = {"value": about[1], "unit": "m"}
    scalars.update(_harmonic_scalars(analysis, about, problem.output.harmonics))
    warnings = list(messages)
    balance = float(np.max(np.atleast_1d(analysis.work_balance.relative)))
    if not balance < 1e-6:
        warnings.append(
            f"The work-energy balance over the analysed crank angles is off by {balance:.2g} (relative): the "
            "crank speed and acceleration given are not consistent (a constant speed needs zero acceleration), "
            "or the crank angles are too coarse for the trapezoidal rule over a partial range."
        )
    diag = analysis.diagnostics
    for w in getattr(diag, "warnings", None) or []:
        if str(w) not in warnings:
            warnings.append(str(w))
    title = problem.meta.name
    return RunResult(
        kind=kind, title=title, problem=problem, problem_text=text,
        summary_rows=_summary_from_scalars(scalars, about), scalars=scalars, warnings=warnings,
        analysis=analysis, mechanism=mech,
    )


def _default_mass_warnings(problem) -> list[str]:
    from .problem.schema import CustomSpec, LinkSpec

    spec = problem.mechanism
    if isinstance(spec, CustomSpec):
        # Custom bodies have no bar to take defaults from: a mass without inertia or centre of mass is a point
        # mass at the body's origin, which may not be what the author meant.
        bare = [
            f"mechanism.bodies[{i}] ('{b.name}')" for i, b in enumerate(spec.bodies)
            if b.mass > 0.0 and not {"inertia", "com"} <= b.model_fields_set
        ]
        if not bare:
            return []
        return [
            f"{', '.join(bare)}: mass given without inertia or com; taken as inertia 0 kg*m^2 about a centre of "
            "mass at the body's origin (0, 0). Give inertia and com for a real link."
        ]
    missing = [
        name for name in type(spec).model_fields
        if isinstance(getattr(spec, name), LinkSpec) and getattr(spec, name).mass is None
    ]
    if not missing:
        return []
    return [
        f"No mass given for {', '.join(missing)}: taken as uniform bar(s) of "
        f"{spec.linear_density:g} kg/m (mechanism.linear_density)."
    ]


def run_linkage(problem, text: str, step: Step = _no_step) -> RunResult:
    """Analyse a :class:`~machdyn.problem.schema.LinkageProblem` over its crank positions."""
    from .problem.build import build_mechanism

    step("model")
    mech = build_mechanism(problem)
    analysis, messages = _analyse(problem, mech, step)
    result = _linkage_result(problem, mech, analysis, _default_mass_warnings(problem) + messages, text, "mechanism")
    if problem.sweep is not None:
        step("design sweep")
        _add_sweep(result, problem)
    return result


# ------------------------------------------------------------------------------------------- sweeps

#: Per-design summaries of a sweep: (attribute of SweepResult, label, unit).
SWEEP_SUMMARIES = (
    ("max_driving_torque", "Peak driving torque", "N*m"),
    ("rms_driving_torque", "RMS driving torque", "N*m"),
    ("mean_input_power", "Mean input power", "W"),
    ("max_shaking_force", "Peak shaking force", "N"),
    ("max_shaking_moment", "Peak shaking moment", "N*m"),
)


def _sweep_variants(problem):
    """The expanded sweep of a problem and the engine model of each variant."""
    from .problem.build import build_mechanism
    from .problem.sweep import expand_sweep

    plan = expand_sweep(problem)
    mechs, problems = [], []
    for i, variant in enumerate(plan.problems):
        try:
            mechs.append(build_mechanism(variant))
        except ProblemFileError as exc:
            problems += [(f"sweep (value {i + 1})", f"{path}: {msg}") for path, msg in exc.problems]
    if problems:
        raise ProblemFileError(problems)
    return plan, mechs


def run_sweep(problem):
    """The design variants of a problem's ``[sweep]``, analysed together: (plan, SweepResult)."""
    import numpy as np

    from .linkage import stack_designs, sweep

    plan, mechs = _sweep_variants(problem)
    angles, _, _ = _angles_and_speed(problem)
    speeds = np.array([v.drive.speed for v in plan.problems])
    accels = np.array([v.drive.acceleration for v in plan.problems])
    stacked = stack_designs(mechs)
    speed = speeds if np.ptp(speeds) > 0 else float(speeds[0])
    accel = accels if np.ptp(accels) > 0 else float(accels[0])
    if np.ndim(speed) and np.size(speed) == np.size(angles):
        raise ProblemFileError([("sweep", "a sweep of the drive needs a number of values different from "
                                          f"drive.positions ({np.size(angles)}); got as many")])
    about = tuple(problem.output.shaking_moment_about)
    return plan, sweep(stacked, angles, speed, accel, shaking_about=about)


def _add_sweep(result: RunResult, problem) -> None:
    import numpy as np

    from .report.html import sweep_section

    plan, res = run_sweep(problem)
    unit = plan.display_unit
    n = len(plan.values_display)
    regular = np.asarray(res.regular, dtype=bool)
    result.scalars[f"sweep.{plan.parameter}"] = {"value": [float(v) for v in plan.values_display], "unit": unit}
    result.scalars["sweep.regular"] = {"value": [bool(v) for v in regular], "unit": ""}
    for attr, _label, u in SWEEP_SUMMARIES:
        result.scalars[f"sweep.{attr}"] = {"value": [float(v) for v in getattr(res, attr)], "unit": u}
    rows = [(f"Sweep of {plan.parameter}", f"{n} designs, {int(regular.sum())} regular", "")]
    if regular.any():
        for attr, label, u in (SWEEP_SUMMARIES[0], SWEEP_SUMMARIES[3]):
            data = np.where(regular, getattr(res, attr), np.inf)
            best = int(np.argmin(data))
            rows.append((f"Sweep: lowest {label.lower()} (at {plan.parameter} = "
                         f"{plan.values_display[best]:.6g} {unit})", float(data[best]), u))
    else:
        result.warnings.append(f"No design of the sweep of {plan.parameter} is regular: each fails to assemble "
                               "or passes a dead position somewhere in the crank range.")
    result.summary_rows += rows
    result.extra_html_sections.append(
        (f"Design sweep of {plan.parameter}", sweep_section(plan.parameter, unit, plan.values_display, res))
    )
    result.sweep_frame = _sweep_frame(plan, res)


def _sweep_frame(plan, res):
    import pandas as pd

    columns = {
        f"{plan.parameter} [{plan.display_unit}]": plan.values_display,
        "assembled": res.assembled,
        "regular": res.regular,
    }
    for attr, _label, unit in SWEEP_SUMMARIES:
        columns[f"{attr} [{unit}]"] = getattr(res, attr)
    for joint, values in res.max_joint_force.items():
        columns[f"joint.{joint}.max_force [N]"] = values
    return pd.DataFrame(columns)


# ------------------------------------------------------------------------------------- rotary screen


def run_rotary_screen(problem, text: str, step: Step = _no_step) -> RunResult:
    """Analyse the rotary screen with the engine and add the paper's energy figures (seed 002)."""
    from .machines.rotary_screen import energy_figures

    step("model")
    screen = problem.screen()
    mech = problem.mechanism()
    analysis, messages = _analyse(problem, mech, step)
    result = _linkage_result(problem, mech, analysis, messages, text, "rotary_screen")
    step("energy figures")
    figures = energy_figures(screen)
    result.summary_rows = _figure_rows(figures) + result.summary_rows
    for key, f in figures.items():
        for col in ("paper", "formula", "engine"):
            if f[col] is not None:
                result.scalars[f"rotary_screen.{key}.{col}"] = {"value": float(f[col]), "unit": f["unit"]}
    result.details = figures
    result.extra_html_sections.append(("Energy figures of seed 002: paper, formula, engine", _figures_html(figures)))
    return result


def _paper(f: dict) -> str:
    return "" if f["paper"] is None else f" (paper {f['paper']:g})"


def _figure_rows(figures: dict[str, dict]) -> list[tuple[str, Any, str]]:
    """Summary rows of the seed 002 figures: the paper's formulas (corrected where wrong) and the engine."""
    f = figures
    w_paper = (f" (paper {f['W_min']['paper']:g} ~ {f['W_max']['paper']:g})" if f["W_min"]["paper"] is not None
               else "")
    return [
        (f"T1max, kinetic energy of the translating mass, eq 15{_paper(f['T1max'])}", f["T1max"]["formula"], "J"),
        ("T1max, exact kinematics (engine)", f["T1max"]["engine"], "J"),
        (f"T2, kinetic energy of the rotating mass, eq 8{_paper(f['T2'])}", f["T2"]["formula"], "J"),
        (f"T3, kinetic energy of the counterweight, eq 9{_paper(f['T3'])}", f["T3"]["formula"], "J"),
        (f"W range, eq 10{w_paper}", f"{f['W_min']['formula']:.7g} ~ {f['W_max']['formula']:.7g}", "J"),
        ("W range, exact kinematics (engine)", f"{f['W_min']['engine']:.7g} ~ {f['W_max']['engine']:.7g}", "J"),
        (f"Power of the energy fluctuation, T1max omega/pi{_paper(f['fluctuation_power'])}",
         f["fluctuation_power"]["formula"], "W"),
        ("Spring stiffness K = m_C omega^2, eq 17", f["K"]["formula"], "N/m"),
        (f"P_r with the spring, eq 26 corrected{_paper(f['P_r'])}", f["P_r"]["formula"], ""),
        ("P_r with the spring, exact kinematics (engine)", f["P_r"]["engine"], ""),
        ("Peak input torque dW/dalpha, no spring (engine)", f["M_in_peak"]["engine"], "N*m"),
        ("Peak input torque dW/dalpha, with spring (engine)", f["M_in_peak_spring"]["engine"], "N*m"),
    ]


def _figures_html(figures: dict[str, dict]) -> str:
    from html import escape

    def cell(v):
        return "" if v is None else f"{v:.7g}"

    head = "<tr><th>figure</th><th>quantity</th><th>paper</th><th>formula</th><th>engine</th><th>unit</th>" \
           "<th>source</th><th>note</th></tr>"
    body = "".join(
        f"<tr><td>{escape(k)}</td><td>{escape(f['quantity'])}</td><td>{cell(f['paper'])}</td>"
        f"<td>{cell(f['formula'])}</td><td>{cell(f['engine'])}</td><td>{escape(f['unit'])}</td>"
        f"<td>{escape(f['source'])}</td><td>{escape(f['note'])}</td></tr>"
        for k, f in figures.items()
    )
    return f"<table class=\"figures\"><thead>{head}</thead><tbody>{body}</tbody></table>"


# ------------------------------------------------------------------------------------ screw conveyor


def run_screw_conveyor(problem, text: str, step: Step = _no_step) -> RunResult:
    from .conveyor.problem import run_conveyor

    step("design")
    with _warnings.catch_warnings():
        _warnings.simplefilter("ignore")
        result = run_conveyor(problem)
    warnings = list(result.warnings)
    for check in result.checks:
        if not check.passed:
            warnings.append(f"Check failed: {check.name}: {check.value:.4g} > {check.limit:.4g} {check.unit}")
    return RunResult(
        kind="screw_conveyor", title=problem.name, problem=problem, problem_text=text,
        summary_rows=list(result.summary_rows()), scalars=result.scalars(), warnings=warnings,
        details=result, extra_html_sections=[result.to_html_section()],
    )


# ------------------------------------------------------------------------------------------------ run


def run_problem(problem: Any, *, text: str | None = None, step: Step = _no_step) -> RunResult:
    """Analyse a problem from :func:`~machdyn.problem.load_problem` (or a path / TOML text).

    ``text`` is the problem file echoed in the report (by default the problem written back as TOML).
    Raises :class:`~machdyn.errors.ProblemFileError` for bad input, :class:`~machdyn.errors.AssemblyError`
    when the linkage cannot close at a requested crank angle.
    """
    if isinstance(problem, str | os.PathLike):
        from .problem.loader import read_text

        text = read_text(problem)[0] if text is None else text
        problem = load_problem(problem)
    kind = problem_kind_of(problem)
    if text is None:
        if kind == "screw_conveyor":
            text = repr(problem)
        else:
            from .problem.dumper import dump_problem

            text = dump_problem(problem)
    if kind == "mechanism":
        return run_linkage(problem, text, step)
    if kind == "rotary_screen":
        return run_rotary_screen(problem, text, step)
    return run_screw_conveyor(problem, text, step)


# re-exported for callers that catch what a run may raise
ERRORS = (ProblemFileError, AssemblyError, InputError, SingularPositionError)
