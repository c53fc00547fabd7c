"""Turn pydantic's validation errors into (path, message) pairs a designer can act on.

Paths are written as in the file (``mechanism.coupler.length``, ``loads.forces[0].point``); unknown keys get a
"did you mean" from the keys allowed at that place; misspelled ``type`` values get one from the known types.
"""

from __future__ import annotations

import difflib
import types
import typing
from typing import Any, Literal

from pydantic import BaseModel, ValidationError


def did_you_mean(word: str, choices: list[str] | tuple[str, ...]) -> str:
    """``"; did you mean 'coupler'?"`` for the nearest choice, else an empty string."""
    near = difflib.get_close_matches(str(word), list(choices), n=1, cutoff=0.6)
    return f"; did you mean '{near[0]}'?" if near else ""


def format_path(parts: list[Any] | tuple[Any, ...]) -> str:
    """``("loads", "forces", 0, "point")`` -> ``"loads.forces[0].point"``."""
    out = ""
    for part in parts:
        if isinstance(part, int):
            out += f"[{part}]"
        else:
            out += ("." if out else "") + str(part)
    return out


def _unwrap(tp: Any) -> list[Any]:
    """The concrete types an annotation may hold (Optional/Annotated/unions flattened)."""
    origin = typing.get_origin(tp)
    if origin is typing.Annotated:
        return _unwrap(typing.get_args(tp)[0])
    if origin in (typing.Union, types.UnionType):
        out = []
        for arg in typing.get_args(tp):
            out += _unwrap(arg)
        return out
    return [tp]


def _tag_of(model: type[BaseModel]) -> str | None:
    field = model.model_fields.get("type")
    if field is None or typing.get_origin(field.annotation) is not Literal:
        return None
    return typing.get_args(field.annotation)[0]


def _step(tp: Any, key: Any) -> tuple[Any, bool]:
    """The type reached from ``tp`` by the location element ``key``; the flag says the key was a union tag."""
    candidates = [t for t in _unwrap(tp) if t is not type(None)]
    models = [t for t in candidates if isinstance(t, type) and issubclass(t, BaseModel)]
    if isinstance(key, str) and len(models) > 1:
        for m in models:
            if _tag_of(m) == key:
                return m, True
    for t in candidates:
        if isinstance(t, type) and issubclass(t, BaseModel):
            if isinstance(key, str) and key in t.model_fields:
                return t.model_fields[key].annotation, False
        origin = typing.get_origin(t)
        if origin in (list, tuple) and isinstance(key, int):
            args = typing.get_args(t)
            if origin is tuple and args and args[-1] is not Ellipsis:
                return (args[key] if key < len(args) else None), False
            return (args[0] if args else None), False
        if origin is dict and isinstance(key, str):
            return typing.get_args(t)[1], False
    return None, False


def _resolve(root: type[BaseModel], loc: tuple[Any, ...]) -> tuple[Any, list[Any]]:
    """Follow ``loc`` from ``root``; return the type at its end and the loc without union tags."""
    tp: Any = root
    clean: list[Any] = []
    for key in loc:
        if tp is None:
            clean.append(key)
            continue
        nxt, was_tag = _step(tp, key)
        if not was_tag:
            clean.append(key)
        tp = nxt
    return tp, clean


def _model_keys(tp: Any) -> list[str]:
    keys: list[str] = []
    for t in _unwrap(tp):
        if isinstance(t, type) and issubclass(t, BaseModel):
            keys += [k for k in t.model_fields if k not in keys]
    return keys


def _show(value: Any) -> str:
    if isinstance(value, dict):
        return "a table"
    if isinstance(value, list):
        return "an empty list" if not value else "a list"
    return repr(value)


def _member_label(key: Any) -> bool:
    """True for the labels pydantic puts in an error's location for the members of a union
    (``literal['on','off']``, ``tuple[function-before[...], ...]``): they are not keys of the file."""
    return isinstance(key, str) and ("[" in key or key.startswith("function-"))


def _merge_alternatives(errors: list[Any]) -> list[dict[str, Any]]:
    """Errors of a value that matches none of a union's members come once per member; keep the members that
    fit the value's type (a list is not a misspelled 'on'), and say the others in one message."""
    groups: dict[tuple, list[dict[str, Any]]] = {}
    order: list[tuple] = []
    for err in errors:
        loc = tuple(err["loc"])
        cut = next((i for i, k in enumerate(loc) if _member_label(k)), None)
        key = loc[:cut] if cut is not None else ("", *loc)
        if key not in groups:
            order.append(key)
            groups[key] = []
        groups[key].append(dict(err, loc=tuple(k for k in loc if not _member_label(k))))
    out: list[dict[str, Any]] = []
    for key in order:
        group = groups[key]
        if len(group) > 1 and key and key[0] != "":
            fitting = [e for e in group if not (e["type"] == "literal_error" and not isinstance(e.get("input"), str))]
            group = fitting or group
        out += group
    return out


