"""Derived formulas of ``[optimise.derived]``: parsed once, checked against limits, evaluated by walking the tree.

A formula is arithmetic (``+ - * / **``, unary signs) of the variables, numbers, ``pi`` and the functions of
:data:`FORMULA_FUNCTIONS`. It is never handed to Python's ``eval``: every number is a 64-bit float (so no
operation can build an integer of millions of digits, as ``9**9**9`` would), a number or a constant exponent
may not exceed :data:`MAX_CONSTANT` / :data:`MAX_EXPONENT` in magnitude, and a formula has at most
:data:`MAX_NODES` operations and :data:`MAX_FORMULA_TEXT` characters. Evaluating one over N designs therefore
costs at most :data:`MAX_NODES` NumPy operations on arrays of N floats; an overflow gives inf, which marks the
design as not buildable.
"""

from __future__ import annotations

import ast
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ...problem.errors import did_you_mean
from ...problem.fields import FieldError, Unit

#: Functions a derived formula may call (numpy, so that they act on a whole population at once).
FORMULA_FUNCTIONS = {
    "sqrt": np.sqrt, "sin": np.sin, "cos": np.cos, "tan": np.tan, "atan2": np.arctan2, "atan": np.arctan,
    "asin": np.arcsin, "acos": np.arccos, "hypot": np.hypot, "abs": np.abs, "min": np.minimum, "max": np.maximum,
}
_ARITY = {"atan2": 2, "hypot": 2, "min": 2, "max": 2}
FORMULA_CONSTANTS = {"pi": math.pi}

#: The longest formula text read.
MAX_FORMULA_TEXT = 500
#: The most nodes (numbers, names, operations, calls) of a formula.
MAX_NODES = 200
#: The largest number (in magnitude) written in a formula.
MAX_CONSTANT = 1e12
#: The largest constant exponent (in magnitude) of ``**``.
MAX_EXPONENT = 16.0

_BINARY = {ast.Add: np.add, ast.Sub: np.subtract, ast.Mult: np.multiply, ast.Div: np.divide, ast.Pow: np.power}
_UNARY = {ast.USub: np.negative, ast.UAdd: np.positive}


@dataclass(frozen=True)
class Formula:
    """A derived quantity: ``path`` = ``expression`` of the variables (SI)."""

    path: str
    expression: str
    unit: Unit
    code: Any = field(repr=False, compare=False)

    def __call__(self, values: dict[str, np.ndarray]) -> np.ndarray:
        scope = {**FORMULA_CONSTANTS, **values}
        with np.errstate(all="ignore"):
            return np.asarray(_evaluate(self.code, scope), dtype=float)


def _evaluate(node: ast.AST, scope: dict[str, Any]) -> Any:
    if isinstance(node, ast.Expression):
        return _evaluate(node.body, scope)
    if isinstance(node, ast.Constant):
        return np.float64(float(node.value))  # type: ignore[arg-type]  # compile_formula admits numbers only
    if isinstance(node, ast.Name):
        return scope[node.id]
    if isinstance(node, ast.BinOp):
        return _BINARY[type(node.op)](_evaluate(node.left, scope), _evaluate(node.right, scope))
    if isinstance(node, ast.UnaryOp):
        return _UNARY[type(node.op)](_evaluate(node.operand, scope))
    if isinstance(node, ast.Call):
        assert isinstance(node.func, ast.Name)
        return FORMULA_FUNCTIONS[node.func.id](*(_evaluate(a, scope) for a in node.args))
    raise AssertionError(f"unchecked node {type(node).__name__}")  # compile_formula lets no other node through


def _constant_value(node: ast.AST) -> float | None:
    """The value of a sub-expression of numbers only (evaluated in floats), None if it uses a variable."""
    if any(isinstance(n, ast.Name) and n.id not in FORMULA_CONSTANTS for n in ast.walk(node)):
        return None
    with np.errstate(all="ignore"):
        return float(_evaluate(node, dict(FORMULA_CONSTANTS)))


