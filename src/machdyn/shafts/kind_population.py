"""The population form of the ``[shaft_line]`` kind (:attr:`machdyn.pipeline.ProblemKind.population`): the results a
run of each design reports — its engine orders, its unbalance, its two correction masses — for N designs at once,
the designs differing in the cylinders' and the masses' fields and the line's speed and reference plane.

The file's line is built once (:func:`.model.build`); each design's values replace its fields, and the population
forms compute what :func:`.model.analyse` computes design by design: the engine figures by
:func:`.engine_population.engine_orders_population` (Uicker, Pennock & Shigley, 5th ed., sec. 16.6; Khurmi &
Gupta, 14th ed., sec. 22.4-22.11), the resultant unbalance and its moment S0 = Σ m r e^{iα}, S1 = Σ m r (z − z_ref)
e^{iα} and the two-plane corrections by :mod:`.population` (Khurmi & Gupta, 14th ed., sec. 21.8). A design whose
run would fail (a rod not longer than its crank, a negative mass, a speed <= 0) gets NaN. A path or a key outside
these (a bearing's reaction, a grade, a plane's holes, field balancing) returns None: the study runs each design.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from typing import Any

import numpy as np

from .engine_population import engine_orders_population
from .model import build
from .population import grade_population, two_plane_population, unbalance_arrays
from .rotating import cycle

CYLINDER_FIELDS = ("position", "phase", "axis", "crank", "rod", "reciprocating_mass", "rotating_mass")
MASS_FIELDS = ("mass", "radius", "angle", "position")
LINE_FIELDS = ("speed", "reference")
_ITEM = re.compile(r"^(cylinders|masses)\[(\d+)\]\.(\w+)$")

#: the engine figures a run reports under ``shaft.engine.<name>``
ENGINE_KEYS = ("primary_force", "secondary_force", "primary_couple", "secondary_couple", "primary_direct",
               "primary_reverse", "secondary_direct", "secondary_reverse", "gross_force", "gross_couple")
#: the engine figures of the two-term series and the crank resultants: closed forms, no exact loads needed
TWO_TERM = ENGINE_KEYS
UNBALANCE_KEYS = ("shaft.unbalance", "shaft.couple_unbalance", "shaft.unbalance.gross",
                  "shaft.couple_unbalance.gross")


def _columns(items: tuple, fields: tuple[str, ...], n: int) -> dict[str, np.ndarray]:
    """(n, M) arrays of the items' fields, every design as the file gives it."""
    return {f: np.tile(np.array([float(getattr(it, f)) for it in items]), (n, 1)) for f in fields}


def _apply(values: Mapping[str, Any], n: int, cyl: dict, mas: dict, line: dict) -> bool:
    """Write each design's values into the arrays; False for a path this form does not vary."""
    for path, arr in values.items():
        column = np.broadcast_to(np.asarray(arr, dtype=float), (n,))
        if path.startswith("shaft_line.") and path.split(".", 1)[1] in LINE_FIELDS:
            line[path.split(".", 1)[1]] = column.copy()
            continue
        found = _ITEM.match(path)
        if found is None:
            return False
        table, index, name = found.group(1), int(found.group(2)), found.group(3)
        target, fields = (cyl, CYLINDER_FIELDS) if table == "cylinders" else (mas, MASS_FIELDS)
        if name not in fields or index >= target[fields[0]].shape[1]:
            return False
        target[name][:, index] = column
    return True


def _over_turn(c: np.ndarray, k: int, theta: np.ndarray) -> np.ndarray:
    """(N, S) Re(sum c e^{i k theta}) = Re C cos k theta - Im C sin k theta over the cylinders' c (N, C)."""
    total = c.sum(axis=1)[:, None]
    return total.real * np.cos(k * theta)[None, :] - total.imag * np.sin(k * theta)[None, :]