def problems_from(exc: ValidationError, root: type[BaseModel], prefix: tuple[Any, ...] = ()) -> list[tuple[str, str]]:
    """One (path, message) per error of ``exc`` raised while validating ``root``."""
    out: list[tuple[str, str]] = []
    seen: set[tuple[str, str]] = set()
    for err in _merge_alternatives(list(exc.errors(include_url=False))):
        loc = tuple(err["loc"])
        kind = err["type"]
        ctx = err.get("ctx") or {}
        value = err.get("input")
        if kind == "extra_forbidden":
            parent, clean_parent = _resolve(root, loc[:-1])
            key = loc[-1]
            allowed = _model_keys(parent)
            hint = did_you_mean(str(key), allowed)
            listing = f" (allowed here: {', '.join(allowed)})" if allowed and not hint else ""
            path = format_path(list(prefix) + clean_parent + [key])
            msg = f"unknown key '{key}'{hint}{listing}"
        else:
            _tp, clean = _resolve(root, loc)
            path = format_path(list(prefix) + clean)
            msg = _message(kind, err["msg"], ctx, value, clean)
            if kind == "missing" and clean and isinstance(clean[-1], int):
                path = format_path(list(prefix) + clean[:-1])
                msg = f"must be a list of 2 values; got a list of {clean[-1]}"
            if kind in ("union_tag_invalid", "union_tag_not_found"):
                path = format_path(list(prefix) + clean + ["type"])
        if (path, msg) not in seen:
            seen.add((path, msg))
            out.append((path, msg))
    # a misspelled key already says "did you mean 'length'?": the "length is missing" beside it is noise
    suggested = {(p.rsplit(".", 1)[0], m.split("did you mean '")[1].split("'")[0]) for p, m in out
                 if m.startswith("unknown key") and "did you mean '" in m and "." in p}
    return [(p, m) for p, m in out
            if not (m == "required, but missing" and "." in p and tuple(p.rsplit(".", 1)) in suggested)]


def _message(kind: str, msg: str, ctx: dict, value: Any, loc: list[Any]) -> str:
    if kind == "missing":
        return "required, but missing"
    if kind == "value_error":
        text = msg.removeprefix("Value error, ")
        return text
    if kind in ("union_tag_invalid", "union_tag_not_found"):
        tags = [t.strip().strip("'") for t in str(ctx.get("expected_tags", "")).split(",") if t.strip()]
        if kind == "union_tag_not_found":
            return f"needs a 'type' (one of: {', '.join(tags)})"
        tag = ctx.get("tag")
        return f"unknown type {tag!r}{did_you_mean(str(tag), tags)} (one of: {', '.join(tags)})"
    if kind == "literal_error":
        expected = ctx.get("expected", "")
        choices = [c.strip().strip("'") for c in str(expected).replace(" or ", ",").split(",") if c.strip()]
        return f"must be one of {expected}; got {_show(value)}{did_you_mean(str(value), choices)}"
    if kind in ("model_type", "model_attributes_type", "dict_type"):
        return f"must be a table; got {_show(value)}"
    if kind in ("list_type", "tuple_type"):
        return f"must be a list; got {_show(value)}"
    if kind == "too_short" and ctx.get("field_type") == "Tuple":
        return f"must be a list of {ctx.get('min_length')} values; got {_show(value)}"
    if kind == "too_long" and ctx.get("field_type") == "Tuple":
        return f"must be a list of {ctx.get('max_length')} values; got {_show(value)}"
    if kind == "too_short":
        return f"must have at least {ctx.get('min_length')} item(s); got {_show(value)}"
    if kind == "bool_type":
        return f"must be true or false; got {_show(value)}"
    if kind in ("int_type", "int_parsing", "int_from_float"):
        return f"must be a whole number; got {_show(value)}"
    if kind in ("string_type",):
        return f"must be text; got {_show(value)}"
    if kind == "string_pattern_mismatch":
        return f"must be a name of letters, digits and '_' (not starting with a digit); got {_show(value)}"
    if kind == "string_too_short":
        return f"must not be empty; got {_show(value)}"
    if kind in ("greater_than_equal", "greater_than", "less_than_equal", "less_than"):
        rule = {"greater_than_equal": ">=", "greater_than": ">", "less_than_equal": "<=", "less_than": "<"}[kind]
        limit = next(iter(ctx.values()), "")
        return f"must be {rule} {limit}; got {_show(value)}"
    return f"{msg[0].lower() + msg[1:] if msg else msg}; got {_show(value)}"