def compile_formula(path: str, text: str, names: list[str], unit: Unit) -> Formula:
    """Check that ``text`` is bounded arithmetic of the variables, numbers, ``pi`` and :data:`FORMULA_FUNCTIONS`.

    Raises :class:`~machdyn.problem.fields.FieldError` naming the rule that ``text`` breaks.
    """
    if len(text) > MAX_FORMULA_TEXT:
        raise FieldError(f"a formula may have at most {MAX_FORMULA_TEXT} characters; got {len(text)}")
    try:
        tree = ast.parse(text, mode="eval")
    except (SyntaxError, RecursionError, MemoryError, ValueError):
        raise FieldError(f"'{text}' is not a formula (e.g. \"hypot(l, h)\")") from None
    nodes = [n for n in ast.walk(tree) if not isinstance(n, ast.operator | ast.unaryop | ast.expr_context)]
    if len(nodes) > MAX_NODES:
        raise FieldError(f"a formula may have at most {MAX_NODES} numbers, names and operations; "
                         f"'{text[:60]}' has {len(nodes)}")
    known = set(names) | set(FORMULA_FUNCTIONS) | set(FORMULA_CONSTANTS)
    callees = {id(n.func) for n in nodes if isinstance(n, ast.Call)}
    for node in nodes:
        if id(node) not in callees:
            _check_node(node, text, names, known)
    return Formula(path, text, unit, tree)


def _check_node(node: ast.AST, text: str, names: list[str], known: set[str]) -> None:
    allowed = (ast.Expression, ast.BinOp, ast.UnaryOp, ast.Name, ast.Call, ast.Constant)
    if not isinstance(node, allowed) or (isinstance(node, ast.BinOp) and type(node.op) not in _BINARY) or (
            isinstance(node, ast.UnaryOp) and type(node.op) not in _UNARY):
        kind = type(getattr(node, "op", node)).__name__
        raise FieldError(f"'{text}' uses {kind}; a formula may use + - * / **, numbers, "
                         f"the variables and {', '.join(FORMULA_FUNCTIONS)}")
    if isinstance(node, ast.Constant):
        if isinstance(node.value, bool) or not isinstance(node.value, int | float):
            raise FieldError(f"'{text}' holds {node.value!r}, which is not a number")
        if not (isinstance(node.value, int) and abs(node.value) <= MAX_CONSTANT
                or isinstance(node.value, float) and math.isfinite(node.value) and abs(node.value) <= MAX_CONSTANT):
            raise FieldError(f"'{text}' holds a number larger than {MAX_CONSTANT:g} in magnitude")
    if isinstance(node, ast.Name) and node.id not in known:
        raise FieldError(f"'{text}' uses '{node.id}', which is no variable{did_you_mean(node.id, names)} "
                         f"(variables: {', '.join(names)})")
    if isinstance(node, ast.Name) and node.id in FORMULA_FUNCTIONS:
        raise FieldError(f"'{text}' uses the function '{node.id}' without calling it")
    if isinstance(node, ast.Call):
        if not (isinstance(node.func, ast.Name) and node.func.id in FORMULA_FUNCTIONS) or node.keywords:
            raise FieldError(f"'{text}' calls something that is not one of {', '.join(FORMULA_FUNCTIONS)}")
        arity = _ARITY.get(node.func.id, 1)
        if len(node.args) != arity or any(isinstance(a, ast.Starred) for a in node.args):
            raise FieldError(f"'{text}' calls {node.func.id} with {len(node.args)} arguments; it takes {arity}")
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Pow):
        exponent = _constant_value(node.right)
        if exponent is not None and not abs(exponent) <= MAX_EXPONENT:
            raise FieldError(f"'{text}' raises to the power {exponent:g}; a constant exponent may be at most "
                             f"{MAX_EXPONENT:g} in magnitude")
