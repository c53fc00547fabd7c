"""The fused engine: a mechanism's kinematics, kinetostatics and per-design summaries in one compiled pass per
crank position, without arrays of designs x positions in between.

:mod:`.fused_source` writes the straight-line code of a mechanism's dyad sequence; it depends on the topology
only (every number is read from a parameter table), so it is compiled once per topology with numba and kept:
in memory for the session and, with numba's own cache, on disk as a module named by the hash of its text
(under ``$MACHDYN_CACHE_DIR``, else ``$XDG_CACHE_HOME/machdyn`` or ``~/.cache/machdyn``). A new topology
costs one compilation (about a second); a known one, a cache load.

The NumPy engine stays the reference: both compute the same closed forms in the same order and agree to
rounding (the test suite checks 1e-12 relative on random mechanisms of every dyad type). numba is imported
here only, and only when the fused engine is used.
"""

from __future__ import annotations

import importlib.util
import os
import sys
import tempfile
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import InputError, check_finite
from .averages import angle_weights
from .dyad_forms import scalar_forms
from .engines import use_fused
from .fused_generator import Unsupported
from .fused_source import KERNEL_BODY_FIELDS, SUMMARY_FIELDS, Generated, generate
from .model import joints
from .motion import DyadReport, Kinematics, SlideMotion, kinematics_result
from .reactions import Forces, Joint, Reaction
from .reductions import compiled_streams
from .refs import GROUND, column, full
from .state import BodyState

_KERNELS: dict[str, Any] = {}
_FORMS: dict[str, Any] = {}


def _forms() -> dict[str, Any]:
    """The dyad forms compiled for scalars, under the names the kernels call them by (``F_rrr_motion`` ...), and
    the streaming reductions of :mod:`.reductions` (``RS_max_abs`` ...)."""
    if not _FORMS:
        _FORMS.update({f"F_{name}": form for name, form in vars(scalar_forms()).items()})
        _FORMS.update(compiled_streams())
    return _FORMS
_NO_ROWS = np.zeros((1, 1))  # the per-position load table of a mechanism without such loads (never read)


def _cache_dir() -> Path | None:
    root = os.environ.get("MACHDYN_CACHE_DIR") or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache"), "machdyn"
    )
    path = Path(root) / "fused"
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError:
        return None
    return path if os.access(path, os.W_OK) else None


def load_kernel(generated: Generated, mode: str):
    """The compiled kernel of ``generated`` in ``mode``: from memory, from the on-disk cache, or compiled
    now."""
    if mode in generated.kernels:
        return generated.kernels[mode]
    source = generated.source(mode)
    key = generated.key(mode)
    if key in _KERNELS:
        generated.kernels[mode] = _KERNELS[key]
        return _KERNELS[key]
    import numba

    folder = _cache_dir()
    if folder is not None:
        path = folder / f"kernel_{key}.py"
        if not path.exists():  # written once, atomically: the text is named by its own hash
            fd, tmp = tempfile.mkstemp(dir=folder, suffix=".py")
            with os.fdopen(fd, "w") as handle:
                handle.write(source)
            os.replace(tmp, path)
        name = f"machdyn_fused_kernel_{key}"
        spec = importlib.util.spec_from_file_location(name, path)
        assert spec is not None and spec.loader is not None
        module = importlib.util.module_from_spec(spec)
        sys.modules[name] = module
        spec.loader.exec_module(module)
        vars(module).update(_forms())
        kernel = numba.njit(cache=True, error_model="numpy", nogil=True)(module.kernel)
    else:  # no writable cache: compile from the text, for this session only
        namespace: dict[str, Any] = dict(_forms())
        exec(compile(source, f"<machdyn fused kernel {key}>", "exec"), namespace)
        kernel = numba.njit(error_model="numpy", nogil=True)(namespace["kernel"])
    _KERNELS[key] = generated.kernels[mode] = kernel
    return kernel


