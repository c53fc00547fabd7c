"""The writer of a fused kernel's text: :class:`Generator` collects the lines of each section (motion, forces,
series) while a mechanism is walked, naming its values and reading every number from a parameter table, so that
the text depends on the topology only. :mod:`.fused_source` walks the mechanism with it; each dyad writes its own
lines through it (:mod:`.fused_dyads`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .refs import GROUND, split_ref

_GROUND_STATE = {"x": "0.0", "y": "0.0", "vx": "0.0", "vy": "0.0", "ax": "0.0", "ay": "0.0",
                 "w": "0.0", "al": "0.0", "c": "1.0", "s": "0.0"}


class Unsupported(Exception):
    """The mechanism uses a feature the fused engine does not compile (the NumPy engine handles it)."""



@dataclass
class Generator:
    """Collects the lines of each section of the kernel while the mechanism is walked."""

    mech: Any
    phi: np.ndarray
    params: list = field(default_factory=list)
    rows: list = field(default_factory=list)
    prologue: list = field(default_factory=list)
    motion: list = field(default_factory=list)
    angles: list = field(default_factory=list)  # (body, how its angle follows), in solution order
    loads: list = field(default_factory=list)
    forces: list = field(default_factory=list)
    series: dict = field(default_factory=dict)
    series_lines: list = field(default_factory=list)
    stored: dict = field(default_factory=dict)
    prefixes: dict = field(default_factory=dict)
    counter: int = 0
    bodies: dict = field(default_factory=dict)
    dead_checks: list = field(default_factory=list)
    assembled: list = field(default_factory=list)
    joint_base: int = 0
    reactions: list = field(default_factory=list)
    force_solvers: list = field(default_factory=list)
    transmissions: list = field(default_factory=list)
    exprs: dict = field(default_factory=dict)

    # -- names and values
    def new(self, prefix: str) -> str:
        self.counter += 1
        return f"{prefix}{self.counter}"

    def param(self, value) -> str:
        """A parameter column read once per design; returns its local name."""
        arr = np.asarray(value, dtype=float)
        if arr.ndim > 1:
            raise Unsupported("parameters with more than one axis")
        name = f"q{len(self.params)}"
        self.params.append(float(arr) if arr.ndim == 0 else arr)
        self.prologue.append(f"{name} = P[ip, {len(self.params) - 1}]")
        return name

    def row(self, values) -> str:
        """A per-position value (a load that depends on the crank angle); returns an expression."""
        arr = np.asarray(values, dtype=float)
        try:
            arr = np.broadcast_to(arr, self.phi.shape)
        except ValueError:
            raise Unsupported("a load that varies by design and crank angle") from None
        self.rows.append(np.ascontiguousarray(arr))
        return f"LP[{len(self.rows) - 1}, j]"

    def local(self, body: str, point: str, value: bool = False) -> tuple[str, str] | None:
        """Parameter names of a body-frame point, or None for a joint at the frame origin of a moving body
        (as the builders place a link's first joint): that shortcut is part of the topology, so it is taken
        for joints only; ground points and ``value`` points (centres of mass, guides, load points) are always
        parameters, so that a value that happens to be zero does not make another topology."""
        xy = self.mech.ground[point] if body == GROUND else self.mech.body(body).points[point]
        return self.local_xy(xy, value or body == GROUND)

    def local_xy(self, xy, value: bool = False) -> tuple[str, str] | None:
        u, v = xy
        if not value and isinstance(u, float | int) and isinstance(v, float | int) and u == 0 and v == 0:
            return None
        return self.param(u), self.param(v)

    def emit(self, section: list, text: str) -> None:
        section.extend(line.strip() for line in text.strip().splitlines())

    def call(self, prefix: str, form: str, outputs: tuple[str, ...], args: list[str],
             section: list | None = None) -> None:
        """``prefix + output`` for each output = the dyad form ``form`` (:mod:`.dyad_forms`) of ``args``."""
        names = ", ".join(prefix + o for o in outputs)
        self.emit(self.motion if section is None else section, f"{names} = F_{form}({', '.join(args)})")

    def state(self, body: str) -> dict[str, str]:
        return _GROUND_STATE if body == GROUND else self.bodies[body]

    # -- kinematic building blocks (the formulas of machdyn.linkage.state)
    def point(self, body: str, local: tuple[str, str] | None, section: list | None = None) -> dict[str, str]:
        """Motion of a body-frame point: x, y, vx, vy, ax, ay."""
        section = self.motion if section is None else section
        s = self.state(body)
        if local is None:
            return {k: s[k] for k in ("x", "y", "vx", "vy", "ax", "ay")}
        u, v = local
        p = self.new("p")
        if body == GROUND:
            self.emit(section, f"{p}x = {u}\n{p}y = {v}")
            return {"x": f"{p}x", "y": f"{p}y", "vx": "0.0", "vy": "0.0", "ax": "0.0", "ay": "0.0"}
        self.emit(section, f"""
            {p}rx = {s['c']} * {u} - {s['s']} * {v}
            {p}ry = {s['s']} * {u} + {s['c']} * {v}
            {p}w2 = {s['w']} * {s['w']}
            {p}x = {s['x']} + {p}rx
            {p}y = {s['y']} + {p}ry
            {p}vx = {s['vx']} - {s['w']} * {p}ry
            {p}vy = {s['vy']} + {s['w']} * {p}rx
            {p}ax = {s['ax']} - {s['al']} * {p}ry - {p}w2 * {p}rx
            {p}ay = {s['ay']} + {s['al']} * {p}rx - {p}w2 * {p}ry
        """)
        return {k: f"{p}{k}" for k in ("x", "y", "vx", "vy", "ax", "ay")}

    def ref_point(self, ref: str, section: list | None = None, value: bool = False) -> dict[str, str]:
        body, name = split_ref(ref)
        return self.point(body, self.local(body, name, value), section)

    def place(self, body: str, p: dict, local, omega: str, alpha: str, c: str, s: str, angle: tuple) -> None:
        """The state of ``body`` whose point ``local`` moves as ``p`` (body_from_point). Its angle is computed
        after the kernel, for the series output only, as ``angle`` says: ("atan2",) from its cos and sin,
        ("crank",) the crank angle, ("plus", other body, parameter) the other's angle plus a parameter, or
        ("value", expression) an expression of the kernel."""
        k = self.new("b")
        if local is None:
            names = {f: p[f] for f in ("x", "y", "vx", "vy", "ax", "ay")}
        else:
            u, v = local
            names = {f: f"{k}{f}" for f in ("x", "y", "vx", "vy", "ax", "ay")}
            self.emit(self.motion, f"""
                {k}rx = {c} * {u} - {s} * {v}
                {k}ry = {s} * {u} + {c} * {v}
                {k}w2 = {omega} * {omega}
                {k}x = {p['x']} - {k}rx
                {k}y = {p['y']} - {k}ry
                {k}vx = {p['vx']} + {omega} * {k}ry
                {k}vy = {p['vy']} - {omega} * {k}rx
                {k}ax = {p['ax']} + {alpha} * {k}ry + {k}w2 * {k}rx
                {k}ay = {p['ay']} - {alpha} * {k}rx + {k}w2 * {k}ry
            """)
        names.update(w=omega, al=alpha, c=c, s=s)
        if angle[0] == "value":
            self.series_out(f"angle.{body}", {"th": angle[1]})
            angle = ("value",)
        elif angle[0] == "plus":
            angle = ("plus", angle[1], int(angle[2][1:]))  # the parameter's column
        self.angles.append((body, angle))
        self.bodies[body] = names
        self.prefixes[body] = k
        self.series_out(f"body.{body}", names)

    def series_out(self, prefix: str, names: dict[str, str]) -> None:
        """Outputs of the series kernels: each a row the kernel writes, unless it is a constant, an input
        (crank speed, acceleration, cos and sin of the crank angle), a parameter or a row already written."""
        for f, expr in names.items():
            self.exprs[f"{prefix}.{f}"] = expr
            if re.fullmatch(r"-?\d+\.\d+", expr):
                self.series[f"{prefix}.{f}"] = ("const", float(expr))
            elif expr in ("om", "ep", "c0", "s0"):
                self.series[f"{prefix}.{f}"] = ("input", expr)
            elif re.fullmatch(r"q\d+", expr):
                self.series[f"{prefix}.{f}"] = ("param", int(expr[1:]))
            else:
                if expr not in self.stored:
                    self.stored[expr] = len(self.stored)
                    self.series_lines.append(f"S_{self.stored[expr]}[j] = {expr}")
                self.series[f"{prefix}.{f}"] = ("row", self.stored[expr])

    def line(self, local_from, local_to) -> tuple[str, str, str]:
        """Per design: length and unit direction from one body-frame point to another (dyads._line)."""
        k = self.new("L")
        fu, fv = local_from if local_from is not None else ("0.0", "0.0")
        tu, tv = local_to if local_to is not None else ("0.0", "0.0")
        self.emit(self.prologue, f"""
            {k}dx = {tu} - {fu}
            {k}dy = {tv} - {fv}
            {k} = math.hypot({k}dx, {k}dy)
            {k}c = {k}dx / {k}
            {k}s = {k}dy / {k}
        """)
        return k, f"{k}c", f"{k}s"

    def dyad_check(self, assembled: str, det: str, name: str, transmission: tuple[str, str]) -> None:
        """A dyad's closure flag and normalised determinant expressions, and its transmission angle [rad] as
        (function, argument): ("acos", x) for arccos(clip(x, -1, 1)), ("asin", x) for arcsin(clip(x, 0, 1))."""
        self.assembled.append(assembled)
        self.dead_checks.append(det)
        self.transmissions.append(transmission)
        self.series_out(f"dyad.{name}", {"assembled": f"1.0 if {assembled} else 0.0", "det": det})

    # -- forces (the formulas of machdyn.linkage.kinetostatics)
    def react(self, index: int, fx: str, fy: str, normal: str | None = None, couple: str | None = None) -> None:
        j = self.joint_base + index
        self.emit(self.forces, f"r{j}x = {fx}\nr{j}y = {fy}")
        outputs = {"fx": f"r{j}x", "fy": f"r{j}y"}
        if normal is not None:
            self.emit(self.forces, f"r{j}n = {normal}\nr{j}c = {couple}")
            outputs.update(normal=f"r{j}n", couple=f"r{j}c")
        self.reactions.append((j, outputs))

    def transmit(self, body: str, x: str, y: str, fx: str, fy: str) -> None:
        t = self.new("t")
        self.emit(self.forces, f"{t}x = -({fx})\n{t}y = -({fy})")
        self.add_force_at(body, x, y, f"{t}x", f"{t}y")

    def add_force_at(self, body: str, x: str, y: str, fx: str, fy: str) -> None:
        if body == GROUND:
            self.emit(self.forces, f"""
                ffx = ffx + {fx}
                ffy = ffy + {fy}
                ffm = ffm + ({x} * {fy} - {y} * {fx})
            """)
        else:
            self.add_load(body, fx, fy, f"{x} * {fy} - {y} * {fx}")

    def add_load(self, body: str, fx: str, fy: str, m: str, section: list | None = None) -> None:
        if body == GROUND:
            return
        k = self.prefixes[body]
        self.emit(self.forces if section is None else section, f"""
            {k}lx = {k}lx + {fx}
            {k}ly = {k}ly + {fy}
            {k}lm = {k}lm + ({m})
        """)

    def couple_back(self, body: str, couple: str) -> None:
        if body == GROUND:
            self.emit(self.forces, f"ffm = ffm + (-({couple}))")
        else:
            self.add_load(body, "0.0", "0.0", f"-({couple})")

    def load(self, body: str) -> tuple[str, str, str]:
        k = self.prefixes[body]
        return f"{k}lx", f"{k}ly", f"{k}lm"

    def on(self, body: str, point: str) -> dict[str, str]:
        """Position of a point of a solved body, recomputed from its frame (ForceContext.on)."""
        return self.point(body, self.local(body, point), self.forces)