def _two_term(cyl: dict[str, np.ndarray], speed: np.ndarray, reference: np.ndarray, samples: int,
              valid: np.ndarray) -> dict[str, np.ndarray]:
    """The two-term figures of N engines without their exact loads: the primary (order k = 1) and secondary
    (k = 2) loads along each line of stroke, m w^2 r cos(k phi) / n^(k-1) with phi = theta + phase - axis (Khurmi &
    Gupta, 14th ed., sec. 22.4-22.5), are Re(A e^{i k theta}) summed over the cylinders first, A = m w^2 r
    e^{i k (phase - axis)} / n^(k-1) times the direction cosines (and the arm z - z_ref for the couples): each
    force and couple over the turn is then one (N, S) array, its peak taken over the same angles as
    :func:`.reciprocating.two_term_loads`. The crank resultants and gross figures as
    :func:`.engine_population.engine_orders_population`."""
    theta = cycle(samples)
    ok = valid[:, None]
    crank = np.where(ok, cyl["crank"], 1.0)
    rod = np.where(ok, cyl["rod"], 2.0)
    m_rec, phase, axis = cyl["reciprocating_mass"], cyl["phase"], cyl["axis"]
    zr = cyl["position"] - reference[:, None]
    amp = m_rec * (speed * speed)[:, None] * crank
    ratio = rod / crank
    ca, sa = np.cos(axis), np.sin(axis)
    out: dict[str, np.ndarray] = {}
    for name, k, size in (("primary", 1, amp), ("secondary", 2, amp / ratio)):
        a = size * np.exp(1j * k * (phase - axis))
        fx, fy = _over_turn(a * ca, k, theta), _over_turn(a * sa, k, theta)
        out[f"{name}_force"] = np.sqrt(np.max(fx * fx + fy * fy, axis=1))
        mx, my = _over_turn(-a * sa * zr, k, theta), _over_turn(a * ca * zr, k, theta)
        out[f"{name}_couple"] = np.sqrt(np.max(mx * mx + my * my, axis=1))
    mr = m_rec * crank
    out["primary_direct"] = np.abs((mr / 2 * np.exp(1j * phase)).sum(axis=1))
    out["primary_reverse"] = np.abs((mr / 2 * np.exp(1j * (2 * axis - phase))).sum(axis=1))
    out["secondary_direct"] = np.abs((mr / (2 * ratio) * np.exp(1j * (2 * phase - axis))).sum(axis=1))
    out["secondary_reverse"] = np.abs((mr / (2 * ratio) * np.exp(1j * (3 * axis - 2 * phase))).sum(axis=1))
    out["gross_force"] = amp.sum(axis=1)
    out["gross_couple"] = (amp * np.abs(zr)).sum(axis=1)
    return out