def _table(values: list) -> np.ndarray:
    """The parameter table: one row per design (one row if every parameter is a single value)."""
    n = max([np.size(v) for v in values if np.ndim(v) > 0], default=1)
    out = np.empty((n, max(len(values), 1)))
    for k, v in enumerate(values):
        out[:, k] = v
    return out


def prepared(mech, phi: np.ndarray):
    """The generated code and parameter table of ``mech``; kept with the model when they do not depend on the
    crank angles (no load given as a function of the crank angle or with a window)."""
    cached = mech._derived.get("fused")
    if cached is not None:
        return cached
    try:
        generated = generate(mech, phi)
    except Unsupported as exc:
        raise InputError(f"The fused engine cannot compile mechanism '{mech.name}': {exc}; use "
                         "engine='numpy'.") from None
    pair = (generated, _table(generated.params))
    if not generated.rows:
        mech._derived["fused"] = pair
    return pair


#: Crank angles per block of :func:`crank_trig`.
_BLOCK = 64


def crank_trig(phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """cos and sin of the crank angles ``phi`` [rad].

    For many evenly spaced angles (as :func:`~machdyn.linkage.kinematics.crank_angles` makes them) they follow
    from those of every 64th angle and of the 64 steps within a block by the angle-addition formulas,
    cos(a + b) = cos a cos b - sin a sin b, sin(a + b) = sin a cos b + cos a sin b: a few multiplications per
    angle instead of two transcendental functions. The result differs from ``np.cos``/``np.sin`` by a few units
    in the last place (two more roundings, and the grid's own rounding of a + b).
    """
    n = phi.size
    if n < 8 * _BLOCK:
        return np.cos(phi), np.sin(phi)
    step = (phi[-1] - phi[0]) / (n - 1)
    if not step > 0 or np.max(np.abs(np.diff(phi) - step)) > 1e-12 * step:
        return np.cos(phi), np.sin(phi)
    coarse = phi[::_BLOCK]
    fine = np.arange(_BLOCK) * step
    cc, sc = np.cos(coarse)[:, None], np.sin(coarse)[:, None]
    cf, sf = np.cos(fine), np.sin(fine)
    c = (cc * cf - sc * sf).ravel()[:n]
    s = (sc * cf + cc * sf).ravel()[:n]
    return c, s


def drive_table(value, phi: np.ndarray, designs: int | None) -> np.ndarray:
    """A crank speed or acceleration as a (1 or N, M) table: a single value, one per crank angle (a 1-D array
    shaped like phi), one per design (any other 1-D array, as the NumPy engine reads it) or both."""
    arr = np.asarray(value, dtype=float)
    if arr.ndim == 0:
        return np.full((1, phi.size), float(arr))
    if arr.ndim == 1:
        arr = arr[None, :] if arr.shape == phi.shape else arr[:, None]
    elif arr.ndim != 2:
        raise InputError(f"The crank speed and acceleration must have at most two axes; got shape {arr.shape}.")
    return np.ascontiguousarray(np.broadcast_to(arr, (arr.shape[0], phi.size)))


#: The NumPy engine (:func:`machdyn.linkage.kinematics.kinematics`), passed in by its caller: the fused engine
#: asks it for what the kernel does not compute (the transmission angles, on demand).
Reference = Callable[..., Kinematics]


@dataclass(frozen=True)
class Run:
    """What a fused pass returns: per-design summaries ``summary`` (N, 7 + joints) and, when asked for, the
    series ``series`` (fields, N, M) laid out as ``generated.series``."""

    generated: Generated
    summary: np.ndarray
    series: np.ndarray | None
    params: np.ndarray
    inputs: dict


def run(mech, phi, speed, acceleration, *, designs: int, about=(0.0, 0.0), series: bool = False,
        forces: bool = True, progress=None, chunk_designs: int | None = None) -> Run:
    """One fused pass over ``designs`` designs x the crank angles ``phi``: the series of the motion (and of
    the forces, with ``forces``) when ``series``, else the per-design summaries of the forces."""
    phi = np.ascontiguousarray(phi, dtype=float)
    generated, P = prepared(mech, phi)
    mode = ("full" if forces else "motion") if series else "summary"
    kernel = load_kernel(generated, mode)
    W = drive_table(speed, phi, mech.design_count)
    E = drive_table(acceleration, phi, mech.design_count)
    LP = np.stack(generated.rows) if generated.rows else _NO_ROWS
    DW = np.ascontiguousarray(np.broadcast_to(angle_weights(phi), phi.shape), dtype=float) if not series else phi
    weighted = bool(np.all(W != 0.0)) if not series else False
    C0, S0 = crank_trig(phi)
    out = np.empty((designs if not series else 0, len(SUMMARY_FIELDS) + len(generated.joints)))
    rows = generated.all_series if mode == "full" else generated.motion_series
    S = np.empty((rows, designs, phi.size)) if series else np.empty((0, 1, 1))
    B = np.empty((6 + len(generated.joints), phi.size)) if not series else np.empty((0, 1))
    about = np.asarray(about, dtype=float)
    step = designs if chunk_designs is None else max(1, int(chunk_designs))
    for start in range(0, designs, step):
        stop = min(designs, start + step)

        def part(table, start=start, stop=stop):
            return table[start:stop] if table.shape[0] > 1 else table

        kernel(part(P), C0, S0, part(W), part(E), DW, LP, about, weighted,
               S[:, start:stop] if series else S, out[start:stop] if not series else out, B)
        if progress is not None:
            progress(stop, designs)
    inputs = {"om": W, "ep": E, "c0": C0[None, :], "s0": S0[None, :]}
    return Run(generated, out, S if series else None, P, inputs)


def fused_kinematics(mech, phi, omega, eps, shape, on_fail: str, reference: Reference) -> Kinematics:
    """:func:`~machdyn.linkage.kinematics.kinematics` by the fused engine (same result, to rounding);
    ``reference`` is the NumPy engine, asked for the transmission angles if they are read."""
    return kinematics_from_run(mech, phi, omega, eps, shape, on_fail,
                               _series_run(mech, phi, omega, eps, shape, forces=False), reference)


def _series_run(mech, phi, omega, eps, shape, forces: bool) -> Run:
    n = shape[0] if len(shape) == 2 else 1
    return run(mech, phi, omega, eps, designs=n, series=True, forces=forces)


def kinematics_from_run(mech, phi, omega, eps, shape, on_fail: str, result: Run, reference: Reference) -> Kinematics:
    """The :class:`Kinematics` held in a series run."""
    states = {}
    with np.errstate(all="ignore"):
        angles = _angles(result, phi, shape)
    for name in mech.moving_bodies:
        fields = {f: series_of(result, f"body.{name}.{f}", shape) for f in KERNEL_BODY_FIELDS}
        states[name] = BodyState(**{_STATE_NAMES[f]: v for f, v in fields.items()}, angle=angles[name])
    slides, reports, failing = {}, [], []
    assembled = np.ones(shape, dtype=bool)
    for i, d in enumerate(mech.dyads):
        ok = series_of(result, f"dyad.{d.a}-{d.b}.assembled", shape) > 0.5
        assembled &= ok
        failing.append((d, ok))
        for body in d.slide_bodies().values():
            slides[body] = SlideMotion(*(full(series_of(result, f"slide.{body}.{f}", shape), shape)
                                         for f in ("s", "v", "a")))

        def transmission(i=i):  # computed on demand, by the reference engine
            return reference(mech, phi, omega, eps, on_fail="mask").dyad_reports[i].transmission

        reports.append(DyadReport(d.kind, (d.a, d.b), series_of(result, f"dyad.{d.a}-{d.b}.det", shape),
                                  transmission))
    return kinematics_result(mech, phi, omega, eps, shape, on_fail, states, slides, reports, failing, assembled)


def fused_kinetostatics(mech, crank_angle, speed, acceleration, engine: str, reference: Reference):
    """:func:`~machdyn.linkage.kinetostatics.kinetostatics` by the fused engine, or None when ``engine``
    'auto' leaves the request to the NumPy engine; ``reference`` as for :func:`fused_kinematics`."""

    phi = np.asarray(crank_angle, dtype=float)
    check_finite("crank angle", phi, "rad")
    check_finite("crank speed", speed, "rad/s")
    check_finite("crank acceleration", acceleration, "rad/s^2")
    omega, eps = np.asarray(speed, dtype=float), np.asarray(acceleration, dtype=float)
    if mech.design_count is not None:
        omega = column(omega) if omega.ndim == 1 and omega.shape != phi.shape else omega
        eps = column(eps) if eps.ndim == 1 and eps.shape != phi.shape else eps
    designs = (mech.design_count, 1) if mech.design_count is not None else ()
    shape = np.broadcast_shapes(designs, np.shape(phi), np.shape(omega), np.shape(eps))
    if not use_fused(engine, mech, phi, int(np.prod(shape))):
        return None
    result = _series_run(mech, phi, omega, eps, shape, forces=True)
    kin = kinematics_from_run(mech, phi, omega, eps, shape, "raise", result, reference)
    joint_list = tuple(Joint(*j) for j in joints(mech))
    reactions = {}
    for j, joint in enumerate(joint_list):
        extra = [series_of(result, f"joint.{j}.{f}", shape) if has_series(result, f"joint.{j}.{f}") else None
                 for f in ("normal", "couple")]
        reactions[joint.name] = Reaction(full(series_of(result, f"joint.{j}.fx", shape), shape),
                                         full(series_of(result, f"joint.{j}.fy", shape), shape),
                                         *(None if v is None else full(v, shape) for v in extra))
    return Forces(kin, joint_list, reactions, *(full(series_of(result, f"forces.{f}", shape), shape)
                                                 for f in ("torque", "fx", "fy", "m")))


_STATE_NAMES = {"x": "x", "y": "y", "vx": "vx", "vy": "vy", "ax": "ax", "ay": "ay", "w": "omega", "al": "alpha",
                "c": "cos", "s": "sin"}


def _angles(result: Run, phi, shape) -> dict[str, np.ndarray]:
    """The body angles of a series run, computed as the NumPy engine computes them (arctan2 of the body's
    cos and sin, the crank angle, a guide's body angle plus the guide's angle)."""
    out: dict[str, np.ndarray] = {}
    for body, how in result.generated.angles:
        if how[0] == "atan2":
            out[body] = np.arctan2(series_of(result, f"body.{body}.s", shape),
                                   series_of(result, f"body.{body}.c", shape))
        elif how[0] == "crank":
            out[body] = phi
        elif how[0] == "value":
            out[body] = series_of(result, f"angle.{body}.th", shape)
        else:
            column = result.params[:, how[2]]
            value = column.reshape(-1, 1) if len(shape) == 2 and column.size > 1 else column[0]
            out[body] = (0.0 if how[1] == GROUND else out[how[1]]) + value
    return out


def series_of(result: Run, name: str, shape):
    """The output ``name`` of a series run: a row the kernel wrote, shaped ``shape``, or a constant, an
    input or a parameter, as a float or an array that broadcasts to ``shape`` (as the NumPy engine keeps
    them until a result is read)."""
    kind, what = result.generated.series[name]
    if kind == "row":
        return result.series[what].reshape(shape)  # type: ignore[index]
    if kind == "const":
        return what
    table = result.inputs[what] if kind == "input" else result.params[:, what:what + 1]
    if len(shape) == 2:
        return table
    return table[0] if kind == "input" else float(table[0, 0])


def has_series(result: Run, name: str) -> bool:
    return name in result.generated.series