def _wanted(keys: Iterable[str], line: Any, grade: Any = None) -> dict[str, str] | None:
    """key -> which figure gives it, or None if some key is outside this form."""
    planes = [p.name for p in line.planes]
    out: dict[str, str] = {}
    orders = range(1, min(line.harmonics, line.positions // 2 - 1) + 1)
    engine = {f"shaft.engine.{k}" for k in ENGINE_KEYS}
    engine |= {f"shaft.engine.order{k}.{what}" for k in orders for what in ("force", "couple")}
    for key in keys:
        if key in engine and line.cylinders:
            out[key] = "engine"
        elif key in UNBALANCE_KEYS and (line.masses or line.cylinders):
            out[key] = "unbalance"
        elif key.startswith("shaft.balance.") and key.split(".")[2:3] and key.split(".")[2] in planes and \
                key.split(".")[3:] in (["mass"], ["angle"]):
            out[key] = "balance"
        elif key.startswith("shaft.grade.") and problem_grade_key(key, line, grade):
            out[key] = "grade"
        else:
            return None
    return out


def problem_grade_key(key: str, line: Any, grade: Any) -> bool:
    """Whether ``key`` is a result of the file's ``[grade]`` check (its bearing planes' names included)."""
    if grade is None:
        return False
    names = list(grade.bearings or [b.name for b in line.bearings][:2])
    plain = {"U_per", "achieved_G", "margin"}
    made = {f"{n}.{what}" for n in names for what in ("allowed", "residual")}
    return key.removeprefix("shaft.grade.") in plain | made


def _grade(spec: Any, line: Any, speed: np.ndarray, mas: dict[str, np.ndarray], fit: dict | None,
           valid: np.ndarray) -> dict[str, np.ndarray]:
    """The ISO 21940-11 figures of N rotors (:func:`.population.grade_population`): the line's own masses, with
    the two fitted corrections for a balanced rotor, judged in the file's two bearing planes (as
    :func:`.model.analyse` judges one design)."""
    names = tuple(spec.bearings or [b.name for b in line.bearings][:2])
    za, zb = (next(b.position for b in line.bearings if b.name == n) for n in names)
    centre = 0.5 * (za + zb) if spec.centre is None else spec.centre
    m, r, a, z = mas["mass"], mas["radius"], mas["angle"], mas["position"]
    if fit is not None:  # the corrections as fitted, at their planes' radii
        left, right = line.planes
        extra_m = np.stack([fit["L.mass"], fit["M.mass"]], axis=1)
        extra_a = np.stack([fit["L.angle"], fit["M.angle"]], axis=1)
        n = len(speed)
        m, a = np.concatenate([m, np.where(valid[:, None], extra_m, 0.0)], axis=1), np.concatenate(
            [a, np.where(valid[:, None], extra_a, 0.0)], axis=1)
        r = np.concatenate([r, np.tile([left.radius, right.radius], (n, 1))], axis=1)
        z = np.concatenate([z, np.tile([left.position, right.position], (n, 1))], axis=1)
    g = grade_population(spec.G, spec.rotor_mass, speed, centre, za, zb, m, r, a, z)
    out = {"shaft.grade.U_per": g["U_per"], "shaft.grade.achieved_G": g["achieved_G"],
           "shaft.grade.margin": np.where(np.isfinite(g["margin"]), g["margin"], np.nan)}
    for name, side in zip(names, ("A", "B"), strict=True):
        out[f"shaft.grade.{name}.allowed"] = g[f"{side}.allowed"]
        out[f"shaft.grade.{name}.residual"] = g[f"{side}.residual"]
    valid &= g["valid"]
    return out


def population(problem: Any, values: Mapping[str, Any], keys: Iterable[str]) -> dict[str, np.ndarray] | None:
    """The ``keys`` of N shaft-line designs, (N,) arrays (module docstring); None where this form cannot stand in
    for the runs."""
    line, problems = build(problem)
    if problems or line is None:
        return None
    wanted = _wanted(keys, line, problem.grade)
    if wanted is None:
        return None
    fitted = "balance" in wanted.values() or ("grade" in wanted.values() and problem.grade.state == "balanced")
    if fitted and (len(line.planes) != 2 or problem.balance.target != "rotating"
                                         or problem.balance.resolution is not None or any(line.holes)
                                         or line.reciprocating_share > 0):
        return None  # a single plane, holes, rounding or the first harmonic: each design is run
    n = len(next(iter(values.values()))) if values else 1
    cyl = _columns(line.cylinders, CYLINDER_FIELDS, n)
    mas = _columns(line.masses, MASS_FIELDS, n)
    at = {"speed": np.full(n, line.speed), "reference": np.full(n, line.reference)}
    if not _apply(values, n, cyl, mas, at):
        return None
    valid = (at["speed"] > 0) & np.isfinite(at["speed"]) & np.isfinite(at["reference"])
    valid &= np.all((mas["mass"] >= 0) & (mas["radius"] >= 0), axis=1)
    valid &= np.all(np.isfinite(np.stack(list(mas.values()), axis=2)), axis=(1, 2))
    out: dict[str, np.ndarray] = {}
    engine_keys = {k.removeprefix("shaft.engine.") for k, v in wanted.items() if v == "engine"}
    cylinders_ok = np.all((cyl["crank"] > 0) & (cyl["rod"] > cyl["crank"]) & (cyl["reciprocating_mass"] >= 0)
                          & (cyl["rotating_mass"] >= 0), axis=1)
    cylinders_ok &= np.all(np.isfinite(np.stack(list(cyl.values()), axis=2)), axis=(1, 2))
    if engine_keys and engine_keys <= set(TWO_TERM):  # the two-term figures alone: no exact loads
        valid &= cylinders_ok
        out |= {f"shaft.engine.{k}": v for k, v in
                _two_term(cyl, at["speed"], at["reference"], line.positions, valid).items()}
    elif engine_keys:
        harmonics = min(line.harmonics, line.positions // 2 - 1)
        eng = engine_orders_population(cyl, at["speed"], line.positions, harmonics, at["reference"],
                                       include_rotating=True)
        valid &= eng["valid"]
        out |= {f"shaft.engine.{k}": v for k, v in eng.items() if k != "valid"}
    else:
        valid &= cylinders_ok
    # the rotating masses: the line's, then each cylinder's at its crank pin (ShaftLine.balanced_masses)
    m = np.concatenate([mas["mass"], cyl["rotating_mass"]], axis=1)
    r = np.concatenate([mas["radius"], cyl["crank"]], axis=1)
    a = np.concatenate([mas["angle"], cyl["phase"]], axis=1)
    z = np.concatenate([mas["position"], cyl["position"]], axis=1)
    if "unbalance" in wanted.values():
        s0, s1 = unbalance_arrays(m, r, a, z, at["reference"])
        u = m * r
        out |= {"shaft.unbalance": np.abs(s0), "shaft.couple_unbalance": np.abs(s1),
                "shaft.unbalance.gross": np.abs(u).sum(axis=1),
                "shaft.couple_unbalance.gross": np.abs(u * (z - at["reference"][:, None])).sum(axis=1)}
    if fitted:
        left, right = line.planes
        fit = two_plane_population(m, r, a, z, left.position, right.position, left.radius, right.radius)
        valid &= fit["valid"]
        for side, plane in (("L", left), ("M", right)):
            out[f"shaft.balance.{plane.name}.mass"] = fit[f"{side}.mass"]
            out[f"shaft.balance.{plane.name}.angle"] = fit[f"{side}.angle"]
    if "grade" in wanted.values():
        out |= _grade(problem.grade, line, at["speed"], mas, fit if fitted else None, valid)
    return {k: np.where(valid, np.asarray(out[k], dtype=float), np.nan) for k in wanted}
